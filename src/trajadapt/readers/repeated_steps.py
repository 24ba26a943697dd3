"""A step written again and again: the model's decoding loop, not something the words ask.

Under greedy decoding a small model can fall into a loop and write the same line, or the same two
lines, over and over until its length runs out: "bring the first 6 waypoints nearer to the chair"
came back as ``t = shift(t, 'left', 0.2)`` five times, "slow down whenever the paddle is within 0.2"
as ``shift(t, 'up', 'slightly')`` and ``shift(t, 'right', 'slightly')`` in turn four times. Each copy
moves the path again, so a loop multiplies whatever the step does; and the readers after this one,
which look for *the one* step of a kind, stand aside before five. Wording never asks for the same
step twice in a row, so a run of back-to-back copies of one line or of one pair of lines keeps its
first copy, and a review note says how many went. A repeated line with something else between the
copies ("up, then left, then up again") is not a loop and is left as it is.
"""

from __future__ import annotations

from collections.abc import Iterable

from trajadapt.code_parse import called_name, parse_code

LONGEST_PERIOD = 2
"""The longest block of lines whose back-to-back copies count as a loop."""


def leave_out_repeats(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each run of back-to-back copies of a step (or a pair of steps) cut to one copy."""
    del asked  # a loop is a loop whatever the words
    return cut_copies(code, "a decoding loop, not asked")


def cut_copies(code: str, why: str) -> tuple[str, list[str]]:
    """``code`` with each run of back-to-back copies cut to one, and a note per run saying ``why``."""
    try:
        parse_code(code)
    except SyntaxError:
        return code, []
    lines = code.splitlines()
    notes: list[str] = []
    index = 0
    while index < len(lines):
        period, copies = _loop_at(lines, index)
        if copies > 1:
            block = lines[index : index + period]
            del lines[index + period : index + period * copies]
            shown = "; ".join(line.strip() for line in block)
            notes.append(f"kept one `{shown}` of {copies} back-to-back copies: {why}")
        index += 1
    return ("\n".join(lines), notes) if notes else (code, [])


def _loop_at(lines: list[str], index: int) -> tuple[int, int]:
    """The block length and the number of back-to-back copies of the loop starting at ``index``."""
    for period in range(1, LONGEST_PERIOD + 1):
        block = [line.strip() for line in lines[index : index + period]]
        if len(block) < period or not all(_is_step(line) for line in block):
            continue
        copies = 1
        while [x.strip() for x in lines[index + period * copies : index + period * (copies + 1)]] == block:
            copies += 1
        if copies > 1:
            return period, copies
    return 1, 1


def _is_step(line: str) -> bool:
    """A line that calls a skill on the trajectory (a copy of ``get_trajectory`` is no loop)."""
    name = called_name(line)
    return name is not None and name not in ("get_trajectory", "detect_objects")

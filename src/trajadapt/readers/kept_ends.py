"""An end of the path the words keep where it is, and steps that move it: the end put back.

"Keep the goal where it is" beside ``pass_over`` of an object near the goal, "keep both ends in
place" beside a ``shift_start`` nobody asked, "keeping start and end the same" beside two whole-path
shifts: the steps moved an end the words keep (``words.kept_ends``: "keep the start fixed", "with
the endpoints pinned", "don't move the start or the goal"). For each kept end:

- a step that moves only that end (``shift_start`` for the start, ``shift_goal`` for the goal) asks
  the opposite of the words and is left out;
- when another step may move that end (any step that changes positions, except those that keep both
  ends by their promise: ``KEEP_ENDS``), the end is put back as the last step: the goal with
  ``reach(t, detect_objects('goal'))``, the start with ``pass_through(t, detect_objects('start'),
  0)`` (both bend the path back smoothly, and do nothing where the end did not move). A program that
  goes on past the goal (``extend``, ``append_segment``) keeps its goal as moved where the words ask
  to go on ("after the goal", "past the end"); where they do not ("then head to the same endpoint",
  "then carry on to the same goal": a going-on towards the kept goal), such a step moves the kept
  goal and is left out. A ``stop_at`` beside a kept goal, where the words say no word of stopping, ends
  the path before it ("the end point stays as is" beside ``stop_at(t, <a midpoint>)``) and is left out.

Code that is not made of skill calls alone is left alone. A review note says what changed and why.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    SPEED_STEPS,
    after_last_step,
    assigned_call,
    called_name,
    part_argument,
    skill_program,
)
from trajadapt.readers.end_words import kept_ends
from trajadapt.readers.stop_words import STOPPING
from trajadapt.skills import SKILL_NAMES

OWN_MOVE = {"start": "shift_start", "goal": "shift_goal"}
"""The step that moves only each end (and so keeps the other: ``shift_goal`` keeps the start)."""
KEEP_ENDS = frozenset(
    {"move_closer", "move_away", "lift_middle", "resample", "wait", "path_size", "midpoint"}
)
"""Steps that change positions and keep both ends where they are, by their promise."""
PUT_BACK = {
    "goal": "{t} = reach({t}, detect_objects('goal'))",
    "start": "{t} = pass_through({t}, detect_objects('start'), 0)",
}
"""The step that puts each end back where the original path has it."""
PAST_THE_GOAL = ("extend", "append_segment")
_GOING_ON_VERB = r"continu\w*|carry\w*\s+on|keep\w*\s+(?:going|moving|on)|go(?:es|ing)?\s+on"
GOING_ON = re.compile(
    rf"\b(?:(?:after|past|beyond)(?=\s+(?:\w+\s+){{0,2}}?(?:goal|end\w*|destination|finish\w*|target|final|there))"
    rf"|further|farther|more|another|{_GOING_ON_VERB}|onwards?|extend\w*|lengthen\w*|prolong\w*|append\w*)\b",
    re.I,
)
"""Words that may ask the path to go on past its goal ("after the goal", "keep going", "0.1 further"): a
going-on beside a kept goal is then kept. "Past", "after" and "beyond" count before an end word only
("brushes right past the ear" goes on nowhere)."""
RESUMING = re.compile(
    rf"\b(?:{_GOING_ON_VERB})\s+(?:on\s+)?(?:to|towards?|into|up\s+to)\s+(?:the\s+|its\s+|your\s+)?"
    r"(?:same|original|usual|old|planned|intended|existing|normal|regular|unchanged)\s+(?:\w+\s+)?"
    r"(?:goal|end\w*|destination|finish\w*|target|final\s+\w+)",
    re.I,
)
"""A going-on whose destination is the kept goal ("then carry on to the same goal", "continue on to
the original end point"): the path resumes towards its goal and goes on nowhere past it."""
LEAVES = {
    "start": ("middle", "second half", "end", "final", "goal"),
    "goal": ("middle", "first half", "start", "beginning"),
}
"""The parts of ``shift_part`` that leave each end where it is."""


def _before_the_closing_limits(lines: list[str], index: int) -> int:
    """Where an end is put back: before the program's closing height limits that keep the ends.

    "Keep the middle low, at or below z = 0, then on to the usual end point": the goal put back after
    ``stay_below(t, 0, keep_ends=True)`` would bend the middle up again.
    """
    while index > 0 and _keeps_ends_in_its_limit(lines[index - 1]):
        index -= 1
    return index


def _keeps_ends_in_its_limit(line: str) -> bool:
    found = assigned_call(line)
    return (
        found is not None
        and found[2] in ("stay_above", "stay_below")
        and any(k.arg == "keep_ends" for k in found[1].keywords)
    )


def keep_kept_ends(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with the ends the words keep left where they are (see the module), and notes."""
    asked = list(asked)
    kept = kept_ends(asked)
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES)
    if not kept or program is None:
        return code, []
    variable, notes = program[1], list[str]()
    for end in sorted(kept):
        for line in [x for x in lines if called_name(x) == OWN_MOVE[end]]:
            lines.remove(line)
            notes.append(f"left out `{line.strip()}`: the words keep the {end} where it is")
    if "goal" in kept and not any(GOING_ON.search(RESUMING.sub(" ", words)) for words in asked):
        for line in [x for x in lines if called_name(x) in PAST_THE_GOAL]:
            lines.remove(line)
            notes.append(f"left out `{line.strip()}`: the words keep the goal and go on nowhere past it")
    if "goal" in kept and not any(STOPPING.search(words) for words in asked):
        for line in [x for x in lines if called_name(x) == "stop_at"]:
            lines.remove(line)
            notes.append(f"left out `{line.strip()}`: the words keep the goal and ask no stop before it")
    moving = {end for end in kept if _moves_ends(lines, end)}  # before any end is put back
    for end in sorted(moving):
        step = PUT_BACK[end].format(t=variable)
        if step not in (x.strip() for x in lines):
            index = _before_the_closing_limits(lines, after_last_step(lines, SKILL_NAMES))
            lines.insert(index, step)
            notes.append(f"added `{step}`: the words keep the {end} where it is, and a step may move it")
    return ("\n".join(lines), notes) if notes else (code, [])


def _moves_ends(lines: list[str], end: str) -> bool:
    """Whether a step may move the end: one that changes positions and does not keep that end."""
    names = [called_name(line) for line in lines]
    if end == "goal" and any(name in PAST_THE_GOAL for name in names):
        return False
    return any(_may_move(line, end) for line in lines)


def _may_move(line: str, end: str) -> bool:
    """Whether the step on ``line`` may move the end (``shift`` keeps the start; a middle keeps both)."""
    name = called_name(line)
    if name not in SKILL_NAMES or name in KEEP_ENDS or name in SPEED_STEPS or name in OWN_MOVE.values():
        return False  # an end's own move is left out above, or keeps this end
    if name == "shift_part":
        return _part(line) not in LEAVES[end]
    return not (name == "shift" and end == "start" and "alternate" not in line)


def _part(line: str) -> str | None:
    """The part a ``shift_part`` line names (its fourth argument or ``part=``), if a word."""
    found = assigned_call(line)
    return None if found is None else part_argument(found[1])

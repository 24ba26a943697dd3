"""Objects a clause asks the path to pass over, and no step that passes over them: ``pass_over``.

"Make sure it flies over the table on its way" came back as ``avoid(t, table, 1.8)``, "fly over the
top of the Person" as ``keep_side(t, 'up', Person)``, "modify the trajectory so it passes above the
red marker and the remote" as ``shift(t, 'up')``: the model read "over" as a side, a height or a
clearance, and the path never crossed the objects. A clause asks to pass over the scene objects it
names after a word of passing over (``OVER_WORDS``: "over", "above", "across the top of", "over the
top of"), unless it negates, moves over to a place ("fly over to the lantern"), or ends or pauses
there ("finish 10 cm above the soap", "hover above it": a place of its own, left to the end and pause
readers), and only objects named right after the word ("over towards the cup", "over 0.2 away from the
box" pass over nothing). A height said before the word ("fly 0.2 over the box") is the pass's
clearance. When no step passes over anything:

- the one step on one of them that is not ``pass_over`` (``avoid``, ``move_away``, ``keep_side``,
  ``pass_through``, ``move_closer``) becomes ``pass_over`` of them;
- else the one upward step of a vague amount (``shift``, ``shift_part``, ``lift_middle`` up, with no
  number) is the model's guess at passing over, and ``pass_over`` takes its place;
- else ``pass_over`` of them is added after the last step.

A program with a ``pass_over`` of its own (the model's reading stands), or code that is not made of skill
calls alone, is left alone. A review note says what changed.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    after_last_step,
    assigned_call,
    call_of,
    called_name,
    detected_names,
    direction_argument,
    in_place_of,
    skill_program,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import NUMBER_TEXT, longest_names, names_in
from trajadapt.skills import SKILL_NAMES

OVER_WORDS = re.compile(
    r"\b(?:(?:right|directly|straight|just)\s+)?(?:over|above|across)(?:\s+the\s+top\s+of)?\b(?!\s+to\b)",
    re.I,
)
"""A word of passing over something ("over the box", "directly above the cup", "over the top of")."""
NOT_PASSING = re.compile(
    r"\b(?:not|never|no|don't|avoid\w*|without)\b|n't\b"
    r"|\b(?:finish\w*|end(?:s|ed|ing)?|stop\w*|land\w*|rest\w*|arriv\w*|hover\w*|paus\w*|wait\w*|linger\w*"
    r"|hold\w*|park\w*|settl\w*)\b",
    re.I,
)
"""Words that make "over X" no passing over: a negation, or an end or a pause placed there."""
LIST_END = re.compile(r",|;|\b(?:instead|rather|while|near|around|beside|past|but|then|before|after)\b", re.I)
"""Where the objects after a word of passing over end ("over the box instead of around the lamp")."""
GUESSED = ("avoid", "move_away", "keep_side", "pass_through", "move_closer")
"""Steps on an object that may be the model's reading of passing over it."""
UPWARD = ("shift", "shift_part", "lift_middle")


def add_asked_pass_overs(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with ``pass_over`` of the objects the words ask to pass over (see the module), noted."""
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    wanted, height = _passes(" ".join(asked), list(names))
    if program is None or not wanted or any(called_name(line) == "pass_over" for line in lines):
        return code, []
    step = _step(program[1], wanted, height)
    index, why = _guessed_step(lines, wanted)
    if index is not None:
        note = f"`{lines[index].strip()}` -> `{step}`: the words ask to pass over {_listed(wanted)}, {why}"
        lines[index] = in_place_of(lines[index], step)
    else:
        lines.insert(after_last_step(lines, SKILL_NAMES), step)
        note = f"added `{step}`: the words ask to pass over {_listed(wanted)} and no step does"
    return "\n".join(lines), [note]


def passed_over(words: str, names: list[str]) -> list[str]:
    """The scene objects the clauses of ``words`` ask the path to pass over, in the order said."""
    return _passes(words, names)[0]


def _passes(words: str, names: list[str]) -> tuple[list[str], str | None]:
    """The objects to pass over, in order, and the one height above them the words give (or None)."""
    found: list[str] = []
    heights: set[str] = set()
    for clause in split_clauses(words, names):
        over = OVER_WORDS.search(clause)
        if over is None or NOT_PASSING.search(clause):
            continue
        after = clause[over.end() :]
        listed = LIST_END.split(after)[0]
        if not any(re.match(rf"\s+(?:the\s+)?{re.escape(n)}\b", after, re.I) for n in names):
            continue  # "over towards the cup", "over 0.2 away from the box": no object right after
        height = re.search(rf"(?<![\w.])({NUMBER_TEXT})\s*$", clause[: over.start()])
        heights |= {height.group(1)} if height else set()
        named = longest_names(names_in(listed, names))
        found += sorted(
            (n for n in named if n not in found), key=lambda n: listed.casefold().find(n.casefold())
        )
    return found, (heights.pop() if len(heights) == 1 else None)


def _guessed_step(lines: list[str], wanted: list[str]) -> tuple[int | None, str]:
    """The step that is the model's reading of passing over, and why; (None, '') where none is."""
    on_them = [i for i, x in enumerate(lines) if _on_them_alone(call_of(x, GUESSED), wanted)]
    if len(on_them) == 1:
        return on_them[0], f"not {called_name(lines[on_them[0]])} of it"
    upward = [i for i, x in enumerate(lines) if _vague_upward(x)]
    if len(upward) == 1:
        return upward[0], "not a move up by no stated amount"
    return None, ""


def _on_them_alone(call: ast.Call | None, wanted: list[str]) -> bool:
    """Whether a step is on some of the objects and no other (any it detects: ``keep_side(t, 'up', X)``)."""
    objects = set(detected_names(call)) - {""} if call is not None else set()
    return bool(objects) and objects <= set(wanted)


def _vague_upward(line: str) -> bool:
    """Whether ``line`` moves the path (or a part) up by a vague amount: a guess at passing over."""
    found = assigned_call(line)
    if found is None or found[2] not in UPWARD or direction_argument(found[1]) != "up":
        return False
    given = found[1].args[2:3] + [k.value for k in found[1].keywords if k.arg == "amount"]
    amount = given[0] if given else None
    return amount is None or (isinstance(amount, ast.Constant) and not isinstance(amount.value, int | float))


def _step(t: str, wanted: list[str], height: str | None) -> str:
    """The ``pass_over`` step of one object or a list of them (at a stated height), on variable ``t``."""
    points = [f"detect_objects({name!r})" for name in wanted]
    clearance = f", {height}" if height else ""
    return (
        f"{t} = pass_over({t}, {points[0] if len(points) == 1 else '[' + ', '.join(points) + ']'}{clearance})"
    )


def _listed(wanted: list[str]) -> str:
    return " and ".join(wanted)

"""A height the user gives with its relation, and a height step with the wrong relation, replaced.

A small model writes ``stay_below(t, 0.1)`` for "stay at a height of 0.1 from the ground": the
number is right, the relation is not (the path should fly at 0.1, not merely under it). The words
around a height number say which skill keeps it: "at a height of 0.1", "at an altitude of 2", "fly
at 1.5" -> ``set_height``; "below", "under", "lower than", "at most" -> ``stay_below``; "above",
"over", "higher than", "at least", "exceed" -> ``stay_above`` (the height may be named by its axis:
"higher than z = 0.2"); a negation just before turns the
relation round ("never higher than 3", "do not exceed 3" -> ``stay_below``). When the words give
exactly one such height and the code has exactly one height step with that number and another
skill, the step's skill is replaced; with no height step at all, so is the one clearance from a
point the code made up by that number (``avoid(t, [0, 0, 0], 0.1)`` for "hold a height of 0.1
from the ground"). A review note says so.

A number the words give as a change is no height at all: "descend by 0.1", "the path raised by
0.2", "climb 0.3" move the path by that much (``clause_amounts.direction_amounts``), where the
model wrote ``set_height(t, 0.1)`` or ``stay_below(t, 0.1)``. When the words give no height, no
ground or floor, and one amount up or down, the one height step with that number becomes
``shift`` by it. A limit the clause holds through the middle of the path ("through the middle of the
flight stay at least 0.3 off the ground") keeps the start and the goal (``keep_ends=True``). A height
with a metric unit is read in metres ("at least 20 cm up" is 0.2).
"""

from __future__ import annotations

import ast
from collections.abc import Iterable

from trajadapt.code_parse import DISTANCE_STEPS, after_last_step, assigned_call, in_place_of, skill_program
from trajadapt.readers.clause_amounts import direction_amounts
from trajadapt.readers.height_words import (
    GROUND,
    HEIGHT_STEPS,
    MIDDLE,
    OWN_LIMITS,
    SIDEWAYS,
    VERTICAL,
    AskedHeight,
    clause_heights,
)
from trajadapt.skills import SKILL_NAMES


def _added_band(code: str, heights: list[AskedHeight]) -> tuple[str, list[str]]:
    """``code`` with both limits of the band the words give added last, and a note each."""
    notes: list[str] = []
    for asked in heights:
        code, added = _added_height(code.splitlines(), asked.skill, asked.height, asked.clause)
        notes += added
    return code, notes


def _is_one_band(heights: list[AskedHeight]) -> bool:
    """Whether the heights the words give are the two limits of one band."""
    skills = [asked.skill for asked in heights]
    return skills == ["stay_above", "stay_below"] and len({asked.clause for asked in heights}) == 1


def relate_heights(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its one height step of the asked number given the asked relation, and a note."""
    words = " ".join(asked)
    heights = clause_heights(words)
    if not heights:
        return _height_as_change(code, words)
    if _is_one_band(heights) and not any(_height_step(x, options=True) for x in code.splitlines()):
        return _added_band(code, heights)
    if len(heights) != 1:
        return code, []
    skill, height, clause, held = heights[0]
    lines = code.splitlines()
    step = _one_height_step(lines, height, options=True)
    if step is None and not any(_height_step(x, options=True) for x in lines):
        step = _clearance_from_a_made_up_point(lines, height)
        if step is None:
            return _added_height(lines, skill, height, clause, _ends_kept(skill, held))
    if step is None or (step[1] == skill and not _through_the_middle(skill, held)):
        return code, []
    line, changed = lines[step[0]], f"t = {skill}(t, {height:g}{_ends_kept(skill, held)})"
    lines[step[0]] = in_place_of(line, changed)
    return "\n".join(lines), [
        f"`{line.strip()}` -> `{changed}`: the instruction asks for {_relation(skill)} {height:g}"
    ]


def _added_height(
    lines: list[str], skill: str, height: float, words: str, option: str = ""
) -> tuple[str, list[str]]:
    """The height the words ask as the last step, when no step keeps any height ("fly no higher than 1.6").

    Only for words that speak of height itself ("above", "below", "higher than", "altitude", "z"): "more
    than 0.5 away from the box" gives no height to add.
    """
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None or not VERTICAL.search(words) or SIDEWAYS.search(words):
        return "\n".join(lines), []
    step = f"{program[1]} = {skill}({program[1]}, {height:g}{option})"
    lines.insert(after_last_step(lines, SKILL_NAMES), step)
    return "\n".join(lines), [
        f"added `{step}`: the instruction asks for {_relation(skill)} {height:g} and no step keeps it"
    ]


def _clearance_from_a_made_up_point(lines: list[str], height: float) -> tuple[int, str] | None:
    """The one distance step from a point the code made up (``avoid(t, [0, 0, 0], 0.1)``) by the height.

    "Hold a height of 0.1 from the ground" came back as a clearance of 0.1 from the origin, which
    leaves the path where it was wherever it is more than 0.1 from that one point.
    """
    steps = []
    for index, line in enumerate(lines):
        found = assigned_call(line)
        if found is None or found[2] not in DISTANCE_STEPS or len(found[1].args) < 3:
            continue
        point, amount = found[1].args[1], found[1].args[2]
        made_up = isinstance(point, ast.List | ast.Tuple) and all(
            isinstance(e, ast.Constant) for e in point.elts
        )
        if made_up and isinstance(amount, ast.Constant) and amount.value == height:
            steps.append((index, found[2]))
    return steps[0] if len(steps) == 1 else None


def _height_as_change(code: str, words: str) -> tuple[str, list[str]]:
    """``code`` with its one height step of the words' one up/down amount made a shift by it."""
    vertical = {d: a for d, a in direction_amounts(words).items() if d in ("up", "down")}
    if len(vertical) != 1 or GROUND.search(words):
        return code, []
    (direction, amount), lines = next(iter(vertical.items())), code.splitlines()
    step = _one_height_step(lines, amount, options=True)
    if step is None:
        return code, []
    line, changed = lines[step[0]], f"t = shift(t, '{direction}', {amount:g})"
    lines[step[0]] = in_place_of(line, changed)
    note = f"`{line.strip()}` -> `{changed}`: the instruction moves the path {direction} by {amount:g}"
    return "\n".join(lines), [note]


def _through_the_middle(skill: str, clause: str) -> bool:
    """Whether the clause holds a height limit through the middle of the path only."""
    return skill in OWN_LIMITS and MIDDLE.search(clause) is not None


def _ends_kept(skill: str, clause: str) -> str:
    """The limit step's option that keeps the start and the goal, where the clause holds it in the middle."""
    return ", keep_ends=True" if _through_the_middle(skill, clause) else ""


def _relation(skill: str) -> str:
    return {"set_height": "a height of", "stay_below": "a height below", "stay_above": "a height above"}[
        skill
    ]


def _one_height_step(lines: list[str], number: float, options: bool) -> tuple[int, str] | None:
    """The index and skill of the code's one height step, if there is one and it holds ``number``."""
    steps = [(i, found) for i, line in enumerate(lines) if (found := _height_step(line, options)) is not None]
    if len(steps) != 1:
        return None
    index, (skill, value) = steps[0]
    if value is None or abs(value - number) > 1e-9 * max(1.0, number):
        return None
    return index, skill


def _height_step(line: str, options: bool = False) -> tuple[str, float | None] | None:
    """The skill and numeric height of a one-argument height step (``stay_below(t, 0.1)``).

    With ``options``, a step with keyword options too (``keep_goal=True``).
    """
    found = assigned_call(line)
    if found is None or found[2] not in HEIGHT_STEPS or len(found[1].args) != 2:
        return None
    if found[1].keywords and not options:
        return None
    height, sign = found[1].args[1], 1.0
    if isinstance(height, ast.UnaryOp) and isinstance(height.op, ast.USub):  # a height below 0: -0.2
        height, sign = height.operand, -1.0
    value = height.value if isinstance(height, ast.Constant) else None
    if isinstance(value, int | float) and not isinstance(value, bool):
        return found[2], sign * float(value)
    return found[2], None

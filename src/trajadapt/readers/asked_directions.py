"""A direction a clause asks the whole path to move in, and no step that moves anything that way.

A small model drops a clause of a compound instruction: "go to the front decelerating to 0 speed"
came back as a deceleration alone, "raise the path slightly" beside a moved start as the start's
move alone. A clause that names exactly one direction (``words.said_directions``: "front", "raise",
"descend", ...), no part or end of the path, no negation, and uses the direction word as a move
rather than a place ("above the lamp", "left of the box", "up to the lamp" are places) asks the path
to move that way, whatever else it asks ("go slightly upwards keeping a smaller distance from the
chair"). When no step of the code has that direction or its opposite among its
arguments (``extend(t, 1.5, 'back')`` goes back; a step the other way is a contradiction, which the
effect report flags, not a dropped clause; a step that moves only the start or the goal the other way
is no contradiction when the words name that end) nor, for up and down, sets a height, the reader adds
``shift(t, direction, <the clause's vague word>)`` as the first step; the readers after it give it
the clause's number ("by 0.1"). Code that is not made of skill calls alone is left alone (what
it moves cannot be read). Code with no step at all gets the shift too: whether the model wrote it or
a reader left out every step it had ("0.3 over to the right" answered with ``pass_over`` of objects
the words never name), the clause asked a move and nothing makes it. A review note says so.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, called_name, skill_program
from trajadapt.model.geometry import DIRECTION_SYNONYMS, OPPOSITE_DIRECTIONS
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import GOAL, PART_OR_END, START, intensity_word, said_directions
from trajadapt.skills import SKILL_NAMES

PLACE_OF = re.compile(
    r"\b(?:above|below|beneath|underneath|under|over(?!\s+to\b)|behind|atop|up to|down to)\b"
    r"|\b(?:left|right|front|back|top|bottom|side)\s+(?:side\s+)?of\b",
    re.I,
)
"""A direction word used as a place ("above the lamp", "to the left of the box"), not a move ("over to
the right" is one)."""
NEGATION = re.compile(r"\b(?:not|never|no|don't|avoid|without)\b|n't\b", re.I)
HEIGHT_STEPS = ("set_height", "stay_above", "stay_below", "lift_middle")
END_STEPS = {"shift_goal": GOAL, "shift_start": START}
"""Steps that move only an end, with the words that name it: where the words name that end, a step the
other way does not undo a move of the whole path ("raise the path a little but move the goal down");
one the same way still makes it ("the goal is off; move it right": "it" is the goal)."""


def add_asked_directions(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with a shift for each direction a clause asks and no step makes (see the module)."""
    lines = code.splitlines()
    words = " ".join(asked)
    named = {step for step, end in END_STEPS.items() if end.search(words)}
    steps = [(called_name(line), _directions(line)) for line in lines]
    moved = {direction for _, directions in steps for direction in directions}
    against = {direction for name, directions in steps if name not in named for direction in directions}
    heights = any(called_name(line) in HEIGHT_STEPS for line in lines)
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    start, variable = program[0] + 1, program[1]
    added: list[str] = []
    notes: list[str] = []
    for clause in (c for words in asked for c in split_clauses(words)):
        direction = asked_move(clause)
        if direction is None or direction in moved or OPPOSITE_DIRECTIONS[direction] in against:
            continue
        if heights and direction in ("up", "down"):
            continue
        word = intensity_word(clause)
        step = f"{variable} = shift({variable}, {direction!r}{f', {word!r}' if word else ''})"
        added.append(step)
        moved.add(direction)
        against.add(direction)
        notes.append(f"added `{step}`: the words ask to go {direction} ({clause.strip()!r}) and no step does")
    if not added:
        return code, []
    return "\n".join([*lines[:start], *added, *lines[start:]]), notes


def _directions(line: str) -> set[str]:
    """The direction words among a step's arguments ('upwards' -> 'up'): ``extend(t, 1.5, 'back')``."""
    found = assigned_call(line)
    if found is None:
        return set()
    words = [node.value for node in ast.walk(found[1]) if isinstance(node, ast.Constant)]
    return {
        DIRECTION_SYNONYMS[w.strip().lower()]
        for w in words
        if isinstance(w, str) and w.strip().lower() in DIRECTION_SYNONYMS
    }


def asked_move(clause: str) -> str | None:
    """The one direction the clause asks the path to move in, or None."""
    directions = said_directions(clause)
    if len(directions) != 1:
        return None
    if PLACE_OF.search(clause) or PART_OR_END.search(clause) or NEGATION.search(clause):
        return None
    return next(iter(directions))

"""A direction a clause asks the whole path to move in, and no step that moves anything that way.

A small model drops a clause of a compound instruction: "go to the front decelerating to 0 speed"
came back as a deceleration alone, "raise the path slightly" beside a moved start as the start's
move alone. A clause that names exactly one direction (``direction_words.said_directions``: "front", "raise",
"descend", ...), no part or end of the path, no negation, and uses the direction word as a move
rather than a place ("above the lamp", "left of the box", "up to the lamp" are places) asks the path
to move that way, whatever else it asks ("go slightly upwards keeping a smaller distance from the
chair"). When no step of the code has that direction or its opposite among its
arguments (``extend(t, 1.5, 'back')`` goes back; a step the other way is a contradiction, which the
effect report flags, not a dropped clause; a step that moves only the start or the goal the other way
is no contradiction when the words name that end) nor, for up and down, sets a height, the reader adds
``shift(t, direction, <the clause's vague word>)`` as the first step; the readers after it give it
the clause's number ("by 0.1"). A clause that asks one end of the path to move ("end 0.2 higher than
now", "finish 0.3 further to the right", "start further left"; not a move past the goal: "once
there, go back") gets ``shift_goal`` / ``shift_start`` in the same way, when no step moves that end
that way. Where exactly one shift of the code goes in a direction no word says, it is the model's
guess at the asked move, and the asked step takes its place instead of being added; so does the one
whole-path shift the way a start move asks, when no other clause asks the path to go that way (a
shift keeps the start, so it cannot be the start's move), and the one part move the way an end move
asks, where the words name no part and no other clause says that way ("end 5 cm higher" answered
with the middle moved up). Code that is
not made of skill calls alone is left alone (what
it moves cannot be read). Code with no step at all gets the shift too: whether the model wrote it or
a reader left out every step it had ("0.3 over to the right" answered with ``pass_over`` of objects
the words never name), the clause asked a move and nothing makes it. A review note says so.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, called_name, in_place_of, skill_program
from trajadapt.model.geometry import DIRECTION_SYNONYMS, OPPOSITE_DIRECTIONS
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.end_words import without_kept_ends
from trajadapt.readers.part_words import ENDS_MOVED
from trajadapt.readers.words import GOAL, PART_OR_END, START, intensity_word, part_named
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
UNSAID_GUESSES = ("shift", "shift_goal", "shift_start", "shift_part")
"""Steps whose direction, when no word says it, is the model's guess at a move the words ask."""
END_STEPS = {"shift_goal": GOAL, "shift_start": START}
"""Steps that move only an end, with the words that name it: where the words name that end, a step the
other way does not undo a move of the whole path ("raise the path a little but move the goal down");
one the same way still makes it ("the goal is off; move it right": "it" is the goal)."""


def add_asked_directions(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with a shift for each direction a clause asks and no step makes (see the module)."""
    lines = code.splitlines()
    words = " ".join(asked)
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    notes = _directed_part_moves(lines, asked, words)
    named = {step for step, end in END_STEPS.items() if end.search(words)}
    steps = [(called_name(line), _directions(line)) for line in lines]
    moved = {direction for _, directions in steps for direction in directions}
    against = {direction for name, directions in steps if name not in named for direction in directions}
    heights = any(called_name(line) in HEIGHT_STEPS for line in lines)
    start, variable = program[0] + 1, program[1]
    added: list[str] = []
    clauses = [c for words in asked for c in split_clauses(words)]
    for clause in clauses:
        skill, direction = asked_end_move(clause)
        made = _end_moves(lines, END_NAMES.get(skill, ""))
        if direction is None:
            skill, direction, made = "shift", asked_move(clause), moved
        if direction is None or direction in made or OPPOSITE_DIRECTIONS[direction] in against:
            continue
        if heights and direction in ("up", "down"):
            continue
        word = intensity_word(clause)
        step = f"{variable} = {skill}({variable}, {direction!r}{f', {word!r}' if word else ''})"
        what = "go" if skill == "shift" else f"move the {END_NAMES[skill]}"
        guess = _guessed_step(lines, words, skill, direction, [c for c in clauses if c != clause])
        if guess is not None and not added:
            index, why = guess
            notes.append(f"`{lines[index].strip()}` -> `{step.strip()}`: the words ask to {what} {direction} "
                         f"({clause.strip()!r}), and {why}")  # fmt: skip
            lines[index] = in_place_of(lines[index], step)
        else:
            added.append(step)
            notes.append(
                f"added `{step}`: the words ask to {what} {direction} ({clause.strip()!r}) and no step does"
            )
        moved.add(direction)
        against.add(direction)
    if not notes:
        return code, []
    return "\n".join([*lines[:start], *added, *lines[start:]]), notes


def _directed_part_moves(lines: list[str], asked: Iterable[str], words: str) -> list[str]:
    """The one part move in a direction no word says, turned the way the clause naming a part asks.

    "Raise the second half of the path by 0.1" came back as ``shift_part(t, 'right', 0.1, part='second
    half')``, "lower the middle about 10 cm" as ``lift_middle(t, 'up', 0.1)``: the part and the amount
    are the clause's, the direction the model's guess.
    """
    guess = _unsaid_shift(lines, words)
    if guess is None or called_name(lines[guess]) != "shift_part":
        guess = _unsaid_shift(lines, words, ("lift_middle",))  # a bow of the middle, where no shift guesses
    found = assigned_call(lines[guess]) if guess is not None else None
    if guess is None or found is None or len(found[1].args) < 2:
        return []
    for clause in (c for request in asked for c in split_clauses(request)):
        directions = said_directions(clause)
        if len(directions) != 1 or part_named(clause) is None:
            continue
        if any(pattern.search(clause) for pattern in (PLACE_OF, NEGATION, ONCE_THERE)):
            continue
        before, direction = lines[guess].strip(), next(iter(directions))
        found[1].args[1] = ast.Constant(direction)
        lines[guess] = in_place_of(lines[guess], ast.unparse(found[0]))
        return [f"`{before}` -> `{lines[guess].strip()}`: the words ask the part to go {direction} "
                f"({clause.strip()!r}), and no word asks the step's direction"]  # fmt: skip
    return []


def _end_moves(lines: list[str], end: str) -> set[str]:
    """The directions the steps move one end in: that end's own, its part's, or the whole path's.

    A whole-path ``shift`` keeps the start (it blends in after it), so it moves only the goal.
    """
    own = {"goal": ("shift", "shift_goal", "extend", "append_segment"), "start": ("shift_start",)}
    return {
        direction
        for line in lines
        if called_name(line) in own.get(end, ("shift",))
        or (called_name(line) == "shift_part" and end in line)
        for direction in _directions(line)
    }


def _guessed_step(
    lines: list[str], words: str, skill: str, direction: str, others: list[str]
) -> tuple[int, str] | None:
    """The step that is the model's reading of the asked move, with why, or None."""
    unsaid = _unsaid_shift(lines, words)
    if unsaid is not None:
        return unsaid, "no word asks the step's direction"
    start_shift = _shift_for_the_start(lines, direction, others) if skill == "shift_start" else None
    if start_shift is not None:
        return start_shift, "a shift keeps the start"
    asked_too = any(direction in said_directions(other) for other in others)
    unnamed = _unnamed_part_move(lines, words, direction) if skill in END_NAMES and not asked_too else None
    if unnamed is not None:
        return unnamed, "no word names the part the step moves"
    return None


def _unnamed_part_move(lines: list[str], words: str, direction: str) -> int | None:
    """The index of the one part move the end's way, of a part the words never name, else None.

    "Have the path end 5 cm higher" answered ``shift_part(t, 'up', None, 'middle')``: the way is the
    clause's, the part the model's guess, and the end move takes its place.
    """
    moves = [
        index
        for index, line in enumerate(lines)
        if called_name(line) == "shift_part" and direction in _directions(line)
    ]
    if len(moves) != 1:
        return None
    found = assigned_call(lines[moves[0]])
    given = (
        [] if found is None else found[1].args[3:4] + [k.value for k in found[1].keywords if k.arg == "part"]
    )
    part = given[0].value if given and isinstance(given[0], ast.Constant) else None
    named = {part_named(clause) for clause in split_clauses(words)}
    return moves[0] if isinstance(part, str) and part not in (*END_PARTS, *named) else None


def _shift_for_the_start(lines: list[str], direction: str, others: list[str]) -> int | None:
    """The index of the one whole-path shift the start's way that no other clause asks, else None.

    "Start half a metre further forward" answered ``shift(t, 'front', 0.5)``: a shift keeps the start,
    so it is the model's reading of the start's move, and ``shift_start`` takes its place.
    """
    if any(asked_move(other) == direction for other in others):
        return None
    shifts = [
        index
        for index, line in enumerate(lines)
        if called_name(line) == "shift" and direction in _directions(line)
    ]
    return shifts[0] if len(shifts) == 1 else None


def _unsaid_shift(lines: list[str], words: str, steps: tuple[str, ...] = ()) -> int | None:
    """The index of the one shift whose direction no word says, the model's guess at a move; else None."""
    said = said_directions(words)
    guesses = [
        index
        for index, line in enumerate(lines)
        if called_name(line) in (steps or UNSAID_GUESSES)
        and (found := _directions(line))
        and not found & said
    ]
    return guesses[0] if len(guesses) == 1 else None


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


END_NAMES = {"shift_goal": "goal", "shift_start": "start"}
END_PARTS = ("start", "beginning", "end", "goal")
"""Parts that are an end of the path: an end move's clause names one (``words.part_named``)."""
ONCE_THERE = re.compile(
    r"\b(?:reach\w*|arriv\w*|got|get(?:s|ting)?\s+(?:to|there)|once|after|when\w*|until|before|past|beyond)\b",
    re.I,
)
"""A time at the goal ("once the goal is reached, go back") or a place past it ("carry on past the end
toward the left"): a move past the goal, not of it."""
OTHER_PARTS = re.compile(r"\b(?:middle|half|halfway|first|waypoints?|section|segment|portion|part)\b", re.I)


def asked_end_move(clause: str) -> tuple[str, str | None]:
    """The end step and the one direction a clause asks one end of the path to move in ('', None if none).

    "End 0.2 higher than now" asks ``shift_goal`` up; "finish 0.3 further to the right" right; a
    clause that names both ends, another part, a place ("above the lamp") or a negation asks no end move.
    """
    clause = without_kept_ends(clause)  # "move the goal back, keeping the start unchanged" moves the goal
    ends = [skill for skill, words in ENDS_MOVED.items() if words.search(clause)]
    directions = said_directions(clause)
    if len(ends) != 1 or len(directions) != 1:
        return "", None
    if any(words.search(clause) for words in (PLACE_OF, NEGATION, OTHER_PARTS, ONCE_THERE)):
        return "", None
    return ends[0], next(iter(directions))


def asked_move(clause: str) -> str | None:
    """The one direction the clause asks the path to move in, or None."""
    directions = said_directions(clause)
    if len(directions) != 1:
        return None
    if PLACE_OF.search(clause) or PART_OR_END.search(clause) or NEGATION.search(clause):
        return None
    return next(iter(directions))

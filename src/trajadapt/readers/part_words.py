"""What the words ask of a part of the path: the start, the goal, past the goal, the first N waypoints.

Each clause of the user's words (``clause_split.split_clauses``) that names one part of the path and
one direction asks a move of that part (``PartMove``); the part-scope reader puts the step written
for it on that part, and adds a going-on past the goal that no step makes.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass

from trajadapt.readers.clause_amounts import in_metres
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import directed_numbers, said_directions
from trajadapt.readers.words import (
    GOAL,
    NUMBER_TEXT,
    PAST_THE_GOAL,
    SPEED_WORDS,
    START,
    intensity_word,
    part_named,
    whole_count,
)

REFERENCE = re.compile(
    r"\b(?:from|at|since|before|until|till|to|towards?|near|in|reach\w*|approach\w*|arriv\w*)\s+$", re.I
)  # a part after these words is a place on the path, not the part that moves
FIRST_COUNT = re.compile(r"\b(?:first|initial|opening|leading)\s+(\d+|[a-z]+)\s+(?:way)?points?\b", re.I)
"""The first N waypoints, in the words for the first ones ("the initial 6 points")."""
KEEPS = re.compile(r"\b(?:keep\w*|same|unchanged|fixed|fix|maintain\w*|retain\w*|hold\w*|stays?)\b", re.I)
FURTHER = re.compile(
    r"\b(?:further|farther|more|another|additional|extra|continu\w*|go(?:es|ing)? on|keep (?:going|moving|on)"
    r"|carry on|onward\w*)\b",
    re.I,
)
AMOUNT_NUMBER = re.compile(
    rf"\b(?:(?:by|for|of)\s+(?:another\s+|an?\s+(?:extra|additional|further)\s+)?|another\s+"
    rf"|an?\s+(?:extra|additional|further)\s+)({NUMBER_TEXT})\b",
    re.I,
)

STRETCHES = ("first half", "second half", "middle", "center")
"""Stretches of the path a clause may move alone ("push the first half 6 cm forward"): a
``shift_part`` of that stretch. Its ends are the start and the goal (``START``, ``GOAL``)."""

PLACED_STRETCH = re.compile(
    r"\b(?:after|before|until|till|from|to|towards?|past|beyond|near|up|ends?\s+up\s+in)\s+(?:the\s+)?$",
    re.I,
)
"""A stretch after these words is a place or a time on the path, not the part that moves."""

THERE = re.compile(r"\bthere\b", re.I)
"""A word that points back to a place said before."""
IT = re.compile(r"\bit\b(?!\s*(?:is|'s|was)\b)", re.I)
"""A word that points back to the thing said before (not "it is": a new statement)."""
SUBJECT_VERB = re.compile(
    r"\s*(?:position\s+|point\s+)?(?:is|are|was|sits|lies)\b"
    r"(?!\s+(?:fine|good|ok|okay|right|correct|kept|fixed|unchanged|the\s+same|where|as\s+it)\b)",
    re.I,
)
"""A verb right after an end that makes it the clause's subject, saying where it is ("the goal *is* too
close", "the start *sits* out of bounds"; not "the start is fine", "the goal is kept")."""


@dataclass(frozen=True)
class PartMove:
    """What one clause asks: a part of the path moved in a direction (None: along the final heading)."""

    part: str  # 'the start', 'the goal', 'past the goal', 'the first N waypoints' or a stretch ('the middle')
    direction: str | None
    amount: float | str | None
    count: int = 0  # for 'first N waypoints'
    goes_on: bool = False  # past the goal: the clause says to go on ("keep going", "another 0.8")
    named: str = ""  # for a named stretch ('first half', 'second half', 'middle'): its ``PART_WORDS`` key

    def call(self, amount: ast.expr | None) -> str:
        """The skill call that makes this move, given the amount the code wrote (None: the clause's own)."""
        given = ast.unparse(amount) if amount is not None else None
        if given is None and self.amount is not None:
            given = repr(self.amount)
        if self.part == "past the goal":
            arguments = [given or "None", repr(self.direction)] if self.direction else [given]
        else:
            arguments = [repr(self.direction), given]
        words = ", ".join(["t", *(a for a in arguments if a is not None)])
        if self.count:
            return f"shift_part({words}, part=(0, {self.count}))"
        if self.named:
            return f"shift_part({words}, part={self.named!r})"
        skill = {"the start": "shift_start", "the goal": "shift_goal"}.get(self.part, "extend")
        return f"{skill}({words})"


def part_moves(words: str) -> list[PartMove]:
    """The part moves the clauses of ``words`` ask for (see the module docstring).

    "There" in the clause right after one that names the goal is the goal ("don't stop at the goal;
    once you get there, carry on further"); "it" in the clause right after one whose subject is an
    end is that end ("the start is out of bounds: move it 1 m to the left").
    """
    moves, goal_before, subject = [], False, None
    for clause in split_clauses(words):
        said = THERE.sub("at the goal", clause) if goal_before else clause
        move = _clause_move(IT.sub(f"the {subject}", said) if subject else said)
        goal_before = bool(GOAL.search(clause))
        subject = _end_as_subject(clause)
        if move is not None:
            moves.append(move)
    return moves


def _end_as_subject(clause: str) -> str | None:
    """The end ('start', 'goal') a clause opens with as its subject ("the start is out of bounds")."""
    for end, pattern in (("start", START), ("goal", GOAL)):
        found = pattern.match(clause.strip())
        if found and SUBJECT_VERB.match(clause.strip()[found.end() :]):
            return end
    return None


def _clause_move(clause: str) -> PartMove | None:
    directions = said_directions(clause)
    if len(directions) > 1 or SPEED_WORDS.search(clause):
        return None
    direction = next(iter(directions), None)
    amount = _clause_amount(clause)
    if PAST_THE_GOAL.search(clause):
        if direction is None and not FURTHER.search(clause):
            return None
        return PartMove("past the goal", direction, amount, goes_on=bool(FURTHER.search(clause)))
    if direction is None or KEEPS.search(clause):
        return None
    count = first_count(clause)
    parts = [p for p, pattern in (("the start", START), ("the goal", GOAL)) if _moved_part(pattern, clause)]
    if count:
        parts.append(f"the first {count} waypoints")
    named = part_named(clause) if not parts else None
    if named in STRETCHES and _moved_stretch(clause, named):
        return PartMove(f"the {named}", direction, amount, named=named)
    if len(parts) != 1:
        return None
    return PartMove(parts[0], direction, amount, count)


def _moved_stretch(clause: str, named: str) -> bool:
    """Whether the clause names the stretch as what moves, not a place ("after the first half")."""
    found = re.search(rf"\b(?:the\s+)?{named}\b", clause, re.I)
    return found is not None and not PLACED_STRETCH.search(clause[: found.start()])


def _moved_part(pattern: re.Pattern[str], clause: str) -> bool:
    """Whether the clause names the part as what moves, not as a place ("go left from the start")."""
    return any(not REFERENCE.search(clause[: found.start()]) for found in pattern.finditer(clause))


def _clause_amount(clause: str) -> float | str | None:
    clause = in_metres(clause)
    number = AMOUNT_NUMBER.search(clause)
    directed = directed_numbers(clause)
    if number:
        return float(number.group(1))
    return directed[0] if len(directed) == 1 else intensity_word(clause)


def first_count(clause: str) -> int:
    """The N of "the first N waypoints" in the clause, 0 when it names none."""
    found = FIRST_COUNT.search(clause)
    return 0 if found is None else whole_count(found.group(1))


ENDS_MOVED = {
    "shift_goal": re.compile(
        rf"{GOAL.pattern}|\b(?:end(?:s|ed|ing)?|finish\w*)\b"
        r"(?!\s+(?:of|part|section|segment|portion|stretch|half)\b)",
        re.I,
    ),
    "shift_start": re.compile(rf"{START.pattern}|\b(?:start|begin)(?:s|ed|ing)?\b", re.I),
}
"""Words that place a move at one end: the goal ("the goal", "end 0.2 higher", "finish further right";
"the end of the path" is a part) or the start ("the start point", "start 0.1 further left")."""

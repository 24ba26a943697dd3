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

THERE = re.compile(r"\bthere\b", re.I)
"""A word that points back to a place said before."""


@dataclass(frozen=True)
class PartMove:
    """What one clause asks: a part of the path moved in a direction (None: along the final heading)."""

    part: str  # 'the start', 'the goal', 'past the goal' or 'the first N waypoints'
    direction: str | None
    amount: float | str | None
    count: int = 0  # for 'first N waypoints'
    goes_on: bool = False  # past the goal: the clause says to go on ("keep going", "another 0.8")

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
        skill = {"the start": "shift_start", "the goal": "shift_goal"}.get(self.part, "extend")
        return f"{skill}({words})"


def part_moves(words: str) -> list[PartMove]:
    """The part moves the clauses of ``words`` ask for (see the module docstring).

    "There" in the clause right after one that names the goal is the goal ("don't stop at the goal;
    once you get there, carry on further").
    """
    moves, goal_before = [], False
    for clause in split_clauses(words):
        move = _clause_move(THERE.sub("at the goal", clause) if goal_before else clause)
        goal_before = bool(GOAL.search(clause))
        if move is not None:
            moves.append(move)
    return moves


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
    if len(parts) != 1:
        return None
    return PartMove(parts[0], direction, amount, count)


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

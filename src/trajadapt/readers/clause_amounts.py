"""Shared by the readers: the amount each direction is given, clause by clause.

A clause (``clause_split.split_clauses``) with exactly one direction word and exactly one number
given to a direction (``words.directed_numbers``: "by 0.2", "0.2 to the left", "raise it 0.2") gives
that direction its amount; a direction given two different amounts has none.
"""

from __future__ import annotations

from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import directed_numbers, said_directions


def direction_amounts(words: str) -> dict[str, float]:
    """The amount each direction is given in the clauses of ``words`` ("upwards by 0.2" -> up: 0.2)."""
    amounts: dict[str, list[float]] = {}
    for clause in split_clauses(words):
        said = said_directions(clause)
        numbers = directed_numbers(clause)
        if len(said) == 1 and len(numbers) == 1:
            amounts.setdefault(next(iter(said)), []).append(numbers[0])
    return {direction: found[0] for direction, found in amounts.items() if len(set(found)) == 1}

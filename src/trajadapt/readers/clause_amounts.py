"""Shared by the readers: the amount each direction is given, clause by clause.

A clause (``clause_split.split_clauses``) with exactly one direction word and exactly one number
given to a direction (``words.directed_numbers``: "by 0.2", "0.2 to the left", "raise it 0.2") gives
that direction its amount; a direction given two different amounts has none. A length with a metric
unit is read in metres ("5 cm lower" is 0.05, "1 m further back" is 1), as a scene's own numbers are.
"""

from __future__ import annotations

import re

from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import directed_numbers, said_directions
from trajadapt.readers.words import NUMBER_TEXT

METRIC = re.compile(
    rf"(?<![\w.])({NUMBER_TEXT})\s*(cm|centimet(?:er|re)s?|mm|millimet(?:er|re)s?|m|met(?:er|re)s?)\b(?!\s*/)",
    re.I,
)
"""A length with its metric unit: "5 cm", "20mm", "1 m", "1.5 metres" (not a speed: "0.3 m/s")."""
SCALE = {"c": 0.01, "m": 0.001}


def in_metres(text: str) -> str:
    """``text`` with each length given in a metric unit written in metres, its unit left out.

    >>> in_metres("drop the end 5 cm lower and go 1 m further back at 0.3 m/s")
    'drop the end 0.05 lower and go 1 further back at 0.3 m/s'
    """

    def metres(found: re.Match[str]) -> str:
        unit = found.group(2).lower()
        factor = 1.0 if unit == "m" or unit.startswith("met") else SCALE[unit[0]]
        return f"{float(found.group(1)) * factor:g}"

    return METRIC.sub(metres, text)


def direction_amounts(words: str) -> dict[str, float]:
    """The amount each direction is given in the clauses of ``words`` ("upwards by 0.2" -> up: 0.2)."""
    amounts: dict[str, list[float]] = {}
    for clause in split_clauses(words):
        said = said_directions(clause)
        numbers = directed_numbers(in_metres(clause))
        if len(said) == 1 and len(numbers) == 1:
            amounts.setdefault(next(iter(said)), []).append(numbers[0])
    return {direction: found[0] for direction, found in amounts.items() if len(set(found)) == 1}

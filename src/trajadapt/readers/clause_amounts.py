"""Shared by the readers: the amount each direction is given, clause by clause.

A clause (``clause_split.split_clauses``) with exactly one direction word and exactly one number
given to a direction (``words.directed_numbers``: "by 0.2", "0.2 to the left", "raise it 0.2") gives
that direction its amount; a clause with several directions, each right after its own number ("0.1
further right and 0.05 lower"), gives each its number; a direction given two different amounts has
none. A length with a metric
unit is read in metres ("5 cm lower" is 0.05, "1 m further back" is 1), as a scene's own numbers are.
The numbers that may be lengths at all (``stated_lengths``) leave out a share of the path, a half of
something and a count.
"""

from __future__ import annotations

import re

from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import directed_numbers, paired_amounts, said_directions
from trajadapt.readers.words import NUMBER_TEXT, stated_numbers

METRIC = re.compile(
    rf"(?<![\w.])({NUMBER_TEXT})\s*(cm|centimet(?:er|re)s?|mm|millimet(?:er|re)s?|m|met(?:er|re)s?)\b(?!\s*/)",
    re.I,
)
"""A length with its metric unit: "5 cm", "20mm", "1 m", "1.5 metres" (not a speed: "0.3 m/s")."""
SPELLED_METRIC = re.compile(
    r"\b(half\s+an?|an?|one)\s+(?:(?:full|whole|good)\s+)?((?:centi|milli)?met(?:er|re))\b"
    r"(?!\s*(?:/|per\b|an?\s+second\b))",
    re.I,
)
"""A length said with a word for its number: "a metre", "one meter", "half a metre", "a full metre", "a
centimetre" (not a speed: "a metre per second")."""
SCALE = {"c": 0.01, "m": 0.001}
SPELLED = {"a": 1.0, "an": 1.0, "one": 1.0, "half": 0.5}


def in_metres(text: str) -> str:
    """``text`` with each length given in a metric unit written in metres, its unit left out.

    >>> in_metres("drop the end 5 cm lower and go 1 m further back at 0.3 m/s")
    'drop the end 0.05 lower and go 1 further back at 0.3 m/s'
    >>> in_metres("stay at least a metre away, then half a metre up")
    'stay at least 1 away, then 0.5 up'
    """

    def metres(found: re.Match[str]) -> str:
        return f"{float(found.group(1)) * _unit_factor(found.group(2)):g}"

    def spelled(found: re.Match[str]) -> str:
        return f"{SPELLED[found.group(1).split()[0].lower()] * _unit_factor(found.group(2)):g}"

    return METRIC.sub(metres, SPELLED_METRIC.sub(spelled, text))


def _unit_factor(unit: str) -> float:
    """Metres in one ``unit`` ("cm": 0.01, "metre": 1)."""
    unit = unit.lower()
    return 1.0 if unit == "m" or unit.startswith("met") else SCALE[unit[0]]


def direction_amounts(words: str) -> dict[str, float]:
    """The amount each direction is given in the clauses of ``words`` ("upwards by 0.2" -> up: 0.2)."""
    amounts: dict[str, list[float]] = {}
    for clause in split_clauses(words):
        said = said_directions(clause)
        numbers = directed_numbers(in_metres(clause))
        if len(said) == 1 and len(numbers) == 1:
            amounts.setdefault(next(iter(said)), []).append(numbers[0])
        elif len(said) > 1 and set(paired := paired_amounts(in_metres(clause))) == said:
            for direction, amount in paired.items():  # "10 cm further right and 5 cm lower"
                amounts.setdefault(direction, []).append(amount)
    return {direction: found[0] for direction, found in amounts.items() if len(set(found)) == 1}


_SHARE = r"(?:halves|half|thirds?|quarters?|fifths?)"
NOT_LENGTHS = re.compile(
    rf"\b(?:first|second|third|last|final|other|latter|former|opening|closing|initial|middle)\s+{_SHARE}"
    rf"|\b(?:half|mid)\s*-?\s*way\b|\b(?:a|one|two|three|half)\s+{_SHARE}\s+of\s+(?:the|its|your)\b"
    rf"|\bhalf\s+(?:of\s+)?(?:the|its|your|as|their|this)\b|\bhalv\w*"
    rf"|\b(?:{NUMBER_TEXT}|one|two|three|four|five|six|seven|eight|nine|ten|a\s+couple\s+of|a\s+few|several)\s+"
    r"(?:more\s+)?(?:time\s*)?(?:waypoints?|steps?|points?|beats?|ticks?|swings?"
    r"|loops?|laps?|turns?|circles?|cycles?|oscillations?|wiggles?|zig\w*|waves?|bends?)\b",
    re.I,
)
"""Numbers that are no length: a share of the path ("the second half", "the last third", "halfway"),
a half of something ("half the speed", "halve it"), a count ("three waypoints", "four swings"). A
multiple ("two times the distance") may scale a length, so it stays."""


def stated_lengths(words: str) -> list[float]:
    """The numbers of ``words`` that may be lengths: ``stated_numbers`` less those ``NOT_LENGTHS`` says.

    >>> stated_lengths("raise the second half by 0.05 and pause for three steps")
    [0.05]
    """
    return stated_numbers(NOT_LENGTHS.sub(" ", words))

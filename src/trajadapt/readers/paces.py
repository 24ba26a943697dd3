"""How much faster or slower the user's words ask: the calibrated factor of their speed clause."""

from __future__ import annotations

import re
from collections.abc import Sequence

from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.end_words import kept_ends
from trajadapt.readers.height_words import asked_heights
from trajadapt.readers.request_words import is_statement
from trajadapt.readers.words import (
    FASTER,
    NUMBER_TEXT,
    NUMBER_WORDS,
    SLOWER,
    SPEED_WORDS,
    amount_size,
    names_in,
    part_named,
)
from trajadapt.skills.speed import SPEED_FACTORS

STOP_RAMP_START = 0.6
"""Where a slowing to a stop begins: over the last 30% of the path, as the prompt's own example
("slow down gradually towards the goal" -> ``speed_profile(t, 'decelerate', start=0.7)``)."""


def speed_factor(words: str, faster: bool) -> float:
    """The calibrated factor for the speed clause of ``words``: 'a bit', plain or 'a lot' faster/slower.

    The amount is the first said by a clause that asks that pace ("walk faster around the dog; it
    should be a lot faster there" is 'a lot'), else by the first clause with a speed word, so an
    amount word of another clause ("go left a lot and walk faster") does not count, and not one
    that only says how the path is now ("it's way too slow near the basket; speed up a lot there").
    """
    said = [amount_size(clause) for clause in _speed_clauses(words, faster)]
    size = next((size for size in said if size), said[0] if said else "")
    return SPEED_FACTORS["faster" if faster else "slower"][size]


def stated_factor(words: str, faster: bool) -> float | None:
    """The one factor the speed clause of ``words`` states in the asked direction, or None.

    "slower by half" states 0.5, "twice as fast" 2, "20% slower" 0.8 (a percentage only with its
    sign; "60% of the speed" is 0.6), "at least 25% slower" 0.7 (``LEAST_MARGIN``); a clause with no
    such number, or with two, states none.

    >>> stated_factor("walk away from the lamp and go slower by half", faster=False)
    0.5
    """
    clause = PATH_SHARE.sub(" ", _speed_clause(words))
    numbers = [n for n in _factor_numbers(clause) if n > 0]
    candidates = set(numbers) | {1 / n for n in numbers}
    if PERCENT_OF_SPEED.search(clause):  # "at 60% of its current speed" is the factor itself
        candidates = {float(n) / 100 for n in PERCENT_OF_SPEED.findall(clause)}
    elif PERCENT.search(clause) or BY_A_SHARE.search(clause):
        percent = [float(n) for n in PERCENT.findall(clause)] + [
            100 / SHARE_PARTS[part.lower()] for part in BY_A_SHARE.findall(clause)
        ]
        candidates = {1 + n / 100 for n in percent} | {1 - n / 100 for n in percent if n < 100}
    asked = {round(c, 6) for c in candidates if (c > 1 if faster else 0 < c < 1)}
    if len(asked) != 1:
        return None
    factor = asked.pop()
    return round(1 + (factor - 1) * LEAST_MARGIN, 6) if AT_LEAST.search(clause) else factor


def asked_factor(words: str, faster: bool) -> float:
    """The factor the speed clause of ``words`` asks: the one it states, else its calibrated size.

    >>> asked_factor("slow to half speed on the approach to the lamp", faster=False)
    0.5
    >>> asked_factor("ease off a little as you near the lamp", faster=False) > 0.5
    True
    """
    stated = stated_factor(words, faster)
    return stated if stated is not None else speed_factor(words, faster)


AT_LEAST = re.compile(r"\b(?:at\s+least|no\s+less\s+than|a\s+minimum\s+of|or\s+more)\b", re.I)
"""Words that state the least change of a pace: "at least 25% slower", "20% faster or more"."""
LEAST_MARGIN = 1.2
"""A least change of pace is met with a fifth more ("at least 25% slower" is 30% slower), so that the
change is more than the least, not on it."""


def _factor_numbers(clause: str) -> list[float]:
    """The numbers a clause gives as factors: "half", "twice", "3 times", "a factor of 2" (no distance)."""
    words = [FACTOR_WORDS[w] for w in re.findall(r"[a-z]+", clause.lower()) if w in FACTOR_WORDS]
    times = [found.group(1) or found.group(2) for found in TIMES.finditer(clause)]
    shares = [SHARE_COUNTS[n.lower()] / SHARE_PARTS[p.lower()] for n, p in SHARE_OF.findall(clause)]
    return words + [float(NUMBER_WORDS.get(n.lower(), 0) or n) for n in times] + shares


FACTOR_WORDS = {
    "half": 0.5, "halve": 0.5, "halved": 0.5, "halving": 0.5, "twice": 2.0, "double": 2.0,
    "doubled": 2.0, "doubling": 2.0, "thrice": 3.0, "triple": 3.0, "tripled": 3.0,
}  # fmt: skip
TIMES = re.compile(
    rf"\b({NUMBER_TEXT}|two|three|four|five)\s*(?:times\b|x\b)|factor\s+of\s+({NUMBER_TEXT}|two|three)\b",
    re.I,
)
SHARE_COUNTS = {"a": 1, "one": 1, "two": 2, "three": 3, "four": 4}
SHARE_PARTS = {
    "third": 3,
    "thirds": 3,
    "quarter": 4,
    "quarters": 4,
    "fourth": 4,
    "fourths": 4,
    "fifth": 5,
    "fifths": 5,
}
SHARE_OF = re.compile(
    r"\b(a|one|two|three|four)[\s-]+(thirds?|quarters?|fourths?|fifths?)\s+of\b"
    r"(?!\s+(?:the\s+)?(?:way|path|route|trajectory|distance|journey|flight|motion|length)\b)",
    re.I,
)
"""A share said as a fraction of something ("a third of the current speed", "two-thirds of its pace"):
a factor; "the last third" (no count before it) and "a quarter of the way" are parts of the path."""
PERCENT = re.compile(rf"({NUMBER_TEXT})\s*(?:%|per\s*cent\b)", re.I)
BY_A_SHARE = re.compile(
    r"\bby\s+(?:about\s+|roughly\s+|around\s+|some\s+)?(?:a|one)\s+(third|quarter|fifth)\b", re.I
)
"""A change by a share of the speed, said as a fraction: "up by about a quarter" is 25% faster."""
_PATH = r"(?:path|route|trajectory|motion|move|movement|way|flight|run|journey|trip|distance|length|course)"
PERCENT_OF_SPEED = re.compile(
    rf"({NUMBER_TEXT})\s*(?:%|per\s*cent\b)\s+of\s+(?:the\s+|its\s+|your\s+|their\s+)?(?:[a-z]+\s+){{0,2}}?"
    r"(?:speed|pace|velocity|tempo)\b",
    re.I,
)
"""A percentage *of* a speed: the factor itself ("slow to 60% of the speed" is 0.6, not 0.4)."""
_NO_SPEED = r"(?!\s+(?:speed|pace|velocity|tempo))"  # "60% of the original motion speed" is a speed
PATH_SHARE = re.compile(
    r"\b(?:last|final|closing|first|opening|initial|second|latter)\s+"
    rf"(?:{NUMBER_TEXT}\s*(?:%|per\s*cent\b)|half|third|quarter|fifth|tenth)"
    rf"|\b{NUMBER_TEXT}\s*(?:%|per\s*cent\b)\s+of\s+(?:the\s+|its\s+|your\s+|this\s+)?(?:\w+\s+)?{_PATH}\b{_NO_SPEED}"
    rf"|\bhalf\s*way\b|\bhalf\s+(?:of\s+)?(?:the\s+|its\s+)?{_PATH}\b{_NO_SPEED}",
    re.I,
)
"""A share of the path, not of the speed: "over the final 40 percent of the motion", "the last 30%",
"the second half", "halfway"."""


def _speed_clause(words: str) -> str:
    """The first clause with a speed word that is no statement (or the first with one)."""
    paced = [c for c in split_clauses(words) if SPEED_WORDS.search(c)]
    return next((c for c in paced if not is_statement(c)), paced[0] if paced else "")


def _speed_clauses(words: str, faster: bool) -> list[str]:
    """The clauses that ask the pace in the ``faster`` direction, else the first speed clause."""
    asked = FASTER if faster else SLOWER
    said = [c for c in split_clauses(words) if asked.search(c) and not is_statement(c)]
    return said or [_speed_clause(words)]


def part_said_for_the_pace(clause: str, words: str, names: Sequence[str]) -> bool:
    """Whether the words name a part of the path the pace may be meant for.

    The pace clause's own part ("slow down near the box in the second half"), or one a clause that asks
    nothing of its own names ("towards the end, go faster near the person", "while you're in the
    middle"); not a number said of the speed ("half speed"), an end another clause keeps ("the
    destination stays where it is") or moves ("move the final point 1 m forward"), nor a part where
    another clause holds a height ("through the middle keep above 0.3").
    """
    others = [
        c
        for c in split_clauses(words, names)
        if c != clause
        and not (names_in(c, names) or said_directions(c) or kept_ends([c]) or asked_heights(c))
    ]
    return part_named(clause) is not None or any(part_named(c) for c in others)


CLOSING_SHARE = re.compile(
    r"\b(?:the\s+)?(?:last|final|closing)\s+"
    rf"(?:(?P<part>half|third|quarter|fifth|tenth)|(?P<percent>{NUMBER_TEXT})\s*(?:%|per\s*cent\b))"
    r"|\b(?:the\s+)?(?P<second>second)\s+half\b",
    re.I,
)
"""The closing share of the path the words name: "the last third", "the final quarter", "the last 20%",
"the second half"."""
SHARES = {"half": 0.5, "third": 1 / 3, "quarter": 0.25, "fifth": 0.2, "tenth": 0.1}


def closing_share_start(words: str) -> float | None:
    """Where the closing share of the path the words name begins ("the last third": 0.667), or None.

    >>> closing_share_start("ramp the speed down over the last third")
    0.667
    """
    found = {_share(m) for m in CLOSING_SHARE.finditer(words)}
    return round(1 - found.pop(), 3) if len(found) == 1 else None


def _share(found: re.Match[str]) -> float:
    """The share of the path one closing share names."""
    if found.group("second"):
        return 0.5
    if found.group("percent"):
        return min(float(found.group("percent")), 100.0) / 100
    return SHARES[found.group("part").lower()]

"""How the user's words are read without a model: clauses, speed words, object names as whole words.

The clearance's exemptions (``constraints.approached_objects``), the calibrated speed factors
(``unstated_amounts``) and the placing of speed steps (``speed_scope``) read instructions the same way.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from trajadapt.geometry import DIRECTION_SYNONYMS

SENTENCE_MARKS = r"[,;!?]|\.(?!\d)"
"""Punctuation that ends a clause; the point of a decimal number ("by 0.2") does not."""

CLAUSE_BREAKS = re.compile(rf"{SENTENCE_MARKS}|\b(?:and|then|but|while)\b", re.I)
"""Where one clause of an instruction ends and the next begins."""

SPEED_WORDS = re.compile(r"\b(?:fast|slow|quick|speed|velocit|pace|hurr|rapid|swift|brisk|leisure)", re.I)
"""Word stems that make a clause about speed."""

PATH_WORDS = re.compile(
    r"\b(?:distance|clear|avoid|away|reach|pass|through|between|around|circle|spiral|loop|extend|continu"
    r"|further|farther|closer|nearer|approach|shift|curv|bend|arc|zig|weav|smooth|height|altitude|above"
    r"|below|over|under|rotat|turn|tilt|scale|waypoint|side|towards?|hug|bow|offset)\w*",
    re.I,
)
"""Word stems that ask where the path goes (its place or shape), not how fast."""


PACE_PHRASES = re.compile(
    r"\b(?:slow|slowing|speed|speeding|calm|hurry|ramp|ramping|wind|winding)\s+(?:down|up)\b", re.I
)
"""Phrasal verbs of pace whose particle is no direction ("slow down", "speed up")."""


def moving_directions(words: str) -> set[str]:
    """The directions the words ask the path to move in: ``said_directions`` less "slow down"'s."""
    return said_directions(PACE_PHRASES.sub(" slow ", words))


def asked_kinds(words: str) -> frozenset[str]:
    """What the words ask about: 'pace' (how fast), 'place' (where the path goes), both or neither."""
    kinds = {"pace"} if asks_pace(words) else set()
    if PATH_WORDS.search(words) or moving_directions(words):
        kinds.add("place")
    return frozenset(kinds)


FASTER = re.compile(
    r"\b(?:fast\w*|quick\w*|rapid\w*|swift\w*|hurr\w*|accelerat\w*|brisk\w*|speed up)\b", re.I
)
SLOWER = re.compile(r"\b(?:slow\w*|decelerat\w*|leisure\w*)\b", re.I)
"""Word stems that ask for more speed, and for less."""


def whole_words(text: str) -> str:
    """Lower-case words with a space on each side, so that names match whole words only.

    >>> whole_words("the Red-Box!")
    ' the red box '
    """
    return f" {' '.join(re.findall(r'[a-z0-9]+', text.casefold()))} "


def names_in(text: str, names: Iterable[str]) -> list[str]:
    """The names that ``text`` contains as whole words, in the order of ``names``."""
    words = whole_words(text)
    return [name for name in names if name and whole_words(name) in words]


def said_directions(words: str) -> set[str]:
    """The directions the words name, canonical ('upwards' -> 'up', 'behind' -> 'back')."""
    return {DIRECTION_SYNONYMS[w] for w in re.findall(r"[a-z]+", words.lower()) if w in DIRECTION_SYNONYMS}


def longest_names(named: list[str]) -> list[str]:
    """The names not inside another of them ('red box' and 'box' found: 'red box')."""
    return [n for n in named if not any(n != o and n.casefold() in o.casefold() for o in named)]


def asks_pace(words: str) -> bool:
    """Whether the words ask about speed: a speed word, or one that asks for more or less of it."""
    return bool(SPEED_WORDS.search(words) or FASTER.search(words) or SLOWER.search(words))

"""What the user's words ask of each object they name: come closer, keep away, a side, a pace near it.

Read clause by clause (``clause_split.split_clauses``: "while" stays inside); an object that two clauses ask
different things of is asked nothing. Used by the readers of object steps and of directions.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.model.geometry import DIRECTION_SYNONYMS, OPPOSITE_DIRECTIONS
from trajadapt.model.scene import without_names
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.stop_words import ENDING_THERE
from trajadapt.readers.words import (
    AWAY,
    CLOSER,
    FASTER,
    MINIMUM_DISTANCE,
    NUMBER_TEXT,
    PLACE_WORDS,
    SENTENCE_END,
    SLOWER,
    asks_distance,
    asks_pace,
    asks_visit,
    longest_names,
    names_in,
)

_SIDE_OF = (
    r"\b(?:([a-z]+)(?:[-\s]?hand)?\s+(?:side\s+)?of|(behind)(?=(?:\s+(?:the|an?))?\s*(?:$|\s{2}|[,.;:!?])))"
)
"""A side of an object: "right of", "left-hand side of", "front side of", "behind" it (its name, taken out
of the clause, right after: not "keep the sofa behind the robot")."""
NOT_SIDE = re.compile(rf"(?:\b(?:not|never|avoid)|n't)\b.*?{_SIDE_OF}", re.I)
KEEP_SIDE = re.compile(rf"\b(?:stay|keep|remain|pass|go|drive|walk|fly)\w*\b.*?{_SIDE_OF}", re.I)
WITHIN = re.compile(
    rf"\b(?:within|inside|(?:no|not)\s+(?:more|further|farther)\s+than|less\s+than)\s+({NUMBER_TEXT})"
    r"(?:\s*(?:m|metres?|meters?|units?))?(?:\s+(?:away|off))?",
    re.I,
)
"""A reach the words give for a speed change: "within 0.2", "inside 0.2 of", "no more than 0.2 away"."""


@dataclass(frozen=True)
class ObjectAsk:
    """What one clause asks of one object: 'faster', 'slower', 'closer', 'away', 'side' or 'by'.

    'by' is to pass close by it ("swing by the lamp", "pass close to the box"): the path visits it.
    """

    name: str
    relation: str
    clause: str
    side: str = ""  # for 'side': the side to keep to
    radius: float | None = None  # for a speed change: "within 0.2"


def object_asks(words: str, names: Iterable[str]) -> dict[str, ObjectAsk]:
    """The one thing the clauses of ``words`` ask of each object they name (none where two clauses differ)."""
    asks: dict[str, list[ObjectAsk]] = {}
    for clause in split_clauses(words, list(names)):
        named = longest_names(names_in(clause, names))
        ask = _clause_ask(clause, named[0]) if len(named) == 1 else None
        if ask is not None:
            asks.setdefault(ask.name, []).append(ask)
    return {name: ask for name, found in asks.items() if (ask := _one_ask(found)) is not None}


def _one_ask(found: list[ObjectAsk]) -> ObjectAsk | None:
    """The one thing asked of an object: the same by every clause, or one way to go with a pace.

    "Go right next to the bed and slow down as you get close to the bed" asks to come closer, and a
    pace there (a pace is a place's, not a way to go); two ways to go, or two paces, ask nothing.
    """
    ways = [ask for ask in found if ask.relation not in PACES]
    if len({ask.relation for ask in found}) == 1 or len({ask.relation for ask in ways}) == 1:
        return ways[0] if ways else found[0]
    return None


PACES = ("faster", "slower")
"""The relations that ask a pace near an object (the others ask a way to go, a side or a visit)."""


def _clause_ask(clause: str, name: str) -> ObjectAsk | None:
    side = _side(without_names(clause, [name]))
    if side and not CLOSER.search(clause):  # "just right of the bed" asks to come close on that side
        return ObjectAsk(name, "side", clause, side=side)
    if asks_pace(clause) and (FASTER.search(clause) or SLOWER.search(clause) or not asks_distance(clause)):
        within = WITHIN.search(clause)
        placed = PLACE_WORDS.search(clause) or within
        if not placed or bool(FASTER.search(clause)) == bool(SLOWER.search(clause)):
            return None
        if asks_distance(WITHIN.sub(" ", clause)):  # "approach the lamp slowly": both, or a place?
            return None
        radius = float(within.group(1)) if within else None
        return ObjectAsk(name, "faster" if FASTER.search(clause) else "slower", clause, radius=radius)
    if MINIMUM_DISTANCE.search(clause):  # "no closer than 0.2 to X", "a minimum clearance of 0.2 from X"
        return ObjectAsk(name, "away", clause)
    closer, away = bool(CLOSER.search(clause)), bool(AWAY.search(clause))
    if closer == away:
        return _visit(clause, name) if not closer else None
    return ObjectAsk(name, "closer" if closer else "away", clause)


def _visit(clause: str, name: str) -> ObjectAsk | None:
    """'by' where the clause asks to pass close by the object, and neither keeps near it nor refuses."""
    return ObjectAsk(name, "by", clause) if asks_visit(without_names(clause, [name])) else None


def _side(clause: str) -> str:
    for pattern, flip in ((NOT_SIDE, True), (KEEP_SIDE, False)):
        found = pattern.search(clause)
        word = DIRECTION_SYNONYMS.get((found.group(1) or found.group(2)).lower(), "") if found else ""
        if word:
            return OPPOSITE_DIRECTIONS[word] if flip else word
    return ""


def asked_words(ask: ObjectAsk) -> str:
    """What the ask wants, in words that read before the object's name ('to come closer to')."""
    return {
        "faster": "for a faster pace near",
        "slower": "for a slower pace near",
        "side": f"to stay {ask.side} of",
        "closer": "to come closer to",
        "away": "to keep further from",
        "by": "to pass close by",
    }[ask.relation]


PLACE_OF_ITS_OWN = re.compile(
    r"\b(?:goal|destination|same|original|usual|(?:at|on|by|beside|near|in|into|onto)\s+(?:the|a|an)\b"
    r"|next\s+to\s+(?:the|a|an)\b|end\s+of)",
    re.I,
)
"""Words that give an ending a place of its own: "finish at the same goal", "stop at the end"."""
PIECES = re.compile(r",|\b(?:and|then|but|before|after)\b", re.I)


def ends_at_the_place(clause: str, words: str) -> bool:
    """Whether the path ends at the place ``clause`` names.

    It does when the clause says so itself, or a piece after it in its sentence ends with no place of
    its own ("swing by the lamp and stop there", "on getting near the scissors, stop"; not "detour by
    the bed, but finish at the same goal").
    """
    if ENDING_THERE.search(clause):
        return True
    found = words.find(clause)
    rest = SENTENCE_END.split(words[found + len(clause) :] if found >= 0 else "")[0]
    return any(ENDING_THERE.search(p) and not PLACE_OF_ITS_OWN.search(p) for p in PIECES.split(rest))

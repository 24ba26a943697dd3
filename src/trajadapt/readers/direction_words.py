"""The directions the user's words ask the path to move in, and the numbers they give a direction.

A direction word is no direction where it belongs to another phrase: a pace ("slow down", "speed
up"), a finishing verb ("end up"), a swing both ways ("left and right"), "right" that stresses a place
("right at the vest"); more or less of a height is up or down, "back up" and "reverse by 3" are back.
Split from ``readers.words`` (the general vocabulary), which these phrases build on.
"""

from __future__ import annotations

import re

from trajadapt.model.geometry import DIRECTION_SYNONYMS, DIRECTION_VERBS, OPPOSITE_DIRECTIONS
from trajadapt.readers.stop_words import DOWN_TO_REST
from trajadapt.readers.words import (
    NUMBER_TEXT,
    OF_DISTANCE,
    OF_SPEED,
    PACE_PHRASES,
    PATH_WORDS,
    asks_pace,
    whole_count,
)

_HEIGHT_NOUN = r"(?:\w+\s+){0,3}?(?:altitude|height|elevation)\b"
MORE_HEIGHT = re.compile(
    rf"\b(?:gain\w*|greater|more|increas\w*|add\w*|extra|bigger|larger)\s+{_HEIGHT_NOUN}", re.I
)
LESS_HEIGHT = re.compile(
    rf"\b(?:los(?:e|es|ing)|lost|less|reduc\w*|decreas\w*|shed\w*|smaller)\s+{_HEIGHT_NOUN}", re.I
)
"""More or less of a height: a direction said with a noun ("gain a bit of altitude", "less height")."""
BACK_UP = re.compile(
    r"\bback(?:s|ed|ing)?\s+(?:(?:it|the\s+(?:whole\s+)?(?:path|route|trajectory|robot|arm))\s+)?up\b", re.I
)
"""The phrasal verb "back up" ("back the whole route up"): backwards, not up."""
LEFT_AS_KEPT = re.compile(
    r"\b((?:(?:is|are|was|were|be|been|being|gets?|got|stays?|remains?)"
    r"|with\s+(?:the\s+|its\s+|both\s+)?(?:goal|start|end|ends|endpoints?|end\s+points?|final\s+\w+))\s+)left\b"
    r"(?=\s+(?:(?:exactly|just)\s+)?(?:where|alone|unchanged|untouched|intact|undisturbed|in\s+place"
    r"|as\s+(?:it|they)\s+(?:is|are|was|were))\b)",
    re.I,
)
""""Left" as what is done to an end, after a verb of being or "with the goal": "with the goal left where
it is", "the start is left alone" (not "turn left where the corridor ends", "push it left just a bit")."""
RIGHT_AS_STRESS = re.compile(
    r"\b(?<!turn )(?<!turns )(?<!turning )(?<!turned )(?<!veer )(?<!bear )(?<!steer )(?<!swerve )(?<!go )"
    r"(?<!move )(?<!shift )(?<!head )(?<!keep )(?<!stay )(?<!to the )(?<!the )(?<!to )"
    r"(?<!\d\s)right\s+(?=(?:at|by(?!\s+(?:\d|\.\d|zero|one|two|three|four|five|six|seven|eight|nine|ten|a|an|some"
    r"|half|about|around|roughly|approximately)\b)|past|next|beside|alongside|through|over|above|below|under|underneath|behind|before"
    r"|after|there|here|in|into|on|onto|where|when|now|away|around|against|up\s+to|down|from)\b)",
    re.I,
)
""""Right" that stresses a place or a time, not the side: "finish right at the vest", "cruise right past
the lamp" ("turn right at the lamp", "move right past it", "to the right of" stay the side)."""
ENDING_UP = re.compile(
    r"\b(?:end(?:s|ed|ing)?|wind(?:s|ing)?|wound|wrap(?:s|ped|ping)?|finish(?:es|ed|ing)?)"
    r"\s+(?:(?:it|things|this|that|everything)\s+)?up\b",
    re.I,
)
"""Phrasal verbs of finishing, with their object or without: "end up 0.8 further front", "wrap up with
a slower finish", "wrap it up beside the vest" ask no up."""
TO_AND_FRO = re.compile(
    r"\b(?:back\s+and\s+forth|forth\s+and\s+back|to\s+and\s+fro|side\s+to\s+side|left\s+and\s+right"
    r"|right\s+and\s+left|up\s+and\s+down|down\s+and\s+up)\b",
    re.I,
)
"""A swing both ways ("weave back and forth", "left and right", "up and down"): no one direction."""
REVERSING = re.compile(
    r"\b(?:revers(?:e|es|ed|ing)|retreat(?:s|ed|ing)?)\b"
    r"(?!\s+(?:the|its|this|that|it|them|order|direction|course|sequence|waypoints?|points?)\b)",
    re.I,
)
"""Reversing or retreating as a move ("reverse by 3", "retreat a little"): backwards. Reversing the
path, its order or its direction is no move that way."""

DIRECTION_WORDS = {**DIRECTION_VERBS, **DIRECTION_SYNONYMS}
"""Every word that names a direction, to its canonical direction."""


_DIRECTION_ALTERNATIVES = "|".join(sorted(DIRECTION_WORDS, key=len, reverse=True))
_ROUGHLY = r"(?:(?:about|around|roughly|approximately|approx\.?|some|nearly|almost)\s+|~\s*)"
_WHAT_MOVES = r"it|everything|(?:the\s+)?(?:whole\s+|entire\s+)?(?:path|route|trajectory)"
_NUMBER_BEFORE_DIRECTION = (
    rf"(?<![\w.])({NUMBER_TEXT})\s+(?:(?:more|further|farther|over)\s+)?(?:(?:to|towards?)\s+(?:the\s+)?)?"
)
"""A number right before its direction word, the word left to follow: "0.1 further ", "0.2 to the "."""
DIRECTED_NUMBER = re.compile(
    rf"\bby\s+{_ROUGHLY}?({NUMBER_TEXT})(?![\w.])"
    rf"|{_NUMBER_BEFORE_DIRECTION}(?:{_DIRECTION_ALTERNATIVES})\b"
    rf"|\b(?:{_DIRECTION_ALTERNATIVES})\s+(?:(?:{_WHAT_MOVES})\s+)?{_ROUGHLY}?({NUMBER_TEXT})(?![\w.])"
    r"(?!\s*(?:(?:way)?points?|steps?|times?|turns?))",
    re.I,
)
"""A number given to a direction: "by 0.2", "by about 0.2", "0.2 to the left", "0.2 further left", "0.2
over to the left", "rise 0.2", "raise the path 0.2", "raise the whole path about 0.2" (not "up 3 times"
or "left 10 points", which count)."""


def directed_numbers(clause: str) -> list[float]:
    """The numbers ``clause`` gives a direction (``DIRECTED_NUMBER``), in order.

    >>> directed_numbers("continue moving 0.2 to the left")
    [0.2]
    """
    return [float(next(group for group in found if group)) for found in DIRECTED_NUMBER.findall(clause)]


def said_directions(words: str) -> set[str]:
    """The directions the words ask the path to move in, canonical ('upwards' -> 'up', 'climb' -> 'up').

    A pace is no direction: "slow down", "speed up" (``PACE_PHRASES``), "coast down to a stop"
    (``DOWN_TO_REST``) and "raise the pace"
    (``OF_SPEED``) are left out, and so is a word before a distance ("lower the clearance":
    ``OF_DISTANCE``). More or less of a height is up or down ("gain altitude", "at a greater
    height", "lose some height": ``MORE_HEIGHT``, ``LESS_HEIGHT``), and "back up", "reverse by 3" and
    "retreat a little" are back (``BACK_UP``, ``REVERSING``); "the goal left where it is" is no side
    (``LEFT_AS_KEPT``).
    """
    text = PACE_PHRASES.sub(" slow ", DOWN_TO_REST.sub(" ", words.lower()))
    text = OF_DISTANCE.sub(" ", OF_SPEED.sub(" ", text))
    text = BACK_UP.sub(
        " back ", LESS_HEIGHT.sub(" down ", MORE_HEIGHT.sub(" up ", LEFT_AS_KEPT.sub(r"\1kept", text)))
    )
    text = RIGHT_AS_STRESS.sub(
        " ", ENDING_UP.sub(" end ", REVERSING.sub(" back ", TO_AND_FRO.sub(" ", text)))
    )
    return {DIRECTION_WORDS[word] for word in re.findall(r"[a-z]+", text) if word in DIRECTION_WORDS}


def asked_kinds(words: str) -> frozenset[str]:
    """What the words ask about: 'pace' (how fast), 'place' (where the path goes), both or neither."""
    kinds = {"pace"} if asks_pace(words) else set()
    if PATH_WORDS.search(words) or said_directions(words):
        kinds.add("place")
    return frozenset(kinds)


PAIRED = re.compile(rf"{_NUMBER_BEFORE_DIRECTION}({_DIRECTION_ALTERNATIVES})\b", re.I)
"""A number right before its direction word: "0.1 further right", "0.05 lower", "0.2 to the left"."""


def paired_amounts(clause: str) -> dict[str, float]:
    """Each direction a number stands right before, with that number, where each has one.

    >>> paired_amounts("put the final position 0.1 further right and 0.05 lower")
    {'right': 0.1, 'down': 0.05}
    """
    found: dict[str, set[float]] = {}
    for number, word in PAIRED.findall(clause):
        found.setdefault(DIRECTION_WORDS[word.lower()], set()).add(float(number))
    return {direction: numbers.pop() for direction, numbers in found.items() if len(numbers) == 1}


ALTERNATION = re.compile(
    r"\b(?:alternat\w*|and so on|and so forth|back and forth|every other|switch\w* (?:back|sides?)"
    r"|(?:continu\w*|keep\w* (?:going|on)|carry\w* on|repeat\w*)\s+"
    r"(?:like\s+(?:this|that)|(?:in\s+)?(?:this|that|the\s+same)\s+(?:way|pattern|manner)|the\s+pattern))\b",
    re.I,
)
"""Words that say the shifts go on alternating ("and so on", "continue like this", "repeat the
pattern")."""
BLOCK = re.compile(
    r"\b(?:(?:blocks?|groups?|sets?|chunks?|batch(?:es)?|runs?|stretch(?:es)?)\s+of\s+(\w+)"
    r"|(?:first|next|following)\s+(\w+)\s+(?:way)?points?"
    r"|(?:way)?points?\s+1\s*(?:-|to|through)\s*(\w+)"
    r"|every\s+(\w+)\s+(?:way)?points?)\b",
    re.I,
)
"""A block of waypoints: "blocks of 10", "the first 10 points", "waypoints 1-10", "every 10 points"."""


def alternation(words: str) -> tuple[str, int] | None:
    """(the direction said first, the block's waypoints) when the words ask alternating shifts."""
    if not ALTERNATION.search(words):
        return None
    blocks = {whole_count(next(g for g in found.groups() if g)) for found in BLOCK.finditer(words)}
    blocks.discard(0)
    spoken = ALTERNATION.sub(" ", words.lower())  # "back and forth" names no direction
    said = [DIRECTION_WORDS[word] for word in re.findall(r"[a-z]+", spoken) if word in DIRECTION_WORDS]
    if len(blocks) != 1 or len(set(said)) != 2 or OPPOSITE_DIRECTIONS.get(said[0]) not in said:
        return None
    return said[0], blocks.pop()

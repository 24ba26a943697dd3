"""Heights the user's words give: the relation and number of each ("above 0.3", "at an altitude of 2").

Shared by the height reader and by readers that need to know a clause asks a height.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from trajadapt.readers.clause_amounts import in_metres
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import NUMBER_TEXT

NUMBER = rf"((?<![\w.-])-?(?:{NUMBER_TEXT}))(?![\d.])(?!\s*(?:%|per\s*cent|percent|times\b|x\b))"
"""A height's number: not a share or a factor ("slow down by at least 30 percent" gives no height)."""
LEVEL = r"(?:height|altitude|elevation)"
BELOW = (
    rf"below|under(?:neath)?|lower than|at most|cap\w*(?:\s+(?:the\s+|its\s+|your\s+)?{LEVEL})?\s+at"
    rf"|ceiling(?:\s+{LEVEL})?\s+(?:of|at|is)|(?:max(?:imum)?|upper\s+limit)\s+{LEVEL}\s+(?:of|at|is)"
)
_MINIMUM = rf"(?:min(?:imum)?|lower\s+limit)\s+{LEVEL}\s+(?:of|at|is)"
ABOVE = rf"above|over|higher than|more than|at least|exceed\w*|{_MINIMUM}"
"""Words of a limit before a height: "below 0.3", "cap the altitude at 1.5", "a ceiling of 2"; "above",
"a minimum altitude of 0.5"."""
AT = rf"at (?:a |an |the )?{LEVEL}(?: of)?|(?:an? |the )?{LEVEL} of|(?:fly|hover|stay|keep|cruise|move)\w* at"
NAMED = rf"(?:(?:an?\s+|the\s+)?{LEVEL}\s+of\s+|z\s*=\s*|(?:a\s+)?z\s+of\s+)?"
"""How a height may be named before its number: "a height of 0.2", "an altitude of 0.1", "z = 0.2",
"a z of 0.2"."""
_HELD = r"(?:held|kept|maintained|fixed|set|stays?|remains?|hold|keep|maintain|is|be)"
HELD_LEVEL = (
    rf"(?:hold|keep|maintain|fix|set)\w*\s+(?:the\s+|its\s+|your\s+)?{LEVEL}\s+(?:\w+\s+){{0,3}}?(?:at|to)"
    rf"|{LEVEL}\s+(?:[\w']+\s+){{0,6}}?{_HELD}\s+(?:at|to)"
)
"""A level said of the height itself: "hold the altitude at 0.3", "the height above the ground should be
held at 0.1" (a height word first: "keep the speed held at 0.4" is a pace)."""
RELATIONS = (
    ("stay_below", re.compile(rf"\b(?:{BELOW})\s+{NAMED}{NUMBER}", re.I)),
    ("stay_above", re.compile(rf"\b(?:{ABOVE})\s+{NAMED}{NUMBER}", re.I)),
    ("set_height", re.compile(rf"\b(?:{AT})\s+{NUMBER}", re.I)),
    ("set_height", re.compile(rf"\b(?:{HELD_LEVEL})\s+{NUMBER}", re.I)),
)
BAND = re.compile(
    rf"\b(?:between|from)\s+{NAMED}(-?(?:{NUMBER_TEXT}))\s+(?:and|to)\s+{NAMED}(-?(?:{NUMBER_TEXT}))(?![\d.])",
    re.I,
)
"""A band of heights: "keep the height between z = -0.2 and z = 0.2" is above the one, below the other."""
HEIGHT_STEPS = ("set_height", "stay_below", "stay_above")
VERTICAL = re.compile(
    r"\b(?:above|below|under(?:neath)?|higher\s+than|lower\s+than|altitude|height|elevation|z\s*=|a\s+z\s+of"
    rf"|off\s+the\s+(?:ground|floor))|(?<![\w.]){NUMBER_TEXT}\s*(?:m|cm)?\s+up\b",
    re.I,
)
"""Words that speak of height itself ("above", "altitude", "off the ground", "at least 0.4 m up"), so
that a height they give may be added as a step."""
MIDDLE = re.compile(r"\b(?:middle|mid-?(?:flight|way|route|path|air)|midway|halfway)\b", re.I)
"""Words that hold a limit through the middle of the path: there it keeps the start and the goal."""
OWN_LIMITS = ("stay_below", "stay_above")
SIDEWAYS = re.compile(r"\b(?:away|from|clearance|distance|apart)\b", re.I)
"""Words of a distance from something: a number after "more than" there is no height."""
GROUND = re.compile(r"\b(?:ground|floor)\b", re.I)


NEGATION = re.compile(
    r"(?:\b(?:not|never|no|nowhere|nothing|none|neither)\b|n't\b)(?:\s+(?!(?:and|but|or|then|while|so)\b)[\w'-]+){0,6}\s*$",
    re.I,
)
"""A negation earlier in the clause, with no joining word after it: "don't let the arm go below"."""
FLIPPED = {"stay_below": "stay_above", "stay_above": "stay_below", "set_height": "set_height"}


def asked_heights(words: str) -> list[tuple[str, float]]:
    """The (skill, height) pairs the words give ("at a height of 0.1" -> ('set_height', 0.1)).

    A negation before the relation in its clause turns it round ("never higher than 3", "don't let
    it drop below 0.5" -> above 0.5). A clause of a distance from something ("at least 0.15 from the
    dog") gives no height unless it speaks of height itself.
    """
    return [(asked.skill, asked.height) for asked in clause_heights(words)]


class AskedHeight(NamedTuple):
    """A height the words give: its step, its number, its clause, and that clause with the one before."""

    skill: str
    height: float
    clause: str
    held: str  # "keep the middle part low, at or below z = 0": the clause before says where it holds


def clause_heights(words: str) -> list[AskedHeight]:
    """Each height the words give, in their order."""
    found: list[AskedHeight] = []
    clauses = split_clauses(in_metres(words))
    for index, clause in enumerate(clauses):
        held = " ".join(clauses[max(index - 1, 0) : index + 1])
        if SIDEWAYS.search(clause) and not (VERTICAL.search(clause) or GROUND.search(clause)):
            continue
        at: list[tuple[int, str, float]] = []
        for skill, pattern in RELATIONS:
            for match in pattern.finditer(clause):
                if any(start == match.start(1) for start, _, _ in at):
                    continue
                negated = NEGATION.search(clause[: match.start()]) is not None
                at.append((match.start(1), FLIPPED[skill] if negated else skill, float(match.group(1))))
        found += [AskedHeight(skill, height, clause, held) for _, skill, height in sorted(at)]
        if VERTICAL.search(clause):
            found += [AskedHeight(skill, height, clause, held) for skill, height in band_limits(clause)]
    return found


def band_limits(clause: str) -> list[tuple[str, float]]:
    """The two limits of a band of heights the clause gives (``BAND``), lower first."""
    found = BAND.search(clause)
    if found is None:
        return []
    low, high = sorted((float(found.group(1)), float(found.group(2))))
    return [("stay_above", low), ("stay_below", high)] if low < high else []

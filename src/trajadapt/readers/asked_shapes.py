"""A shape a clause asks (a sideways weave, a loop) and no step makes: the step added.

The shape twin of ``asked_pauses``: "weave side to side along the way" came back as a shift to the
right, "throw in one full loop somewhere along the route" as two passes over an object. A clause
asks (in its words outside the scene's object names: "the king snake" asks no weave)

- a weave when it says "zigzag", "weave", "slalom", "snake", "wiggle", "serpentine", "sinusoidal",
  "wavy" or to swing "side to side" -> ``zigzag(t)``;
- a loop when it says "loop", "circle", "orbit", "spiral", "full turn" or "360" -> ``circle_around(t,
  <object>, turns=<count>)`` around the one scene object it names, else ``spiral(t, turns=<count>)``
  (the count the clause gives: "twice", "two loops", "3 turns"; the skill's own when it gives none).

A clause that undoes a shape ("straighten out the wiggles", "less wavy", "without weaving"), says
it in a negation, or only speaks of the path as it is asks none. The clause is served when a step
of that shape is already in the code (shifts weave too: one that alternates in blocks, or shifts
both ways along one axis where the words give the blocks, which the alternating-shifts reader
reads); otherwise the step is added
after the last step that moves the path, and a review note says which words asked it. Code that
is not made of skill calls alone is left alone.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.code_parse import (
    SPEED_STEPS,
    after_last_step,
    call_of,
    called_name,
    direction_argument,
    skill_program,
)
from trajadapt.model.scene import without_names
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import alternation
from trajadapt.readers.request_words import is_statement
from trajadapt.readers.words import longest_names, names_in, whole_count
from trajadapt.skills import SKILL_NAMES

WEAVE = re.compile(
    r"\b(?:zig\s*-?\s*zag\w*|weav(?:e|es|ed|ing)|slalom\w*|snak(?:e|es|ed|ing)|wiggl(?:e|es|ed|ing)"
    r"|serpentin\w*|sinusoid\w*|wavy|(?:swing|sway|swerv|veer|drift|mov|go|weav|sweep|rock|wander|oscillat"
    r"|meander)\w*\s+(?:\w+\s+)?(?:from\s+)?side\s+to\s+side|meander(?:s|ed)?\b|meandering(?!\s+\w)|oscillat(?:e|es|ed|ing)"
    r"\s+(?:sideways|laterally|across))\b",
    re.I,
)
"""Words that ask the path to swing sideways and back along the way ("sweep from side to side")."""
LOOP = re.compile(
    r"\b(?<!half\s)(?<!half-)(?<!quarter\s)(?:loop(?:s|ed|ing)?|circl(?:e|es|ed|ing)|orbit\w*|spiral\w*"
    r"|full\s+(?:turn|revolution)|360)\b",
    re.I,
)
"""Words that ask a loop: "one full loop", "circle twice around the fan", "orbit the lamp"."""
UNDONE = re.compile(
    r"\b(?:not|never|no|without|less|fewer|remov\w*|reduc\w*|straighten\w*|smooth\w*|flatten\w*"
    r"|get\s+rid|iron\w*\s+out|instead\s+of|rather\s+than)\b|n't\b",
    re.I,
)
"""Words that take a shape away or refuse it: the clause asks no shape."""
COUNT = re.compile(
    r"\b(\d+|one|two|three|four|five|six)\s+(?:full\s+|complete\s+|whole\s+)?(?:loops?|circles?|turns?"
    r"|times|revolutions?|orbits?|laps?)\b|\b(once|twice|thrice)\b",
    re.I,
)
"""A count of loops: "two loops", "3 turns", "twice"."""
ONCE = {"once": 1, "twice": 2, "thrice": 3}
SHAPE_STEPS = {"zigzag": ("zigzag",), "loop": ("spiral", "circle_around")}
"""The steps that make each shape: one of them serves a clause that asks it."""
ALTERNATE = re.compile(r"\balternate\s*=")
"""A shift that alternates its sign in blocks of waypoints weaves too."""
OPPOSITES = ({"left", "right"}, {"up", "down"}, {"front", "back"})
MOVES_THE_PATH = frozenset(SKILL_NAMES) - frozenset(SPEED_STEPS)


@dataclass(frozen=True)
class AskedShape:
    """A shape one clause asks: the clause, the shape ('zigzag' or 'loop') and the step that makes it."""

    clause: str
    shape: str
    step: str


def asked_shape(clause: str, names: list[str], variable: str = "t") -> AskedShape | None:
    """The shape ``clause`` asks, if it asks one (see the module).

    >>> asked_shape("snake from side to side", []).step
    't = zigzag(t)'
    >>> asked_shape("orbit the lamp twice", ["lamp"]).step
    "t = circle_around(t, detect_objects('lamp'), turns=2)"
    """
    said = without_names(clause, names)  # "the king snake" asks no weave
    if UNDONE.search(said) or is_statement(clause):
        return None
    weave, loop = bool(WEAVE.search(said)), bool(LOOP.search(said))
    if weave and not loop:
        return AskedShape(clause, "zigzag", f"{variable} = zigzag({variable})")
    if not loop or weave:
        return None
    turns = _count(said)
    given = "" if turns is None else f", turns={turns}"
    named = longest_names(names_in(clause, names))
    step = (
        f"circle_around({variable}, detect_objects({named[0]!r}){given})"
        if len(named) == 1
        else f"spiral({variable}{given})"
    )
    return AskedShape(clause, "loop", f"{variable} = {step}")


def _count(clause: str) -> int | None:
    """The count of loops the clause gives, None when it gives none (the skill's own)."""
    found = COUNT.search(clause)
    if found is None:
        return None
    return ONCE[found.group(2).lower()] if found.group(2) else max(whole_count(found.group(1)), 1)


def _weaving_shifts(lines: list[str], words: str) -> bool:
    """Whether shifts weave already: one alternating in blocks, or shifts both ways in given blocks.

    Shifts both ways along one axis weave where the words give the blocks
    (``direction_words.alternation``: the alternating-shifts reader, after this one, makes them
    alternate). Whole-path shifts both ways with no blocks cancel out: "weave side to side a few
    times" answered right, left, right, left weaves nowhere.
    """
    if any(ALTERNATE.search(line) for line in lines):
        return True
    ways = {direction_argument(call_of(line, ("shift",))) for line in lines}
    return alternation(words) is not None and any(pair <= ways for pair in OPPOSITES)


def add_asked_shapes(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with a step for each shape a clause asks and no step makes (see the module)."""
    names, asked = list(names), list(asked)
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    weaving = _weaving_shifts(lines, " ".join(asked))
    made = {called_name(line) for line in lines} | ({"zigzag"} if weaving else set())
    added: list[str] = []
    notes: list[str] = []
    for words in asked:
        for clause in split_clauses(words, names):
            shape = asked_shape(clause, names, program[1])
            if shape is None or made & set(SHAPE_STEPS[shape.shape]):
                continue
            made |= set(SHAPE_STEPS[shape.shape])
            added.append(shape.step)
            notes.append(f"added `{shape.step}`: the words ask it ({clause.strip()!r}) and no step makes it")
    if not added:
        return code, []
    at = after_last_step(lines, MOVES_THE_PATH)
    return "\n".join([*lines[:at], *added, *lines[at:]]), notes

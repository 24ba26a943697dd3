"""A distance from an object the words multiply by a factor: ``scale_about`` that object.

"Increase the distance of the waypoints by two times from the table" asks every waypoint twice as
far from the table; the skill that does it is ``scale_about(t, detect_objects('table'), 2)``. A
small model reads the factor as a speed (``scale_speed(t, 2.0, near=detect_objects('table'))``,
which ``unasked-steps`` then leaves out, so the path stays as it was) or as a plain
``move_away``, which does not double anything.

A clause asks it when it names one scene object, a distance ("distance", "far", "away",
"clearance", "gap", "apart") and a factor ("two times", "2x", "twice", "double", "three-fold", "by a
factor of 3", "half as far", "halve"). When no ``scale_about`` is in the code, its
``move_away`` / ``move_closer`` steps on the object leave, and ``scale_about(t,
detect_objects(<object>), <factor>)`` is added as the last step. Code that is not made of skill
calls alone is left alone. A review note says what changed and why.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.code_parse import after_last_step, call_of, called_name, on_object, skill_program
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import NUMBER_TEXT, NUMBER_WORDS, longest_names, names_in
from trajadapt.skills import SKILL_NAMES

_COUNT_WORD = "|".join(word for word, value in NUMBER_WORDS.items() if value >= 1 and value == int(value))
FACTOR = re.compile(
    rf"\b(?:({NUMBER_TEXT}|{_COUNT_WORD})(?:\s*|-)(?:times|x|fold)\b"
    rf"|by\s+a\s+factor\s+of\s+({NUMBER_TEXT}|{_COUNT_WORD})\b"
    r"|(twice|doubl\w*|tripl\w*|thrice|quadrupl\w*|halv\w*|half(?=\s+(?:as|the)\b)))",
    re.I,
)
"""A factor said with a count ("two times", "3x", "three-fold", "by a factor of 2") or in one word
("twice", "double", "triple", "halve", "half as far")."""
DISTANCE = re.compile(r"\b(?:distance|far|farther|further|away|apart|clearance|gap|separation)\b", re.I)
SPOKEN_FACTORS = {"twi": 2.0, "dou": 2.0, "tri": 3.0, "thr": 3.0, "qua": 4.0, "hal": 0.5}
"""A one-word factor by its first letters ("doubling", "tripled", "halve")."""
DISTANCE_STEPS = ("move_away", "move_closer")


@dataclass(frozen=True)
class ScaledDistance:
    """What one clause asks: every waypoint's distance from ``name`` multiplied by ``factor``."""

    name: str
    factor: float
    clause: str


def scaled_distances(words: str, names: Iterable[str]) -> list[ScaledDistance]:
    """The distances the clauses of ``words`` multiply (see the module), in order."""
    names = list(names)
    found = []
    for clause in split_clauses(words, names):
        named = longest_names(names_in(clause, names))
        factor = FACTOR.search(clause)
        if len(named) == 1 and factor is not None and DISTANCE.search(clause):
            found.append(ScaledDistance(named[0], _factor(factor), clause))
    return found


def scale_distances(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with ``scale_about`` for each distance the words multiply and no step scales."""
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    variable = program[1]
    notes: list[str] = []
    for asked_scale in scaled_distances(" ".join(asked), names):
        if any(called_name(line) == "scale_about" for line in lines):
            continue  # answered with the skill that scales (its point may be the object's position)
        said = asked_scale.clause.strip()
        name = asked_scale.name
        for line in [x for x in lines if on_object(call_of(x, DISTANCE_STEPS), name)]:
            lines.remove(line)
            notes.append(f"left out `{line.strip()}`: {said!r} multiplies the distance from the {name}")
        step = f"{variable} = scale_about({variable}, detect_objects({name!r}), {asked_scale.factor:g})"
        lines.insert(after_last_step(lines, SKILL_NAMES), step)
        notes.append(
            f"added `{step}`: {said!r} multiplies every waypoint's distance from the {asked_scale.name}"
        )
    return ("\n".join(lines), notes) if notes else (code, [])


def _factor(found: re.Match[str]) -> float:
    """The factor a match of ``FACTOR`` says."""
    counted = found.group(1) or found.group(2)
    if counted is None:
        return SPOKEN_FACTORS[found.group(3).lower()[:3]]
    return float(counted) if counted[0].isdigit() or counted[0] == "." else NUMBER_WORDS[counted.lower()]

"""A step that bends the path the other way from what the words ask: more curve, or less.

"Make the trajectory more curved" and "make the path curve more" came back as ``smooth(t, 0.8)``,
which takes bends out; the skill that puts more in is ``exaggerate_curve``. The words ask more
curve when they put a word of more before a word of bending ("more curved", "increase the
curvature", "exaggerate the bends", "a wider arc") or after it ("curve more", "bend it more"), and
less when they ask it straight ("straighten", "flatten the curve", "less curved", "fewer bends").
Less also when they ask a more direct way ("more direct", "less winding", "less meandering").
When they ask one and not the other, a step that does the other is replaced: ``smooth`` or a
reducing ``exaggerate_curve`` by ``exaggerate_curve(t)`` for more; for less, an exaggerating one,
and ``smooth`` unless the words ask smoothing too, by ``exaggerate_curve(t, 0.5)``, which draws the
path towards its start-goal line (``smooth`` rounds off turns but keeps a wide bend; "smoothly" says
how, and asks neither). When no step bends either way, the asked step takes the place of a
whole-path ``shift`` in a direction the words never say ("make the trajectory curvier" came back as
``shift(t, 'right', 0.15)``), or is added to a program whose steps only change its pace or pause it
("let the path curve out wider, and speed up over the last part" came back as the speed step
alone), where a clause of its own asks the bend (not "slow down where the path bends more
sharply"). Code that is not made of skill calls alone is left alone. A review note says what changed
and why.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    SPEED_STEPS,
    after_last_step,
    call_of,
    called_name,
    direction_argument,
    in_place_of,
    number_arguments,
    skill_program,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.words import NEGATED, asks_pace
from trajadapt.skills import SKILL_NAMES

_BENDING = r"(?:curv\w*|bend\w*|arc\w*)"
MORE_CURVE = re.compile(
    rf"\b(?:more|increas\w*|exaggerat\w*|amplif\w*|accentuat\w*|sharpen\w*|deepen\w*|bigger|larger|stronger|deeper|sharper"
    rf"|wider)\s+(?:\w+\s+){{0,2}}?{_BENDING}"
    rf"|\b{_BENDING}\s+(?:\w+\s+){{0,3}}?(?:more|wider|deeper|sharper|stronger)\b|\bcurvier\b",
    re.I,
)
"""Words that ask the path to bend more."""
LESS_CURVE = re.compile(
    rf"\b(?:straighten\w*|straighter|(?:make|keep)\w*\s+(?:\w+\s+){{0,2}}?straight|flatten\w*|less\s+{_BENDING}"
    rf"|fewer\s+{_BENDING}|(?:reduc|decreas)\w*\s+(?:the\s+)?{_BENDING}|{_BENDING}\s+(?:\w+\s+){{0,2}}?less\b"
    r"|\b(?:less|fewer)\s+(?:wind\w*|meander\w*|twist\w*|curvy|bendy|loopy|wiggl\w*|detour\w*)|\bmore\s+direct\b)",
    re.I,
)
"""Words that ask the path to bend less."""
ASKED_STEP = {"more": "exaggerate_curve(t)", "less": "exaggerate_curve(t, 0.5)"}
"""For each ask, the step that makes it: less bend is the path drawn halfway towards its start-goal
line (``smooth`` only rounds off turns and jitter: a path that bends wide keeps its bend), more is
the path pushed away from it."""
TIMING_STEPS = (*SPEED_STEPS, "wait")
"""Steps that change only when the path is travelled: none of them can be the model's bend."""
SMOOTHING = re.compile(r"\bsmooth\w*|\bjitter\w*|\bjerk\w*", re.I)
"""Words that ask smoothing too: a ``smooth`` step stays beside a straightening."""


def asked_curve(words: str) -> str | None:
    """'more' or 'less' when the words ask the path to bend more or less (and not both), else None."""
    more, less = bool(MORE_CURVE.search(words)), bool(LESS_CURVE.search(words))
    return None if more == less else "more" if more else "less"


def bend_as_asked(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each step that bends the path the other way replaced (see the module)."""
    lines = code.splitlines()
    words = " ".join(asked)
    program = skill_program(lines, SKILL_NAMES, empty=True)
    ask = asked_curve(words)
    if program is None or ask is None:
        return code, []
    variable = program[1]
    step = f"{variable} = {ASKED_STEP[ask].replace('(t', f'({variable}', 1)}"
    notes: list[str] = []
    for index, line in enumerate(lines):
        if _bends_the_other_way(line, ask, words):
            notes.append(f"`{line.strip()}` -> `{step}`: the words ask the path to bend {ask}")
            lines[index] = in_place_of(line, step)
    if not notes and not any(
        called_name(line) == called_name(step) and not _bends_the_other_way(line, ask, words)
        for line in lines
    ):
        _bend_where_none_does(lines, notes, step, ask, words)
    return ("\n".join(lines), notes) if notes else (code, [])


def _bends_the_other_way(line: str, ask: str, words: str) -> bool:
    """Whether ``line`` bends the path against the ask (more or less bend).

    A smoothing is against more, and against less unless the words ask smoothing too; a curve
    exaggerated (factor above 1) is against less, a curve reduced against more.
    """
    name = called_name(line)
    if name == "smooth":
        return ask == "more" or not SMOOTHING.search(words)
    if name != "exaggerate_curve":
        return False
    factors = number_arguments(call_of(line, ("exaggerate_curve",)))
    value = factors[0] if factors else 1.5  # the skill's default factor
    return (value < 1.0) == (ask == "more")


def _bend_where_none_does(lines: list[str], notes: list[str], step: str, ask: str, words: str) -> None:
    """The asked bend, for a whole-path shift in a direction nobody said, or beside steps of pace alone."""
    said = said_directions(words)
    for index, line in enumerate(lines):
        direction = direction_argument(call_of(line, ("shift",)))
        if direction is not None and direction not in said:
            notes.append(f"`{line.strip()}` -> `{step}`: the words ask the path to bend {ask}, and "
                         f"say no direction {direction}")  # fmt: skip
            lines[index] = in_place_of(line, step)
            return
    if any(called_name(line) in SKILL_NAMES and called_name(line) not in TIMING_STEPS for line in lines):
        return  # a step that moves the path may be the model's bend
    if any(called_name(line) in TIMING_STEPS for line in lines) and not _a_bend_of_its_own(words):
        return  # "slow down where the path bends more sharply": the bend says where, not what
    lines.insert(after_last_step(lines, SKILL_NAMES), step)
    notes.append(f"added `{step}`: the words ask the path to bend {ask} and no step does")


def _a_bend_of_its_own(words: str) -> bool:
    """Whether a clause asks the bend with no pace and no negation ("let it curve out wider")."""
    asking = [c for c in split_clauses(words) if MORE_CURVE.search(c) or LESS_CURVE.search(c)]
    return any(not asks_pace(c) and not NEGATED.search(c) for c in asking)

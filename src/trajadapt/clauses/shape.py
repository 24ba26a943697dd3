"""The answer's shape against the instruction's clauses: no step at all, or the same step repeated.

Whatever the wording, an answer of skill calls that changes nothing while the words ask for a change
is wrong, and so, nearly always, is one that writes the same call twice: the small model's way of
running on. In the stored model runs of sessions 14 to 16 (ovita-dev and the blind paraphrase sets,
456 judged answers) all 24 answers with such a finding failed; more steps than two per clause,
without a repeat, came only in answers that passed (2), so that is not a finding. The session asks
afresh with the findings in words (``AdaptationSession.draft``, ``shape_check``).
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Sequence

from trajadapt.readers.clause_split import only_keeps
from trajadapt.sandbox.api import RESULT_VARIABLE

STEPS_PER_CLAUSE = 2
"""The most skill calls one clause is expected to need (a clause's step is one or two lines); the
answer asked afresh may have this many per clause that asks for something."""

_STEP = re.compile(r"t\s*=\s*\w+\(.*\)")
_FRAME = re.compile(rf"t\s*=\s*get_trajectory\(\s*\)|{RESULT_VARIABLE}\s*=\s*t")


def program_steps(code: str) -> tuple[str, ...] | None:
    """The skill calls of a program, in order; None when it is not a plain list of ``t = skill(...)``."""
    lines = [line.rstrip() for line in code.splitlines() if line.strip()]
    if any(line != line.lstrip() for line in lines):
        return None  # indented code: loops or functions, not a list of steps
    body = [line for line in lines if not line.startswith("#") and not _FRAME.fullmatch(line)]
    return tuple(body) if all(_STEP.fullmatch(line) for line in body) else None


def asking_clauses(clauses: Sequence[str], names: Sequence[str]) -> tuple[str, ...]:
    """The clauses that ask for a change (not those that only keep something as it is)."""
    return tuple(clause for clause in clauses if not only_keeps(clause, names))


def shape_findings(code: str, asking: Sequence[str]) -> list[str]:
    """What is wrong with the shape of ``code`` for these asking clauses, in words for the model."""
    steps = program_steps(code)
    if steps is None or not asking:
        return []
    if not steps:
        return ["it leaves the path unchanged"]
    return [f"it repeats `{step}` {times} times" for step, times in Counter(steps).items() if times > 1]

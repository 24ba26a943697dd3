"""With clause steps: each clause's lines of an answer, run alone, read against that clause's words."""

from __future__ import annotations

from collections.abc import Sequence

from trajadapt.checks.effect import measure_effect
from trajadapt.checks.review import validate_result
from trajadapt.clauses.check import clause_findings
from trajadapt.clauses.grammar import attribute_lines
from trajadapt.errors import InvalidTrajectory
from trajadapt.llm.answer import parse_answer
from trajadapt.model.case import Case
from trajadapt.sandbox.api import RESULT_VARIABLE
from trajadapt.sandbox.runner import ExecutionOptions, Sandbox
from trajadapt.session.settings import SessionSettings

Findings = list[tuple[str, list[str]]]


def count(found: Findings) -> int:
    """How many findings in all."""
    return sum(len(findings) for _, findings in found)


def findings_by_clause(
    answer: str, clauses: Sequence[str], case: Case, sandbox: Sandbox, settings: SessionSettings
) -> tuple[Findings, float]:
    """(clause, findings) for each clause whose lines of ``answer`` contradict it; seconds spent."""
    lines = parse_answer(answer).code.splitlines()[1:-1]
    divided = attribute_lines(lines, tuple(clauses), case.scene.names())
    found, seconds = [], 0.0
    for clause, part in divided or ():
        findings, spent = _findings_alone(clause, part, case, sandbox, settings)
        found.append((clause, findings))
        seconds += spent
    return [(clause, findings) for clause, findings in found if findings], seconds


def _findings_alone(
    clause: str, lines: tuple[str, ...], case: Case, sandbox: Sandbox, settings: SessionSettings
) -> tuple[list[str], float]:
    """What a clause's lines, run alone on the original path, contradict in the clause's words."""
    code = "\n".join(["t = get_trajectory()", *lines, f"{RESULT_VARIABLE} = t"])
    options = ExecutionOptions(
        skills=True, positive_x=settings.axes.positive_x, near_rule=settings.near_rule, accept_last=True
    )
    result = sandbox.run(code, case.trajectory, case.scene, options)
    if result.error is not None or result.rows is None:
        problem = result.error.describe() if result.error else "no trajectory"
        return [f"the step failed: {problem}"], result.duration_s
    try:
        trajectory = validate_result(result.rows)
    except InvalidTrajectory as exc:
        return [f"the step gave no valid trajectory: {exc}"], result.duration_s
    axes = settings.axes.frame
    effect = measure_effect(case.trajectory, trajectory, case.scene.objects, axes)
    return clause_findings(clause, effect, axes), result.duration_s

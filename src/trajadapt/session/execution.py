"""Running a plan's code: the sandbox, then the result checked and held to the constraints.

The closing limit steps of a skill program are held together first (``checks.closing_limits``).

``execute`` returns one ``Execution`` record (the outcome, what the code printed, the sandbox's and
the projection's notes, how far the projection moved waypoints), so a session keeps the record of
the result it keeps and drops the others whole.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from trajadapt.checks.closing_limits import hold_closing_limits, kept_clearances
from trajadapt.checks.constraints import ConstraintMove, Constraints, constraints_for, new_violations
from trajadapt.checks.even_steps import evened_steps
from trajadapt.checks.projection import Kept, project
from trajadapt.checks.review import validate_result
from trajadapt.checks.robot_limits import robot_constraints
from trajadapt.errors import CodeRejected, DependencyNotInstalled, InvalidTrajectory
from trajadapt.model.case import Case
from trajadapt.model.geometry import Array
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.runner import ExecutionOptions, Sandbox
from trajadapt.sandbox.skill_program import check_skill_program
from trajadapt.session.records import Failure, Outcome
from trajadapt.session.settings import SessionSettings


@dataclass(frozen=True)
class Execution:
    """One run of a plan's code and what came of it."""

    outcome: Outcome
    stdout: str = ""
    notes: tuple[str, ...] = ()
    moves: tuple[ConstraintMove, ...] = ()
    seconds: float = 0.0
    layers: tuple[str, ...] = ()
    refused: bool = False  # the code was not a skill program and never ran

    @property
    def trajectory(self) -> Trajectory | None:
        """The result when the code gave one that keeps the constraints."""
        return self.outcome if isinstance(self.outcome, Trajectory) else None


def execute(
    code: str,
    case: Case,
    sandbox: Sandbox,
    settings: SessionSettings,
    asked: Sequence[str],
    held_to_grammar: bool,
) -> Execution:
    """Run ``code`` on the case and check its result; ``asked`` are the user's words so far.

    ``held_to_grammar``: the answer was written under the skills grammar, so code that is not a skill
    program is refused before it runs (a server may ignore the grammar it was sent).
    """
    if held_to_grammar:
        try:
            check_skill_program(code)
        except CodeRejected as exc:
            message = f"{exc} (the answer must be a program of skill calls)"
            return Execution(Failure.of("CodeRejected", message), refused=True)
    skills = settings.mode == "skills"
    options = ExecutionOptions(
        skills=skills, positive_x=settings.axes.positive_x, near_rule=settings.near_rule, accept_last=skills
    )
    result = sandbox.run(code, case.trajectory, case.scene, options)
    ran = Execution(Failure("NoResult", "the code produced no trajectory"), result.stdout, result.notes,
                    seconds=result.duration_s, layers=tuple(result.layers))  # fmt: skip
    if result.error is not None:
        return replace(ran, outcome=Failure(result.error.type, result.error.describe()))
    if result.rows is None:
        return ran
    try:
        trajectory = validate_result(result.rows)
    except InvalidTrajectory as exc:
        return replace(ran, outcome=Failure.of("InvalidTrajectory", str(exc)))
    kept: Kept = ()
    if skills:
        kept = kept_clearances(code, case.scene)
        held, note = hold_closing_limits(code, trajectory.array, case.scene)
        if note is not None:
            trajectory, ran = validate_result(held), replace(ran, notes=(*ran.notes, note))
    return held_to_constraints(ran, trajectory, case, settings, " ".join(asked), kept)


def held_to_constraints(
    ran: Execution, trajectory: Trajectory, case: Case, settings: SessionSettings, asked: str, kept: Kept = ()
) -> Execution:
    """The run with ``trajectory`` if it keeps the constraints (projected if asked), or why not.

    ``kept``: the clearances the program keeps at its close, which a projection keeps too.
    """
    limits = constraints_for(case.scene, settings.constraints, robot_constraints(settings.robot), asked)
    original = case.trajectory.array
    violations = new_violations(trajectory.array, original, case.scene, limits)
    if violations and settings.project:
        broken = "; ".join(v.message for v in violations)
        try:
            projection = project(trajectory.array, original, case.scene, limits, kept)
        except DependencyNotInstalled as exc:
            return replace(ran, outcome=Failure.of("ConstraintViolation", f"{broken} ({exc})"))
        note = f"{projection.describe()} (the code's result broke: {broken})"
        ran = replace(ran, notes=(*ran.notes, note), moves=projection.moves)
        trajectory = validate_result(projection.trajectory)
        violations = new_violations(trajectory.array, original, case.scene, limits)
    if violations:
        return replace(
            ran, outcome=Failure.of("ConstraintViolation", "; ".join(v.message for v in violations))
        )
    evened = evened_steps(trajectory.array, original)
    if evened is not None and _keeps_what_it_kept(evened, trajectory.array, case, limits, kept):
        longest = float(trajectory.step_lengths().max())
        note = f"waypoints placed evenly round a step of {longest:.3g}, far longer than the original's"
        return replace(ran, outcome=validate_result(evened), notes=(*ran.notes, note))
    return replace(ran, outcome=trajectory)


def _keeps_what_it_kept(evened: Array, before: Array, case: Case, limits: Constraints, kept: Kept) -> bool:
    """Whether ``evened`` breaks no constraint and comes no nearer a kept clearance's point than it may."""
    if new_violations(evened, case.trajectory.array, case.scene, limits):
        return False
    for point, distance in kept:
        nearest = [
            float(np.linalg.norm(t[:, :3] - np.asarray(point), axis=1).min()) for t in (evened, before)
        ]
        if nearest[0] < min(distance, nearest[1]) - 1e-9:
            return False
    return True

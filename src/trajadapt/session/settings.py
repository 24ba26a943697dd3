"""SessionSettings: how a session talks to the model and how hard it tries, from the user's settings."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from trajadapt import __version__
from trajadapt.checks.constraints import Constraints
from trajadapt.model.geometry import AXIS_CONVENTIONS, AxisConvention
from trajadapt.settings import Settings


@dataclass(frozen=True)
class SessionSettings:
    """How a session talks to the LLM and how hard it tries before giving up.

    ``constraints`` adds the user's limits to those the scene states; a result that breaks them is
    projected onto them (``project``, the default; a review note says what bound it and how far
    waypoints moved), or, with ``project=False``, goes back for repair with the measured numbers.
    ``grammar`` (skills mode) sends the answer grammar of the case's scene with each request, for
    backends that can constrain decoding to it (see ``answer_grammar``).
    """

    axes: AxisConvention = AXIS_CONVENTIONS["paper"]
    mode: str = "skills"
    repair_attempts: int = 2
    format_retries: int = 1
    constraints: Constraints | None = None
    robot: str = "none"
    check_constraints: bool = True
    project: bool = True
    temperature: float = 0.0
    max_tokens: int = 1024
    seed: int | None = 0
    waypoints_in_prompt: bool = False
    grammar: bool = True
    examples: int = 3
    leave_out_unasked: bool = True
    repair_contradictions: bool = False
    clause_steps: bool = False
    clause_check: bool = True

    @classmethod
    def from_settings(cls, settings: Settings, constraints: Constraints | None = None) -> SessionSettings:
        """The one way from the user's settings (config, environment, flags) to a session's."""
        return cls(
            axes=AXIS_CONVENTIONS[settings.axes],
            mode=settings.mode,
            repair_attempts=settings.repair_attempts,
            constraints=constraints,
            robot=settings.robot,
            project=settings.project,
            temperature=settings.temperature,
            seed=settings.seed,
            waypoints_in_prompt=settings.waypoints_in_prompt,
            grammar=settings.grammar,
            examples=settings.examples,
            leave_out_unasked=settings.leave_out_unasked,
            repair_contradictions=settings.repair_contradictions,
            clause_steps=settings.clause_steps,
            clause_check=settings.clause_check,
        )

    def describe(self) -> dict[str, Any]:
        """What reproduces a run, for result files and the log."""
        return {
            "trajadapt_version": __version__,
            "mode": self.mode,
            "axes": self.axes.name,
            "temperature": self.temperature,
            "seed": self.seed,
            "max_tokens": self.max_tokens,
            "repair_attempts": self.repair_attempts,
            "waypoints_in_prompt": self.waypoints_in_prompt,
            "project": self.project,
            "robot": self.robot,
            "constraints": list(self.constraints.sources) if self.constraints else [],
            "grammar": self.grammar,
            "examples": self.examples,
            "leave_out_unasked": self.leave_out_unasked,
            "repair_contradictions": self.repair_contradictions,
            "clause_steps": self.clause_steps,
            "clause_check": self.clause_check,
        }

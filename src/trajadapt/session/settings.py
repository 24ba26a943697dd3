"""SessionSettings: how a session talks to the model and how hard it tries, from the user's settings."""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any

from trajadapt import __version__
from trajadapt.checks.constraints import Constraints
from trajadapt.memory import Retrieval
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
    near_rule: str = "zone"
    mode: str = "skills"
    repair_attempts: int = 2
    format_retries: int = 1
    constraints: Constraints | None = None
    robot: str = "none"
    project: bool = True
    temperature: float = 0.0
    max_tokens: int = 1024
    seed: int | None = 0
    waypoints_in_prompt: bool = False
    grammar: bool = True
    examples: int = 3
    retrieval: Retrieval = "words"
    read_against_words: bool = True
    repair_contradictions: bool = False
    clause_steps: bool = False
    clause_check: bool = True
    shape_check: bool = True

    @property
    def leave_out_unasked(self) -> bool:
        """The old name of ``read_against_words``."""
        return self.read_against_words

    @classmethod
    def from_settings(cls, settings: Settings, constraints: Constraints | None = None) -> SessionSettings:
        """The one way from the user's settings (config, environment, flags) to a session's.

        Every setting a session has under the same name is copied; ``axes`` becomes its convention.
        """
        shared = {f.name for f in fields(cls)} & {f.name for f in fields(Settings)}
        values: dict[str, Any] = {name: getattr(settings, name) for name in shared}
        values["axes"] = AXIS_CONVENTIONS[settings.axes]
        return cls(**values, constraints=constraints)

    def describe(self) -> dict[str, Any]:
        """What reproduces a run, for result files and the log: every field, and the version."""
        described: dict[str, Any] = {"trajadapt_version": __version__}
        for item in fields(self):
            described[item.name] = getattr(self, item.name)
        described["axes"] = self.axes.name
        described["constraints"] = list(self.constraints.sources) if self.constraints else []
        return described

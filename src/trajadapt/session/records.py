"""What a session passes around and hands back: turns, checkpoints, failures, timings, the result."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, Literal

from trajadapt.backends.base import Completion
from trajadapt.checks.effect import Effect
from trajadapt.checks.review import ReviewNote
from trajadapt.llm.answer import Plan
from trajadapt.model.case import Case
from trajadapt.model.trajectory import Trajectory
from trajadapt.readers import ReaderNote

TurnKind = Literal["draft", "feedback", "repair", "format-retry"]


@dataclass(frozen=True)
class Explanation:
    """What the code does in plain words: exact from the skills, or the model's own reading of other code."""

    source: Literal["skills", "model"]
    lines: tuple[str, ...]

    def to_dict(self) -> dict[str, Any]:
        """The result file's ``explanation`` field."""
        return {"source": self.source, "lines": list(self.lines)}


@dataclass(frozen=True)
class Turn:
    """One request to the LLM and what came of it."""

    kind: TurnKind
    user_text: str
    plan: Plan | None
    completion: Completion | None
    error: str | None = None


@dataclass(frozen=True)
class Checkpoint:
    """The conversation right after a plan: where to cut back to on undo, and the words said by then."""

    messages: int
    turns: int
    plan: Plan
    asked: tuple[str, ...]
    left_out: tuple[ReaderNote, ...]


@dataclass(frozen=True)
class Timings:
    """Seconds spent waiting for the LLM, executing code, and in all."""

    llm_s: float = 0.0
    exec_s: float = 0.0
    total_s: float = 0.0

    def to_dict(self) -> dict[str, float]:
        """The result file's ``timings_s`` field."""
        return {
            "llm": round(self.llm_s, 4),
            "exec": round(self.exec_s, 4),
            "total": round(self.total_s, 4),
        }


@dataclass(frozen=True)
class Failure:
    """Why code gave no trajectory, typed: what kind of failure, and the line people read.

    ``kind`` is an exception type (TypeError, ...) or one of ConstraintViolation, InvalidTrajectory,
    NoResult, RepairUnreadable and a backend error's type; ``message`` is the whole line shown to
    people and sent back for repair.
    """

    kind: str
    message: str

    @classmethod
    def of(cls, kind: str, detail: str) -> Failure:
        """A failure whose message is 'kind: detail'."""
        return cls(kind, f"{kind}: {detail}")

    def __str__(self) -> str:
        return self.message


Outcome = Trajectory | Failure


@dataclass(frozen=True)
class AdaptationResult:
    """The outcome of an approved plan: the new trajectory, or why there is none."""

    case: Case
    status: Literal["ok", "error"]
    plan: Plan | None
    trajectory: Trajectory | None
    failure: Failure | None
    attempts: int
    backend: str
    model: str
    timings: Timings
    notes: tuple[ReviewNote, ...] = ()
    stdout: str = ""
    tokens: dict[str, int] = field(default_factory=dict)
    settings: dict[str, Any] = field(default_factory=dict)
    effect: Effect | None = None
    contradictions: tuple[str, ...] = ()
    explanation: Explanation | None = None
    recalled: tuple[str, ...] = ()
    """Ids of the user's remembered examples that were in the prompt."""
    remembered_as: str = ""
    """The id this approved answer is remembered under ('' when memory is off or it failed)."""
    answer: str = ""
    """The model's own answer behind ``plan``, before the readers changed it ('' when unknown)."""

    @property
    def ok(self) -> bool:
        """True when the code ran and produced a valid trajectory."""
        return self.status == "ok"

    @property
    def error(self) -> str | None:
        """Why there is no trajectory, in one line (None when there is one)."""
        return self.failure.message if self.failure else None

    def to_dict(self) -> dict[str, Any]:
        """The result file's content."""
        return {
            "case": self.case.name,
            "case_source": str(self.case.source) if self.case.source else None,
            "instruction": self.case.instruction,
            "high_level_plan": list(self.plan.steps) if self.plan else [],
            "code": self.plan.code if self.plan else "",
            "modified_trajectory": self.trajectory.to_rows() if self.trajectory else None,
            "original_trajectory": self.case.trajectory.to_rows(),
            "objects": [obj.to_dict() for obj in self.case.scene.objects],
            "status": self.status,
            "error": self.error,
            "error_kind": self.failure.kind if self.failure else None,
            "attempts": self.attempts,
            "backend": self.backend,
            "model": self.model,
            "timings_s": self.timings.to_dict(),
            "tokens": self.tokens,
            "review_notes": [note.message for note in self.notes],
            "stdout": self.stdout,
            "settings": self.settings,
            "explanation": self.explanation.to_dict() if self.explanation else None,
            "effect": (
                {
                    **self.effect.to_dict(),
                    "in_words": self.effect.describe(),
                    "contradictions": list(self.contradictions),
                }
                if self.effect
                else None
            ),
            "memory": {"recalled": list(self.recalled), "remembered_as": self.remembered_as or None},
            "answer": self.answer or None,
        }


ProgressCallback = Callable[[str], None]

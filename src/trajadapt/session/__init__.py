"""A session on one case: the conversation with the model, the run of its code and the result.

``AdaptationSession`` (``session.adaptation``) orchestrates; its settings (``session.settings``), the
records it passes and returns (``session.records``), the run of the code (``session.execution``), the
clause check (``session.clause_check``) and the log (``session.log``) each have their module.
"""

from trajadapt.session.adaptation import AdaptationSession, skill_hints
from trajadapt.session.execution import Execution
from trajadapt.session.records import (
    AdaptationResult,
    Checkpoint,
    Explanation,
    Failure,
    Outcome,
    ProgressCallback,
    Timings,
    Turn,
)
from trajadapt.session.settings import SessionSettings

__all__ = [
    "AdaptationResult",
    "AdaptationSession",
    "Checkpoint",
    "Execution",
    "Explanation",
    "Failure",
    "Outcome",
    "ProgressCallback",
    "SessionSettings",
    "Timings",
    "Turn",
    "skill_hints",
]

"""A session's exchanges, written to the SQLite log as they happen (nothing when there is no store)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from trajadapt.backends.base import ChatMessage
from trajadapt.files.store import NewExchange, NewSession, Store
from trajadapt.model.case import Case
from trajadapt.session.execution import Execution
from trajadapt.session.records import Failure, Turn


class SessionLog:
    """Writes one session's exchanges to ``store``; every method does nothing without one."""

    def __init__(self, store: Store | None) -> None:
        self.store = store
        self.session_id: str | None = None

    def start(self, case: Case, backend: str, model: str, settings: dict[str, Any]) -> None:
        """Log the session itself, before its first exchange."""
        if self.store is None:
            return
        self.session_id = self.store.start_session(NewSession(
            case_name=case.name,
            case_source=str(case.source) if case.source else None,
            instruction=case.instruction,
            backend=backend,
            model=model,
            case=case.to_dict(),
            settings=settings,
        ))  # fmt: skip

    def turn(self, turn: Turn, messages: Sequence[ChatMessage]) -> None:
        """Log a request and its answer (``messages``: the conversation, the answer last)."""
        completion = turn.completion
        self.exchange(turn.kind, turn.plan.code if turn.plan else "", {
            "plan": list(turn.plan.steps) if turn.plan else None,
            "answer": completion.text if completion else None,
            "request": [{"role": m.role, "content": m.content} for m in messages[:-1]],
            "user_text": turn.user_text,
            "usage": vars(completion.usage) if completion else None,
        }, turn.error, {"llm": completion.duration_s if completion else None})  # fmt: skip

    def execution(self, code: str, run: Execution) -> None:
        """Log a run of the code and its outcome."""
        trajectory = run.trajectory
        problem = run.outcome.message if isinstance(run.outcome, Failure) else None
        if run.refused:
            self.exchange("execution", code, {"ok": False}, problem, {})
            return
        self.exchange("execution", code, {
            "ok": trajectory is not None,
            "stdout": run.stdout,
            "layers": list(run.layers),
            "waypoints": len(trajectory) if trajectory is not None else None,
            "trajectory": trajectory.to_rows() if trajectory is not None else None,
        }, problem, {"exec": run.seconds})  # fmt: skip

    def exchange(
        self, kind: str, code: str, details: dict[str, Any], error: str | None, timings: dict[str, Any]
    ) -> None:
        """Log one exchange of any kind (an undo, a draft, an execution)."""
        if self.store is None or self.session_id is None:
            return
        self.store.log_exchange(self.session_id, NewExchange(
            kind=kind,
            code=code,
            user_text=details.pop("user_text", None),
            request=details.pop("request", None),
            answer=details.pop("answer", None),
            plan="\n".join(details.get("plan") or []),
            outcome=details,
            error=error,
            timings=timings,
        ))  # fmt: skip

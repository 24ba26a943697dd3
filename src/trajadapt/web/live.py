"""Review sessions held by the server: one AdaptationChain each, worked on by background jobs.

An LLM call takes seconds to a minute, so every request that needs one starts a job on a thread and
returns at once; the page polls the session's state. Cancelling abandons the job: the page is free
at once and whatever the abandoned call adds to the conversation is rolled back when it returns.
"""

from __future__ import annotations

import threading
import time
import traceback
import uuid
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from trajadapt.chain import AdaptationChain
from trajadapt.errors import SessionStateError, TrajadaptError
from trajadapt.llm.answer import Plan
from trajadapt.model.case import Case
from trajadapt.model.trajectory import Trajectory
from trajadapt.session import AdaptationResult
from trajadapt.skills.explain import explain_code

Status = Literal["working", "ready", "approved", "failed"]


@dataclass
class Version:
    """One plan shown to the user, what led to it and the path its code proposes."""

    index: int
    request: str  # the instruction or the feedback that produced it
    plan: Plan
    proposed: list[list[float]] | None
    problem: str | None
    checkpoint: int  # the session's plan version to rewind to
    on: str = "original"  # what the feedback changed: the original trajectory or the current result
    explanation: list[str] | None = None  # the code in words, from the skills (None: not only skill calls)

    def to_dict(self) -> dict[str, Any]:
        """JSON form for the page."""
        return {
            "index": self.index, "request": self.request, "steps": list(self.plan.steps),
            "code": self.plan.code, "proposed": self.proposed, "problem": self.problem,
            "explanation": self.explanation, "on": self.on,
        }  # fmt: skip


@dataclass
class LiveSession:
    """A session the server is working on, with its versions, job state and outputs."""

    case: Case
    session: AdaptationChain
    id: str = field(default_factory=lambda: uuid.uuid4().hex[:12])
    versions: list[Version] = field(default_factory=list)
    current: int = -1
    status: Status = "working"
    activity: str = "starting"
    activity_since: float = field(default_factory=time.time)
    error: str | None = None
    result: AdaptationResult | None = None
    simulation: dict[str, Any] | None = None
    job: int = 0
    lock: threading.Lock = field(default_factory=threading.Lock)  # held by the job touching ``session``
    used: float = field(default_factory=time.monotonic)  # when the page last asked about it
    forgotten: set[str] = field(default_factory=set)  # remembered examples forgotten from this page

    def to_dict(self) -> dict[str, Any]:
        """The state the page draws."""
        return {
            "id": self.id, "live": True, "status": self.status,
            "activity": self.activity, "elapsed_s": round(time.time() - self.activity_since, 1),
            "error": self.error, "case": _case_view(self.case), "current": self.current,
            "versions": [v.to_dict() for v in self.versions],
            "result": self.session.to_dict(self.result) if self.result else None,
            "simulation": self.simulation, "memory": self.memory_view(),
        }  # fmt: skip

    def memory_view(self) -> dict[str, Any]:
        """The remembered examples the first prompt showed, and what this result is remembered as."""
        shown = self.session.steps[0].recalled_examples
        kept = self.result.remembered_as if self.result else ""
        recalled = [{"id": e.remembered, "instruction": e.instruction} for e in shown
                    if e.remembered not in self.forgotten]  # fmt: skip
        return {"recalled": recalled, "remembered_as": "" if kept in self.forgotten else kept}

    def say(self, activity: str) -> None:
        """Progress from the session ("asking local", "running the code")."""
        self.activity, self.activity_since = activity, time.time()


def _case_view(case: Case) -> dict[str, Any]:
    return {"name": case.name, **case.to_dict()}


class Jobs:
    """Runs one job at a time per live session on a thread; maps failures to words for the page."""

    def start(self, live: LiveSession, what: str, work: Callable[[], None], undo: Callable[[], None]) -> None:
        """Run ``work`` in the background; ``undo`` rolls its effect back if it was cancelled meanwhile.

        Raises:
            SessionStateError: the session is already working.
        """
        if live.status == "working":
            raise SessionStateError(f"the session is busy ({live.activity}); wait or cancel it")
        live.job += 1
        token = live.job
        live.status, live.error = "working", None
        live.say(what)
        threading.Thread(target=self._run, args=(live, token, work, undo), daemon=True).start()

    @staticmethod
    def _run(live: LiveSession, token: int, work: Callable[[], None], undo: Callable[[], None]) -> None:
        with live.lock:
            if token != live.job:
                return  # cancelled before it started
            try:
                work()
            except TrajadaptError as exc:
                outcome: tuple[Status, str | None] = (
                    "ready" if live.versions else "failed",
                    f"{type(exc).__name__}: {exc}",
                )
            except Exception as exc:  # noqa: BLE001 - shown on the page in words, logged in full
                traceback.print_exc()
                outcome = (
                    "ready" if live.versions else "failed",
                    f"internal error ({type(exc).__name__}: {exc})",
                )
            else:
                outcome = ("approved" if live.result is not None else "ready", None)
            if token != live.job:
                undo()
                return
            live.status, live.error = outcome
            live.say("idle")

    @staticmethod
    def cancel(live: LiveSession) -> None:
        """Abandon the running job; the page may go on at once."""
        if live.status != "working":
            raise SessionStateError("nothing is running to cancel")
        live.job += 1
        live.status = "ready" if live.versions else "failed"
        live.error = "cancelled: the answer of that request will be discarded"
        live.say("idle")


def add_version(live: LiveSession, request: str, plan: Plan, on: str = "original") -> None:
    """Record a new plan with its preview (the code run once on the trajectory)."""
    live.say("running the code for a preview")
    outcome = live.session.preview()
    proposed = outcome.to_rows() if isinstance(outcome, Trajectory) else None
    problem = None if isinstance(outcome, Trajectory) else outcome.message
    checkpoint = len(live.session.versions) - 1
    explanation = explain_code(plan.code)
    live.versions.append(
        Version(len(live.versions), request, plan, proposed, problem, checkpoint, on, explanation)
    )
    live.current = len(live.versions) - 1


def result_file_name(live: LiveSession) -> str:
    """The download name of the result."""
    return f"{live.case.name}.result.json"


def work_folder(root: Path, live: LiveSession) -> Path:
    """Where a session's simulation pictures go."""
    folder = root / live.id
    folder.mkdir(parents=True, exist_ok=True)
    return folder


MAX_LIVE_SESSIONS = 64
"""Sessions a server holds in memory at once; the log keeps every one after it is let go."""
IDLE_EXPIRY_S = 3600.0
"""A session nobody asked about for this long is let go (it can still be viewed from the log)."""


def make_room(live: dict[str, LiveSession], now: float | None = None) -> None:
    """Let go of expired sessions, then of the least recently used idle ones, to hold one more.

    Raises:
        SessionStateError: every session held is at work (a job running); try again later.
    """
    now = time.monotonic() if now is None else now
    idle = sorted((s for s in list(live.values()) if s.status != "working"), key=lambda s: s.used)
    for session in idle:
        if now - session.used > IDLE_EXPIRY_S or len(live) >= MAX_LIVE_SESSIONS:
            live.pop(session.id, None)
    if len(live) >= MAX_LIVE_SESSIONS:
        raise SessionStateError(
            f"the server is working on {len(live)} sessions already; try again when one is done"
        )

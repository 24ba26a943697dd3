"""Earlier sessions from the SQLite log, shown read-only after a restart."""

from __future__ import annotations

from typing import Any

from trajadapt.errors import SessionStateError
from trajadapt.files.store import Store

PLAN_KINDS = ("draft", "feedback", "repair")


def stored_session(store: Store | None, session_id: str) -> dict[str, Any]:
    """A logged session in the shape the page draws (status ``stored``).

    Raises:
        SessionStateError: no such session in the log, or no log (logging is off).
    """
    if store is None:
        raise SessionStateError(
            f"no session {session_id!r} on this server (logging is off: nothing is stored)"
        )
    case = store.session_case(session_id)
    if case is None:
        raise SessionStateError(f"no session {session_id!r} on this server or in its log")
    versions: list[dict[str, Any]] = []
    for record in store.recent_exchanges(limit=10_000, session_id=session_id):
        if record.kind in PLAN_KINDS and record.code:
            versions.append({
                "index": len(versions), "request": record.user_text, "steps": record.plan.splitlines(),
                "code": record.code, "proposed": None, "problem": None,
            })  # fmt: skip
        elif record.kind == "execution" and versions:
            versions[-1]["proposed"] = record.outcome.get("trajectory")
            versions[-1]["problem"] = record.error or None
    return {
        "id": session_id, "live": False, "status": "stored", "activity": "", "elapsed_s": 0, "error": None,
        "case": {"name": case.get("name", "case"), **case}, "current": len(versions) - 1,
        "versions": versions, "result": None, "simulation": None,
    }  # fmt: skip

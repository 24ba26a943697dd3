"""The messages between the sandbox's processes, read as untrusted input on every hop.

Generated code runs in a child that may have been taken over, so what it writes on its result pipe is
checked by the worker, and what the worker writes on its stdout is checked again by the host: one
JSON object, of bounded size, with exactly the expected fields and types. Anything else is a
``ProtocolError`` in words; the host then replaces the worker. The layers a result reports are never
taken from the child: the worker reads them from the kernel (``/proc/PID/status`` and ``limits``).
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any

from trajadapt.model.trajectory import MAX_WAYPOINTS
from trajadapt.safe_text import MESSAGE_CHARS, safe_text

MAX_CHILD_BYTES = 16 * 1024 * 1024
"""Largest result a child may write (100,000 waypoints of four numbers fit well within it)."""

MAX_ANSWER_CHARS = MAX_CHILD_BYTES + 64 * 1024
"""Largest answer line the host reads from the worker."""

MAX_NOTES = 20
MAX_STDOUT_CHARS = 1_000_000
MAX_LINE = 1_000_000
VERIFIED_LAYERS = ("unprivileged-user", "rlimits", "seccomp-allowlist")


class ProtocolError(ValueError):
    """A message between sandbox processes is not of the agreed form."""


@dataclass(frozen=True)
class ChildResult:
    """What a child reports: rows or an error, the text it printed, notes on how its code was read."""

    ok: bool
    rows: list[list[float]] | None
    stdout: str
    error: dict[str, Any] | None
    notes: list[str]

    def to_json(self) -> dict[str, Any]:
        """The JSON form, as the child writes it."""
        data: dict[str, Any] = {
            "ok": self.ok,
            "stdout": self.stdout,
            "error": self.error,
            "notes": self.notes,
        }
        if self.rows is not None:
            data["trajectory"] = self.rows
        return data


@dataclass(frozen=True)
class WorkerAnswer:
    """What the worker reports to the host for one job: the child's result and the verified layers."""

    result: ChildResult
    duration_s: float
    layers: tuple[str, ...]


def error_result(kind: str, message: str, line: int | None = None, stdout: str = "") -> ChildResult:
    """A failed result with an error of ``kind`` (an exception name, 'Timeout', 'Crash', ...)."""
    return ChildResult(False, None, stdout, {"type": kind, "message": message, "line": line}, [])


def decode_json(data: bytes | str, limit: int) -> Any:
    """Parse one JSON document of at most ``limit`` bytes or characters.

    Raises:
        ProtocolError: too large, not UTF-8, not JSON, or nested too deep.
    """
    if len(data) > limit:
        raise ProtocolError(f"message of {len(data)} bytes is over the limit of {limit}")
    try:
        return json.loads(data)
    except (ValueError, RecursionError) as exc:  # UnicodeDecodeError and JSONDecodeError are ValueErrors
        raise ProtocolError(f"message is not JSON ({type(exc).__name__})") from None


def read_child_result(data: Any) -> ChildResult:
    """Check a decoded child message and return it with every text made safe.

    Raises:
        ProtocolError: a field is missing, of the wrong type or out of range, or an unknown field is present.
    """
    fields = _object(data, {"ok", "stdout", "error", "notes"}, {"trajectory"}, "result")
    ok = fields["ok"]
    if not isinstance(ok, bool):
        raise ProtocolError("result.ok must be true or false")
    rows = _rows(fields["trajectory"]) if "trajectory" in fields else None
    error = None if fields["error"] is None else _error(fields["error"])
    if ok != (rows is not None and error is None):
        raise ProtocolError("result.ok must be true exactly when a trajectory and no error are given")
    return ChildResult(
        ok, rows, _text(fields["stdout"], MAX_STDOUT_CHARS, "stdout"), error, _notes(fields["notes"])
    )


def worker_answer_json(result: ChildResult, duration_s: float, layers: list[str]) -> str:
    """The worker's answer line for one job (ASCII JSON, no newline)."""
    return json.dumps({"result": result.to_json(), "duration_s": duration_s, "layers": layers})


def read_worker_answer(line: str) -> WorkerAnswer:
    """Check one answer line from the worker.

    Raises:
        ProtocolError: the line is cut, too long, not JSON, or not of the agreed form.
    """
    if not line.endswith("\n"):
        raise ProtocolError("the answer line was cut off or too long")
    data = _object(decode_json(line, MAX_ANSWER_CHARS), {"result", "duration_s", "layers"}, set(), "answer")
    duration = data["duration_s"]
    if not _is_number(duration) or not 0 <= duration < 86_400:
        raise ProtocolError("answer.duration_s must be a number of seconds")
    layers = data["layers"]
    if not isinstance(layers, list) or any(layer not in VERIFIED_LAYERS for layer in layers):
        raise ProtocolError(f"answer.layers must name only {', '.join(VERIFIED_LAYERS)}")
    return WorkerAnswer(read_child_result(data["result"]), float(duration), tuple(layers))


def _object(data: Any, required: set[str], optional: set[str], what: str) -> dict[str, Any]:
    if not isinstance(data, dict):
        raise ProtocolError(f"{what} must be a JSON object")
    missing, unknown = required - data.keys(), data.keys() - required - optional
    if missing or unknown:
        raise ProtocolError(f"{what}: missing {sorted(missing)}, unknown {sorted(unknown)[:5]}")
    return data


def _rows(value: Any) -> list[list[float]]:
    if not isinstance(value, list) or len(value) > MAX_WAYPOINTS:
        raise ProtocolError(f"result.trajectory must be a list of at most {MAX_WAYPOINTS} rows")
    for row in value:
        if not isinstance(row, list) or len(row) != 4 or not all(_is_number(v) for v in row):
            raise ProtocolError("result.trajectory rows must be four numbers each")
    return [[float(v) for v in row] for row in value]


def _error(value: Any) -> dict[str, Any]:
    fields = _object(value, {"type", "message", "line"}, set(), "result.error")
    kind, line = fields["type"], fields["line"]
    if not isinstance(kind, str) or not kind.isidentifier() or len(kind) > 100:
        raise ProtocolError("result.error.type must be a name")
    if line is not None and (
        not isinstance(line, int) or isinstance(line, bool) or not 0 <= line <= MAX_LINE
    ):
        raise ProtocolError("result.error.line must be a line number or null")
    return {"type": kind, "message": _text(fields["message"], MESSAGE_CHARS, "error.message"), "line": line}


def _notes(value: Any) -> list[str]:
    if not isinstance(value, list) or len(value) > MAX_NOTES:
        raise ProtocolError(f"result.notes must be a list of at most {MAX_NOTES} texts")
    return [_text(note, MESSAGE_CHARS, "notes") for note in value]


def _text(value: Any, limit: int, what: str) -> str:
    if not isinstance(value, str):
        raise ProtocolError(f"result.{what} must be text")
    return safe_text(value, limit)


def _is_number(value: Any) -> bool:
    """A JSON number that fits a float (NaN and infinity pass: the trajectory check names them)."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        return False
    try:
        float(value)
    except OverflowError:
        return False
    return True

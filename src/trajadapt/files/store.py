"""Store: every exchange with the LLM, logged to a local SQLite file as it happens."""

from __future__ import annotations

import json
import sqlite3
import threading
import time
import uuid
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from trajadapt.errors import LogUnusable
from trajadapt.safe_text import ANSWER_CHARS, safe_optional, safe_text

MIGRATIONS = (
    """
    CREATE TABLE sessions (
        id TEXT PRIMARY KEY,
        created REAL NOT NULL,
        case_name TEXT,
        case_source TEXT,
        instruction TEXT,
        backend TEXT,
        model TEXT,
        case_json TEXT
    );
    CREATE TABLE exchanges (
        id INTEGER PRIMARY KEY AUTOINCREMENT,
        session_id TEXT NOT NULL REFERENCES sessions(id),
        created REAL NOT NULL,
        kind TEXT NOT NULL,
        user_text TEXT,
        request_json TEXT,
        answer TEXT,
        plan TEXT,
        code TEXT,
        outcome_json TEXT,
        error TEXT,
        timings_json TEXT
    );
    CREATE INDEX exchanges_session ON exchanges(session_id);
    """,
    "ALTER TABLE sessions ADD COLUMN settings_json TEXT;",
)


@dataclass(frozen=True)
class NewSession:
    """A session to log: the case, who answers it, and the settings that reproduce the run.

    ``settings`` holds mode, axes, temperature, seed, max tokens and the rest of
    ``SessionSettings.describe()``, plus the trajadapt version.
    """

    case_name: str
    case_source: str | None
    instruction: str
    backend: str
    model: str
    case: dict[str, Any]
    settings: dict[str, Any]


@dataclass(frozen=True)
class NewExchange:
    """One exchange to log.

    A draft, feedback, repair or format retry (with the request and answer), an execution (with its
    outcome) or an undo.
    """

    kind: str
    code: str = ""
    user_text: str | None = None
    request: list[dict[str, str]] | None = None
    answer: str | None = None
    plan: str = ""
    outcome: dict[str, Any] | None = None
    error: str | None = None
    timings: dict[str, Any] | None = None


@dataclass(frozen=True)
class SessionSummary:
    """A logged session as the session list shows it."""

    id: str
    created: float
    case_name: str
    instruction: str
    backend: str
    model: str
    settings: dict[str, Any]

    def to_dict(self) -> dict[str, Any]:
        """JSON form for the page."""
        return asdict(self)


@dataclass(frozen=True)
class ExchangeRecord:
    """One logged exchange, as ``trajadapt logs`` shows it."""

    id: int
    session_id: str
    created: float
    kind: str
    user_text: str
    instruction: str
    backend: str
    model: str
    plan: str
    code: str
    error: str
    outcome: dict[str, Any]
    timings: dict[str, Any]


class Store:
    """A SQLite log; each write is committed at once so a crash loses nothing already said.

    One connection serves every thread (the review page logs from many), behind a lock: each write is
    one transaction, and readers never see a half-written one. The file is in WAL mode, so another
    process (``trajadapt logs``) can read while a server writes, and waits up to
    ``BUSY_TIMEOUT_S`` for a lock held by another process instead of failing. Every text is made safe
    first (a lone surrogate cannot be stored as UTF-8), and an exchange must name a logged session.
    """

    BUSY_TIMEOUT_S = 30.0

    def __init__(self, path: Path) -> None:
        """Open (or create) the log at ``path``.

        Raises:
            LogUnusable: the file or its folder cannot be used (not a database, damaged, a folder,
                written by a newer trajadapt, no permission), with what to do about it.
        """
        self.path = path
        self._lock = threading.RLock()
        with self._mapped("open"):
            path.parent.mkdir(parents=True, exist_ok=True)
            self._connection = sqlite3.connect(path, check_same_thread=False, timeout=self.BUSY_TIMEOUT_S)
        try:
            with self._mapped("open"):
                self._connection.row_factory = sqlite3.Row
                self._connection.execute("PRAGMA journal_mode=WAL")
                self._connection.execute("PRAGMA foreign_keys=ON")
                self._migrate()
        except LogUnusable:
            self._connection.close()
            raise

    @contextmanager
    def _mapped(self, doing: str) -> Iterator[None]:
        """Foreign errors of the file or SQLite, as a LogUnusable that says what to do."""
        try:
            yield
        except (sqlite3.Error, OSError) as exc:
            raise LogUnusable(
                f"cannot {doing} the log {self.path} ({type(exc).__name__}: {exc}); move the file aside "
                "to start a new log, set TRAJADAPT_HOME to another folder, or turn logging off with "
                "TRAJADAPT_LOG=false"
            ) from exc

    def close(self) -> None:
        """Close the database."""
        with self._lock:
            self._connection.close()

    def _migrate(self) -> None:
        """Bring the schema up to date, one process at a time (a write lock before reading the version)."""
        with self._lock:
            connection = self._connection
            connection.execute("BEGIN IMMEDIATE")
            try:
                version = int(connection.execute("PRAGMA user_version").fetchone()[0])
                if version > len(MIGRATIONS):
                    raise sqlite3.DatabaseError(
                        f"its schema is version {version}, written by a newer trajadapt (this one knows "
                        f"up to {len(MIGRATIONS)})"
                    )
                for number, script in enumerate(MIGRATIONS[version:], start=version + 1):
                    for statement in filter(str.strip, script.split(";")):
                        connection.execute(statement)
                    connection.execute(f"PRAGMA user_version = {number}")
                connection.commit()
            except BaseException:
                connection.rollback()
                raise

    @contextmanager
    def _transaction(self) -> Iterator[sqlite3.Cursor]:
        with self._lock, self._mapped("write to"):
            cursor = self._connection.cursor()
            try:
                yield cursor
                self._connection.commit()
            except BaseException:
                self._connection.rollback()
                raise
            finally:
                cursor.close()

    def _read(self, query: str, parameters: tuple[Any, ...]) -> list[sqlite3.Row]:
        with self._lock, self._mapped("read"):
            return self._connection.execute(query, parameters).fetchall()

    def start_session(self, new: NewSession) -> str:
        """Record a new session; returns its id."""
        session_id = uuid.uuid4().hex[:12]
        with self._transaction() as cursor:
            cursor.execute(
                "INSERT INTO sessions (id, created, case_name, case_source, instruction, backend, "
                "model, case_json, settings_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (session_id, time.time(), _text(new.case_name), _text(new.case_source),
                 _text(new.instruction), _text(new.backend), _text(new.model), _json(new.case),
                 _json(new.settings)),
            )  # fmt: skip
        return session_id

    def log_exchange(self, session_id: str, new: NewExchange) -> int:
        """Record one exchange (draft, feedback, repair, execution or undo) of a session."""
        with self._transaction() as cursor:
            cursor.execute(
                "INSERT INTO exchanges (session_id, created, kind, user_text, request_json, "
                "answer, plan, code, outcome_json, error, timings_json) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (session_id, time.time(), new.kind, _text(new.user_text), _json(new.request),
                 _text(new.answer), _text(new.plan), _text(new.code), _json(new.outcome),
                 _text(new.error), _json(new.timings)),
            )  # fmt: skip
            return int(cursor.lastrowid or 0)

    def recent_exchanges(self, limit: int = 20, session_id: str | None = None) -> list[ExchangeRecord]:
        """The latest exchanges, newest last; all of one session when ``session_id`` is given."""
        query = (
            "SELECT e.*, s.instruction, s.backend, s.model FROM exchanges e "
            "JOIN sessions s ON s.id = e.session_id "
        )
        parameters: tuple[Any, ...] = ()
        if session_id:
            query += "WHERE e.session_id LIKE ? "
            parameters = (session_id + "%",)
        query += "ORDER BY e.id DESC LIMIT ?"
        rows = self._read(query, (*parameters, limit))
        return [_record(row) for row in reversed(rows)]

    def recent_sessions(self, limit: int = 50) -> list[SessionSummary]:
        """The latest sessions, newest first."""
        rows = self._read(
            "SELECT id, created, case_name, instruction, backend, model, settings_json FROM sessions "
            "ORDER BY created DESC LIMIT ?",
            (limit,),
        )
        return [
            SessionSummary(
                id=row["id"],
                created=row["created"],
                case_name=row["case_name"] or "",
                instruction=row["instruction"] or "",
                backend=row["backend"] or "",
                model=row["model"] or "",
                settings=_loaded_dict(row["settings_json"]),
            )  # fmt: skip
            for row in rows
        ]

    def session_case(self, session_id: str) -> Any:
        """The case a session worked on (OVITA form), or None for an unknown id."""
        rows = self._read("SELECT case_json FROM sessions WHERE id = ?", (session_id,))
        return None if not rows else _loaded(rows[0][0])

    def request_of(self, exchange_id: int) -> Any:
        """The full request (messages) and answer of one exchange."""
        rows = self._read("SELECT request_json, answer FROM exchanges WHERE id = ?", (exchange_id,))
        return None if not rows else {"request": _loaded(rows[0][0]), "answer": rows[0][1]}

    def integrity_check(self) -> str:
        """SQLite's own check of the file: 'ok' when it is sound."""
        return str(self._read("PRAGMA integrity_check", ())[0][0])


def _text(value: Any) -> str | None:
    return safe_optional(value, ANSWER_CHARS)


def _json(value: Any) -> str:
    """JSON of ``value`` with every string in it made safe, so it stores and reads back cleanly."""
    return json.dumps(_clean(value), default=lambda other: safe_text(other, ANSWER_CHARS))


def _clean(value: Any) -> Any:
    if isinstance(value, str):
        return safe_text(value, ANSWER_CHARS)
    if isinstance(value, dict):
        return {safe_text(key): _clean(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_clean(item) for item in value]
    return value


def _loaded(text: Any) -> Any:
    """A stored JSON column; None where it is missing or not JSON (a damaged or foreign row)."""
    try:
        return json.loads(text) if isinstance(text, str | bytes) else None
    except ValueError:
        return None


def _loaded_dict(text: Any) -> dict[str, Any]:
    """A stored JSON object column, {} where it is missing, not JSON or not an object."""
    value = _loaded(text)
    return value if isinstance(value, dict) else {}


def _record(row: sqlite3.Row) -> ExchangeRecord:
    return ExchangeRecord(
        id=row["id"],
        session_id=row["session_id"],
        created=row["created"],
        kind=row["kind"],
        user_text=row["user_text"] or "",
        instruction=row["instruction"] or "",
        backend=row["backend"] or "",
        model=row["model"] or "",
        plan=row["plan"] or "",
        code=row["code"] or "",
        error=row["error"] or "",
        outcome=_loaded_dict(row["outcome_json"]),
        timings=_loaded_dict(row["timings_json"]),
    )

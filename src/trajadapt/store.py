"""Store: every exchange with the LLM, logged to a local SQLite file as it happens."""

from __future__ import annotations

import json
import sqlite3
import time
import uuid
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

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
)


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
    """A SQLite log; each write is committed at once so a crash loses nothing already said."""

    def __init__(self, path: Path) -> None:
        self.path = path
        path.parent.mkdir(parents=True, exist_ok=True)
        self._connection = sqlite3.connect(path, check_same_thread=False)
        self._connection.row_factory = sqlite3.Row
        self._migrate()

    def close(self) -> None:
        """Close the database."""
        self._connection.close()

    def _migrate(self) -> None:
        with self._transaction() as cursor:
            version = cursor.execute("PRAGMA user_version").fetchone()[0]
            for number, script in enumerate(MIGRATIONS[version:], start=version + 1):
                cursor.executescript(script)
                cursor.execute(f"PRAGMA user_version = {number}")

    @contextmanager
    def _transaction(self) -> Iterator[sqlite3.Cursor]:
        cursor = self._connection.cursor()
        try:
            yield cursor
            self._connection.commit()
        except BaseException:
            self._connection.rollback()
            raise
        finally:
            cursor.close()

    def start_session(self, fields: dict[str, Any]) -> str:
        """Record a new session; returns its id."""
        session_id = uuid.uuid4().hex[:12]
        with self._transaction() as cursor:
            cursor.execute(
                "INSERT INTO sessions (id, created, case_name, case_source, instruction, backend, "
                "model, case_json) VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
                (session_id, time.time(), fields.get("case_name"), fields.get("case_source"),
                 fields.get("instruction"), fields.get("backend"), fields.get("model"),
                 json.dumps(fields.get("case"))),
            )  # fmt: skip
        return session_id

    def log_exchange(self, session_id: str, kind: str, fields: dict[str, Any]) -> int:
        """Record one exchange (draft, feedback, repair or execution) of a session."""
        with self._transaction() as cursor:
            cursor.execute(
                "INSERT INTO exchanges (session_id, created, kind, user_text, request_json, "
                "answer, plan, code, outcome_json, error, timings_json) "
                "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                (session_id, time.time(), kind, fields.get("user_text"),
                 json.dumps(fields.get("request")), fields.get("answer"), fields.get("plan"),
                 fields.get("code"), json.dumps(fields.get("outcome")), fields.get("error"),
                 json.dumps(fields.get("timings"))),
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
        rows = self._connection.execute(query, (*parameters, limit)).fetchall()
        return [_record(row) for row in reversed(rows)]

    def recent_sessions(self, limit: int = 50) -> list[dict[str, Any]]:
        """The latest sessions, newest first: id, created, case name, instruction, backend, model."""
        rows = self._connection.execute(
            "SELECT id, created, case_name, instruction, backend, model FROM sessions "
            "ORDER BY created DESC LIMIT ?",
            (limit,),
        ).fetchall()
        return [dict(row) for row in rows]

    def session_case(self, session_id: str) -> Any:
        """The case a session worked on (OVITA form), or None for an unknown id."""
        row = self._connection.execute(
            "SELECT case_json FROM sessions WHERE id = ?", (session_id,)
        ).fetchone()
        return None if row is None else json.loads(row[0])

    def request_of(self, exchange_id: int) -> Any:
        """The full request (messages) and answer of one exchange."""
        row = self._connection.execute(
            "SELECT request_json, answer FROM exchanges WHERE id = ?", (exchange_id,)
        ).fetchone()
        return None if row is None else {"request": json.loads(row[0]), "answer": row[1]}


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
        outcome=json.loads(row["outcome_json"] or "null") or {},
        timings=json.loads(row["timings_json"] or "null") or {},
    )

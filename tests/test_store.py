"""The SQLite log: typed records in and out, the migration of older files, what reproduces a run."""

from __future__ import annotations

import json
import sqlite3
from pathlib import Path

import pytest

from trajadapt import __version__
from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.files.store import MIGRATIONS, NewExchange, NewSession, Store
from trajadapt.model.case import Case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings


def new_session(**changes: object) -> NewSession:
    fields: dict[str, object] = {
        "case_name": "c", "case_source": None, "instruction": "go left", "backend": "scripted",
        "model": "m", "case": {"trajectory": [[0, 0, 0, 1], [1, 0, 0, 1]]}, "settings": {"seed": 3},
    }  # fmt: skip
    fields.update(changes)
    return NewSession(**fields)  # type: ignore[arg-type]


def test_records_go_in_typed_and_come_back(tmp_path: Path) -> None:
    store = Store(tmp_path / "log.db")
    session_id = store.start_session(new_session())
    store.log_exchange(
        session_id, NewExchange("execution", code="x = 1", outcome={"ok": False}, error="E: no")
    )
    (summary,) = store.recent_sessions()
    assert (summary.id, summary.instruction, summary.settings) == (session_id, "go left", {"seed": 3})
    (record,) = store.recent_exchanges(session_id=session_id)
    assert (record.kind, record.code, record.error, record.outcome) == (
        "execution",
        "x = 1",
        "E: no",
        {"ok": False},
    )
    assert store.session_case(session_id)["trajectory"][1] == [1, 0, 0, 1]
    store.close()


def test_a_misspelled_field_fails_where_it_is_written() -> None:
    with pytest.raises(TypeError, match="user_txt"):
        NewExchange("draft", user_txt="hello")  # type: ignore[call-arg]


def test_a_log_written_before_the_settings_column_opens_and_keeps_its_sessions(tmp_path: Path) -> None:
    path = tmp_path / "old.db"
    with sqlite3.connect(path) as old:
        old.executescript(MIGRATIONS[0])
        old.execute("PRAGMA user_version = 1")
        old.execute("INSERT INTO sessions (id, created, instruction) VALUES ('abc', 1.0, 'older')")
    store = Store(path)
    (summary,) = store.recent_sessions()
    assert (summary.id, summary.instruction, summary.settings) == ("abc", "older", {})
    store.start_session(new_session())
    assert len(store.recent_sessions()) == 2 and store.integrity_check() == "ok"
    store.close()


def test_the_log_records_what_reproduces_a_run(tmp_path: Path, simple_case: Case, sandbox: Sandbox) -> None:
    answer = json.dumps(
        {"high_level_plan": "1) Keep.", "python_code": "modified_trajectory = get_trajectory()"}
    )
    store = Store(tmp_path / "log.db")
    settings = SessionSettings(temperature=0.3, seed=11, max_tokens=500)
    session = AdaptationSession(simple_case, ScriptedBackend(answers=[answer]), sandbox, settings, store)
    session.draft()
    (summary,) = store.recent_sessions()
    recorded = summary.settings
    assert (recorded["temperature"], recorded["seed"], recorded["max_tokens"]) == (0.3, 11, 500)
    assert (recorded["mode"], recorded["axes"], recorded["trajadapt_version"]) == (
        "skills",
        "paper",
        __version__,
    )
    assert summary.model == session.backend.model
    store.close()

"""The log file as an attacker or an accident leaves it: each case is an error in words, never a traceback."""

import multiprocessing
import sqlite3
from pathlib import Path

import pytest
from click.testing import CliRunner

from trajadapt.cli import cli
from trajadapt.errors import LogUnusable
from trajadapt.files.store import MIGRATIONS, NewExchange, NewSession, Store

SESSION = NewSession("case", None, "go left", "scripted", "m", {}, {})


def a_log(path: Path) -> Path:
    store = Store(path)
    store.log_exchange(store.start_session(SESSION), NewExchange("draft", code="t = 1"))
    store.close()
    return path


@pytest.mark.parametrize(
    "make",
    [
        lambda p: p.write_bytes(b"this is not a database at all" * 100),
        lambda p: p.mkdir(),
        lambda p: p.write_bytes(a_log(p.with_name("whole.db")).read_bytes()[:1500]),
    ],
    ids=["garbage", "a folder", "truncated"],
)
def test_a_log_that_is_not_a_database_is_refused_in_words(tmp_path, make):
    path = tmp_path / "logs.db"
    make(path)
    with pytest.raises(LogUnusable, match="move the file aside"):
        store = Store(path)
        store.recent_exchanges()


def test_a_log_from_a_newer_trajadapt_is_refused(tmp_path):
    path = a_log(tmp_path / "logs.db")
    with sqlite3.connect(path) as connection:
        connection.execute(f"PRAGMA user_version = {len(MIGRATIONS) + 5}")
    with pytest.raises(LogUnusable, match="newer trajadapt"):
        Store(path)


def test_a_home_that_is_a_file_is_refused(tmp_path):
    home = tmp_path / "home"
    home.write_text("a file")
    with pytest.raises(LogUnusable):
        Store(home / "logs.db")


def test_rows_with_bad_json_are_read_as_empty(tmp_path, monkeypatch):
    path = a_log(tmp_path / "logs.db")
    with sqlite3.connect(path) as connection:
        connection.execute("UPDATE exchanges SET outcome_json = '{not json', timings_json = '[1, 2]'")
        connection.execute("UPDATE sessions SET settings_json = 'nope'")
    store = Store(path)
    (record,) = store.recent_exchanges()
    assert record.outcome == {} and record.timings == {}
    assert store.recent_sessions()[0].settings == {}
    monkeypatch.setenv("TRAJADAPT_HOME", str(tmp_path))
    shown = CliRunner().invoke(cli, ["logs", "--json"])
    assert shown.exit_code == 0, shown.output


def _create(path: str) -> None:
    Store(Path(path)).close()


def test_processes_creating_a_new_log_at_once_all_succeed(tmp_path):
    path = str(tmp_path / "logs.db")
    context = multiprocessing.get_context("spawn")
    workers = [context.Process(target=_create, args=(path,)) for _ in range(8)]
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join(60)
    assert [worker.exitcode for worker in workers] == [0] * 8
    assert Store(Path(path)).integrity_check() == "ok"


def test_the_cli_says_what_is_wrong_with_the_log(tmp_path, monkeypatch):
    monkeypatch.setenv("TRAJADAPT_HOME", str(tmp_path))
    (tmp_path / "logs.db").write_bytes(b"garbage" * 500)
    shown = CliRunner().invoke(cli, ["logs"])
    assert shown.exit_code != 0 and "Traceback" not in shown.output and "logs.db" in shown.output

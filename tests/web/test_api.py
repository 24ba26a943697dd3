"""The review server's API: the whole loop, undo, persistence, and bad uploads answered in words."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from tests.web.conftest import CASE, FIRST, SECOND, build_app, wait_idle
from trajadapt.web.app import MAX_UPLOAD_BYTES


def start(client: TestClient) -> dict:
    response = client.post("/api/sessions", json={"case": CASE, "instruction": "go left", "name": "line"})
    assert response.status_code == 200, response.text
    return wait_idle(client, response.json()["id"])


def test_plan_feedback_undo_approve_download(client: TestClient) -> None:
    state = start(client)
    assert state["status"] == "ready" and state["versions"][0]["steps"] == [
        "Shift the path left by 0.1, keeping the start."
    ]
    assert abs(state["versions"][0]["proposed"][-1][0] - 0.1) < 1e-9  # the preview ran the code
    sid = state["id"]
    assert client.post(f"/api/sessions/{sid}/feedback", json={"text": "more, and slower"}).status_code == 200
    state = wait_idle(client, sid)
    assert [v["request"] for v in state["versions"]] == ["go left", "more, and slower"] and state[
        "current"
    ] == 1
    state = client.post(f"/api/sessions/{sid}/undo", json={"version": 0}).json()
    assert len(state["versions"]) == 1 and state["current"] == 0
    client.post(f"/api/sessions/{sid}/approve")
    state = wait_idle(client, sid)
    assert state["status"] == "approved" and state["result"]["status"] == "ok"
    download = client.get(f"/api/sessions/{sid}/result")
    assert download.headers["content-disposition"] == 'attachment; filename="line.result.json"'
    assert abs(download.json()["modified_trajectory"][-1][0] - 0.1) < 1e-9


def test_cases_folder(client: TestClient) -> None:
    assert client.get("/api/cases").json()["cases"] == ["room/line.json"]
    assert client.get("/api/cases/room/line.json").json()["instruction"] == "go left"
    outside = client.get("/api/cases/../answers.json")
    assert outside.status_code in (400, 404)


@pytest.mark.parametrize("name", ["room%00line.json", "x" * 5000, "room/%00", "%2e%2e/%00"])
def test_a_case_name_no_file_can_have_is_answered_in_words(client: TestClient, name: str) -> None:
    """A NUL byte or an over-long name is the client's mistake: a 400, and no exception in the server."""
    response = client.get(f"/api/cases/{name}")  # the test client re-raises any exception the app lets out
    assert response.status_code == 400 and "no case" in response.json()["error"]


def test_bad_uploads_are_explained(client: TestClient) -> None:
    not_json = client.post("/api/upload?name=x.json", content=b"trajectory: [1, 2]")
    assert not_json.status_code == 400 and "not JSON" in not_json.json()["error"]
    shape = client.post("/api/upload?name=x.json", json={"trajectory": [[0, 0, 0], [1, 1, 1]]})
    assert shape.status_code == 400 and "expected 4 numbers" in shape.json()["error"]
    big = b"[" + b"0," * (10 * 1024 * 1024) + b"0]"  # 20 MB
    too_big = client.post("/api/upload?name=big.json", content=big)
    assert (
        too_big.status_code == 413 and f"limit is {MAX_UPLOAD_BYTES / 1e6:.0f} MB" in too_big.json()["error"]
    )
    good = client.post("/api/upload?name=mine.json", content=json.dumps(CASE).encode())
    assert good.status_code == 200 and good.json()["name"] == "mine"


def test_errors_are_words_not_traces(client: TestClient) -> None:
    missing = client.get("/api/sessions/nope")
    assert missing.status_code == 409 and "no session 'nope'" in missing.json()["error"]
    empty = client.post("/api/sessions", json={"case": CASE, "instruction": "  "})
    assert empty.status_code == 400 and "type an instruction" in empty.json()["error"]
    malformed = client.post("/api/sessions", json={"instruction": "go"})
    assert malformed.status_code == 422 and "case" in malformed.json()["error"]
    state = start(client)
    assert (
        client.get(f"/api/sessions/{state['id']}/result").json()["error"] == "there is no approved result yet"
    )
    assert "Traceback" not in missing.text + empty.text + malformed.text


def test_a_restarted_server_shows_earlier_sessions(tmp_path: Path) -> None:
    with TestClient(build_app(tmp_path, [FIRST])) as first:
        start(first)
    with TestClient(build_app(tmp_path, [SECOND])) as second:
        sessions = second.get("/api/sessions").json()["sessions"]
        assert len(sessions) == 1 and not sessions[0]["live"] and sessions[0]["instruction"] == "go left"
        stored = second.get(f"/api/sessions/{sessions[0]['id']}").json()
        assert stored["status"] == "stored" and stored["versions"][0]["code"].strip() == FIRST["python_code"]
        assert stored["versions"][0]["proposed"] is not None


def test_token_is_required_when_set(tmp_path: Path) -> None:
    with TestClient(build_app(tmp_path, [FIRST], token="s3cret")) as guarded:
        refused = guarded.get("/api/cases")
        assert refused.status_code == 401 and "token" in refused.json()["error"]
        assert guarded.get("/api/cases", headers={"X-Trajadapt-Token": "s3cret"}).status_code == 200
        assert guarded.get("/api/cases?token=s3cret").status_code == 200
        assert guarded.get("/").status_code == 200  # the page itself loads; it sends the token from its URL


def test_feedback_on_the_approved_result_chains_and_the_page_gets_effect_and_explanation(
    tmp_path: Path,
) -> None:
    with TestClient(build_app(tmp_path, [FIRST, SECOND])) as client:
        state = start(client)
        sid = state["id"]
        assert state["versions"][0]["explanation"] is None or isinstance(
            state["versions"][0]["explanation"], list
        )
        refused = client.post(f"/api/sessions/{sid}/feedback", json={"text": "more", "on": "current"})
        assert refused.status_code == 200  # accepted as a job; it fails in words: nothing approved yet
        state = wait_idle(client, sid)
        assert "approve a plan first" in state["error"] and len(state["versions"]) == 1
        client.post(f"/api/sessions/{sid}/approve")
        state = wait_idle(client, sid)
        first = state["result"]["modified_trajectory"]
        assert state["result"]["effect"]["in_words"] and state["result"]["effect"]["contradictions"] == []
        client.post(f"/api/sessions/{sid}/feedback", json={"text": "more, and slower", "on": "current"})
        state = wait_idle(client, sid)
        assert state["versions"][1]["on"] == "current" and state["result"] is None
        client.post(f"/api/sessions/{sid}/approve")
        state = wait_idle(client, sid)
        chain = state["result"]["chain"]
        assert [step["instruction"] for step in chain] == ["go left", "more, and slower"]
        assert chain[0]["trajectory"] == first
        assert abs(state["result"]["modified_trajectory"][-1][0] - (first[-1][0] + 0.3)) < 1e-9
        assert client.get(f"/api/sessions/{sid}/result").json()["chain"] == chain


def test_the_pages_limits_bind_the_session_and_the_effect_says_what_they_moved(client: TestClient) -> None:
    limits = {"workspace": [-1, 0.05, -5, 5, -5, 5], "fixed_ends": "start"}
    response = client.post("/api/sessions", json={"case": CASE, "instruction": "go left", "limits": limits})
    sid = response.json()["id"]
    wait_idle(client, sid)
    client.post(f"/api/sessions/{sid}/approve")
    result = wait_idle(client, sid)["result"]
    assert max(row[0] for row in result["modified_trajectory"]) <= 0.05 + 1e-6
    assert result["modified_trajectory"][0][:3] == CASE["trajectory"][0][:3]
    assert any(line.startswith("projected: x upper bound") for line in result["effect"]["in_words"])
    assert "your workspace -1 0.05 -5 5 -5 5" in result["settings"]["constraints"]
    for bad, words in (
        ({"robot": "tank"}, "no robot limits called 'tank'"),
        ({"workspace": [1, 0, 0, 1, 0, 1]}, "each minimum must be at most its maximum"),
    ):
        refused = client.post("/api/sessions", json={"case": CASE, "instruction": "go left", "limits": bad})
        assert refused.status_code == 400 and words in refused.json()["error"]


def test_a_server_with_logging_off_writes_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from trajadapt.checks.constraints import Constraints
    from trajadapt.cli.serve import _build_app
    from trajadapt.settings import load_settings

    home = tmp_path / "home"
    monkeypatch.setenv("TRAJADAPT_HOME", str(home))
    monkeypatch.setenv("TRAJADAPT_ISOLATION", "process")
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([json.dumps(FIRST)]))
    settings = load_settings({"backend": "scripted", "log": False})
    app = _build_app(settings, None, (("answers", str(answers)),), None, Constraints(), None, ("testserver",))
    with TestClient(app) as client:
        sid = start(client)["id"]
        client.post(f"/api/sessions/{sid}/approve")
        assert wait_idle(client, sid)["status"] == "approved"
        assert [s["live"] for s in client.get("/api/sessions").json()["sessions"]] == [True]
        missing = client.get("/api/sessions/abcdef")
        assert missing.status_code == 409 and "logging is off" in missing.json()["error"]
    assert not (home / "logs.db").exists()

"""A review server on the scripted backend, for the API and browser tests."""

from __future__ import annotations

import json
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient

from trajadapt.backends.registry import get_backend
from trajadapt.files.store import Store
from trajadapt.memory import MemoryBank
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import SessionSettings
from trajadapt.web.app import create_app
from trajadapt.web.services import Services, pybullet_simulator

FIRST = {"high_level_plan": "1) Shift the path left by 0.1, keeping the start.",
         "python_code": "t = get_trajectory()\nt = shift(t, 'left', 0.1)\nmodified_trajectory = t"}  # fmt: skip
SECOND = {"high_level_plan": "1) Shift the path left by 0.3. 2) Halve the speed.",
          "python_code": "t = get_trajectory()\nt = shift(t, 'left', 0.3)\nt = scale_speed(t, 0.5)\nmodified_trajectory = t"}  # fmt: skip
CASE = {
    "trajectory": [[0.0, 0.1 * k, 0.5, 0.2] for k in range(11)],
    "objects": [{"name": "box", "x": 0.2, "y": 0.5, "z": 0.5}],
    "instruction": "go left",
}


def build_app(
    tmp_path: Path,
    answers: list[dict[str, Any]],
    cases_dir: Path | None = None,
    token: str | None = None,
    memory: MemoryBank | None = None,
) -> FastAPI:
    """An app whose backend replies with ``answers`` in turn; its log in ``tmp_path``."""
    answer_file = tmp_path / "answers.json"
    answer_file.write_text(json.dumps([json.dumps(a) for a in answers]))
    services = Services(
        backend=get_backend("scripted", {"answers": str(answer_file)}),
        sandbox=Sandbox(isolation="process"),
        store=Store(tmp_path / "log.db"),
        settings=SessionSettings(read_against_words=False),  # the answers use numbers the instructions lack
        work_dir=tmp_path / "web",
        cases_dir=cases_dir,
        simulator=pybullet_simulator("left"),
        memory=memory,
    )
    return create_app(services, token, allowed_hosts=("testserver",))


@pytest.fixture
def client(tmp_path: Path) -> Iterator[TestClient]:
    """A test client on a fresh server with two scripted answers and a folder of one case."""
    cases = tmp_path / "cases"
    (cases / "room").mkdir(parents=True)
    (cases / "room" / "line.json").write_text(json.dumps(CASE))
    with TestClient(build_app(tmp_path, [FIRST, SECOND], cases)) as test_client:
        yield test_client


def wait_idle(client: TestClient, session_id: str, timeout_s: float = 60) -> dict[str, Any]:
    """Poll a session until its job is done."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        state: dict[str, Any] = client.get(f"/api/sessions/{session_id}").json()
        if state["status"] != "working":
            return state
        time.sleep(0.05)
    raise AssertionError(f"session {session_id} still working after {timeout_s} s")

"""The review page and memory: an approved result is remembered, the next session shows it, and
"forget this one" removes it from the bank."""

from __future__ import annotations

import json
from pathlib import Path

from fastapi.testclient import TestClient

from tests.web.conftest import CASE, FIRST, build_app, wait_idle
from trajadapt.memory import MemoryBank


def test_remembered_recalled_and_forgotten_from_the_page(tmp_path: Path) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    app = build_app(tmp_path, [FIRST, FIRST], memory=bank)
    with TestClient(app) as client:
        first = client.post(
            "/api/sessions", json={"case": CASE, "instruction": "go left", "name": "line"}
        ).json()
        wait_idle(client, first["id"])
        client.post(f"/api/sessions/{first['id']}/approve")
        state = wait_idle(client, first["id"])
        kept = state["memory"]["remembered_as"]
        assert kept and [e.id for e in bank.examples()] == [kept]
        second = client.post(
            "/api/sessions", json={"case": CASE, "instruction": "go left", "name": "line"}
        ).json()
        state = wait_idle(client, second["id"])
        assert state["memory"]["recalled"] == [{"id": kept, "instruction": "go left"}]
        forgot = client.post(f"/api/sessions/{second['id']}/forget", json={"example": kept})
        assert forgot.status_code == 200 and forgot.json()["memory"]["recalled"] == []
        assert bank.examples() == []
        again = client.post(f"/api/sessions/{second['id']}/forget", json={"example": kept})
        assert again.status_code == 400 and "no remembered example" in again.json()["error"]
    assert json.loads((tmp_path / "memory.jsonl").read_text().splitlines()[-1])["op"] == "remove"

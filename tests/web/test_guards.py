"""The review server against hostile clients: host names, body sizes, tokens, odd names, many sessions."""

from __future__ import annotations

import json
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from tests.web.conftest import CASE, FIRST, build_app, wait_idle
from trajadapt.files.store import Store
from trajadapt.web.guards import MAX_BODY_BYTES, attachment, host_name


@pytest.mark.parametrize(
    ("header", "name"),
    [("127.0.0.1:8765", "127.0.0.1"), ("[::1]:80", "::1"), ("LocalHost.", "localhost"), ("::1", "::1")],
)
def test_host_names_are_read_without_port(header: str, name: str) -> None:
    assert host_name(header) == name


def test_requests_for_another_host_are_refused(client: TestClient) -> None:
    assert client.get("/api/sessions", headers={"host": "evil.example"}).status_code == 421
    assert client.get("/api/sessions", headers={"host": "attacker.test:8765"}).status_code == 421
    assert client.get("/api/sessions", headers={"host": "127.0.0.1:8765"}).status_code == 200
    assert client.get("/", headers={"host": "localhost:8765"}).status_code == 200


def test_bodies_over_the_limit_are_refused_on_every_endpoint(client: TestClient) -> None:
    big = b"x" * (MAX_BODY_BYTES + 1)
    for path in ("/api/sessions", "/api/upload", "/api/sessions/abc/feedback"):
        assert client.post(path, content=big).status_code == 413, path

    def streamed() -> Iterator[bytes]:
        for _ in range(9):
            yield b" " * (1024 * 1024)

    response = client.post("/api/upload", content=streamed())  # chunked: no Content-Length
    assert response.status_code == 413 and "limit" in response.json()["error"]
    bad_length = client.post("/api/upload", content=b"{}", headers={"content-length": "12x"})
    assert bad_length.status_code == 400


def test_any_wrong_token_is_a_401(tmp_path: Path) -> None:
    with TestClient(build_app(tmp_path, [FIRST], token="s3cret")) as secured:
        assert secured.get("/api/sessions", params={"token": "s3cret"}).status_code == 200
        assert secured.get("/api/sessions", params={"token": "wrong"}).status_code == 401
        assert secured.get("/api/sessions", params={"token": "sécret✓"}).status_code == 401
        assert (
            secured.get(
                "/api/sessions", headers={"x-trajadapt-token": "s\xe9cret".encode("latin-1")}
            ).status_code
            == 401
        )
        assert secured.get("/api/sessions").status_code == 401


@pytest.mark.parametrize("name", ["Café plan", "line\r\nX-Injected: yes", "路径", 'a"b;c'])
def test_download_names_are_rfc_6266(name: str) -> None:
    header = attachment(f"{name}.result.json")
    assert "\r" not in header and "\n" not in header
    header.encode("latin-1")  # what an HTTP header can carry
    assert header.startswith('attachment; filename="') and "filename*=UTF-8''" in header


def test_a_session_with_odd_text_does_not_break_the_session_list(client: TestClient) -> None:
    body = json.dumps({"case": CASE, "instruction": "go \\ud800 left \x1b[2J", "name": "odd\\udfff\r\nname"})
    response = client.post(
        "/api/sessions", content=body.replace("\\\\", "\\"), headers={"content-type": "application/json"}
    )
    assert response.status_code == 200, response.text
    wait_idle(client, response.json()["id"])
    listing = client.get("/api/sessions")
    assert listing.status_code == 200
    download_name = listing.json()["sessions"][0]["case_name"]
    assert "\ud800" not in download_name and "\udfff" not in download_name


def test_fifty_parallel_sessions_are_all_logged(tmp_path: Path) -> None:
    count = 50
    with TestClient(build_app(tmp_path, [FIRST] * count)) as client:

        def one_session(_: int) -> str:
            response = client.post(
                "/api/sessions", json={"case": CASE, "instruction": "go left", "name": "line"}
            )
            assert response.status_code == 200, response.text
            session_id: str = response.json()["id"]
            wait_idle(client, session_id, timeout_s=120)
            assert client.post(f"/api/sessions/{session_id}/approve").status_code == 200
            state = wait_idle(client, session_id, timeout_s=120)
            assert state["status"] == "approved", state
            return session_id

        with ThreadPoolExecutor(max_workers=count) as pool:
            ids = list(pool.map(one_session, range(count)))
    store = Store(tmp_path / "log.db")
    try:
        assert store.integrity_check() == "ok"
        sessions = store.recent_sessions(limit=1000)
        assert len(sessions) == count
        exchanges = store.recent_exchanges(limit=10_000)
        logged = {exchange.session_id for exchange in exchanges}
        assert logged == {session.id for session in sessions}
        assert all(
            sum(e.session_id == s.id and e.kind == "execution" for e in exchanges) >= 2 for s in sessions
        )
    finally:
        store.close()
    assert len(set(ids)) == count


def test_uploads_nested_too_deep_or_with_huge_integers_are_explained(client: TestClient) -> None:
    for body in (b"[" * 5000 + b"]" * 5000, b'{"trajectory": [[' + b"9" * 5000 + b", 0, 0, 1]]}"):
        response = client.post("/api/upload?name=x.json", content=body)
        assert response.status_code == 400 and "not JSON" in response.json()["error"]


@pytest.mark.parametrize(
    "header", ["[::1]evil.example", "127.0.0.1:80:80", "localhost evil", "127.0.0.1:99999999", "a_b.com", ""]
)
def test_a_host_header_that_is_not_exactly_a_name_and_port_names_no_host(header: str) -> None:
    assert host_name(header) == ""


def test_a_page_of_another_site_cannot_change_a_session(client: TestClient) -> None:
    state = client.post("/api/sessions", json={"case": CASE, "instruction": "go left", "name": "line"}).json()
    wait_idle(client, state["id"])
    for headers in ({"origin": "http://evil.example"}, {"origin": "null"}, {"sec-fetch-site": "cross-site"}):
        refused = client.post(f"/api/sessions/{state['id']}/approve", headers=headers)
        assert refused.status_code == 403, headers
    own = client.post(f"/api/sessions/{state['id']}/approve", headers={"origin": "http://127.0.0.1:8765"})
    assert own.status_code != 403
    assert (
        client.get(f"/api/sessions/{state['id']}", headers={"origin": "http://evil.example"}).status_code
        == 200
    )


def test_every_answer_forbids_framing(client: TestClient) -> None:
    for path in ("/", "/api/sessions"):
        headers = client.get(path).headers
        assert (
            headers["x-frame-options"] == "DENY"
            and "frame-ancestors 'none'" in headers["content-security-policy"]
        )


def test_a_body_that_never_finishes_is_refused_at_the_deadline(monkeypatch: pytest.MonkeyPatch) -> None:
    """A client that sends half a body and stops gets a 408; the app never sees the request."""
    import asyncio

    from trajadapt.web import guards

    monkeypatch.setattr(guards, "BODY_TIMEOUT_S", 0.2)
    reached: list[str] = []

    async def app(scope, receive, send):
        reached.append("app")

    sent: list[dict] = []
    parts = [{"type": "http.request", "body": b"{", "more_body": True}]

    async def receive():
        if parts:
            return parts.pop()
        await asyncio.sleep(3600)  # the rest never comes

    async def send(message):
        sent.append(message)

    scope = {
        "type": "http",
        "method": "POST",
        "path": "/api/sessions",
        "headers": [(b"content-length", b"100")],
    }
    asyncio.run(asyncio.wait_for(guards.BodyLimit(app)(scope, receive, send), 5))
    assert sent[0]["status"] == 408 and reached == []

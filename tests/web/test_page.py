"""End to end in headless Chromium: load a case, ask, read the plan, give feedback, approve, download."""

from __future__ import annotations

import json
import socket
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
import uvicorn

from tests.conftest import REPO_ROOT
from tests.web.conftest import CASE, FIRST, SECOND, build_app

pytestmark = pytest.mark.browser
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync"]  # fmt: skip
SCREENSHOT = REPO_ROOT / "docs" / "images" / "review-page.png"


@contextmanager
def chromium_page(url: str) -> Iterator[Any]:
    """The review page at ``url`` in headless Chromium (1280 x 900); the browser is closed after."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            page.goto(url)
            yield page
        finally:
            browser.close()


@pytest.fixture
def server_url(tmp_path: Path) -> Iterator[str]:
    """A review server on a free loopback port, with the scripted backend and one case in its folder."""
    cases = tmp_path / "cases"
    cases.mkdir()
    (cases / "line.json").write_text(json.dumps(CASE))
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    server = uvicorn.Server(
        uvicorn.Config(build_app(tmp_path, [FIRST, SECOND], cases), port=port, log_level="warning")
    )
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    while not server.started:
        time.sleep(0.05)
    yield f"http://127.0.0.1:{port}/"
    server.should_exit = True
    thread.join(timeout=10)


def test_review_loop_in_chromium(server_url: str, tmp_path: Path) -> None:
    from playwright.sync_api import expect

    with chromium_page(server_url) as page:
        page.select_option("#case-list", "line.json")
        expect(page.locator("#case-name")).to_contain_text("11 waypoints")
        page.fill("#instruction", "go left")
        page.click("#ask")
        expect(page.locator("#plan li")).to_have_text(["Shift the path left by 0.1, keeping the start."])
        expect(page.locator("#code .fn").first).to_have_text("get_trajectory")
        page.fill("#feedback", "further left, and slower")
        page.click("#send-feedback")
        expect(page.locator("#plan li")).to_have_text(["Shift the path left by 0.3.", "Halve the speed."])
        expect(page.locator("#history li")).to_have_count(2)
        expect(page.locator("#history .undo")).to_have_text("Undo to version 1")
        page.click("#approve")
        expect(page.locator("#result-status")).to_contain_text("Approved: 11 waypoints")
        red = page.evaluate("document.getElementById('plot').data.find(t => t.name === 'proposed').x")
        assert abs(red[-1] - 0.3) < 1e-9  # the red path is the approved one
        with page.expect_download() as download_info:
            page.click("#download")
        saved = tmp_path / "downloaded.json"
        download_info.value.save_as(saved)
        assert json.loads(saved.read_text())["status"] == "ok"
        expect(page.locator("#error")).to_be_hidden()
        SCREENSHOT.parent.mkdir(parents=True, exist_ok=True)
        page.screenshot(path=str(SCREENSHOT), full_page=True)


def test_errors_show_on_the_page(server_url: str) -> None:
    from playwright.sync_api import expect

    with chromium_page(server_url) as page:
        page.set_input_files("#case-file", files=[{"name": "bad.json", "mimeType": "application/json",
                                                  "buffer": b"{not json"}])  # fmt: skip
        expect(page.locator("#error")).to_contain_text("the file is not JSON")
        expect(page.locator("#error")).not_to_contain_text("Traceback")


def test_limits_toggle_explanation_and_effect_in_chromium(server_url: str) -> None:
    from playwright.sync_api import expect

    with chromium_page(server_url) as page:
        page.select_option("#case-list", "line.json")
        expect(page.locator("#case-name")).to_contain_text("11 waypoints")
        page.click("#limits summary")
        page.fill("#limit-workspace", "-1 0.35 -5 5 -5 5")
        page.select_option("#limit-fixed-ends", "start")
        page.fill("#instruction", "go left")
        page.click("#ask")
        expect(page.locator("#explanation-box")).to_be_visible()
        expect(page.locator("#explanation li").first).to_contain_text("left")
        expect(page.locator("#feedback-on option[value=current]")).to_be_disabled()
        page.click("#approve")
        expect(page.locator("#effect")).to_contain_text("mostly left")
        page.select_option("#feedback-on", "current")
        page.fill("#feedback", "further left, and slower")
        page.click("#send-feedback")
        expect(page.locator("#history li").last).to_contain_text("On the result: further left, and slower")
        page.click("#approve")
        expect(page.locator("#effect")).to_contain_text("projected: x upper bound: waypoints")
        x = page.evaluate("document.getElementById('plot').data.find(t => t.name === 'proposed').x")
        assert max(x) <= 0.35 + 1e-9 and x[0] == 0  # 0.1 then 0.3 more would be 0.4: the box holds it
        expect(page.locator("#error")).to_be_hidden()

"""docs/python-api.md's example runs as written and does what the page says."""

from __future__ import annotations

import json
import runpy
from pathlib import Path

from tests.conftest import REPO_ROOT


def test_the_python_api_example_runs(tmp_path: Path, capsys) -> None:  # type: ignore[no-untyped-def]
    module = runpy.run_path(str(REPO_ROOT / "examples" / "python_api.py"))
    module["main"](tmp_path)
    printed = capsys.readouterr().out
    assert "plan after feedback: 1) Bring the path closer to the box.\n2) Slow down near it." in printed
    assert "contradictions: none" in printed
    result = json.loads((tmp_path / "python-api.result.json").read_text())
    assert result["status"] == "ok" and result["explanation"]["source"] == "skills"
    box = result["effect"]["objects"][0]
    assert box["closest_after"] < box["closest_before"] and box["speed_near_after"] < box["speed_near_before"]


def test_the_page_shows_the_example_it_tests() -> None:
    page = (REPO_ROOT / "docs" / "python-api.md").read_text()
    assert "examples/python_api.py" in page and "AdaptationSession" in page

"""Scoring against reference targets (the latte-dev layout) with LaTTe's own metrics."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tests.conftest import REPO_ROOT
from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.bench.metrics import latte_scores
from trajadapt.bench.report import render_markdown, summarize
from trajadapt.bench.runner import BenchConfig, discover_cases, run_benchmark, target_path

LATTE_DEV = REPO_ROOT.parent / "shared" / "data" / "latte-dev"
KEEP = json.dumps({"high_level_plan": "1) Keep.", "python_code": "modified_trajectory = get_trajectory()"})
LEFT = json.dumps(
    {
        "high_level_plan": "1) Left.",
        "python_code": "t = get_trajectory()\nt[1:, 0] += 0.05\nmodified_trajectory = t",
    }
)


def test_latte_scores_on_hand_made_pairs() -> None:
    target = np.zeros((3, 4))
    prediction = target.copy()
    prediction[1:, 0] = 0.1  # waypoints 1 and 2 off by 0.1 in x; waypoint 0 is never scored
    scores = latte_scores(target, prediction)
    assert scores["mse"] == pytest.approx(0.01 / 4) and scores["mae"] == pytest.approx(0.1 / 4)
    assert scores["dtw"] == pytest.approx(0.2) and scores["dfd"] == pytest.approx(0.1)
    assert latte_scores(target, np.zeros((5, 4)))["mse"] == 0.0  # other lengths are resampled


@pytest.mark.skipif(not LATTE_DEV.is_dir(), reason="latte-dev not found")
def test_copying_the_input_gives_the_published_numbers_of_latte_dev() -> None:
    expected = {"cartesian": (0.00122, 0.0705), "dist": (0.00154, 0.0911), "speed": (0.01013, 0.2562)}
    for kind, (mse, dfd) in expected.items():
        scores = []
        for case in sorted((LATTE_DEV / "cases" / kind).glob("*.json")):
            target = json.loads((LATTE_DEV / "targets" / kind / case.name).read_text())["output_traj"]
            scores.append(latte_scores(target, json.loads(case.read_text())["trajectory"]))
        assert np.mean([s["mse"] for s in scores]) == pytest.approx(mse, abs=5e-6)
        assert np.mean([s["dfd"] for s in scores]) == pytest.approx(dfd, abs=5e-5)


def _layout(tmp_path: Path) -> Path:
    root = tmp_path / "set"
    trajectory = [[0.0, 0.1 * k, 0.0, 1.0] for k in range(5)]
    target = [[0.05 if k else 0.0, 0.1 * k, 0.0, 1.0] for k in range(5)]
    for kind in ("cartesian", "speed"):
        (root / "cases" / kind).mkdir(parents=True)
        (root / "targets" / kind).mkdir(parents=True)
        # the answers: LEFT for the cartesian case, KEEP for the speed case
        words = "go to the left" if kind == "cartesian" else "keep the path as it is"
        case = {"trajectory": trajectory, "objects": [], "instruction": words}
        (root / "cases" / kind / "c.json").write_text(json.dumps(case))
        (root / "targets" / kind / "c.json").write_text(json.dumps({"output_traj": target}))
    return root


def test_bench_reports_the_tool_against_copying_the_input(tmp_path: Path) -> None:
    root = _layout(tmp_path)
    cases = discover_cases([root / "cases"])
    assert all(target_path(case.path) is not None for case in cases)
    records = run_benchmark(
        cases, ScriptedBackend(answers=[LEFT, KEEP]), BenchConfig(out_dir=tmp_path / "out")
    )
    assert len(records) == 2 and all(record["target_scores"]["tool_ran"] for record in records)
    summary = summarize(records)
    targets = summary["targets"]
    assert set(targets) == {"cartesian", "speed", "overall"} and targets["overall"]["cases"] == 2
    assert targets["cartesian"]["tool"]["mse"] == pytest.approx(0.0)  # the left shift is the target
    assert targets["speed"]["tool"]["mse"] == pytest.approx(targets["speed"]["copy"]["mse"])  # kept
    assert "LaTTe's metrics against the reference targets" in render_markdown(summary, records)


def test_cases_without_targets_have_no_target_scores(tmp_path: Path) -> None:
    folder = tmp_path / "plain"
    folder.mkdir()
    (folder / "c.json").write_text(
        json.dumps({"trajectory": [[0, 0, 0, 1], [0, 1, 0, 1]], "instruction": "go"})
    )
    records = run_benchmark(
        discover_cases([folder]), ScriptedBackend(answers=[KEEP]), BenchConfig(out_dir=tmp_path / "o")
    )
    assert records[0]["target_scores"] is None and summarize(records)["targets"] is None

"""The loop from nothing on the command line: plan -> adapt (scripted) -> simulate, and its bad inputs."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.test_cli import read_result, run_cli

pytestmark = pytest.mark.sim
SHIFT_LEFT = json.dumps(
    {
        "high_level_plan": "1) Shift the path left by 10, keeping the start.",
        "python_code": "t = get_trajectory()\nt = shift(t, 'left', 10)\nmodified_trajectory = t",
    }
)


def write_scene(tmp_path: Path) -> Path:
    scene = tmp_path / "scene.json"
    objects = [{"name": "person", "x": 62, "y": 45, "z": 0}, {"name": "box", "x": 45, "y": 25, "z": 0}]
    scene.write_text(json.dumps({"objects": objects, "Env_descp": "a 100 x 100 room"}))
    return scene


def test_plan_adapt_simulate(tmp_path: Path) -> None:
    case = tmp_path / "planned.json"
    planned = run_cli("plan", "--scene", str(write_scene(tmp_path)), "--start", "10", "10", "0", "--goal", "90", "90",
                      "0", "--planner", "astar", "--speed", "4", "-i", "go left by 10", "--out", str(case))  # fmt: skip
    assert planned.exit_code == 0, planned.output
    assert len(read_result(case)["trajectory"]) == 50  # type: ignore[arg-type]
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([SHIFT_LEFT]))
    out = tmp_path / "planned.result.json"
    adapted = run_cli("adapt", str(case), "-b", "scripted", "-o", "answers", str(answers), "--yes", "--out", str(out),
                      "--simulate", "ground")  # fmt: skip
    assert adapted.exit_code == 0, adapted.output
    assert "tracking error: mean" in adapted.output
    report = json.loads((tmp_path / "planned.ground.sim.json").read_text())
    assert report["tracking_m"]["mean"] < 0.1 and report["mapping"].startswith("robot = ")
    assert (tmp_path / "planned.ground.png").is_file()
    gif = tmp_path / "run.gif"
    again = run_cli("simulate", str(out), "--robot", "drone", "--gif", str(gif))
    assert again.exit_code == 0, again.output
    assert gif.read_bytes()[:6] == b"GIF89a" and "animation:" in again.output


def test_simulate_refuses_bad_inputs_in_words(tmp_path: Path) -> None:
    failed = tmp_path / "failed.result.json"
    failed.write_text(json.dumps({"status": "error", "modified_trajectory": None, "objects": []}))
    result = run_cli("simulate", str(failed), "--robot", "arm")
    assert result.exit_code == 1 and "has no adapted trajectory" in result.output
    missing = run_cli("simulate", str(tmp_path / "absent.json"), "--robot", "arm")
    assert missing.exit_code == 1 and "absent.json" in missing.output
    wrong = run_cli("simulate", str(failed), "--robot", "boat")
    assert wrong.exit_code == 2 and "'boat' is not one of" in wrong.output
    offset_only = run_cli("simulate", str(failed), "--robot", "arm", "--offset", "0", "0", "0")
    assert offset_only.exit_code == 1 and "--offset needs --scale" in offset_only.output


def test_plan_explains_a_blocked_start(tmp_path: Path) -> None:
    result = run_cli("plan", "--scene", str(write_scene(tmp_path)), "--start", "62", "45", "0", "--goal", "90", "90",
                     "0", "--planner", "astar", "--out", str(tmp_path / "p.json"))  # fmt: skip
    assert result.exit_code == 1 and "PlanningError: the start" in result.output
    assert not (tmp_path / "p.json").exists()


def test_simulate_reads_the_convention_the_result_was_adapted_in(tmp_path: Path) -> None:
    from trajadapt.sim.inputs import load_run_input

    rows = [[0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0]]
    result = {
        "modified_trajectory": rows,
        "original_trajectory": rows,
        "objects": [],
        "settings": {"axes": "ovita"},
    }
    path = tmp_path / "r.result.json"
    path.write_text(json.dumps(result))
    assert load_run_input(path).axes == "ovita"
    path.write_text(json.dumps({**result, "settings": {"axes": "sideways"}}))
    assert load_run_input(path).axes is None  # unknown: the settings decide

"""The trajadapt command line: every OVITA case adapts to a valid result file; bad inputs fail clearly."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner, Result

from tests.conftest import REPO_ROOT
from tests.mock_openai_server import Reply, mock_openai_server
from trajadapt.cli import cli

ANSWERS = REPO_ROOT / "examples" / "answers"
KEEP = json.dumps(
    {
        "high_level_plan": "1) Keep the trajectory as it is.",
        "python_code": "modified_trajectory = get_trajectory()",
    }
)

Check = Callable[[np.ndarray, np.ndarray, dict[str, np.ndarray]], bool]


def _near(objects: dict[str, np.ndarray], name: str, t: np.ndarray) -> np.ndarray:
    d = np.linalg.norm(t[:, :3] - objects[name], axis=1)
    return d < np.quantile(d, 0.2)


# What each hand-written answer must achieve (paper axes: +x left, +y front, +z up).
CHECKS: dict[str, Check] = {
    "latte_subset/latte_32": lambda o, a, _: a[-1, 0] - o[-1, 0] > 0.05 and np.allclose(a[0], o[0]),
    "latte_subset/latte_2": lambda o, a, _: a[-1, 1] - o[-1, 1] < -0.05,
    "latte_subset/latte_20": lambda o, a, _: (a[:, 2] - o[:, 2]).mean() < -0.03,
    "latte_subset/latte_0": lambda o, a, obj: (
        np.linalg.norm(a[:, :3] - obj["labyrinth"], axis=1).min()
        < np.linalg.norm(o[:, :3] - obj["labyrinth"], axis=1).min()
    ),
    "latte_subset/latte_14": lambda o, a, obj: (
        np.linalg.norm(a[:, :3] - obj["pretzel"], axis=1).mean()
        > np.linalg.norm(o[:, :3] - obj["pretzel"], axis=1).mean()
    ),
    "latte_subset/latte_10": lambda o, a, obj: (
        (a[:, 3] <= o[:, 3] + 1e-12).all()
        and a[_near(obj, "damselfly", o), 3].mean() < 0.7 * o[_near(obj, "damselfly", o), 3].mean()
    ),
    "latte_subset/latte_16": lambda o, a, obj: (
        a[_near(obj, "irish water spaniel", o), 3].mean()
        > 1.3 * o[_near(obj, "irish water spaniel", o), 3].mean()
    ),
    "extended_subset/extended_0": lambda o, a, _: np.isclose(a[-1, 0] - o[-1, 0], -0.3),
    "extended_subset/extended_8": lambda o, a, obj: (
        len(a) < len(o)
        and a[-1, 3] == 0
        and np.linalg.norm(a[-1, :3] - obj["stinkhorn"])
        == np.linalg.norm(o[:, :3] - obj["stinkhorn"], axis=1).min()
    ),
    "extended_subset/extended_38": lambda o, a, _: len(a) > len(o) and np.allclose(a[: len(o)], o),
    "extended_subset/extended_12": lambda o, a, _: len(a) == len(o) + 5 and (a[20:26, 3] == 0).sum() >= 5,
    "ground_robot/trajectory_0": lambda o, a, _: (
        np.isclose(a[-1, 1] - o[-1, 1], -3.0, atol=0.05) and (a[:, 2] == 0).all()
    ),
    "drone/drone_trajectory_8": lambda o, a, _: a[-1, 3] == 0 and (np.diff(a[26:, 3]) <= 1e-12).all(),
    "manipulator/trajectory_6": lambda o, a, _: (
        (a[:, 2] - o[:, 2]).max() > 0.1 and np.allclose(a[[0, -1]], o[[0, -1]])
    ),
}


def run_cli(*args: str, input_text: str | None = None) -> Result:
    return CliRunner().invoke(cli, list(args), input=input_text, catch_exceptions=False)


def read_result(path: Path) -> dict[str, object]:
    data: dict[str, object] = json.loads(path.read_text())
    return data


def assert_valid_result(data: dict[str, object]) -> None:
    assert data["status"] == "ok", data["error"]
    rows = np.asarray(data["modified_trajectory"], dtype=float)
    assert rows.ndim == 2 and rows.shape[1] == 4 and len(rows) >= 2
    assert np.isfinite(rows).all() and (rows[:, 3] >= 0).all()
    for key in (
        "case",
        "instruction",
        "high_level_plan",
        "code",
        "attempts",
        "backend",
        "model",
        "timings_s",
    ):
        assert key in data


def test_hand_written_answers_cover_at_least_ten_cases() -> None:
    assert len(CHECKS) >= 10
    assert {str(p.relative_to(ANSWERS).with_suffix("")) for p in ANSWERS.rglob("*.json")} == set(CHECKS)


def test_every_ovita_case_gives_a_valid_result_file(ovita_dir: Path, tmp_path: Path) -> None:
    keep = tmp_path / "keep.json"
    keep.write_text(json.dumps([KEEP]))
    cases = sorted(ovita_dir.rglob("*.json"))
    for case in cases:
        key = str(case.relative_to(ovita_dir).with_suffix(""))
        answers = ANSWERS / f"{key}.json" if key in CHECKS else keep
        out = tmp_path / "out" / f"{key}.result.json"
        instruction = ["-i", "keep the path"] if not json.loads(case.read_text())["instruction"] else []
        result = run_cli("adapt", str(case), *instruction, "-b", "scripted", "-o", "answers", str(answers),
                         "--yes", "--out", str(out), "--no-log")  # fmt: skip
        assert result.exit_code == 0, f"{key}: {result.output}"
        data = read_result(out)
        assert_valid_result(data)
        assert out.with_name(out.name.replace(".result.json", ".png")).stat().st_size > 1000
        if key in CHECKS:
            original = np.asarray(data["original_trajectory"])
            adapted = np.asarray(data["modified_trajectory"])
            objects = {o["name"].lower(): np.array([o["x"], o["y"], o["z"]]) for o in data["objects"]}  # type: ignore[union-attr]
            assert CHECKS[key](original, adapted, objects), f"{key}: the hand-written answer is wrong"
    assert len(cases) == 116


def test_against_a_local_openai_compatible_server(ovita_dir: Path, tmp_path: Path) -> None:
    with mock_openai_server() as server:
        for key in CHECKS:
            answer = json.loads((ANSWERS / f"{key}.json").read_text())["answers"][0]
            server.enqueue(json.dumps(answer))
            out = tmp_path / f"{key.replace('/', '_')}.result.json"
            result = run_cli("adapt", str(ovita_dir / f"{key}.json"), "-b", "openai", "-o", "base_url",
                             server.base_url, "-o", "model", "mock", "--yes", "--out", str(out))  # fmt: skip
            assert result.exit_code == 0, result.output
            data = read_result(out)
            assert_valid_result(data)
            assert data["backend"] == "openai" and data["model"] == "mock"
        assert len(server.requests) == len(CHECKS)


def test_interactive_feedback_then_approve(ovita_dir: Path, tmp_path: Path) -> None:
    answers = tmp_path / "a.json"
    wrong = {
        "high_level_plan": "1) Shift right.",
        "python_code": "t = get_trajectory()\nt[:, 0] -= 0.1\nmodified_trajectory = t",
    }
    right = json.loads((ANSWERS / "latte_subset/latte_32.json").read_text())["answers"][0]
    answers.write_text(json.dumps([wrong, right]))
    out = tmp_path / "r.json"
    result = run_cli("adapt", str(ovita_dir / "latte_subset/latte_32.json"), "-b", "scripted", "-o", "answers",
                     str(answers), "--out", str(out), input_text="f\nleft is +x\na\n")  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "Shift right." in result.output and "Shift the goal to the left" in result.output
    assert read_result(out)["high_level_plan"][1].startswith("Shift the goal to the left")  # type: ignore[index]
    logs = run_cli("logs", "-n", "10")
    assert "feedback" in logs.output and "go to the left" in logs.output


def test_quit_writes_nothing(ovita_dir: Path, tmp_path: Path) -> None:
    out = tmp_path / "r.json"
    answers = ANSWERS / "latte_subset/latte_32.json"
    result = run_cli("adapt", str(ovita_dir / "latte_subset/latte_32.json"), "-b", "scripted", "-o", "answers",
                     str(answers), "--out", str(out), input_text="q\n")  # fmt: skip
    assert result.exit_code == 1 and "nothing was written" in result.output
    assert not out.exists()


def write_case(tmp_path: Path, trajectory: object, instruction: str = "go left") -> Path:
    path = tmp_path / "case.json"
    path.write_text(json.dumps({"trajectory": trajectory, "objects": [{"name": "box", "x": 0, "y": 1, "z": 0}],
                                "instruction": instruction}))  # fmt: skip
    return path


GOOD_TRAJECTORY = [[0, 0, 0, 1], [0, 1, 0, 1], [0, 2, 0, 1]]


@pytest.mark.parametrize(
    ("trajectory", "message"),
    [
        ([[0, 0, 0], [1, 1, 1]], "expected 4 numbers"),
        ([], "at least 2 waypoints, got 0"),
        ("NaN-case", "must be finite"),
    ],
)
def test_bad_case_files(tmp_path: Path, trajectory: object, message: str) -> None:
    if trajectory == "NaN-case":
        path = tmp_path / "case.json"
        path.write_text('{"trajectory": [[0, 0, 0, 1], [NaN, 1, 0, 1]], "instruction": "x"}')
    else:
        path = write_case(tmp_path, trajectory)
    out = tmp_path / "r.json"
    result = run_cli("adapt", str(path), "-b", "scripted", "--yes", "--out", str(out))
    assert result.exit_code != 0
    assert message in result.output and "Traceback" not in result.output
    assert not out.exists()


def test_missing_file(tmp_path: Path) -> None:
    result = run_cli("adapt", str(tmp_path / "absent.json"), "-b", "scripted", "--yes")
    assert result.exit_code != 0 and "file not found" in result.output


def scripted(tmp_path: Path, *answers: str) -> list[str]:
    path = tmp_path / "answers.json"
    path.write_text(json.dumps(list(answers)))
    return ["-b", "scripted", "-o", "answers", str(path)]


def adapt_with(tmp_path: Path, *answers: str, extra: tuple[str, ...] = ()) -> tuple[Result, Path]:
    out = tmp_path / "r.json"
    case = write_case(tmp_path, GOOD_TRAJECTORY)
    result = run_cli("adapt", str(case), *scripted(tmp_path, *answers), "--yes", "--out", str(out), *extra)
    return result, out


def test_non_json_answer(tmp_path: Path) -> None:
    result, out = adapt_with(tmp_path, "I am a language model.", "Still prose.")
    assert (
        result.exit_code != 0
        and "AnswerParseError" in result.output
        and "neither a JSON object" in result.output
    )
    assert not out.exists()


def test_answer_without_code(tmp_path: Path) -> None:
    no_code = json.dumps({"high_level_plan": "1) think"})
    result, out = adapt_with(tmp_path, no_code, no_code)
    assert result.exit_code != 0 and "has no Python code" in result.output
    assert not out.exists()


def test_code_that_returns_nothing(tmp_path: Path) -> None:
    nothing = json.dumps({"high_level_plan": "1) a", "python_code": "size = len(get_trajectory())"})
    result, out = adapt_with(tmp_path, nothing, nothing, nothing)
    assert result.exit_code == 1
    assert "did not set the variable 'modified_trajectory'" in result.output
    data = read_result(out)
    assert data["status"] == "error" and data["attempts"] == 3 and data["modified_trajectory"] is None
    assert not out.with_name("r.png").exists()


def test_unknown_object(tmp_path: Path) -> None:
    code = "t = get_trajectory()\nsofa = detect_objects('sofa')\nt[:, 0] += sofa[0]\nmodified_trajectory = t"
    bad = json.dumps({"high_level_plan": "1) go to the sofa", "python_code": code})
    result, out = adapt_with(tmp_path, bad, extra=("--repairs", "0"))
    assert result.exit_code == 1
    assert "no object named 'sofa'" in result.output and "objects in the scene: 'box'" in result.output
    assert read_result(out)["status"] == "error"


def test_backend_down(tmp_path: Path) -> None:
    import socket

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    out = tmp_path / "r.json"
    case = write_case(tmp_path, GOOD_TRAJECTORY)
    result = run_cli("adapt", str(case), "-b", "openai", "-o", "base_url", f"http://127.0.0.1:{port}/v1",
                     "--yes", "--out", str(out))  # fmt: skip
    assert (
        result.exit_code != 0
        and "BackendUnavailable" in result.output
        and "is the server running" in result.output
    )
    assert not out.exists()


def test_server_error_reply(tmp_path: Path) -> None:
    with mock_openai_server() as server:
        server.enqueue(Reply(status=500))
        out = tmp_path / "r.json"
        case = write_case(tmp_path, GOOD_TRAJECTORY)
        result = run_cli("adapt", str(case), "-b", "openai", "-o", "base_url", server.base_url, "--yes",
                         "--out", str(out))  # fmt: skip
    assert result.exit_code != 0 and "HTTP 500" in result.output and not out.exists()


def test_unknown_backend_and_option(tmp_path: Path) -> None:
    case = write_case(tmp_path, GOOD_TRAJECTORY)
    result = run_cli("adapt", str(case), "-b", "scriptd", "--yes")
    assert result.exit_code != 0 and "Did you mean 'scripted'?" in result.output
    result = run_cli("adapt", str(case), "-b", "openai", "-o", "modle", "x", "--yes")
    assert result.exit_code != 0 and "has no option 'modle'" in result.output


def test_trajectory_and_scene_files(tmp_path: Path) -> None:
    (tmp_path / "t.csv").write_text("x,y,z,v\n0,0,0,1\n0,1,0,1\n0,2,0,1\n")
    (tmp_path / "s.json").write_text(json.dumps({"objects": [{"name": "box", "x": 1, "y": 1, "z": 0}]}))
    keep = tmp_path / "keep.json"
    keep.write_text(json.dumps([KEEP]))
    out = tmp_path / "r.json"
    result = run_cli("adapt", "--trajectory", str(tmp_path / "t.csv"), "--scene", str(tmp_path / "s.json"),
                     "-i", "keep it", "-b", "scripted", "-o", "answers", str(keep), "--yes", "--out", str(out))  # fmt: skip
    assert result.exit_code == 0, result.output
    assert_valid_result(read_result(out))
    result = run_cli("adapt", "--trajectory", str(tmp_path / "t.csv"), "-b", "scripted", "--yes")
    assert result.exit_code != 0 and "no instruction" in result.output


def test_backends_command() -> None:
    result = run_cli("backends")
    assert result.exit_code == 0
    for name in ("local", "openai", "scripted"):
        assert name in result.output


def test_help_explains() -> None:
    result = run_cli("adapt", "--help")
    assert "approve" in result.output and "--backend" in result.output and "--yes" in result.output

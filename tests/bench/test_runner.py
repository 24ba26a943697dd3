"""The benchmark runner and `trajadapt bench`: result layout, resume, scoring, report, parallel jobs."""

from __future__ import annotations

import json
import os
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.bench.report import summarize
from trajadapt.bench.runner import BenchConfig, discover_cases, run_benchmark
from trajadapt.cli import cli
from trajadapt.session import SessionSettings

SHIFT_LEFT = json.dumps(
    {
        "high_level_plan": "1) Shift left.",
        "python_code": "modified_trajectory = shift(get_trajectory(), 'left')",
    }
)
KEEP = json.dumps({"high_level_plan": "1) Keep.", "python_code": "modified_trajectory = get_trajectory()"})
SHIFT_RIGHT = json.dumps(
    {
        "high_level_plan": "1) Shift right.",
        "python_code": "modified_trajectory = shift(get_trajectory(), 'right')",
    }
)  # the other way: a contradiction the readers leave to the judge (an empty answer gets the asked shift)

EXPECTATIONS = """
version = 2
["ground/case"]
checks = [{kind = "shift", direction = "left"}]
["arm/case"]
checks = [{kind = "shift", direction = "left"}]
["arm/vague"]
skip = "cannot be judged"
"""


def make_folder(tmp_path: Path, ovita_dir: Path) -> Path:
    folder = tmp_path / "cases"
    for sub, name in (("ground", "case"), ("arm", "case"), ("arm", "vague")):
        (folder / sub).mkdir(parents=True, exist_ok=True)
        shutil.copy(ovita_dir / "latte_subset" / "latte_32.json", folder / sub / f"{name}.json")
    (folder / "expectations.toml").write_text(EXPECTATIONS)
    return folder


def test_same_file_names_in_subfolders_never_collide_and_runs_resume(tmp_path: Path, ovita_dir: Path) -> None:
    folder = make_folder(tmp_path, ovita_dir)
    cases = discover_cases([folder])
    assert sorted(case.key for case in cases) == ["arm/case", "arm/vague", "ground/case"]
    config = BenchConfig(out_dir=tmp_path / "out")
    # answers for arm/case, arm/vague, ground/case
    backend = ScriptedBackend(answers=[SHIFT_LEFT, SHIFT_LEFT, SHIFT_RIGHT])
    records = run_benchmark(cases, backend, config)
    assert (tmp_path / "out" / "arm" / "case.result.json").is_file()
    assert (tmp_path / "out" / "ground" / "case.result.json").is_file()
    by_task = {r["evaluation"]["task_id"]: r["evaluation"] for r in records}
    assert by_task["cases/arm/case-v2"]["passed"] is True
    assert by_task["cases/arm/vague-v2"]["judged"] is False
    assert by_task["cases/ground/case-v2"]["passed"] is False
    again = ScriptedBackend(answers=[])
    assert len(run_benchmark(cases, again, config)) == 3 and again.requests == []  # resumed: nothing to do
    summary = summarize(records)
    assert summary["overall"]["judged"] == 2 and summary["overall"]["passed"] == 1
    assert summary["subsets"]["arm"]["pass_rate"] == 1.0


def test_bench_command_writes_report_and_figures(tmp_path: Path, ovita_dir: Path) -> None:
    folder = make_folder(tmp_path, ovita_dir)
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([SHIFT_RIGHT] * 6))
    out = tmp_path / "out"
    result = CliRunner().invoke(
        cli,
        [
            "bench",
            str(folder),
            "-b",
            "scripted",
            "-o",
            "answers",
            str(answers),
            "--out",
            str(out),
            "--jobs",
            "2",
        ],
    )
    assert result.exit_code == 0, result.output
    assert "passed 0 of 2 judged cases" in result.output
    report = (out / "report.md").read_text()
    assert "| cases/ground/case-v2 |" in report and "check: shift" in report
    assert len(list((out / "figures").glob("*.png"))) == 2
    summary = json.loads((out / "summary.json").read_text())
    assert summary["failure_kinds"] == [["check: shift", 2]]


def test_errors_are_scored_as_failures(tmp_path: Path, ovita_dir: Path) -> None:
    folder = make_folder(tmp_path, ovita_dir)
    cases = [case for case in discover_cases([folder]) if case.key == "ground/case"]
    records = run_benchmark(
        cases, ScriptedBackend(answers=["no code here", "still none"]), BenchConfig(out_dir=tmp_path / "o")
    )
    assert records[0]["status"] == "error" and "AnswerParseError" in records[0]["error"]
    assert records[0]["evaluation"]["passed"] is False


def test_rescore_judges_stored_results_again(tmp_path: Path, ovita_dir: Path) -> None:
    folder = make_folder(tmp_path, ovita_dir)
    out = tmp_path / "out"
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([SHIFT_LEFT] * 3))
    runner = CliRunner()
    assert (
        runner.invoke(
            cli, ["bench", str(folder), "-b", "scripted", "-o", "answers", str(answers), "--out", str(out)]
        ).exit_code
        == 0
    )
    (folder / "expectations.toml").write_text(
        EXPECTATIONS.replace('direction = "left"', 'direction = "right"')
    )
    result = runner.invoke(cli, ["bench", str(folder), "--rescore", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "judged 3 stored result(s) again" in result.output and "passed 0 of 2" in result.output


def test_waypoints_in_prompt_reaches_the_request(tmp_path: Path, ovita_dir: Path) -> None:
    folder = make_folder(tmp_path, ovita_dir)
    cases = [case for case in discover_cases([folder]) if case.key == "ground/case"]
    for waypoints in (False, True):
        backend = ScriptedBackend(answers=[SHIFT_LEFT])
        config = BenchConfig(
            out_dir=tmp_path / str(waypoints), session=SessionSettings(waypoints_in_prompt=waypoints)
        )
        record = run_benchmark(cases, backend, config)[0]
        user_text = backend.requests[0].messages[1].content
        assert ("waypoints [x, y, z, velocity]" in user_text) is waypoints
        assert record["waypoints_in_prompt"] is waypoints


def test_a_backend_that_answers_one_at_a_time_runs_in_parallel_processes(
    tmp_path: Path, ovita_dir: Path
) -> None:
    from tests.bench.one_at_a_time import OneAtATimeBackend

    folder = tmp_path / "cases"
    folder.mkdir()
    for index in range(0, 12, 2):
        shutil.copy(ovita_dir / "latte_subset" / f"latte_{index}.json", folder / f"case_{index}.json")
    cases = discover_cases([folder])
    serial = run_benchmark(cases, OneAtATimeBackend(), BenchConfig(out_dir=tmp_path / "serial"))
    done: list[str] = []
    parallel = run_benchmark(
        cases,
        OneAtATimeBackend(),
        BenchConfig(out_dir=tmp_path / "parallel", jobs=2),
        lambda c, _: done.append(c.key),
    )
    assert sorted(done) == sorted(case.key for case in cases)
    answered_by = {record["model"] for record in parallel}
    assert 1 <= len(answered_by) <= 2 and f"pid-{os.getpid()}" not in answered_by  # worker processes answered
    for one, other in zip(serial, parallel, strict=True):
        assert one["code"] == other["code"] and one["modified_trajectory"] == other["modified_trajectory"]


def test_a_figure_that_cannot_be_drawn_does_not_lose_the_report(
    tmp_path: Path, ovita_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import trajadapt.bench.report as report

    folder = make_folder(tmp_path, ovita_dir)
    records = run_benchmark(
        discover_cases([folder]),
        ScriptedBackend(answers=[SHIFT_LEFT, SHIFT_LEFT, KEEP]),
        BenchConfig(out_dir=tmp_path / "out"),
    )

    def broken(path: Path, record: dict) -> None:
        raise ValueError("mathtext cannot parse '$\\\\frac{'")

    monkeypatch.setattr(report, "_figure", broken)
    summary = report.write_report(tmp_path / "out", records)
    assert summary["overall"]["judged"] == 2
    assert (tmp_path / "out" / "report.md").is_file() and (tmp_path / "out" / "summary.json").is_file()


def test_the_bench_sandboxes_use_the_isolation_asked_for(
    tmp_path: Path, ovita_dir: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    import trajadapt.bench.runner as runner

    asked: list[str] = []
    real = runner.Sandbox

    def recording(*args: object, isolation: str = "auto", **kwargs: object) -> object:
        asked.append(isolation)
        return real(*args, isolation=isolation, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(runner, "Sandbox", recording)
    folder = make_folder(tmp_path, ovita_dir)
    config = BenchConfig(out_dir=tmp_path / "out", isolation="process")
    run_benchmark(discover_cases([folder]), ScriptedBackend(answers=[KEEP] * 3), config)
    assert asked == ["process"]

"""``trajadapt bench``: every case non-interactively, judged, scored and reported."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import click

from trajadapt.bench.report import write_report
from trajadapt.bench.runner import BenchConfig, discover_cases, result_path, run_benchmark
from trajadapt.bench.runner import rescore as rescore_results
from trajadapt.cli.common import (
    backend_option,
    examples_option,
    grammar_option,
    isolation_of,
    make_backend,
    near_rule_option,
    option_option,
)
from trajadapt.cli.console import CaseProgress
from trajadapt.errors import InputError
from trajadapt.memory import MemoryBank
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import PROMPT_MODES
from trajadapt.session import SessionSettings
from trajadapt.settings import load_settings


@click.command()
@click.argument("cases", nargs=-1, required=True, type=click.Path(path_type=Path))
@backend_option
@option_option
@click.option(
    "--mode",
    type=click.Choice(PROMPT_MODES),
    default=None,
    help="skills (default): the prompt lists the skill library; paper: only get_trajectory/detect_objects.",
)
@examples_option
@grammar_option
@click.option(
    "--out",
    "out_dir",
    type=click.Path(path_type=Path),
    default=None,
    help="Output folder (default: bench-out/<mode>).",
)
@click.option(
    "--jobs",
    "-j",
    type=click.IntRange(1, 64),
    default=1,
    show_default=True,
    help="Cases in flight at once: requests side by side to a served model (vLLM, Ollama), or that many "
    "model processes with the local backend (one thread each on 2 cores; results equal a serial run).",
)
@click.option("--force", is_flag=True, help="Run cases again even if they have a result.")
@click.option(
    "--rescore", is_flag=True, help="Only judge the stored results again (after the checks changed)."
)
@click.option(
    "--expectations",
    type=click.Path(path_type=Path),
    default=None,
    help="Expectations TOML (default: CASES/expectations.toml or the packaged file).",
)
@click.option("--axes", type=click.Choice(sorted(AXIS_CONVENTIONS)), default=None, help="Axis convention.")
@near_rule_option
@click.option("--repairs", type=click.IntRange(0, 10), default=None, help="Repair rounds (default 2).")
@click.option(
    "--waypoints-in-prompt/--summary-in-prompt",
    default=None,
    help="Send every waypoint to the LLM, or only the trajectory's summary (default; see the README).",
)
@click.option(
    "--project/--no-project",
    "project_onto",
    default=None,
    help="Project results that break a case's constraints onto them (default), or fail them.",
)
@click.option("--memory", "memory_file", type=click.Path(path_type=Path, dir_okay=False), default=None,
              help="Recall examples from this bank of remembered answers too (read only; 'trajadapt "
              "examples export' writes one). Without it a run never reads or writes the user's "
              "bank.")  # fmt: skip
def bench(
    cases: tuple[Path, ...],
    backend: str | None,
    options: tuple[tuple[str, str], ...],
    mode: str | None,
    examples: int | None,
    grammar: bool | None,
    out_dir: Path | None,
    jobs: int,
    force: bool,
    rescore: bool,
    expectations: Path | None,
    axes: str | None,
    near_rule: str | None,
    repairs: int | None,
    waypoints_in_prompt: bool | None,
    project_onto: bool | None,
    memory_file: Path | None,
) -> None:
    """Run every case in CASES (files or folders) and score the results against expectations.

    Writes one result file per case, summary.json, report.md and a figure per failed case into the
    output folder. Cases that already have a result are skipped unless --force.
    """
    settings = load_settings(
        {
            "backend": backend,
            "axes": axes,
            "near_rule": near_rule,
            "repair_attempts": repairs,
            "waypoints_in_prompt": waypoints_in_prompt,
            "project": project_onto,
            "mode": mode,
            "examples": examples,
            "grammar": grammar,
        }
    )
    found = discover_cases(list(cases), expectations)
    config = BenchConfig(
        out_dir or Path("bench-out") / settings.mode,
        SessionSettings.from_settings(settings),
        jobs=jobs,
        force=force,
        isolation=isolation_of(settings),
        memory=memory_file,
    )
    if memory_file is not None:
        if not memory_file.is_file():
            raise InputError(f"--memory {memory_file}: no such file")
        recalled = MemoryBank(memory_file, read_only=True).examples()
        click.echo(f"recalling from {len(recalled)} remembered example(s) in {memory_file}")
    if rescore:
        click.echo(f"judged {rescore_results(found, config)} stored result(s) again")
        stored = [result_path(config, case) for case in found]
        _report(config, [json.loads(path.read_text()) for path in stored if path.is_file()])
        return
    chosen = make_backend(settings, options)
    todo = sum(1 for case in found if force or not result_path(config, case).is_file())
    click.echo(
        f"{len(found)} case(s), {todo} to run with {chosen.describe()}, mode {settings.mode}, "
        f"{settings.examples} example(s), grammar {'on' if settings.grammar else 'off'} -> {config.out_dir}"
    )
    try:
        with CaseProgress(todo) as progress:
            records = run_benchmark(
                found, chosen, config, lambda case, record: progress.advance(case.key, _outcome(record))
            )
    finally:
        chosen.close()
    _report(config, records)


def _report(config: BenchConfig, records: list[dict[str, Any]]) -> None:
    summary = write_report(config.out_dir, records)
    overall = summary["overall"]
    rate = "-" if overall["pass_rate"] is None else f"{100 * overall['pass_rate']:.1f}%"
    report = config.out_dir / "report.md"
    click.echo(f"passed {overall['passed']} of {overall['judged']} judged cases ({rate}); report: {report}")


def _outcome(record: dict[str, Any]) -> str:
    evaluation = record["evaluation"]
    if record["status"] != "ok":
        return "error: " + str(record["error"])[:80]
    if not evaluation["judged"]:
        return "not judged"
    return "pass" if evaluation["passed"] else "fail: " + str(evaluation["reason"])[:80]

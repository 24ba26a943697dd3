"""Benchmark runner: every case non-interactively (first plan approved, repair on), scored and saved.

Results go to ``OUT/<path of the case relative to the folder given>/<stem>.result.json``, so cases
with the same file name in different subfolders never collide. A case with a result file is skipped
unless ``force`` is set, so an interrupted run resumes where it stopped.
"""

from __future__ import annotations

import atexit
import json
import multiprocessing
import queue
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor, as_completed
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from trajadapt.backends.base import Backend
from trajadapt.bench.expectations import EXPECTATIONS_FILENAME, ExpectationSet, find_expectations
from trajadapt.bench.judges import CheckContext, run_check
from trajadapt.bench.metrics import discrete_frechet, dynamic_time_warping, latte_scores, roughness
from trajadapt.errors import InputError, TrajadaptError
from trajadapt.files.atomic_files import write_json_atomic
from trajadapt.memory import MemoryBank
from trajadapt.model.case import Case, load_case
from trajadapt.model.geometry import AXIS_CONVENTIONS, Axes
from trajadapt.model.trajectory import Trajectory, read_json_file
from trajadapt.sandbox.runner import Isolation, Sandbox
from trajadapt.session import AdaptationSession, Failure, SessionSettings


@dataclass(frozen=True)
class BenchCase:
    """One case file found under a folder given to the benchmark."""

    key: str
    path: Path
    expectations: ExpectationSet | None

    @property
    def subset(self) -> str:
        """The first folder of the key ('latte_subset'), or the folder's name for flat folders."""
        return (
            self.key.split("/")[0]
            if "/" in self.key
            else (self.expectations.name if self.expectations else ".")
        )


@dataclass(frozen=True)
class BenchConfig:
    """How to run: prompt mode, axes, repairs, output folder, parallel jobs, re-run or resume."""

    out_dir: Path
    session: SessionSettings = field(default_factory=SessionSettings)
    jobs: int = 1
    force: bool = False
    isolation: Isolation = "auto"
    memory: Path | None = None
    """A bank of remembered examples to recall from (read only); None: the shipped bank alone."""


def discover_cases(paths: list[Path], expectations_file: Path | None = None) -> list[BenchCase]:
    """Every case file under ``paths`` (files or folders), with the expectations that go with it.

    Raises:
        InputError: a path does not exist.
    """
    cases: list[BenchCase] = []
    for path in paths:
        if path.is_file():
            files = [path]
        elif path.is_dir():
            files = sorted(p for p in path.rglob("*.json") if not p.name.endswith(".result.json"))
        else:
            raise InputError(f"{path}: no such case file or folder")
        cases.extend(
            _located_case(file, path if path.is_dir() else path.parent, expectations_file) for file in files
        )
    return cases


def _located_case(path: Path, given: Path, expectations_file: Path | None) -> BenchCase:
    """Key a case relative to the nearest folder (the given one or above) whose expectations name it.

    So ``ovita-dev/latte_subset`` alone still finds ``ovita-dev``'s expectations.
    """
    for folder in (given, *given.parents):
        expectations = find_expectations(folder, expectations_file)
        key = str(path.relative_to(folder).with_suffix(""))
        if expectations is not None and key in expectations.cases:
            return BenchCase(key, path, expectations)
    return BenchCase(
        str(path.relative_to(given).with_suffix("")), path, find_expectations(given, expectations_file)
    )


def result_path(config: BenchConfig, case: BenchCase) -> Path:
    """Where the result of ``case`` is written."""
    return config.out_dir / f"{case.key}.result.json"


ProgressCallback = Callable[[BenchCase, dict[str, Any]], None]


def run_benchmark(
    cases: list[BenchCase],
    backend: Backend,
    config: BenchConfig,
    on_case_done: ProgressCallback | None = None,
) -> list[dict[str, Any]]:
    """Run the cases that have no result yet (all with ``force``); return every case's record.

    With ``config.jobs`` > 1, cases run side by side: on threads sharing ``backend`` where it takes
    concurrent requests (a served model), else in that many processes, each with its own copy of the
    backend (the embedded model: one llama.cpp context per process, the cores shared out).
    """
    todo = [case for case in cases if config.force or not result_path(config, case).is_file()]
    jobs = max(config.jobs, 1)
    if jobs > 1 and not backend.concurrent and todo:
        _run_in_processes(todo, backend, config, jobs, on_case_done)
    else:
        _run_in_threads(todo, backend, config, jobs, on_case_done)
    return [
        json.loads(result_path(config, case).read_text())
        for case in cases
        if result_path(config, case).is_file()
    ]


def _run_in_threads(
    todo: list[BenchCase],
    backend: Backend,
    config: BenchConfig,
    jobs: int,
    on_case_done: ProgressCallback | None,
) -> None:
    with _sandbox_pool(jobs, config.isolation) as sandboxes, ThreadPoolExecutor(jobs) as pool:
        futures = [pool.submit(_run_and_save, case, backend, config, sandboxes) for case in todo]
        for case, future in zip(todo, futures, strict=True):
            record = future.result()
            if on_case_done is not None:
                on_case_done(case, record)


def _run_in_processes(
    todo: list[BenchCase],
    backend: Backend,
    config: BenchConfig,
    jobs: int,
    on_case_done: ProgressCallback | None,
) -> None:
    worker = (type(backend), backend.process_options(jobs), config)
    context = multiprocessing.get_context("spawn")  # llama.cpp and the sandbox worker do not survive fork
    with ProcessPoolExecutor(jobs, mp_context=context, initializer=_start_worker, initargs=worker) as pool:
        futures = {pool.submit(_run_in_worker, case): case for case in todo}
        for future in as_completed(futures):
            record = future.result()
            if on_case_done is not None:
                on_case_done(futures[future], record)


_worker: tuple[Backend, Sandbox, BenchConfig] | None = None


def _start_worker(backend_type: type[Backend], options: Any, config: BenchConfig) -> None:
    """In a bench process: build its own backend and sandbox, closed when the process ends."""
    global _worker
    backend, sandbox = backend_type(options), Sandbox(isolation=config.isolation)
    _worker = (backend, sandbox, config)
    atexit.register(sandbox.close)
    atexit.register(backend.close)


def _run_in_worker(case: BenchCase) -> dict[str, Any]:
    assert _worker is not None, "bench worker process not started"
    backend, sandbox, config = _worker
    record = run_case(case, backend, sandbox, config)
    write_json_atomic(result_path(config, case), record)
    return record


@contextmanager
def _sandbox_pool(size: int, isolation: Isolation) -> Iterator[queue.Queue[Sandbox]]:
    sandboxes: queue.Queue[Sandbox] = queue.Queue()
    created = [Sandbox(isolation=isolation) for _ in range(size)]
    for sandbox in created:
        sandboxes.put(sandbox)
    try:
        yield sandboxes
    finally:
        for sandbox in created:
            sandbox.close()


def _run_and_save(
    case: BenchCase, backend: Backend, config: BenchConfig, sandboxes: queue.Queue[Sandbox]
) -> dict[str, Any]:
    sandbox = sandboxes.get()
    try:
        record = run_case(case, backend, sandbox, config)
    finally:
        sandboxes.put(sandbox)
    write_json_atomic(result_path(config, case), record)
    return record


def run_case(case: BenchCase, backend: Backend, sandbox: Sandbox, config: BenchConfig) -> dict[str, Any]:
    """Adapt one case (first plan approved) and score it; failures become an error record."""
    loaded = load_case(case.path)
    memory = MemoryBank(config.memory, read_only=True) if config.memory else None
    session = AdaptationSession(loaded, backend, sandbox, config.session, memory=memory)
    try:
        session.draft()
        record = session.approve().to_dict()
    except TrajadaptError as exc:
        record = session.failure(Failure.of(type(exc).__name__, str(exc))).to_dict()
    record.update(
        {key: record["settings"][key] for key in ("mode", "waypoints_in_prompt", "project", "axes")}
    )
    record["repair_rounds"] = sum(1 for turn in session.turns if turn.kind == "repair")
    record["evaluation"] = evaluate(case, loaded, record, config.session.axes.frame)
    record["metrics"] = shape_metrics(loaded, record)
    record["target_scores"] = target_scores(case.path, loaded, record)
    return record


def evaluate(case: BenchCase, loaded: Case, record: dict[str, Any], axes: Axes) -> dict[str, Any]:
    """Run the case's expectation checks on a result record."""
    expectation = case.expectations.cases.get(case.key) if case.expectations else None
    base = {"task_id": case.expectations.task_id(case.key) if case.expectations else case.key}
    if expectation is None:
        return {
            **base,
            "judged": False,
            "passed": None,
            "reason": f"no expectations (add them to {EXPECTATIONS_FILENAME})",
            "checks": [],
        }
    if expectation.skip:
        return {
            **base,
            "judged": False,
            "passed": None,
            "reason": f"not judged: {expectation.skip}",
            "checks": [],
        }
    if record["status"] != "ok":
        return {
            **base,
            "judged": True,
            "passed": False,
            "reason": "no trajectory: " + str(record["error"])[:200],
            "checks": [],
        }
    context = CheckContext(
        original=loaded.trajectory.array,
        adapted=np.asarray(record["modified_trajectory"], dtype=np.float64),
        objects={obj.name.casefold(): np.asarray(obj.position) for obj in loaded.scene.objects},
        axes=axes,
    )
    verdicts = [run_check(context, dict(spec)) for spec in expectation.checks]
    failed = [v for v in verdicts if not v.passed]
    reason = "; ".join(f"{v.kind}: {v.detail}" for v in failed)
    return {
        **base,
        "judged": True,
        "passed": not failed,
        "reason": reason,
        "checks": [{"kind": v.kind, "passed": v.passed, "detail": v.detail} for v in verdicts],
    }


def rescore(cases: list[BenchCase], config: BenchConfig) -> int:
    """Judge the stored results again with the current expectations and checks; returns how many."""
    count = 0
    for case in cases:
        path = result_path(config, case)
        if not path.is_file():
            continue
        record = json.loads(path.read_text())
        loaded = load_case(case.path)
        axes = AXIS_CONVENTIONS[record.get("axes", config.session.axes.name)].frame
        record["evaluation"] = evaluate(case, loaded, record, axes)
        record["metrics"] = shape_metrics(loaded, record)
        record["target_scores"] = target_scores(case.path, loaded, record)
        write_json_atomic(path, record)
        count += 1
    return count


def shape_metrics(case: Case, record: dict[str, Any]) -> dict[str, float | None]:
    """Fréchet and DTW distance to the original, and roughness before and after."""
    if record.get("modified_trajectory") is None:
        return {
            "frechet": None,
            "dtw": None,
            "roughness": None,
            "roughness_original": roughness(case.trajectory.array),
        }
    adapted = np.asarray(record["modified_trajectory"], dtype=np.float64)
    original = case.trajectory.array
    return {
        "frechet": discrete_frechet(original, adapted),
        "dtw": dynamic_time_warping(original, adapted),
        "roughness": roughness(adapted),
        "roughness_original": roughness(original),
    }


def target_path(case_path: Path) -> Path | None:
    """The reference target of a case in the latte-dev layout (``targets/`` beside ``cases/``), if any."""
    for folder in case_path.parents:
        if folder.name == "cases" and (folder.parent / "targets").is_dir():
            candidate = folder.parent / "targets" / case_path.relative_to(folder)
            return candidate if candidate.is_file() else None
    return None


def target_scores(case_path: Path, case: Case, record: dict[str, Any]) -> dict[str, Any] | None:
    """LaTTe's metrics of the tool's result and of copying the input, against the case's target.

    A case whose code failed is scored as the path it leaves: the input unchanged.

    Raises:
        InputError: the target file is not of the documented form.
    """
    path = target_path(case_path)
    if path is None:
        return None
    data = read_json_file(path)
    rows = data.get("output_traj") if isinstance(data, dict) else None
    target = Trajectory.from_rows(rows, f"{path}: output_traj").array
    original = case.trajectory.array
    adapted = record.get("modified_trajectory")
    prediction = np.asarray(adapted, dtype=np.float64) if adapted else original
    return {
        "tool": latte_scores(target, prediction),
        "copy": latte_scores(target, original),
        "tool_ran": adapted is not None,
    }

"""Latency of the embedded model: cold start and warm answers, idle and beside a busy process.

Cold start = a fresh process doing import + model load + first answer (run as a subprocess, so the
import is counted), with and without the on-disk prompt state. Warm = later answers in the same
process, the instructions taken in turn (each answer reads its own instruction; no repair round),
once on an idle machine and once while a CPU-bound process (started and stopped here) runs beside
it. Reports p50/p90 per answer, tokens per second, prefill vs generation vs sandbox time, the
thread layout, and peak RSS.

Run: .venv/bin/python benchmarks/local_latency.py [--repeats 5] [--case FILE] [-o n_threads 2]
"""

from __future__ import annotations

import argparse
import json
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

INSTRUCTIONS = (
    "go to the left",
    "walk a lot slower in the surrounding of the damselfly",
    "Go slower if paddle is within 0.2 and keep a distance of at least 0.2 from marmoset",
)
DEFAULT_CASE = Path(__file__).resolve().parents[1].parent / "shared/data/ovita-dev/latte_subset/latte_10.json"


def one_answer(case_path: Path, instruction: str, cache_dir: Path, prompt_cache: bool) -> dict[str, float]:
    """Adapt once in this process; return timings and token counts."""
    from trajadapt.backends.local import LocalBackend, LocalOptions
    from trajadapt.model.case import load_case
    from trajadapt.sandbox.runner import Sandbox
    from trajadapt.session import AdaptationSession, SessionSettings

    backend = _backend(LocalBackend, LocalOptions, cache_dir, prompt_cache)
    case = load_case(case_path).with_instruction(instruction)
    with Sandbox() as sandbox:
        session = AdaptationSession(case, backend, sandbox, SessionSettings(repair_attempts=0))
        started = time.perf_counter()
        session.draft()
        result = session.approve()
        total = time.perf_counter() - started
    completion = session.turns[-1].completion
    details = completion.details if completion else {}
    return {
        "total_s": total,
        "llm_s": result.timings.llm_s,
        "exec_s": result.timings.exec_s,
        "prefill_s": float(details.get("prefill_s", 0.0)),
        "generation_s": float(details.get("generation_s", 0.0)),
        "restored_tokens": float(details.get("restored_prompt_tokens", 0)),
        "prompt_tokens": float(result.tokens.get("prompt", 0)),
        "completion_tokens": float(result.tokens.get("completion", 0)),
        "ok": float(result.ok),
    }


_BACKENDS: dict[tuple[str, bool], object] = {}
THREADS: dict[str, int] = {}  # n_threads / n_threads_batch given on the command line


def _backend(backend_type: type, options_type: type, cache_dir: Path, prompt_cache: bool) -> object:
    key = (str(cache_dir), prompt_cache)
    if key not in _BACKENDS:
        _BACKENDS[key] = backend_type(options_type(cache_dir=cache_dir, prompt_cache=prompt_cache, **THREADS))
    return _BACKENDS[key]


@contextmanager
def busy_core() -> Iterator[None]:
    """A CPU-bound process beside the model for the duration of the block."""
    hog = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    try:
        time.sleep(0.5)
        yield
    finally:
        hog.kill()
        hog.wait()


def warm_answers(case_path: Path, cache_dir: Path, repeats: int) -> list[dict[str, float]]:
    """``repeats`` rounds over the instructions, after one unmeasured answer."""
    one_answer(case_path, INSTRUCTIONS[-1], cache_dir, True)
    return [one_answer(case_path, text, cache_dir, True) for _ in range(repeats) for text in INSTRUCTIONS]


def describe_warm(label: str, runs: list[dict[str, float]]) -> str:
    """One line: p50/p90 per answer and where the median answer's time goes."""
    totals = sorted(run["total_s"] for run in runs)
    p90 = totals[min(len(totals) - 1, round(0.9 * (len(totals) - 1)))]
    rates = [run["completion_tokens"] / max(run["generation_s"], 1e-9) for run in runs]
    median = {key: statistics.median(run[key] for run in runs) for key in runs[0]}
    return (
        f"warm, {label}: p50 {statistics.median(totals):.1f} s, p90 {p90:.1f} s per answer "
        f"({len(runs)} answers); median prefill {median['prefill_s']:.1f} s + generation "
        f"{median['generation_s']:.1f} s ({median['completion_tokens']:.0f} tokens, "
        f"{statistics.median(rates):.1f} tok/s) + sandbox {1000 * median['exec_s']:.0f} ms"
    )


def cold_start(case_path: Path, cache_dir: Path, prompt_cache: bool) -> dict[str, float]:
    """Run one adaptation in a fresh interpreter and time it from the process start."""
    code = (
        "import json, sys, time; t0 = time.perf_counter(); sys.path.insert(0, 'benchmarks');"
        f"import local_latency as m; m.THREADS.update({THREADS!r});"
        f"r = m.one_answer(m.Path({str(case_path)!r}), {INSTRUCTIONS[0]!r}, m.Path({str(cache_dir)!r}), {prompt_cache});"
        "r['cold_s'] = time.perf_counter() - t0; r['rss_mb'] = m.peak_rss_mb(); print(json.dumps(r))"
    )
    output = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return json.loads(output.stdout.strip().splitlines()[-1])


def peak_rss_mb() -> float:
    """Peak resident memory of this process in MB."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def main() -> None:
    """Measure and print a small report."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--case", type=Path, default=DEFAULT_CASE)
    parser.add_argument("-o", "--option", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                        help="n_threads or n_threads_batch for the model (default: chosen from the machine)")  # fmt: skip
    args = parser.parse_args()
    THREADS.update(
        {name: int(value) for name, value in args.option if name in ("n_threads", "n_threads_batch")}
    )
    if not args.case.is_file():
        parser.error(f"case {args.case} not found; give one with --case FILE (default: ovita-dev's latte_10)")
    from trajadapt.llm.model_file import ensure_model
    from trajadapt.settings import default_home

    models = default_home() / "models"
    ensure_model(models)
    scratch = Path(tempfile.mkdtemp(prefix="trajadapt-latency-"))
    (scratch / "models").mkdir()
    for item in models.glob("*.gguf*"):
        (scratch / "models" / item.name).symlink_to(item)
    try:
        without = cold_start(args.case, scratch / "models", prompt_cache=False)
        first = cold_start(args.case, scratch / "models", prompt_cache=True)  # writes the prompt state
        warm_start = cold_start(args.case, scratch / "models", prompt_cache=True)  # reads it
        print(
            f"cold start, no prompt state: {without['cold_s']:.1f} s (prefill {without['prefill_s']:.1f} s), RSS {without['rss_mb']:.0f} MB"
        )
        print(f"cold start, saving state:    {first['cold_s']:.1f} s, RSS {first['rss_mb']:.0f} MB")
        print(f"cold start, prompt state:    {warm_start['cold_s']:.1f} s (prefill {warm_start['prefill_s']:.1f} s, "
              f"{warm_start['restored_tokens']:.0f} tokens restored), RSS {warm_start['rss_mb']:.0f} MB")  # fmt: skip
        from trajadapt.backends.local import thread_layout

        layout = thread_layout(generate=THREADS.get("n_threads"), read_prompt=THREADS.get("n_threads_batch"))
        print(f"threads: {layout.generate} generating, {layout.read_prompt} reading the prompt")
        idle = warm_answers(args.case, scratch / "models", args.repeats)
        print(describe_warm("idle", idle))
        with busy_core():
            busy = warm_answers(args.case, scratch / "models", args.repeats)
        print(describe_warm("one CPU-bound process beside it", busy))
        ratio = statistics.median(r["total_s"] for r in busy) / statistics.median(r["total_s"] for r in idle)
        print(f"busy / idle p50: {ratio:.2f}x")
        print(f"peak RSS of the warm process: {peak_rss_mb():.0f} MB")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()

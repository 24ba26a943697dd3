"""Latency of the embedded model against its raw budget: cold start, warm answers idle and beside a busy process.

Raw budget = the same loaded model, called directly in this process with the same threads, reading
300 fresh prompt tokens in an empty context and then writing 65 tokens greedily with no grammar
(issue #26's yardstick). Warm = whole first answers (``draft`` + ``approve``, no repair round) of
four dev cases of different kinds in turn, after one unmeasured answer, once on an idle machine and
once while a CPU-bound process (started and stopped here) runs beside it. Cold start = a fresh process
doing import + model load + first answer (run as a subprocess, so the import is counted), with the
saved prompt state. Per answer: total, reading (fresh prompt tokens), writing (tokens written,
forced, model evaluations), the time until the first plan step is on screen, and peak RSS.

Run: .venv/bin/python benchmarks/local_latency.py [--repeats 3] [--case FILE ...] [-o decoder llama.cpp]
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

DEV = Path(__file__).resolve().parents[1].parent / "shared/data/ovita-dev"
DEFAULT_CASES = (
    DEV / "latte_subset/latte_0.json",
    DEV / "extended_subset/extended_2.json",
    DEV / "drone/drone_trajectory_6.json",
    DEV / "ground_robot/trajectory_12.json",
)
RAW_READ, RAW_WRITE = 300, 65

_BACKENDS: dict[tuple[str, bool], object] = {}
OPTIONS: dict[str, str] = {}  # -o NAME VALUE given on the command line


def one_answer(case_path: Path, cache_dir: Path, prompt_cache: bool = True) -> dict[str, float]:
    """Adapt ``case_path`` once in this process (no memory, no repair); return timings and tokens."""
    from trajadapt.model.case import load_case
    from trajadapt.sandbox.runner import Sandbox
    from trajadapt.session import AdaptationSession, SessionSettings

    backend = _backend(cache_dir, prompt_cache)
    first_step: list[float] = []
    with Sandbox() as sandbox:
        started = time.perf_counter()

        def on_progress(message: str) -> None:
            if message.startswith("plan: ") and not first_step:
                first_step.append(time.perf_counter() - started)

        session = AdaptationSession(
            load_case(case_path),
            backend,
            sandbox,
            SessionSettings(repair_attempts=0),
            on_progress=on_progress,
        )
        session.draft()
        result = session.approve()
        total = time.perf_counter() - started
    completion = session.turns[0].completion
    details = dict(completion.details) if completion else {}
    return {
        "total_s": total,
        "llm_s": result.timings.llm_s,
        "exec_s": result.timings.exec_s,
        "first_step_s": first_step[0] if first_step else float("nan"),
        "read_s": float(details.get("prefill_s", 0.0)),
        "write_s": float(details.get("generation_s", 0.0)),
        "read_tokens": float(details.get("fresh_prompt_tokens", 0)),
        "written_tokens": float(completion.usage.completion_tokens or 0) if completion else 0.0,
        "forced_tokens": float(details.get("forced_tokens", 0)),
        "decodes": float(details.get("decodes", 0)),
        "restored_tokens": float(details.get("restored_prompt_tokens", 0)),
        "ok": float(result.ok),
    }


def _backend(cache_dir: Path, prompt_cache: bool) -> object:
    from trajadapt.backends.local import LocalBackend

    key = (str(cache_dir), prompt_cache)
    if key not in _BACKENDS:
        _BACKENDS[key] = LocalBackend.from_options(
            {**OPTIONS, "cache_dir": str(cache_dir), "prompt_cache": str(prompt_cache)}
        )
    return _BACKENDS[key]


def raw_budget(cache_dir: Path) -> dict[str, float]:
    """Read RAW_READ fresh tokens in an empty context, then write RAW_WRITE greedily: the model alone."""
    import numpy as np

    backend = _backend(cache_dir, True)
    llama = backend._load(backend.model_path())  # type: ignore[attr-defined]
    text = (Path(__file__).resolve().parents[1] / "src/trajadapt/prompts/system_skills.md").read_text()
    tokens = llama.tokenize(text.encode(), add_bos=False)[:RAW_READ]
    llama.reset()
    started = time.perf_counter()
    llama.eval(tokens)
    read = time.perf_counter() - started
    import llama_cpp

    for _ in range(RAW_WRITE):
        logits = np.ctypeslib.as_array(
            llama_cpp.llama_get_logits_ith(llama._ctx.ctx, -1), shape=(llama.n_vocab(),)
        )
        llama.eval([int(np.argmax(logits))])
    write = time.perf_counter() - started - read
    llama.reset()
    return {"read_s": read, "write_s": write, "total_s": read + write}


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


def warm_answers(cases: list[Path], cache_dir: Path, repeats: int) -> list[dict[str, float]]:
    """``repeats`` rounds over the cases, after one unmeasured answer."""
    one_answer(cases[-1], cache_dir)
    return [one_answer(case, cache_dir) for _ in range(repeats) for case in cases]


def describe_warm(label: str, runs: list[dict[str, float]]) -> str:
    """One line: p50/p90 per answer and where the median answer's time goes."""
    totals = sorted(run["total_s"] for run in runs)
    p90 = totals[min(len(totals) - 1, round(0.9 * (len(totals) - 1)))]
    median = {key: statistics.median(run[key] for run in runs) for key in runs[0]}
    return (
        f"warm, {label}: p50 {statistics.median(totals):.1f} s, p90 {p90:.1f} s per answer "
        f"({len(runs)} answers); median reading {median['read_s']:.1f} s ({median['read_tokens']:.0f} fresh "
        f"tokens) + writing {median['write_s']:.1f} s ({median['written_tokens']:.0f} tokens, "
        f"{median['forced_tokens']:.0f} forced, {median['decodes']:.0f} evaluations) + sandbox "
        f"{1000 * median['exec_s']:.0f} ms; first plan step after {median['first_step_s']:.1f} s"
    )


def cold_start(case_path: Path, cache_dir: Path) -> dict[str, float]:
    """Run one adaptation in a fresh interpreter and time it from the process start."""
    code = (
        "import json, sys, time; t0 = time.perf_counter(); sys.path.insert(0, 'benchmarks');"
        f"import local_latency as m; m.OPTIONS.update({OPTIONS!r});"
        f"r = m.one_answer(m.Path({str(case_path)!r}), m.Path({str(cache_dir)!r}));"
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
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument(
        "--case", type=Path, action="append", help="a case file (repeatable; default: 4 dev cases)"
    )
    parser.add_argument("-o", "--option", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                        help="an option of the local backend (n_threads, n_threads_batch, decoder, ...)")  # fmt: skip
    args = parser.parse_args()
    OPTIONS.update(dict(args.option))
    cases = args.case or list(DEFAULT_CASES)
    missing = [str(case) for case in cases if not case.is_file()]
    if missing:
        parser.error(f"case {missing[0]} not found; give cases with --case FILE")
    from trajadapt.llm.model_file import ensure_model
    from trajadapt.settings import default_home

    models = default_home() / "models"
    ensure_model(models)
    scratch = Path(tempfile.mkdtemp(prefix="trajadapt-latency-"))
    (scratch / "models").mkdir()
    for item in models.glob("*.gguf*"):
        (scratch / "models" / item.name).symlink_to(item)
    try:
        one_answer(cases[0], scratch / "models")  # writes the prompt state the cold start reads
        _BACKENDS.clear()
        cold = cold_start(cases[0], scratch / "models")
        print(f"cold start with the prompt state: {cold['cold_s']:.1f} s ({cold['restored_tokens']:.0f} tokens "
              f"restored, first plan step after {cold['first_step_s']:.1f} s of the answer), RSS {cold['rss_mb']:.0f} MB")  # fmt: skip
        print(f"backend: {_backend(scratch / 'models', True).describe()}")  # type: ignore[attr-defined]
        raw = raw_budget(scratch / "models")
        print(f"raw budget: read {RAW_READ} fresh tokens {raw['read_s']:.1f} s + write {RAW_WRITE} tokens "
              f"{raw['write_s']:.1f} s = {raw['total_s']:.1f} s")  # fmt: skip
        idle = warm_answers(cases, scratch / "models", args.repeats)
        print(describe_warm("idle", idle))
        with busy_core():
            busy = warm_answers(cases, scratch / "models", args.repeats)
        print(describe_warm("one CPU-bound process beside it", busy))
        idle_p50 = statistics.median(r["total_s"] for r in idle)
        busy_p50 = statistics.median(r["total_s"] for r in busy)
        print(
            f"idle p50 / raw budget: {idle_p50 / raw['total_s']:.2f}x; busy / idle p50: {busy_p50 / idle_p50:.2f}x"
        )
        print(f"peak RSS of the warm process: {peak_rss_mb():.0f} MB")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()

"""Latency of the embedded model: cold start and warm answers, where the time goes, peak memory.

Cold start = a fresh process doing import + model load + first answer (run as a subprocess, so the
import is counted), with and without the on-disk prompt state. Warm = later answers in the same
process (median of --repeats per instruction). Reports tokens in/out, tokens per second, prefill
vs generation vs sandbox time, and peak RSS.

Run: .venv/bin/python benchmarks/local_latency.py [--repeats 5] [--case FILE]
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
    from trajadapt.case import load_case
    from trajadapt.sandbox.runner import Sandbox
    from trajadapt.session import AdaptationSession

    backend = _backend(LocalBackend, LocalOptions, cache_dir, prompt_cache)
    case = load_case(case_path).with_instruction(instruction)
    with Sandbox() as sandbox:
        session = AdaptationSession(case, backend, sandbox)
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


def _backend(backend_type: type, options_type: type, cache_dir: Path, prompt_cache: bool) -> object:
    key = (str(cache_dir), prompt_cache)
    if key not in _BACKENDS:
        _BACKENDS[key] = backend_type(options_type(cache_dir=cache_dir, prompt_cache=prompt_cache))
    return _BACKENDS[key]


def cold_start(case_path: Path, cache_dir: Path, prompt_cache: bool) -> dict[str, float]:
    """Run one adaptation in a fresh interpreter and time it from the process start."""
    code = (
        "import json, sys, time; t0 = time.perf_counter(); sys.path.insert(0, 'benchmarks');"
        "import local_latency as m;"
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
    args = parser.parse_args()
    if not args.case.is_file():
        parser.error(f"case {args.case} not found; give one with --case FILE (default: ovita-dev's latte_10)")
    from trajadapt.model_file import ensure_model
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
        for instruction in INSTRUCTIONS:
            runs = [
                one_answer(args.case, instruction, scratch / "models", True) for _ in range(args.repeats + 1)
            ][1:]
            median = {key: statistics.median(run[key] for run in runs) for key in runs[0]}
            rate = median["completion_tokens"] / max(median["generation_s"], 1e-9)
            print(
                f"warm, {instruction[:40]!r}: median {median['total_s']:.1f} s = prefill {median['prefill_s']:.1f} s "
                f"+ generation {median['generation_s']:.1f} s ({median['completion_tokens']:.0f} tokens, {rate:.1f} tok/s) "
                f"+ sandbox {1000 * median['exec_s']:.0f} ms; prompt {median['prompt_tokens']:.0f} tokens; ok {median['ok']:.0%}"
            )
        print(f"peak RSS of the warm process: {peak_rss_mb():.0f} MB")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()

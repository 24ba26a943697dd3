"""Run a benchmark's stored answers again through today's pipeline, without asking the model.

Measures changes that act after the answer (leaving out unasked steps, replacing made-up amounts,
skill constants, projection, the judges) on exactly the answers a run got: each stored result's
plan and code are replayed by the scripted backend, in case order, with no repair round.

Run: .venv/bin/python benchmarks/replay_answers.py STORED_OUT CASES... --out NEW_OUT
Then compare: .venv/bin/python benchmarks/compare_runs.py STORED_OUT NEW_OUT
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.bench.report import write_report
from trajadapt.bench.runner import BenchConfig, discover_cases, result_path, run_benchmark
from trajadapt.session import SessionSettings


def main() -> None:
    """Replay every stored answer and write the new results, summary and report."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("stored", type=Path)
    parser.add_argument("cases", nargs="+", type=Path)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    cases = discover_cases(args.cases)
    stored_config = BenchConfig(out_dir=args.stored)
    answers, replayed = [], []
    for case in cases:
        path = result_path(stored_config, case)
        if not path.is_file():
            continue
        record = json.loads(path.read_text())
        steps = record.get("high_level_plan") or []
        plan = " ".join(f"{i}) {step}" for i, step in enumerate(steps, start=1))
        answers.append(
            json.dumps({"high_level_plan": plan or "1) (no plan)", "python_code": record.get("code") or ""})
        )
        replayed.append(case)
    stored = json.loads(next(args.stored.rglob("*.result.json")).read_text()).get("settings") or {}
    settings = SessionSettings(repair_attempts=0, format_retries=0)
    if stored.get("axes") == "ovita":
        from trajadapt.prompts import AXIS_CONVENTIONS

        settings = SessionSettings(axes=AXIS_CONVENTIONS["ovita"], repair_attempts=0, format_retries=0)
    records = run_benchmark(
        replayed, ScriptedBackend(answers=answers), BenchConfig(out_dir=args.out, session=settings)
    )
    write_report(args.out, records)
    print(f"replayed {len(records)} stored answers -> {args.out}")


if __name__ == "__main__":
    main()

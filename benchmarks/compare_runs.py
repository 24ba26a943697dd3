"""Compare two benchmark output folders on the cases both have judged.

Run: .venv/bin/python benchmarks/compare_runs.py BEFORE_DIR AFTER_DIR [--first-answers]

Prints, per subset and overall, how many of the common judged cases passed in each run, the median
and 90th percentile of the LLM time per case, the mean completion tokens, and which cases were gained
or lost, and in how many the code is the same; then the same for each half of the cases (``trajadapt.bench.halves``: the development half
a change was written from, the validation half it was not). With --first-answers a case counts as passed only if it passed without a repair round (the
answer the user would have seen first).
"""

from __future__ import annotations

import argparse
import json
import statistics
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from trajadapt.bench.halves import HALVES, half_of


@dataclass(frozen=True)
class Outcome:
    """What one stored result says about its case."""

    passed: bool
    llm_s: float
    completion_tokens: int
    code: str = ""


def stored_results(folder: Path) -> Iterator[tuple[str, dict[str, Any]]]:
    """Each result under a bench output ``folder`` with its case key: its path less the suffix."""
    for path in sorted(folder.rglob("*.result.json")):
        yield (
            str(path.relative_to(folder)).removesuffix(".result.json"),
            json.loads(path.read_text(encoding="utf-8")),
        )


def load_outcomes(folder: Path, first_answers: bool) -> dict[str, Outcome]:
    """Judged results under ``folder``, keyed by their path relative to it (without the suffix)."""
    outcomes = {}
    for key, result in stored_results(folder):
        evaluation = result.get("evaluation") or {}
        if not evaluation.get("judged"):
            continue
        passed = bool(evaluation.get("passed"))
        if first_answers and result.get("repair_rounds", 0):
            passed = False
        outcomes[key] = Outcome(
            passed=passed,
            llm_s=float((result.get("timings_s") or {}).get("llm") or 0.0),
            completion_tokens=int((result.get("tokens") or {}).get("completion") or 0),
            code=str(result.get("code") or ""),
        )
    return outcomes


def percentile(values: list[float], fraction: float) -> float:
    """The value below which ``fraction`` of ``values`` lie (nearest rank)."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def summary_row(name: str, keys: list[str], before: dict[str, Outcome], after: dict[str, Outcome]) -> str:
    """One markdown table row: passes and timing of both runs on ``keys``."""
    cells = [name, str(len(keys))]
    for run in (before, after):
        passed = sum(run[k].passed for k in keys)
        times = [run[k].llm_s for k in keys]
        tokens = statistics.mean(run[k].completion_tokens for k in keys)
        cells += [
            f"{passed} ({passed / len(keys):.0%})",
            f"{statistics.median(times):.1f} / {percentile(times, 0.9):.1f}",
            f"{tokens:.0f}",
        ]
    return "| " + " | ".join(cells) + " |"


def main() -> None:
    """Read both folders and print the comparison."""
    formatter = argparse.RawDescriptionHelpFormatter
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=formatter)
    parser.add_argument("before", type=Path)
    parser.add_argument("after", type=Path)
    parser.add_argument("--first-answers", action="store_true", help="a repaired pass counts as a fail")
    args = parser.parse_args()
    before = load_outcomes(args.before, args.first_answers)
    after = load_outcomes(args.after, args.first_answers)
    common = sorted(before.keys() & after.keys())
    if not common:
        parser.error(f"no judged case is in both {args.before} and {args.after}")
    print(f"{len(common)} judged case(s) in both: {args.before} -> {args.after}\n")
    print("| subset | cases | passed before | LLM s median / p90 | tokens out | passed after | "
          "LLM s median / p90 | tokens out |")  # fmt: skip
    print("|---|---|---|---|---|---|---|---|")
    subsets = sorted({key.split("/")[0] for key in common if "/" in key})
    for subset in subsets:
        print(summary_row(subset, [k for k in common if k.startswith(subset + "/")], before, after))
    print(summary_row("all", common, before, after))
    for half in HALVES:
        keys = [k for k in common if half_of(k) == half]
        if keys:
            print(summary_row(f"{half} half", keys, before, after))
    gained = [k for k in common if after[k].passed and not before[k].passed]
    lost = [k for k in common if before[k].passed and not after[k].passed]
    print(f"\ngained ({len(gained)}): {', '.join(gained) or '-'}")
    print(f"lost ({len(lost)}): {', '.join(lost) or '-'}")
    same = sum(before[k].code == after[k].code for k in common)
    print(f"the same code in {same} of {len(common)}")


if __name__ == "__main__":
    main()

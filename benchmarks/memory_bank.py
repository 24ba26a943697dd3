"""Build the bank of remembered examples a user would have after one pass over a benchmark.

Issue #28's measurement: the user approves every answer the first pass got right and corrects each
one it got wrong, once, with the expected program (``benchmarks/data/memory_corrections.json``).
Both go into a bank file through ``MemoryBank.remember``, exactly as an approval does.

Run: .venv/bin/python benchmarks/memory_bank.py FIRST_PASS_OUT CASES... --bank BANK.jsonl
Then: trajadapt bench PARAPHRASED_CASES --memory BANK.jsonl --out bench-out/NAME
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from trajadapt.bench.runner import BenchConfig, discover_cases, result_path
from trajadapt.memory import MemoryBank
from trajadapt.model.case import load_case

CORRECTIONS = Path(__file__).resolve().parent / "data" / "memory_corrections.json"


def main() -> None:
    """Remember the first pass's passing answers and the corrections of its failing ones."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("first_pass", type=Path)
    parser.add_argument("cases", nargs="+", type=Path)
    parser.add_argument("--bank", type=Path, required=True)
    parser.add_argument("--corrections", type=Path, default=CORRECTIONS)
    args = parser.parse_args()
    if args.bank.exists():
        parser.error(f"{args.bank} exists: give a new file")
    corrections = json.loads(args.corrections.read_text())
    bank = MemoryBank(args.bank)
    approved = corrected = 0
    for case in discover_cases(args.cases):
        stored = result_path(BenchConfig(out_dir=args.first_pass), case)
        if not stored.is_file():
            continue
        record = json.loads(stored.read_text())
        loaded = load_case(case.path)
        passed = (record.get("evaluation") or {}).get("passed")
        if passed:
            plan = " ".join(f"{i}) {s}" for i, s in enumerate(record["high_level_plan"], start=1))
            bank.remember(loaded.instruction, plan, record["code"], loaded.scene.names())
            approved += 1
        elif passed is False and case.key in corrections:
            fix = corrections[case.key]
            bank.remember(loaded.instruction, fix["plan"], fix["code"], loaded.scene.names())
            corrected += 1
    print(f"{args.bank}: {approved} approved and {corrected} corrected answers remembered")


if __name__ == "__main__":
    main()

"""Keep a run's model answers in one small file, so that later sessions can replay them.

A bench output folder is large and not kept with the sources; the model's own answers are all a
replay needs (``benchmarks/replay_answers.py`` takes this file in place of the folder). Each line is
one case: its key, the axes it ran with, the instruction as said and the model's answer. A later
folder given after the first replaces the answers of the cases it holds (a rerun of a few cases).

Run: .venv/bin/python benchmarks/keep_answers.py OUT_FILE BENCH_OUT [BENCH_OUT ...]
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from compare_runs import stored_results  # benchmarks/, beside this script


def kept_lines(folder: Path) -> dict[str, dict[str, Any]]:
    """One line per result of ``folder`` that keeps the model's answer, by case key."""
    return {
        key: {
            "case": key,
            "axes": (record.get("settings") or {}).get("axes", "paper"),
            "instruction": record.get("instruction"),
            "answer": record["answer"],
        }
        for key, record in stored_results(folder)
        if record.get("answer")
    }


def main() -> None:
    """Write the kept answers of the folders, later folders first for the cases they share."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("out", type=Path, help="the file to write (JSON lines)")
    parser.add_argument("folders", nargs="+", type=Path, help="bench output folders")
    args = parser.parse_args()
    lines: dict[str, dict[str, Any]] = {}
    for folder in args.folders:
        if not folder.is_dir():
            parser.error(f"{folder} is not a folder of bench results")
        lines.update(kept_lines(folder))
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text("".join(json.dumps(line) + "\n" for _, line in sorted(lines.items())))
    print(f"kept {len(lines)} answers -> {args.out}")


if __name__ == "__main__":
    main()

"""Write the dev cases again with their instructions reworded, to run beside the originals.

The paraphrases (tests/data/paraphrases/ovita-dev.json) were written blind, before any system ran
on them: same scene, same judges, only the words changed. The copies go to OUT/ovita-dev/..., so
`trajadapt bench` finds the packaged ovita-dev expectations for them by the folder's name.

Run: .venv/bin/python benchmarks/paraphrase_cases.py ../shared/data/ovita-dev out/paraphrases
Then: trajadapt bench out/paraphrases/ovita-dev --out bench-out/NAME
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

PARAPHRASES = Path(__file__).resolve().parent.parent / "tests" / "data" / "paraphrases" / "ovita-dev.json"


def write_paraphrased_cases(cases: Path, out: Path, paraphrases: Path = PARAPHRASES) -> list[Path]:
    """One copy of each paraphrased case under ``out/ovita-dev``, its instruction replaced."""
    reworded: dict[str, str] = json.loads(paraphrases.read_text(encoding="utf-8"))["paraphrases"]
    written = []
    for key, instruction in reworded.items():
        case = json.loads((cases / f"{key}.json").read_text(encoding="utf-8"))
        case["instruction"] = instruction
        target = out / "ovita-dev" / f"{key}.json"
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(json.dumps(case), encoding="utf-8")
        written.append(target)
    return written


def main() -> None:
    """Write the paraphrased copies and say how many."""
    formatter = argparse.RawDescriptionHelpFormatter
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=formatter)
    parser.add_argument("cases", type=Path, help="the ovita-dev folder")
    parser.add_argument("out", type=Path, help="where the copies go (OUT/ovita-dev/...)")
    parser.add_argument("--paraphrases", type=Path, default=PARAPHRASES, help="the set to use")
    args = parser.parse_args()
    written = write_paraphrased_cases(args.cases, args.out, args.paraphrases)
    print(f"wrote {len(written)} paraphrased case(s) under {args.out / 'ovita-dev'}")


if __name__ == "__main__":
    main()

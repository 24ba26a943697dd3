"""How much a run loses to rewording: the paraphrased cases against the same cases in their own words.

Issue #24's bar is that paraphrases pass within 5 points of their originals. Given a run over the
original cases and a run over a paraphrase set (``benchmarks/paraphrase_cases.py`` writes its cases),
this prints, for the cases both judged, how many pass in each wording, the gap in points, per half
(``trajadapt.bench.halves``), and which cases pass in only one wording.

Run: .venv/bin/python benchmarks/paraphrase_gap.py ORIGINALS_OUT PARAPHRASES_OUT
"""

from __future__ import annotations

import argparse
from pathlib import Path

from compare_runs import load_outcomes  # benchmarks/, beside this script

from trajadapt.bench.halves import HALVES, half_of


def passed_cases(folder: Path) -> dict[str, bool]:
    """Whether each judged case under ``folder`` passed (``compare_runs.load_outcomes``)."""
    return {key: outcome.passed for key, outcome in load_outcomes(folder, first_answers=False).items()}


def gap_lines(originals: dict[str, bool], reworded: dict[str, bool]) -> list[str]:
    """The table and the one-wording cases, as printed lines."""
    common = sorted(set(originals) & set(reworded))
    lines = [
        "| cases | judged in both | originals pass | paraphrases pass | gap (points) |",
        "|---|---|---|---|---|",
    ]
    for label, keys in [
        ("all", common),
        *((half, [k for k in common if half_of(k) == half]) for half in HALVES),
    ]:
        if not keys:
            continue
        own, other = sum(originals[k] for k in keys), sum(reworded[k] for k in keys)
        gap = 100.0 * (own - other) / len(keys)
        lines.append(f"| {label} | {len(keys)} | {own} | {other} | {gap:.1f} |")
    only_own = [k for k in common if originals[k] and not reworded[k]]
    only_other = [k for k in common if reworded[k] and not originals[k]]
    lines.append(f"\npass only in their own words ({len(only_own)}): {', '.join(only_own) or '-'}")
    lines.append(f"pass only reworded ({len(only_other)}): {', '.join(only_other) or '-'}")
    return lines


def main() -> None:
    """Print the gap between two runs' shared judged cases."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("originals", type=Path, help="a bench output folder over the original cases")
    parser.add_argument("paraphrases", type=Path, help="a bench output folder over their paraphrases")
    args = parser.parse_args()
    for folder in (args.originals, args.paraphrases):
        if not folder.is_dir():
            parser.error(f"{folder} is not a folder of bench results")
    originals, reworded = passed_cases(args.originals), passed_cases(args.paraphrases)
    if not set(originals) & set(reworded):
        parser.error("the two folders share no judged case: is the second a run over paraphrased copies?")
    print("\n".join(gap_lines(originals, reworded)))


if __name__ == "__main__":
    main()

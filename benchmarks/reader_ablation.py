"""What each reader gains or loses: the stored answers replayed with one reader left out at a time.

Issue #24 keeps a reader "only where it still gains on unseen wording". Each reader was written from
failing development cases, so it passes those; this measures it on every stored answer of every set
given, the blind paraphrase sets included. For each stored answer (the model's own text, kept in the
result's ``answer``) and each reader, the readers run once with and once without it; only where the
code differs is the case replayed, both ways, through today's pipeline (execution, projection, the
judges; no model, no repair round). The table gives, per reader and set, the answers it changes and
how many of those pass with it and without it.

Run: .venv/bin/python benchmarks/reader_ablation.py --set NAME STORED_OUT CASES [--set ...] --out DIR
(``NAME`` labels the set in the table; ``CASES`` is the folder its cases were run from.)

Not exact where a reader's change decides whether the session asks again (the shape check): a
replay gives the stored answer to a second request too, so it measures the first answer only.
"""

from __future__ import annotations

import argparse
import json
from dataclasses import dataclass, field
from pathlib import Path
from unittest import mock

from replay_answers import (
    StoredAnswers,
    replay_settings,
    request_key,
)  # the sibling script (run from benchmarks/)

from trajadapt import readers
from trajadapt.bench.halves import half_of
from trajadapt.bench.runner import BenchCase, BenchConfig, discover_cases, result_path, run_benchmark
from trajadapt.llm.answer import parse_answer
from trajadapt.model.case import Case, load_case


@dataclass
class StoredSet:
    """One set's stored answers: its cases and, for each, the case file and the model's own answer."""

    name: str
    cases: list[tuple[BenchCase, Case, str]] = field(default_factory=list)
    axes: str = "paper"


def load_set(name: str, stored: Path, cases: Path) -> StoredSet:
    """The stored answers of one run over ``cases`` (results without the model's own answer skipped)."""
    found = StoredSet(name)
    for case in discover_cases([cases]):
        path = result_path(BenchConfig(out_dir=stored), case)
        if not path.is_file():
            continue
        record = json.loads(path.read_text())
        if not record.get("answer") or not (record.get("evaluation") or {}).get("judged"):
            continue
        found.axes = (record.get("settings") or {}).get("axes", found.axes)
        found.cases.append((case, load_case(case.path), record["answer"]))
    return found


def without(name: str) -> tuple[readers.Reader, ...]:
    """The readers in run order, less the one called ``name``."""
    return tuple(reader for reader in readers.READERS if reader.name != name)


def changed_by(name: str, stored: StoredSet) -> list[tuple[BenchCase, Case, str]]:
    """The answers whose code after the readers differs when the reader ``name`` is left out."""
    changed = []
    for entry in stored.cases:
        _, case, answer = entry
        code, asked, names = parse_answer(answer).code, [case.instruction], case.scene.names()
        with_it = readers.read_against_words(code, asked, names)[0]
        with mock.patch.object(readers, "READERS", without(name)):
            if readers.read_against_words(code, asked, names)[0] != with_it:
                changed.append(entry)
    return changed


def replay(entries: list[tuple[BenchCase, Case, str]], axes: str, out: Path) -> dict[str, bool]:
    """Pass or fail of each replayed case, by its key, under the readers in force."""
    answers = [(request_key(case), answer) for _, case, answer in entries]
    config = BenchConfig(out_dir=out, session=replay_settings(axes), force=True)
    cases = [bench for bench, _, _ in entries]
    records = run_benchmark(cases, StoredAnswers(answers), config)
    return {case.key: bool((record.get("evaluation") or {}).get("passed"))
            for case, record in zip(cases, records, strict=True)}  # fmt: skip


def main() -> None:
    """Replay, per reader and set, the answers the reader changes, with it and without it."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--set", nargs=3, action="append", required=True, metavar=("NAME", "STORED", "CASES"),
                        help="a label, a bench output folder and the case folder it ran")  # fmt: skip
    parser.add_argument("--out", type=Path, required=True, help="where the replays are written")
    args = parser.parse_args()
    sets = [load_set(name, Path(stored), Path(cases)) for name, stored, cases in args.set]
    print("| reader | set | answers changed | pass with it | pass without | gained | lost | changed cases |")
    print("|---|---|---|---|---|---|---|---|")
    for reader in readers.READERS:
        for stored in sets:
            entries = changed_by(reader.name, stored)
            if not entries:
                continue
            out = args.out / reader.name / stored.name
            with_it = replay(entries, stored.axes, out / "with")
            with mock.patch.object(readers, "READERS", without(reader.name)):
                without_it = replay(entries, stored.axes, out / "without")
            gained = sorted(key for key in with_it if with_it[key] and not without_it.get(key))
            lost = sorted(key for key in with_it if without_it.get(key) and not with_it[key])
            keys = ", ".join(f"{key}{'+' if key in gained else '-' if key in lost else ''}"
                             f" ({half_of(key)[0]})" for key in sorted(with_it))  # fmt: skip
            print(
                f"| {reader.name} | {stored.name} | {len(entries)} | {sum(with_it.values())} | "
                f"{sum(without_it.values())} | {len(gained)} | {len(lost)} | {keys} |",
                flush=True,
            )


if __name__ == "__main__":
    main()

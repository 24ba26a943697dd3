"""What constrained decoding and retrieved examples cost per answer with the embedded model.

For each case (first answer only, no execution), asks the local backend in four settings: grammar
on/off x k examples (0 and 3 by default), in one process with one loaded model, and reports per
setting the median prefill time (reading the uncached part of the prompt), generation time,
completion tokens and time per generated token. Run it alone: the numbers are wall-clock.

Run: .venv/bin/python benchmarks/grammar_cost.py CASE_OR_FOLDER... [--limit 12] [--examples 0 3] [-t 1]
"""

from __future__ import annotations

import argparse
import statistics
from pathlib import Path

from trajadapt.backends.base import ChatRequest
from trajadapt.backends.local import LocalBackend, LocalOptions
from trajadapt.llm.answer_grammar import answer_grammar
from trajadapt.model.case import Case, load_case
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import first_messages


def cases_under(paths: list[Path], limit: int) -> list[Case]:
    """Up to ``limit`` cases from files or folders, spread over the folders in sorted order."""
    files = sorted(
        f for p in paths for f in ([p] if p.is_file() else p.rglob("*.json")) if "expect" not in f.name
    )
    return [load_case(f) for f in files[:: max(1, len(files) // limit)][:limit]]


def answer(backend: LocalBackend, case: Case, grammar: bool, examples: int) -> dict[str, float]:
    """One first answer: timings and tokens."""
    messages = first_messages(case, AXIS_CONVENTIONS["ovita"], "skills", examples=examples)
    text = answer_grammar(tuple(o.name for o in case.scene.objects)).to_gbnf() if grammar else None
    completion = backend.complete(ChatRequest(messages=messages, max_tokens=1024, grammar=text))
    tokens = completion.usage.completion_tokens or 0
    generation = float(completion.details["generation_s"])
    return {
        "prefill_s": float(completion.details["prefill_s"]),
        "generation_s": generation,
        "tokens": tokens,
        "ms_per_token": 1000 * generation / max(tokens - 1, 1),
    }


def main() -> None:
    """Ask every case in every setting and print one table row per setting."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("paths", nargs="+", type=Path)
    parser.add_argument("--limit", type=int, default=12)
    parser.add_argument("--examples", type=int, nargs="+", default=[0, 3])
    parser.add_argument("-t", "--threads", type=int, default=1, help="llama.cpp threads (generate and read)")
    args = parser.parse_args()
    backend = LocalBackend(LocalOptions(n_threads=args.threads, n_threads_batch=args.threads))
    backend.prepare()
    cases = cases_under(args.paths, args.limit)
    answer(backend, cases[0], False, 0)  # warm: the fixed prefix's state
    print(f"{len(cases)} case(s), {args.threads} thread(s); medians per answer")
    print("| grammar | examples | prefill s | generation s | tokens | ms/token |")
    print("|---|---|---|---|---|---|")
    for grammar in (False, True):
        for examples in args.examples:
            runs = [answer(backend, case, grammar, examples) for case in cases]
            cells = [
                statistics.median(r[key] for r in runs)
                for key in ("prefill_s", "generation_s", "tokens", "ms_per_token")
            ]
            print(
                f"| {'on' if grammar else 'off'} | {examples} | {cells[0]:.2f} | {cells[1]:.2f} | {cells[2]:.0f} | {cells[3]:.0f} |"
            )


if __name__ == "__main__":
    main()

"""Run a benchmark's stored answers again through today's pipeline, without asking the model.

Measures changes that act after the answer (leaving out unasked steps, replacing made-up amounts,
skill constants, projection, the judges) on exactly the answers a run got: each stored result's
``answer`` (the model's own text, kept since session 15) is given back as the answer to that case's
request, with no repair round. Older results have only the plan and code after the readers, so
their replay starts from what the readers of that run made (a lower bound for a new reader).

Run: .venv/bin/python benchmarks/replay_answers.py STORED CASES... --out NEW_OUT [--memory BANK]
STORED is a bench output folder, or a file of kept answers (``benchmarks/keep_answers.py``; the
model's answers of recent runs are kept in ``benchmarks/answers/``).
Then compare: .venv/bin/python benchmarks/compare_runs.py STORED_OUT NEW_OUT
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

from compare_runs import stored_results  # benchmarks/, beside this script

from trajadapt.backends.base import Backend, ChatRequest, Completion
from trajadapt.bench.report import write_report
from trajadapt.bench.runner import BenchConfig, discover_cases, run_benchmark
from trajadapt.llm.answer import answer_json
from trajadapt.model.case import Case, load_case
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import describe_environment
from trajadapt.readers.request_words import request_words
from trajadapt.session import SessionSettings
from trajadapt.settings import CHOICES


class StoredAnswers(Backend):
    """Answers a request with the stored answer of the case its task text is about."""

    name = "stored"

    def __init__(self, answers: list[tuple[tuple[str, str], str]]) -> None:
        super().__init__()
        self.answers = answers  # ((the case's environment text, its instruction line), the answer)

    @property
    def model(self) -> str:
        """Where the answers come from."""
        return "stored answers"

    def complete(self, request: ChatRequest) -> Completion:
        """The stored answer whose case the request's task text names."""
        task = request.messages[1].content
        found = [
            (len(line), answer)
            for (environment, line), answer in self.answers
            if environment in task and line in task
        ]  # the longest instruction that matches: "Go left by 20" is inside "Go left by 20 keeping ..."
        return Completion(text=max(found)[1] if found else "no stored answer", model=self.model)


def request_key(case: Case) -> tuple[str, str]:
    """What a request's task text holds for ``case``: its environment and its instruction line.

    The line holds the request the model is shown (``request_words``: the words less what they only
    say about the path now), which is the instruction itself unless it states a problem.
    """
    return describe_environment(case), "INSTRUCTION: " + request_words(case.instruction, case.scene.names())


def replay_settings(axes: str, read_against_words: bool = True, near_rule: str = "zone") -> SessionSettings:
    """The session of a replay: the stored run's axes, no repair round, no format retry."""
    return SessionSettings(axes=AXIS_CONVENTIONS[axes], repair_attempts=0, format_retries=0,
                           read_against_words=read_against_words, near_rule=near_rule)  # fmt: skip


def _answer_after_readers(record: dict[str, Any]) -> str:
    """The stored plan and code as an answer: what a result that does not keep the model's own gives."""
    plan = " ".join(f"{i}) {step}" for i, step in enumerate(record.get("high_level_plan") or [], start=1))
    return answer_json(plan or "1) (no plan)", record.get("code") or "")


def _stored_results(folder: Path) -> dict[str, tuple[str, str]]:
    """(axes, answer) of each case a bench output folder holds a result of, by case key."""
    return {
        key: (
            (record.get("settings") or {}).get("axes", "paper"),
            record.get("answer") or _answer_after_readers(record),
        )
        for key, record in stored_results(folder)
    }


def _kept_answers(path: Path) -> dict[str, tuple[str, str]]:
    """(axes, answer) by case key from a file of kept answers (``benchmarks/keep_answers.py``)."""
    lines = [json.loads(line) for line in path.read_text().splitlines() if line.strip()]
    return {line["case"]: (line.get("axes", "paper"), line["answer"]) for line in lines}


def main() -> None:
    """Replay every stored answer and write the new results, summary and report."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("stored", type=Path, help="a bench output folder, or a file of kept answers")
    parser.add_argument("cases", nargs="+", type=Path)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--memory", type=Path, default=None,
                        help="recall from this bank of remembered examples, as the stored run did "
                        "(bench --memory)")  # fmt: skip
    parser.add_argument("--no-readers", action="store_true",
                        help="run the answers as they are, without reading them against the words "
                        "(read_against_words off)")  # fmt: skip
    parser.add_argument("--near-rule", choices=CHOICES["near_rule"], default="zone",
                        help="what near an object means to a speed change (bench --near-rule)")  # fmt: skip
    args = parser.parse_args()
    if args.out.exists() and any(args.out.iterdir()):
        parser.error(f"{args.out} is not empty: the runner would keep its results instead of replaying; "
                     "give a new folder")  # fmt: skip
    stored = _kept_answers(args.stored) if args.stored.is_file() else _stored_results(args.stored)
    answers, replayed, axes = [], [], "paper"
    for case in discover_cases(args.cases):
        if case.key not in stored:
            continue
        axes, answer = stored[case.key]
        answers.append((request_key(load_case(case.path)), answer))
        replayed.append(case)
    settings = replay_settings(axes, read_against_words=not args.no_readers, near_rule=args.near_rule)
    config = BenchConfig(out_dir=args.out, session=settings, memory=args.memory)
    records = run_benchmark(replayed, StoredAnswers(answers), config)
    write_report(args.out, records)
    print(f"replayed {len(records)} stored answers -> {args.out}")


if __name__ == "__main__":
    main()

"""Sessions and memory: approval keeps the answer, a failure or a read-only bank keeps nothing, a
correction replaces what was kept, and the next session in other words is shown it first."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

from click.testing import CliRunner

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.chain import AdaptationChain
from trajadapt.cli import cli
from trajadapt.memory import MemoryBank
from trajadapt.model.case import Case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings

CLOSER = (
    "t = get_trajectory()\nt = move_closer(t, detect_objects('Red Mug'), 'a bit')\nmodified_trajectory = t"
)
AWAY = "t = get_trajectory()\nt = move_away(t, detect_objects('Red Mug'), 0.1)\nmodified_trajectory = t"
BROKEN = "t = get_trajectory()\nmodified_trajectory = t[0]"


def answer(plan: str, code: str) -> str:
    return json.dumps({"high_level_plan": plan, "python_code": code})


def session(case: Case, sandbox: Sandbox, bank: MemoryBank | None, *answers: str) -> AdaptationSession:
    settings = SessionSettings(repair_attempts=0, read_against_words=False)
    return AdaptationSession(case, ScriptedBackend(answers=answers), sandbox, settings, memory=bank)


def test_an_approved_result_is_remembered_and_shown_first_next_time(
    simple_case: Case, sandbox: Sandbox, tmp_path: Path
) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    first = session(
        simple_case.with_instruction("hug the Red Mug"), sandbox, bank, answer("1) Closer.", CLOSER)
    )
    first.draft()
    result = first.approve()
    assert (
        result.ok
        and result.remembered_as
        and result.to_dict()["memory"]["remembered_as"] == result.remembered_as
    )
    later = session(
        simple_case.with_instruction("please hug the box"), sandbox, bank, answer("1) Closer.", CLOSER)
    )
    assert later.recalled == (result.remembered_as,)
    assert "hug the box" in later.messages[1].content  # the example, with this scene's object
    assert "detect_objects('box')" in later.messages[1].content


def test_a_failed_result_and_a_read_only_bank_keep_nothing(
    simple_case: Case, sandbox: Sandbox, tmp_path: Path
) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    failing = session(simple_case, sandbox, bank, answer("1) Broken.", BROKEN))
    failing.draft()
    assert not failing.approve().ok
    reading = session(
        simple_case,
        sandbox,
        MemoryBank(tmp_path / "memory.jsonl", read_only=True),
        answer("1) Closer.", CLOSER),
    )
    reading.draft()
    assert reading.approve().ok
    assert bank.examples() == []


def test_a_correction_replaces_what_the_session_remembered(
    simple_case: Case, sandbox: Sandbox, tmp_path: Path
) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    chain = AdaptationChain(
        simple_case.with_instruction("keep clear of the Red Mug"), ScriptedBackend(answers=[answer("1) Closer.", CLOSER), answer("1) Away.", AWAY)]),
        sandbox, SessionSettings(repair_attempts=0, read_against_words=False), memory=bank,
    )  # fmt: skip
    chain.draft()
    chain.approve()
    chain.feedback("no, away from it", on="original")
    chain.approve()
    (kept,) = bank.examples()
    assert "move_away" in kept.code and kept.instruction == "keep clear of the <object 1>"


def test_a_recalled_approved_program_is_not_rewritten_by_the_word_readers(
    simple_case: Case, sandbox: Sandbox, tmp_path: Path
) -> None:
    """'take a breather over it' has no pause word the readers know; the user's own approved program keeps its wait."""
    program = "t = get_trajectory()\nt = append_segment(t, detect_objects('box'))\nt = wait(t, 'goal', 5)\nmodified_trajectory = t"
    bank = MemoryBank(tmp_path / "memory.jsonl")
    bank.remember(
        "after the goal, go to the box and take a breather over it",
        "1) To the box. 2) Hover.",
        program,
        ["box"],
    )
    case = simple_case.with_instruction("after the goal, go to the box and take a breather over it")
    readers_on = replace(SessionSettings(repair_attempts=0), read_against_words=True)
    kept = AdaptationSession(
        case,
        ScriptedBackend(answers=[answer("1) To the box. 2) Hover.", program)]),
        sandbox,
        readers_on,
        memory=bank,
    )
    assert "wait(t, 'goal', 5)" in kept.draft().code
    fresh = AdaptationSession(
        case, ScriptedBackend(answers=[answer("1) To the box. 2) Hover.", program)]), sandbox, readers_on
    )
    assert "wait(" not in fresh.draft().code  # without the memory the readers leave the pause out


def test_adapt_remembers_unless_told_not_to_and_examples_manages_the_bank(tmp_path: Path) -> None:
    case = tmp_path / "case.json"
    case.write_text(json.dumps({"trajectory": [[0.0, 0.1 * k, 0.5, 0.2] for k in range(11)],
                                "objects": [{"name": "box", "x": 0.2, "y": 0.5, "z": 0.5}],
                                "instruction": "go left by 0.1"}))  # fmt: skip
    answers = tmp_path / "answers.json"
    left = answer(
        "1) Left by 0.1.", "t = get_trajectory()\nt = shift(t, 'left', 0.1)\nmodified_trajectory = t"
    )
    answers.write_text(json.dumps([left, left]))
    runner = CliRunner()
    base = ["adapt", str(case), "-b", "scripted", "-o", "answers", str(answers), "--yes", "--no-log"]
    off = runner.invoke(cli, [*base, "--no-memory", "--out", str(tmp_path / "a.result.json")])
    assert off.exit_code == 0, off.output
    assert "No remembered examples" in runner.invoke(cli, ["examples", "list"]).output
    on = runner.invoke(cli, [*base, "--out", str(tmp_path / "b.result.json")])
    assert on.exit_code == 0 and "remembered as example" in on.output, on.output
    listing = runner.invoke(cli, ["examples", "list"]).output
    example_id = listing.split()[0]
    assert "go left by 0.1" in listing
    shown = runner.invoke(cli, ["examples", "show", example_id[:4]]).output
    assert "shift(t, 'left', 0.1)" in shown
    exported = runner.invoke(cli, ["examples", "export", str(tmp_path / "bank.jsonl")])
    assert exported.exit_code == 0 and "Wrote 1 example" in exported.output
    removed = runner.invoke(cli, ["examples", "remove", example_id])
    assert (
        removed.exit_code == 0 and "No remembered examples" in runner.invoke(cli, ["examples", "list"]).output
    )
    imported = runner.invoke(cli, ["examples", "import", str(tmp_path / "bank.jsonl")])
    assert imported.exit_code == 0 and "Imported 1 example" in imported.output
    missing = runner.invoke(cli, ["examples", "show", "zzzz"])
    assert missing.exit_code != 0 and "no example with id 'zzzz'" in missing.output


def test_a_remembered_program_is_kept_as_approved_only_for_a_request_it_answers_in_full(
    simple_case: Case, sandbox: Sandbox, tmp_path: Path
) -> None:
    """Session 13: a program remembered for "keep a smaller distance" is no approval of "keep a larger
    distance" (or of "rise and keep a smaller distance"): the readers read it against the words."""
    bank = MemoryBank(tmp_path / "memory.jsonl")
    bank.remember("keep a smaller distance from the Red Mug", "1) Closer.", CLOSER, ["Red Mug"])
    settings = SessionSettings(repair_attempts=0)

    def drafted(instruction: str) -> str:
        case = simple_case.with_instruction(instruction)
        later = AdaptationSession(case, ScriptedBackend(answers=[answer("1) Closer.", CLOSER)]), sandbox,
                                  settings, memory=bank)  # fmt: skip
        return later.draft().code

    assert "move_closer" in drafted("stay a little nearer to the Red Mug")  # the same request: kept
    assert "move_away" in drafted("leave a wider gap to the Red Mug")  # the opposite: read again


def test_the_very_same_words_get_the_remembered_answer_without_asking_the_model(
    simple_case: Case, sandbox: Sandbox, tmp_path: Path
) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    corrected = session(simple_case.with_instruction("stay clear of the Red Mug"), sandbox, bank,
                        answer("1) Away.", AWAY))  # fmt: skip
    corrected.draft()
    kept = corrected.approve().remembered_as
    backend = ScriptedBackend(answers=[])  # the model has nothing to say
    settings = SessionSettings(repair_attempts=0, read_against_words=False)
    again = AdaptationSession(simple_case.with_instruction("Stay clear of  the Red Mug."), backend, sandbox,
                              settings, memory=bank)  # fmt: skip
    plan = again.draft()
    assert plan.code.strip() == AWAY and backend.requests == []
    assert again.turns[0].completion is not None and again.turns[0].completion.model == f"memory:{kept}"
    other_words = session(simple_case.with_instruction("keep away from the Red Mug"), sandbox, bank,
                          answer("1) Closer.", CLOSER))  # fmt: skip
    assert (
        other_words.draft().code.strip() == CLOSER
    )  # other words: the model answers, the example only shown

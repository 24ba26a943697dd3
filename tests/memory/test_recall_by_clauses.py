"""Examples chosen by clauses and by what the words ask (``retrieval=clauses``, opt-in): every clause
of a compound instruction gets its own example, the same request in other words is read the same,
and ``by="words"`` (the default) is the plain BM25 ranking exactly."""

from __future__ import annotations

from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.llm.example_bank import default_bank
from trajadapt.memory import choose_examples
from trajadapt.memory.meaning import asked_meanings
from trajadapt.memory.recall import shipped_bank
from trajadapt.model.case import Case
from trajadapt.readers.clause_split import split_clauses
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings

COMPOUND = [
    ("slow down near the crate and move a bit upwards", ["crate"]),
    ("get closer to the plant and keep a steady speed of 0.3", ["plant"]),
    ("drift right by 0.1, then wait at the goal for 4 steps", []),
    ("stay away from the oven, and go faster in the second half", ["oven"]),
    ("lower the path by 0.2 and finish at the sink", ["sink"]),
]


@pytest.mark.parametrize(("words", "names"), COMPOUND)
def test_each_clause_of_a_compound_instruction_gets_its_best_example(words: str, names: list[str]) -> None:
    clauses = split_clauses(words, names)
    assert len(clauses) == 2
    chosen = choose_examples(words, 3, names, by="clauses")
    bank = shipped_bank("clauses")
    for clause in clauses:
        assert bank.examples[bank.ranked(clause, names)[0]] in chosen, clause


@pytest.mark.parametrize(("words", "names"), COMPOUND)
def test_the_chosen_are_shown_in_their_order_for_the_whole_instruction(words: str, names: list[str]) -> None:
    bank = shipped_bank("clauses")
    order = bank.ranked(words, names)
    positions = [
        order.index(bank.examples.index(example))
        for example in choose_examples(words, 3, names, by="clauses")
    ]
    assert positions == sorted(positions)


@settings(max_examples=60, deadline=None)
@given(st.text(alphabet=st.sampled_from("abcdefghij klmnop,.0123"), max_size=60), st.integers(0, 6))
def test_by_words_is_the_plain_bm25_ranking(words: str, k: int) -> None:
    assert choose_examples(words, k, [], by="words") == default_bank().nearest(words, k)


@pytest.mark.parametrize(
    ("first", "second", "meaning"),
    [
        ("go quicker when you pass the lamp", "hurry as you go by the lamp", "@faster"),
        ("stay further from the box", "keep a larger distance from the box", "@away"),
        ("approach the kettle", "come nearer to the kettle", "@closer"),
        ("lift the final point", "raise the end of the path", "@goal"),
    ],
)
def test_two_wordings_of_one_request_share_its_meaning(first: str, second: str, meaning: str) -> None:
    assert meaning in asked_meanings(first) and meaning in asked_meanings(second)


def test_a_pace_particle_is_no_direction() -> None:
    assert asked_meanings("slow down near the lamp") == ["@slower"]
    assert "@up" not in asked_meanings("speed up in the middle")


def test_the_setting_chooses_the_first_prompts_examples(simple_case: Case, sandbox: Sandbox) -> None:
    words = "slow down near the box and move a bit upwards"
    case = replace(simple_case, instruction=words)
    prompts = {}
    for by in ("words", "clauses"):
        settings = SessionSettings(retrieval=by)
        session = AdaptationSession(case, ScriptedBackend(answers=()), sandbox, settings)
        expected = choose_examples(words, settings.examples, case.scene.names(), by=by)
        assert session.messages[1].content.count("Instruction: ") == len(expected)
        assert all(example.instruction in session.messages[1].content for example in expected)
        prompts[by] = session.messages[1].content
    assert prompts["words"] != prompts["clauses"]

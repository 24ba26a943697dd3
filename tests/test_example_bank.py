"""The example bank: every example is a valid answer, every skill is shown, and retrieval finds the family."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from trajadapt.llm.answer_grammar import answer_grammar, is_statement_skill
from trajadapt.llm.example_bank import Example, ExampleBank, default_bank, read_examples, terms
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import first_messages
from trajadapt.skills import SKILLS


def test_every_example_is_in_the_grammar_of_its_own_objects() -> None:
    for example in default_bank().examples:
        grammar = answer_grammar(tuple(example.object_names))
        answer = json.dumps({"high_level_plan": example.high_level_plan, "python_code": example.code})
        assert grammar.matches(answer), example.instruction
        assert example.render().endswith(answer)


def test_every_skill_that_changes_the_path_is_shown_by_an_example() -> None:
    used = {name for e in default_bank().examples for name in re.findall(r"([a-z_]+)\(", e.code)}
    missing = {f.__name__ for f in SKILLS if is_statement_skill(f)} - used
    assert not missing


def test_no_instruction_of_the_dev_benchmark_is_in_the_bank(ovita_dir: Path) -> None:
    bank = {" ".join(e.instruction.lower().split()) for e in default_bank().examples}
    for case in ovita_dir.rglob("*.json"):
        record = json.loads(case.read_text())
        if isinstance(record, dict) and "instruction" in record:
            assert " ".join(str(record["instruction"]).lower().split()) not in bank, case


@pytest.mark.parametrize(
    ("instruction", "names", "expected_call"),
    [
        ("walk a good deal closer to the giraffe", ["giraffe"], "move_closer"),
        ("steer well away from the red bucket", ["red bucket"], "move_away"),
        ("be slower when passing by the oven", ["oven"], "scale_speed"),
        ("take a break of 3 timesteps near the toaster", ["toaster"], "wait"),
        ("make a circle around the post", ["post"], "circle_around"),
        ("move to the bottom", [], "shift"),
        ("keep at least 0.25 from the rack", ["rack"], "avoid"),
        ("end the path 0.1 lower", [], "shift_goal"),
    ],
)
def test_retrieval_finds_the_family_of_a_paraphrase(
    instruction: str, names: list[str], expected_call: str
) -> None:
    nearest = default_bank().nearest(instruction, 3, names)
    assert any(f"t = {expected_call}(" in example.code for example in nearest), [
        e.instruction for e in nearest
    ]


def test_object_names_are_left_out_of_the_query() -> None:
    assert terms("pass closer to the slow cooker", ["slow cooker"]) == ["pass", "close", "pass+close"]


def test_an_object_name_is_left_out_only_as_whole_words() -> None:
    assert terms("move nearer to the ear, then pass the bow", ["ear", "bow"]) == [
        "close",
        "pass",
        "close+pass",
    ]
    assert "elbow" in terms("bend the elbow gently", ["bow"])


def test_a_small_bank_ranks_by_overlap_and_k_zero_is_empty() -> None:
    bank = ExampleBank([Example("go left", "1) a", "x"), Example("go much faster", "1) b", "y")])
    assert [e.code for e in bank.nearest("a lot faster please", 1)] == ["y"]
    assert bank.nearest("go left", 0) == []


def test_a_broken_bank_line_is_named() -> None:
    with pytest.raises(ValueError, match="line 2"):
        read_examples(['{"instruction": "a", "high_level_plan": "b", "code": "c"}', '{"instruction": 1}'])


def test_examples_follow_the_fixed_prefix_in_skills_mode_only(simple_case) -> None:  # type: ignore[no-untyped-def]
    axes = AXIS_CONVENTIONS["paper"]
    without = first_messages(simple_case, axes, "skills", examples=0)
    with_examples = first_messages(simple_case, axes, "skills", examples=3)
    assert without[0] == with_examples[0]  # the cached system prefix does not change
    assert with_examples[1].content.startswith("EXAMPLES CLOSE TO THIS INSTRUCTION")
    assert with_examples[1].content.count("Instruction: ") == 3
    assert "EXAMPLES CLOSE" not in first_messages(simple_case, axes, "paper", examples=3)[1].content

"""Reading plan and code out of LLM answers in the shapes models really produce."""

from __future__ import annotations

import json

import pytest

from trajadapt.errors import AnswerParseError
from trajadapt.llm.answer import parse_answer

CODE = "traj = get_trajectory()\nmodified_trajectory = traj\n"


def test_plain_json() -> None:
    plan = parse_answer(json.dumps({"high_level_plan": "1) Keep start. 2) Move goal.", "python_code": CODE}))
    assert plan.steps == ("Keep start.", "Move goal.")
    assert plan.code == CODE


def test_fenced_json_with_prose_around() -> None:
    answer = (
        "Sure! Here it is:\n```json\n"
        + json.dumps({"high_level_plan": ["a", "b"], "python_code": CODE})
        + "\n```\nDone."
    )
    plan = parse_answer(answer)
    assert plan.steps == ("a", "b") and plan.code == CODE


def test_paper_style_single_quotes_and_spaced_key() -> None:
    answer = "{'high_level_plan': '1) Shift left\\n2) Smooth', 'Python code': 'x = 1\\nmodified_trajectory = get_trajectory()'}"
    plan = parse_answer(answer)
    assert plan.steps == ("Shift left", "Smooth")
    assert plan.code == "x = 1\nmodified_trajectory = get_trajectory()\n"


def test_code_with_escaped_newlines_as_literal_text() -> None:
    raw = '{"high_level_plan": "1) a", "python_code": "x = 1\\\\ny = 2"}'
    assert parse_answer(raw).code == "x = 1\ny = 2\n"


def test_code_fenced_inside_the_json_string() -> None:
    answer = json.dumps({"high_level_plan": "1) a", "python_code": "```python\n" + CODE + "```"})
    assert parse_answer(answer).code == CODE


def test_raw_newlines_inside_json_strings() -> None:
    answer = (
        '{"high_level_plan": "1) a\n2) b", "python_code": "x = 1\nmodified_trajectory = get_trajectory()"}'
    )
    plan = parse_answer(answer)
    assert plan.steps == ("a", "b") and plan.code.startswith("x = 1\n")


def test_fenced_python_without_json() -> None:
    answer = "Plan:\n1) Keep the start.\n2) Shift the goal.\n\n```python\n" + CODE + "```\n"
    plan = parse_answer(answer)
    assert plan.code == CODE
    assert plan.steps[-2:] == ("Keep the start.", "Shift the goal.")


@pytest.mark.parametrize(
    "answer", ["I cannot help with that.", "", '{"high_level_plan": "1) a"}', "```json\n{}\n```"]
)
def test_no_code_is_a_clear_error(answer: str) -> None:
    with pytest.raises(AnswerParseError, match="code"):
        parse_answer(answer)

"""The plan's steps passed on as the answer is written, whatever the pieces' boundaries."""

from __future__ import annotations

import json

from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.llm.plan_stream import PlanStream

ANSWER = json.dumps(
    {
        "high_level_plan": '1) Find the "red" box. 2) Move the path left by 0.2.\n3) Slow down near it.',
        "python_code": "t = get_trajectory()\nmodified_trajectory = t",
    }
)


def streamed(text: str, cuts: list[int]) -> list[tuple[int, str]]:
    """(characters fed so far, step) for each step passed on."""
    seen: list[tuple[int, str]] = []
    fed = 0
    stream = PlanStream(lambda step: seen.append((fed, step)))
    bounds = sorted({0, len(text), *(c % (len(text) + 1) for c in cuts)})
    for start, end in zip(bounds, bounds[1:], strict=False):
        fed = end
        stream.feed(text[start:end])
    return seen


STEPS = ['1) Find the "red" box.', "2) Move the path left by 0.2.", "3) Slow down near it."]


@settings(deadline=None)
@given(st.lists(st.integers(min_value=0, max_value=10_000), max_size=40))
def test_each_step_is_passed_on_once_in_order_however_the_answer_is_cut(cuts: list[int]) -> None:
    assert [step for _, step in streamed(ANSWER, cuts)] == STEPS


def test_a_step_is_passed_on_as_soon_as_the_next_one_begins() -> None:
    seen = streamed(ANSWER, list(range(len(ANSWER))))
    first_fed, first = seen[0]
    assert first == '1) Find the "red" box.'
    assert ANSWER[:first_fed].endswith("2) ")
    assert seen[-1][1] == "3) Slow down near it."
    assert seen[-1][0] < ANSWER.index("python_code")


def test_a_plan_without_numbers_is_one_step_and_other_text_none() -> None:
    assert [s for _, s in streamed('{"high_level_plan": "Go left.", "python_code": ""}', [5, 30])] == [
        "Go left."
    ]
    assert streamed("not an answer at all", [3]) == []

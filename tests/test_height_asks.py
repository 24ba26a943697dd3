"""A height given with its relation; a height step with the wrong relation gets the asked one."""

from __future__ import annotations

import pytest

from trajadapt.readers.height_asks import asked_heights, relate_heights

CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("words", "heights"),
    [
        ("fly at an altitude of 2.5 over the field", [("set_height", 2.5)]),
        ("hover at 1 near the lamp", [("set_height", 1.0)]),
        ("never go higher than 3", [("stay_below", 3.0)]),  # a negation turns the relation round
        ("do not exceed 3 and stay above 0.5", [("stay_below", 3.0), ("stay_above", 0.5)]),
        ("stay at least 0.2 over the floor", [("stay_above", 0.2)]),
        ("keep under 1.2", [("stay_below", 1.2)]),
    ],
)
def test_the_words_around_a_height_say_its_relation(words: str, heights: list[tuple[str, float]]) -> None:
    assert asked_heights(words) == heights


def test_a_height_step_with_the_asked_number_and_another_relation_is_replaced() -> None:
    code, notes = relate_heights(CODE.format(step="t = stay_below(t, 0.4)"), ["cruise at a height of 0.4"])
    assert "t = set_height(t, 0.4)" in code.splitlines()
    assert "asks for a height of 0.4" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = stay_below(t, 0.4)", "stay below 0.4"),  # already right
        ("t = stay_below(t, 0.3)", "cruise at a height of 0.4"),  # another number
        ("t = stay_below(t, 0.4)", "fly at 0.4 and never under 0.2"),  # two heights
        ("t = set_height(t, 0.4, keep_goal=False)", "stay below 0.4"),  # more than a height
    ],
)
def test_right_relations_other_numbers_and_two_heights_stay(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert relate_heights(code, [words]) == (code, [])

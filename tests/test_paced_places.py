"""A step that moves the path by an object the words only place a pace near is left out."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.paced_places import leave_out_moves_of_paced_places

NAMES = ["kettle", "lamp", "red mug"]
SPEED = "t = scale_speed(t, 0.65, near=detect_objects('kettle'))"


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "step"),
    [
        (
            "ease off a little whenever you are close to the kettle",
            "t = pass_through(t, detect_objects('kettle'), 1)",
        ),
        ("take it slower in the vicinity of the kettle", "t = avoid(t, detect_objects('kettle'), 0.2)"),
        ("go faster as you pass by the kettle", "t = move_closer(t, detect_objects('kettle'))"),
        (
            "reduce the speed around the kettle, then go left",
            "t = keep_side(t, 'left', detect_objects('kettle'))",
        ),
    ],
)
def test_a_move_by_an_object_only_a_pace_is_placed_near_is_left_out(words: str, step: str) -> None:
    code, notes = leave_out_moves_of_paced_places(program(step, SPEED), [words], NAMES)
    assert code == program(SPEED)
    assert notes == [
        f"left out `{step}`: the instruction only places a pace near kettle, it asks no move by it"
    ]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("go slowly through the kettle", "t = pass_through(t, detect_objects('kettle'), 1)"),  # asked
        ("slow down near the kettle and keep away from it", "t = avoid(t, detect_objects('kettle'), 0.2)"),
        (
            "decelerate close to the kettle, staying left of it",
            "t = keep_side(t, 'left', detect_objects('kettle'))",
        ),
        ("go to the kettle, slowing down near the kettle", "t = reach(t, detect_objects('kettle'))"),
        ("slow down near the kettle; pass over the kettle", "t = pass_over(t, detect_objects('kettle'))"),
        ("slow down near the lamp", "t = avoid(t, detect_objects('kettle'), 0.2)"),  # another object
        (
            "slower near the kettle and the lamp",
            "t = avoid(t, [detect_objects('kettle'), detect_objects('lamp')], 0.2)",
        ),
    ],
)
def test_a_move_the_words_ask_or_of_another_object_stays(words: str, step: str) -> None:
    code = program(step, SPEED)
    assert leave_out_moves_of_paced_places(code, [words], NAMES) == (code, [])


def test_without_a_speed_step_near_the_object_the_move_stays_for_object_asks() -> None:
    code = program("t = avoid(t, detect_objects('kettle'), 0.2)", "t = scale_speed(t, 0.65)")
    assert leave_out_moves_of_paced_places(code, ["slow down near the kettle"], NAMES) == (code, [])


def test_in_the_stage_the_note_names_the_reader() -> None:
    code, notes = read_against_words(
        program(
            "t = pass_through(t, detect_objects('red mug'), 1)",
            "t = scale_speed(t, 1.4, near=detect_objects('red mug'))",
        ),
        ["hurry up when going past the red mug"],
        NAMES,
    )
    assert "pass_through" not in code and "scale_speed(t, 1.4, near=detect_objects('red mug'))" in code
    assert [n.reader for n in notes] == ["paced-places"]


def test_the_midpoint_of_an_object_and_itself_is_that_object() -> None:
    code, notes = leave_out_moves_of_paced_places(
        program(
            "t = pass_through(t, midpoint(detect_objects('kettle'), detect_objects('kettle')))",
            "t = scale_speed(t, 0.65, near=detect_objects('kettle'))",
        ),
        ["take it gently around the kettle"],
        NAMES,
    )
    assert code == program("t = scale_speed(t, 0.65, near=detect_objects('kettle'))") and notes

"""An amount the user gave for a direction, put back where the code wrote a vague word."""

from __future__ import annotations

import pytest

from trajadapt.readers.clause_amounts import direction_amounts
from trajadapt.readers.stated_amounts import use_stated_amounts

CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("words", "amounts"),
    [
        ("climb upwards by 0.5 while passing a bit closer to the lamp", {"up": 0.5}),
        ("go left by 20, then lower by 5", {"left": 20.0, "down": 5.0}),
        # one clause (split_clauses keeps "and left" with "go up", as "0.5 to the left and 0.3 up"):
        # two directions, one amount, so neither is given it
        ("go up and left by 0.2", {}),
        ("go up by 0.1, then left by 0.2", {"up": 0.1, "left": 0.2}),
        # a number beside its direction, without "by" (words.directed_numbers)
        ("drift 0.3 towards the right, then descend 0.05", {"right": 0.3, "down": 0.05}),
        ("carry on 1.2 further back", {"back": 1.2}),
        ("raise it 0.3", {"up": 0.3}),  # the thing moved between the verb and its amount
        ("lift the middle by about 0.3", {"up": 0.3}),  # a rough amount is the amount
        ("raise the whole path about 0.1", {"up": 0.1}),  # a rough amount right after what moves
        ("go left by roughly 0.2, then drop by ~0.1", {"left": 0.2, "down": 0.1}),
        ("lower the entire route 0.05", {"down": 0.05}),
        ("raise it 2 times", {}),  # a count
        ("shift the first 4 waypoints up", {}),  # a count, not an amount
        ("go left or right by 0.2", {}),  # two directions in one clause
        ("go left by 0.2 or by 0.3", {}),  # two numbers
        ("go left by 0.2. go left by 0.3", {}),  # two amounts for one direction
        # several directions in one clause, each right after its own number
        ("set the end point 0.1 further right and 0.05 lower", {"right": 0.1, "down": 0.05}),
        ("move it 20 cm forward and 0.1 up", {"front": 0.2, "up": 0.1}),
        ("go 0.1 to the left and up", {}),  # up has no number of its own
    ],
)
def test_each_direction_gets_the_one_number_its_clause_gives(words: str, amounts: dict[str, float]) -> None:
    assert direction_amounts(words) == amounts


@pytest.mark.parametrize(
    ("step", "expected"),
    [
        ("t = shift(t, 'upwards', 'slightly')", "t = shift(t, 'upwards', 0.5)"),
        ("t = shift_goal(t, 'up')", "t = shift_goal(t, 'up', 0.5)"),
        ("t = lift_middle(t, 'up')", "t = lift_middle(t, 'up', 0.5)"),
        (
            "t = shift_part(t, 'up', -0.5, part='middle')",
            "t = shift_part(t, 'up', 0.5, part='middle')",
        ),  # a sign slip
    ],
)
def test_a_vague_or_missing_amount_becomes_the_stated_one_with_a_note(step: str, expected: str) -> None:
    code, notes = use_stated_amounts(
        CODE.format(step=step), ["climb upwards by 0.5 a bit closer to the lamp"]
    )
    assert expected in code.splitlines()
    assert notes == [f"`{step}` -> `{expected}`: the instruction gives up the amount 0.5"]


@pytest.mark.parametrize(
    "step",
    [
        "t = shift(t, 'up', 0.3)",  # a number of its own
        "t = shift(t, 'up', -0.3)",  # a negative number of its own, not the stated one
        "t = shift(t, 'left', 'slightly')",  # another direction
        "t = shift(t, 'up', 'a bit')\nt = shift_goal(t, 'up')",  # which one?
    ],
)
def test_steps_with_a_number_another_direction_or_a_twin_stay(step: str) -> None:
    code = CODE.format(step=step)
    assert use_stated_amounts(code, ["climb upwards by 0.5"]) == (code, [])


@pytest.mark.parametrize(
    ("words", "step", "expected"),
    [
        (
            "drift a little to the left, and past the goal carry on 0.3 further forward",
            "t = shift(t, 'left', 0.3)",
            "t = shift(t, 'left', 'a little')",
        ),
        (
            "nudge the start 0.2 up; the route should sit lower",
            "t = shift(t, 'down', 0.2)",
            "t = shift(t, 'down')",
        ),
    ],
)
def test_a_number_the_words_give_to_another_direction_is_not_this_steps(words, step, expected):
    code, notes = use_stated_amounts(CODE.format(step=step), [words])
    assert code.splitlines()[1] == expected and "not" in notes[0]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        (
            "once at the goal, back up by 1.5",
            "t = shift(t, 'up', 1.5)",
        ),  # 'up' is said nowhere: the step for 'back'
        ("go left by 0.2, then up by 0.2", "t = shift(t, 'up', 0.2)"),  # the number is given twice
        ("go up 0.1 and 0.1 to the left", "t = shift(t, 'up', 0.1)"),
    ],
)
def test_a_number_the_words_may_give_to_this_step_stays(words, step):
    assert use_stated_amounts(CODE.format(step=step), [words])[0].splitlines()[1] == step


@pytest.mark.parametrize(
    ("words", "amounts"),
    [
        ("sink the last point by 8 cm", {"down": 0.08}),
        ("nudge it 15 millimetres to the right", {"right": 0.015}),
        ("finish 2 metres further forward", {"front": 2.0}),
        ("go 0.4m to the left, at 0.2 m/s", {"left": 0.4}),  # a speed is no length
        ("drift half a metre to the left", {"left": 0.5}),  # a number said in words (session 31)
        ("climb a meter", {"up": 1.0}),
        ("ease one centimetre back", {"back": 0.01}),
        ("rise a full metre", {"up": 1.0}),
    ],
)
def test_a_length_in_a_metric_unit_is_read_in_metres(words: str, amounts: dict[str, float]) -> None:
    assert direction_amounts(words) == pytest.approx(amounts)


@pytest.mark.parametrize(
    ("words", "step", "given"),
    [
        ("lift the middle 0.3 and finish 0.1 higher", "t = shift_goal(t, 'up')", "t = shift_goal(t, 'up', 0.1)"),
        ("go left by 0.5, then start 0.2 further left", "t = shift_start(t, 'left', 'a bit')",
         "t = shift_start(t, 'left', 0.2)"),
    ],
)  # fmt: skip
def test_an_end_moves_own_amount_where_two_clauses_give_its_direction_two(
    words: str, step: str, given: str
) -> None:
    code = CODE.format(step=step)
    assert given in use_stated_amounts(code, [words])[0].splitlines()

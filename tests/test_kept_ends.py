"""An end the words keep where it is stays there (readers.kept_ends), whatever step moved it.

Written from fresh-a/fresh-b (new instructions: "keep both ends in place", "keep the goal where it
is"); the wordings here are none of any set's.
"""

from __future__ import annotations

import pytest

from trajadapt.readers.end_words import kept_ends
from trajadapt.readers.kept_ends import keep_kept_ends


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def steps_after(words: str, *steps: str) -> list[str]:
    return keep_kept_ends(program(*steps), [words])[0].splitlines()[1:-1]


@pytest.mark.parametrize(
    ("words", "ends"),
    [
        ("with the endpoints pinned, push the middle up", {"start", "goal"}),
        ("the two ends stay put", {"start", "goal"}),
        ("the ends stay put while you weave", {"start", "goal"}),
        ("don't touch the start or the goal", {"start", "goal"}),
        ("keep both the beginning and the destination fixed", {"start", "goal"}),
        ("leave the start where it was", {"start"}),
        # a word of degree before the state (session 31; fresh-j's "exactly where they are")
        ("keep the goal precisely where it is", {"goal"}),
        ("hold the start and end points just as they were", {"start", "goal"}),
        ("keep the goal speed the same", set()),  # a pace of an end, not its place
        ("keep the start fixed. now move the start left", set()),  # taken back by a later request
        # either end is both; a drone's landing spot or touchdown is its goal, its take-off its start
        ("do not move either end", {"start", "goal"}),
        ("fix either end point", {"start", "goal"}),
        ("keep the landing spot where it is", {"goal"}),
        ("the touchdown point should stay exactly where it is", {"goal"}),
        ("leave the take-off point as it was", {"start"}),
        ("with the same start and end", {"start", "goal"}),
        ("land with the original goal", {"goal"}),
        ("end with the same speed", set()),  # a pace, no end named after "same"
        ("keep the landing gear where it is", set()),  # landing names a place only as a spot or point
        ("then finish where you normally would", {"goal"}),
        ("stop where the robot usually stops", {"goal"}),
        ("end where you like", set()),
        ("neither end is fixed: shift everything left", set()),  # a negation before the end
        ("with the start and end positions left unchanged, pull the middle left", {"start", "goal"}),
        # a modal before the keeping verb; "alone" as a state (fresh-p)
        ("push it forward, but the goal has to stay exactly where it is", {"goal"}),
        ("the start needs to remain fixed", {"start"}),
        ("the end point must be kept unchanged", {"goal"}),
        ("leave the goal alone", {"goal"}),
        ("the goal should be the lamp", set()),  # a new goal, not a kept one
        ("neither end has to stay fixed", set()),
        # said without a verb (fresh-q)
        ("go slower past the fan; goal unchanged", {"goal"}),
        ("start and end fixed, bow the middle left", {"start", "goal"}),
        ("move the goal a fixed distance left", set()),
        ("the end point stays as is", {"goal"}),
    ],
)
def test_the_ends_the_words_keep(words: str, ends: set[str]) -> None:
    assert kept_ends(words.split(". ")) == ends


def test_a_stop_beside_a_kept_goal_the_words_never_ask_is_left_out() -> None:
    written = ("t = stop_at(t, midpoint(detect_objects('start'), detect_objects('goal')))",)
    assert steps_after("stay above 0.3 through the middle; the end point stays as is", *written) == []
    asked = ("t = stop_at(t, detect_objects('box'))",)  # a stop the words ask stays (the goal put back)
    assert asked[0] in steps_after("stop at the box, and keep the goal where it is", *asked)


def test_a_step_that_moves_only_a_kept_end_is_left_out() -> None:
    assert steps_after("arc the middle left, ends untouched... the ends stay put", "t = lift_middle(t, 'left')",
                       "t = shift_goal(t, 'left', 0.1)") == ["t = lift_middle(t, 'left')"]  # fmt: skip


def test_a_kept_end_another_step_may_move_is_put_back_last() -> None:
    assert steps_after("tilt it 20 degrees with the endpoints pinned", "t = rotate(t, 20)") == [
        "t = rotate(t, 20)",
        "t = reach(t, detect_objects('goal'))",
        "t = pass_through(t, detect_objects('start'), 0)",
    ]


@pytest.mark.parametrize(
    "steps",
    [
        ("t = lift_middle(t, 'up', 0.1)",),  # keeps both ends by its promise
        ("t = shift_part(t, 'up', 0.1, 'middle')",),
        ("t = move_away(t, detect_objects('box'))", "t = scale_speed(t, 0.5)"),
    ],
)
def test_steps_that_keep_the_ends_get_nothing(steps: tuple[str, ...]) -> None:
    assert steps_after("keep the goal where it is", *steps) == list(steps)


def test_a_going_on_the_words_ask_beside_a_kept_goal_moves_it_as_asked() -> None:
    steps = ("t = shift(t, 'up')", "t = extend(t, 0.2)")
    assert steps_after("keep the goal where it is, then carry on 0.2 past it", *steps) == list(steps)


def test_a_going_on_nobody_asks_beside_a_kept_goal_is_left_out() -> None:
    steps = ("t = shift(t, 'up')", "t = extend(t, 0.2)")
    assert steps_after("keep the goal where it is", *steps) == [
        "t = shift(t, 'up')",
        "t = reach(t, detect_objects('goal'))",
    ]


def test_a_whole_path_shift_keeps_its_start_so_only_the_goal_is_put_back() -> None:
    assert steps_after("the ends stay put; drift up a bit", "t = shift(t, 'up', 'a bit')") == [
        "t = shift(t, 'up', 'a bit')",
        "t = reach(t, detect_objects('goal'))",
    ]


def test_a_move_of_the_other_end_keeps_this_one() -> None:
    written = ("t = shift_goal(t, 'left', 0.15)", "t = scale_speed(t, 0.65)")
    assert steps_after("move the goal 0.15 left without touching the start", *written) == list(written)


@pytest.mark.parametrize(
    "words",
    [
        "hold a moment by the box, then continue on to the original end point",
        "after the pause keep going towards the same destination",
        "wait near the lamp and finish up as it did before",
        "brush past the lamp, keeping the same goal",  # past an object, not past the goal
    ],
)
def test_a_going_on_towards_the_kept_goal_goes_on_nowhere_past_it(words: str) -> None:
    assert steps_after(words, "t = wait(t, 'middle', 4)", "t = extend(t)") == ["t = wait(t, 'middle', 4)"]


@pytest.mark.parametrize(
    "words",
    [
        "keep the same goal, then carry on beyond the end for 0.1",
        "with the goal where it is, go on past it 0.2 to the left",
        "keep the goal as it is and keep going after reaching it",
    ],
)
def test_a_going_on_past_the_kept_goal_stays(words: str) -> None:
    assert "t = extend(t)" in steps_after(words, "t = extend(t)")


def test_an_end_is_put_back_before_a_closing_limit_that_keeps_the_ends() -> None:
    steps = steps_after(
        "keep the middle low, below 0, then on to the usual end point",
        "t = shift(t, 'down')",
        "t = stay_below(t, 0, keep_ends=True)",
    )
    assert steps == [
        "t = shift(t, 'down')",
        "t = reach(t, detect_objects('goal'))",
        "t = stay_below(t, 0, keep_ends=True)",
    ]


@pytest.mark.parametrize(
    ("words", "ends"),
    [
        ("lower the middle a little, ending at the same spot", {"goal"}),
        ("swing wide of the lamp but finish where it finishes now", {"goal"}),
        ("start from the same point and go left", {"start"}),
        ("stop at the same height as the box", set()),
        ("end at the same spot as the cup", set()),  # a place named: the end goes there
    ],
)
def test_an_end_at_the_same_spot_is_kept(words: str, ends: set[str]) -> None:
    assert kept_ends([words]) == ends

"""An object the words ask the path to end at gets the step that ends it there (readers.end_places).

Written from fresh-c (new instructions: "finish at X", "make X your end point", "wrap up beside X");
the wordings here are none of any set's.
"""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.end_places import asked_end, end_at_asked_places
from trajadapt.skills.events import BESIDE_GAP, WITHIN_SHARE, stop_at

NAMES = ["lamp", "box", "chair", "red cup", "cup"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def steps_after(words: str, *steps: str) -> list[str]:
    return end_at_asked_places(program(*steps), [words], NAMES)[0].splitlines()[1:-1]


@pytest.mark.parametrize(
    ("clause", "place", "skill"),
    [
        ("conclude the run at the lamp", "lamp", "reach"),
        ("land squarely on the box", "box", "reach"),
        ("arrive at the red cup", "red cup", "reach"),
        ("come to rest on the chair", "chair", "reach"),
        ("touch down on the box", "box", "reach"),
        ("park right at the lamp", "lamp", "reach"),
        ("pull up beside the chair", "chair", "stop_at"),
        ("lower the arm onto the box to finish", "box", "reach"),
        ("at the very end head over to the lamp", "lamp", "reach"),
        ("have the lamp be your finishing point", "lamp", "reach"),
        ("the final position should be the box", "box", "reach"),
        ("finish up alongside the chair", "chair", "stop_at"),
        ("wind up close to the lamp", "lamp", "stop_at"),
        # where the path passes nearest the object (fresh-q)
        ("end the motion where the arm gets closest to the red cup", "red cup", "stop_at"),
        ("stop the path where it comes closest to the lamp", "lamp", "stop_at"),
        ("cut it short at the point where it passes nearest to the box", "box", "stop_at"),
        ("have the arm stop where it gets nearest to the lamp rather than carrying on", "lamp", "stop_at"),
    ],
)
def test_an_end_place_is_read_with_the_step_that_makes_it(clause: str, place: str, skill: str) -> None:
    end = asked_end(clause, NAMES)
    assert end is not None and (end.place, end.skill) == (place, skill)


@pytest.mark.parametrize(
    "clause",
    [
        "slow down at the end near the box",  # "end" a noun
        "towards the finish by the lamp go slower",
        "stop at the lamp",  # stop_at's own words, left to the model
        "before arriving at the goal, loop round the box",  # the place is the goal, not the box
        "end at the midpoint of the lamp and the box",  # a point made of two objects
        "make the path end higher",
        "finish at the lamp or the box",  # two objects
        "finally drift closer to the box",  # closer, not onto it
        "slow down near the box at the end",  # a pace placed, no end
    ],
)
def test_words_that_ask_no_end_at_one_object(clause: str) -> None:
    assert asked_end(clause, NAMES) is None


@pytest.mark.parametrize(
    ("clause", "before", "place"),
    [
        ("end there", "bring the gripper to the lamp", "lamp"),  # the object of the clause before
        ("head over to the red cup and finish right there", "", "red cup"),  # named in the clause itself
        ("land there", "fly over to the box", "box"),
    ],
)
def test_an_end_there_is_the_object_named_just_before(clause: str, before: str, place: str) -> None:
    end = asked_end(clause, NAMES, before)
    assert end is not None and (end.place, end.skill) == (place, "reach")


@pytest.mark.parametrize(
    ("clause", "before"),
    [
        ("end there", "go between the lamp and the box"),  # two objects
        ("end there", ""),
        ("coming to rest there", "stop where it passes closest to the box"),  # a rest where the path is
    ],
)
def test_an_end_there_with_no_one_object_before_asks_none(clause: str, before: str) -> None:
    assert asked_end(clause, NAMES, before) is None


def test_beside_an_end_where_the_path_passes_nearest_a_visit_there_leaves() -> None:
    """The end is on the path as it was: a pass through the object would move that nearest point."""
    written = ["t = pass_through(t, detect_objects('cup'))", "t = stop_at(t, detect_objects('cup'))"]
    after = steps_after("end the motion where the arm gets closest to the cup", *written)
    assert after == ["t = stop_at(t, detect_objects('cup'))"]


def test_beside_an_end_where_the_path_passes_nearest_a_clearance_of_it_leaves() -> None:
    written = ["t = avoid(t, detect_objects('lamp'), 0.3)", "t = stop_at(t, detect_objects('lamp'))"]
    after = steps_after("have the arm stop where it gets nearest to the lamp", *written)
    assert after == ["t = stop_at(t, detect_objects('lamp'))"]


def test_a_pause_at_the_end_stays_after_the_stop() -> None:
    written = ["t = wait(t, detect_objects('lamp'), 3)"]
    after = steps_after("stop where it comes closest to the lamp and hold still there for 3 steps", *written)
    assert after == ["t = stop_at(t, detect_objects('lamp'))", "t = wait(t, detect_objects('lamp'), 3)"]


def test_an_end_there_leaves_the_steps_written_for_that_object() -> None:
    written = ["t = pass_over(t, detect_objects('lamp'))", "t = scale_speed(t, 0.65, part='end')"]
    after = steps_after("bring the gripper to the lamp and end there, slower at the end", *written)
    assert after == ["t = reach(t, detect_objects('lamp'))", "t = scale_speed(t, 0.65, part='end')"]


def test_a_missing_end_step_is_added_after_the_moves_and_before_the_speed_steps() -> None:
    steps = steps_after(
        "Bring it closer to the box and conclude at the lamp, slowing down towards the end",
        "t = move_closer(t, detect_objects('box'))",
        "t = speed_profile(t, 'decelerate', start=0.6)",
    )
    assert steps == [
        "t = move_closer(t, detect_objects('box'))",
        "t = reach(t, detect_objects('lamp'))",
        "t = speed_profile(t, 'decelerate', start=0.6)",
    ]


def test_a_step_written_for_the_end_object_alone_gives_way() -> None:
    steps = steps_after(
        "Finish up alongside the chair.", "t = keep_side(t, 'right', detect_objects('chair'))"
    )
    assert steps == ["t = stop_at(t, detect_objects('chair'))"]


def test_the_end_object_leaves_a_list_of_passes() -> None:
    steps = steps_after(
        "Fly above the box and then arrive at the lamp",
        "t = pass_over(t, [detect_objects('box'), detect_objects('lamp')])",
    )
    assert steps == ["t = pass_over(t, detect_objects('box'))", "t = reach(t, detect_objects('lamp'))"]


def test_a_step_of_the_object_another_clause_asks_stays() -> None:
    steps = steps_after(
        "Slow down near the lamp and land on the lamp",
        "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        "t = move_closer(t, detect_objects('lamp'))",
    )
    assert steps == [
        "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        "t = move_closer(t, detect_objects('lamp'))",
        "t = reach(t, detect_objects('lamp'))",
    ]


@pytest.mark.parametrize(
    "step", ["t = reach(t, detect_objects('lamp'))", "t = append_segment(t, detect_objects('lamp'))"]
)
def test_a_step_that_ends_there_already_is_enough(step: str) -> None:
    assert steps_after("terminate at the lamp", step) == [step]


def test_code_beyond_the_skills_is_left_alone() -> None:
    code = program("t[:, 0] += 0.1")
    assert end_at_asked_places(code, ["finish at the lamp"], NAMES) == (code, [])


def test_the_stage_notes_the_added_end() -> None:
    code, notes = read_against_words(
        program("t = shift(t, 'left')"), ["Go left and end up on the box."], NAMES
    )
    assert "t = reach(t, detect_objects('box'))" in code
    assert any(note.reader == "end-places" for note in notes)


def test_a_stop_beside_the_object_comes_after_the_speed_steps() -> None:
    steps = steps_after(
        "keep a steady 0.3 and wind up close to the lamp", "t = set_speed(t, 0.3)", "t = shift(t, 'left')"
    )
    assert steps[-1] == "t = stop_at(t, detect_objects('lamp'))"


SLOWING_TO_REST = "t = speed_profile(t, 'decelerate', start=0.6)"


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        ("land on the box and stay stationary there", ["t = reach(t, detect_objects('box'))"]),
        ("come to a halt right on the lamp", ["t = stop_at(t, detect_objects('lamp'))"]),
        ("bring the arm to rest at the red cup", []),
        ("finish at the chair, motionless", ["t = shift(t, 'left')"]),
        ("wrap things up on the box and come to a full rest", []),
    ],
)
def test_an_end_the_words_leave_at_rest_ends_there_slowing_to_a_stop(words: str, steps: list[str]) -> None:
    after = steps_after(words, *steps)
    assert any(step.startswith("t = reach(") for step in after)
    assert after[-1] == SLOWING_TO_REST and not any("stop_at" in step for step in after)


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        ("finish at the lamp, then slow down near the box", ["t = reach(t, detect_objects('lamp'))"]),
        ("rather than stopping early, end at the chair", []),  # the stop is not at the end place
        ("end at the lamp without moving the start", []),
    ],
)
def test_an_end_with_no_rest_asked_keeps_its_pace(words: str, steps: list[str]) -> None:
    assert SLOWING_TO_REST not in steps_after(words, *steps)


def test_an_end_already_at_rest_gets_no_second_stop() -> None:
    steps = steps_after(
        "touch down on the box and come to a standstill",
        "t = reach(t, detect_objects('box'))",
        SLOWING_TO_REST,
    )
    assert steps == ["t = reach(t, detect_objects('box'))", SLOWING_TO_REST]


@pytest.mark.parametrize(
    ("words", "raised"),
    [
        ("land about 0.2 above the lamp", "t = shift_goal(t, 'up', 0.2)"),
        ("wrap up just above the lamp", "t = shift_goal(t, 'up', 0.2)"),  # the model's number stands
    ],
)
def test_an_end_above_an_object_ends_there_then_raises_the_goal(words: str, raised: str) -> None:
    code = program("t = shift_goal(t, 'up', 0.2)", "t = avoid(t, detect_objects('lamp'), 0.2)")
    lines = end_at_asked_places(code, [words], NAMES)[0].splitlines()
    assert lines[1:-1] == ["t = reach(t, detect_objects('lamp'))", raised]


def test_an_end_already_raised_after_its_reach_stays() -> None:
    code = program("t = reach(t, detect_objects('lamp'))", "t = shift_goal(t, 'up', 0.2)")
    assert end_at_asked_places(code, ["finish 0.2 above the lamp"], NAMES) == (code, [])


def test_an_end_just_above_an_object_with_no_raise_written_is_raised_slightly() -> None:
    code = program("t = avoid(t, detect_objects('lamp'), 0.2)")
    lines = end_at_asked_places(code, ["wrap up just above the lamp"], NAMES)[0].splitlines()
    assert lines[1:-1] == ["t = reach(t, detect_objects('lamp'))", "t = shift_goal(t, 'up', 'slightly')"]


@pytest.mark.parametrize(
    "words",
    [
        "finish up right against the chair",
        "pull up right alongside the chair",
        "come to rest directly next to the chair instead of at the old goal",
        "end just beside the chair",
    ],
)
def test_an_end_beside_the_object_stops_beside_it(words: str) -> None:
    assert steps_after(words, "t = stop_at(t, detect_objects('chair'))") == [
        "t = stop_at(t, detect_objects('chair'), beside=True)"
    ]
    assert (
        steps_after(words, "t = shift(t, 'left')")[-1]
        == "t = stop_at(t, detect_objects('chair'), beside=True)"
    )


@pytest.mark.parametrize(
    "words",
    [
        "stop where the path comes closest to the chair",
        "end at its point nearest the chair",
        "stop at the chair",
    ],
)
def test_an_end_where_the_path_passes_nearest_stays_there(words: str) -> None:
    assert steps_after(words, "t = stop_at(t, detect_objects('chair'))") == [
        "t = stop_at(t, detect_objects('chair'))"
    ]


def straight_path() -> np.ndarray:
    """41 waypoints from x = -1 to 1 at speed 1: 0.05 apart."""
    return np.c_[np.linspace(-1.0, 1.0, 41), np.zeros(41), np.zeros(41), np.ones(41)]


def test_a_stop_beside_the_object_goes_on_to_beside_it_from_the_nearest_pass() -> None:
    path = straight_path()
    chair = np.array([0.0, 0.8, 0.0])
    nearest = stop_at(path, chair)
    beside = stop_at(path, chair, beside=True)
    np.testing.assert_array_equal(beside[: len(nearest) - 1, :3], nearest[:-1, :3])  # the path up to its pass
    assert np.linalg.norm(beside[-1, :3] - chair) == pytest.approx(BESIDE_GAP * 2.0)
    assert beside[-1, 3] == 0.0 and np.all(beside[:-1, 3] > 0)
    steps = np.linalg.norm(np.diff(beside[:, :3], axis=0), axis=1)
    assert steps.max() <= 0.06  # no jump: the way on is spaced as the path was (0.05)


def test_a_stop_beside_an_object_the_path_already_passes_close_to_is_the_plain_stop() -> None:
    path = straight_path()
    chair = np.array([0.0, 0.1, 0.0])
    np.testing.assert_array_equal(stop_at(path, chair, beside=True), stop_at(path, chair))


def test_the_way_on_to_beside_the_object_keeps_the_speed_the_path_had_there() -> None:
    path = straight_path()
    path[:, 3] = np.linspace(1.0, 2.0, 41)
    path[15:26, 3] = 0.5  # slowed by the object
    beside = stop_at(path, np.array([0.0, 0.8, 0.0]), beside=True)
    assert np.all(beside[21:-1, 3] == 0.5) and beside[-1, 3] == 0.0


def test_a_stop_beside_on_a_path_with_no_length_or_far_from_the_object_stays_bounded() -> None:
    still = np.c_[np.zeros((5, 3)), np.ones(5)]
    np.testing.assert_array_equal(
        stop_at(still, np.array([0.5, 0.0, 0.0]), beside=True)[:, :3], still[:2, :3]
    )
    far = stop_at(straight_path(), np.array([0.0, 50.0, 0.0]), beside=True)
    assert len(far) <= 21 + 41


@pytest.mark.parametrize(
    ("words", "within"),
    [
        ("settle within 0.3 of the chair", 0.3),
        ("land no further than 0.25 from the chair", 0.25),
        ("come to a halt at most 0.2 away from the chair", 0.2),
        ("wrap things up within roughly 0.5 of the chair", 0.5),
    ],
)
def test_an_end_within_a_distance_of_the_object_stops_within_it(words: str, within: float) -> None:
    asked = asked_end(words, NAMES)
    assert asked is not None and asked.skill == "stop_at" and float(asked.within) == within
    assert steps_after(words, "t = stop_at(t, detect_objects('chair'))") == [
        f"t = stop_at(t, detect_objects('chair'), within={within!r})"
    ]
    assert (
        steps_after(words, "t = shift(t, 'left')")[-1]
        == f"t = stop_at(t, detect_objects('chair'), within={within!r})"
    )


@pytest.mark.parametrize(
    "words", ["stay within 0.3 of the chair", "keep no more than 0.2 from the chair the whole way"]
)
def test_a_distance_kept_without_an_ending_word_asks_no_end(words: str) -> None:
    assert asked_end(words, NAMES) is None


def test_an_end_within_reach_already_there_comes_to_rest_when_the_words_say_so() -> None:
    assert steps_after(
        "bring the gripper to rest within 0.1 of the chair", "t = reach(t, detect_objects('chair'))"
    ) == [
        "t = reach(t, detect_objects('chair'))",
        "t = speed_profile(t, 'decelerate', start=0.6)",
    ]


@pytest.mark.parametrize("within", [0.05, 0.1, 0.5, 2.0])
def test_a_stop_within_a_distance_ends_inside_it_and_at_rest(within: float) -> None:
    chair = np.array([0.0, 0.8, 0.0])  # the path passes 0.8 from it
    stopped = stop_at(straight_path(), chair, within=within)
    gap = float(np.linalg.norm(stopped[-1, :3] - chair))
    if within >= 0.8:  # the nearest pass is within it: the plain stop
        np.testing.assert_array_equal(stopped, stop_at(straight_path(), chair))
    else:
        assert gap == pytest.approx(min(WITHIN_SHARE * within, BESIDE_GAP * 2.0))
    assert gap <= max(within, 0.8) and stopped[-1, 3] == 0.0

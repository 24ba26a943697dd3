"""A place the words ask the robot to go once it has reached the goal (readers.past_the_goal).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.past_the_goal import add_destination, after_goal

NAMES = ["vase", "blue cup", "cup", "shelf"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "destination"),
    [
        ("when the robot arrives at the goal, steer toward the vase and linger above it", "vase"),
        ("go left, then after the end make your way to the blue cup", "blue cup"),
        ("travel on to the shelf after reaching the goal", "shelf"),
        ("On getting to the destination, proceed to the cup.", "cup"),
        ("Reach the goal first. Then carry on to the vase.", None),  # "first" does not open it
        ("First get to the goal. Then carry on to the vase.", "vase"),
        ("once past the goal, continue 0.3 forward", None),  # a move, no place
        ("head to the vase", None),  # nothing after the goal
        ("after the goal, go to the vase and then to the shelf", None),  # two places: which is the end?
        ("once the goal is reached keep going, with the path raised toward the shelf", None),  # the path
        ("prolong the route until it gets to the shelf", "shelf"),  # lengthening is going past the goal
        ("extend it by 0.3 toward the shelf", None),  # a length: not to the shelf itself
        ("extend the path and slow down near the vase", None),  # the vase is no place to go
        ("once at the goal, nip across to the shelf", "shelf"),  # any verb with "across to"
        ("when you're done at the goal, scoot back to the cup", "cup"),
    ],
)  # fmt: skip
def test_the_place_to_go_after_the_goal(words: str, destination: str | None) -> None:
    assert after_goal(words, NAMES).destination == destination


@pytest.mark.parametrize(
    ("steps", "words", "kept"),
    [
        (("t = move_closer(t, detect_objects('goal'))",), "upon reaching the destination, travel to the vase", ()),
        (("t = pass_over(t, detect_objects('vase'))",), "once at the end, fly over to the vase", ()),
        (("t = extend(t, 'a bit', 'up')",), "after the goal, head up to the vase", ()),
        (("t = shift(t, 'up', 'a bit')",), "when you reach the goal, move to the vase and stay above it", ()),
        (
            ("t = shift(t, 'up', 'a bit')",),
            "go up a bit, and when you reach the goal, move to the vase and stay above it",
            ("t = shift(t, 'up', 'a bit')",),
        ),  # the rise is asked before the goal
        (
            ("t = move_away(t, detect_objects('vase'))",),
            "keep away from the vase, and when you reach the goal, go to the vase",
            ("t = move_away(t, detect_objects('vase'))",),
        ),  # the vase is named before the goal too
        (
            ("t = shift(t, 'left', 'a bit')", "t = extend(t)"),
            "nudge it left a bit and lengthen it smoothly so it reaches the vase",
            ("t = shift(t, 'left', 'a bit')",),
        ),  # the lengthening's clause also moves the path
        (
            ("t = scale_speed(t, 0.5, near=detect_objects('vase'))",),
            "after the goal, approach the vase slowly",
            ("t = scale_speed(t, 0.5, near=detect_objects('vase'))",),
        ),  # a speed step says how fast, not where to go
    ],
)  # fmt: skip
def test_the_steps_written_for_the_place_leave_and_a_segment_to_it_ends_the_code(
    steps: tuple[str, ...], words: str, kept: tuple[str, ...]
) -> None:
    code, notes = add_destination(program(*steps), [words], NAMES)
    assert code == program(*kept, "t = append_segment(t, detect_objects('vase'))")
    assert len(notes) == len(steps) - len(kept) + 1
    assert all("the goal" in note for note in notes)


@pytest.mark.parametrize(
    ("code", "words"),
    [
        (program("t = append_segment(t, detect_objects('vase'))"), "after the goal, go to the vase"),
        (program("t = move_closer(t, detect_objects('vase'))"), "go to the vase"),
        ("t = get_trajectory()\nt[:, 0] += 1\nmodified_trajectory = t", "after the goal, go to the vase"),
    ],
)
def test_a_segment_there_no_place_after_the_goal_or_code_it_cannot_follow_stays(
    code: str, words: str
) -> None:
    assert add_destination(code, [words], NAMES) == (code, [])


def test_in_the_stage_the_place_comes_before_the_pause_there() -> None:
    code, notes = read_against_words(
        program("t = pass_over(t, detect_objects('vase'))"),
        ["once you get to the goal, steer toward the vase and idle above it for a little while"],
        NAMES,
    )
    assert code.splitlines()[1:3] == [
        "t = append_segment(t, detect_objects('vase'))",
        "t = wait(t, detect_objects('vase'), 10)",
    ]
    readers = ["request-words", "past-the-goal", "past-the-goal", "asked-pauses"]  # "above it": the vase
    assert [note.reader for note in notes] == readers


def test_a_pause_at_the_place_stays_and_comes_after_the_segment() -> None:
    code, _ = add_destination(
        program("t = wait(t, detect_objects('Vase'), 5)", "t = smooth(t)"),
        ["after the goal, fly to the vase and hover there for 5 timesteps"],
        NAMES,
    )
    assert code == program(
        "t = append_segment(t, detect_objects('vase'))",
        "t = wait(t, detect_objects('Vase'), 5)",
        "t = smooth(t)",
    )


@pytest.mark.parametrize(
    ("words", "written", "directed"),
    [
        ("once you are at the end point, push on 0.3 further up", "t = extend(t, 0.3)",
         "t = extend(t, 0.3, direction='up')"),
        ("after the goal, carry on backwards a little", "t = extend(t, distance='a little')",
         "t = extend(t, distance='a little', direction='back')"),
    ],
)  # fmt: skip
def test_an_undirected_extension_gets_the_direction_said_after_the_goal(
    words: str, written: str, directed: str
) -> None:
    code, notes = read_against_words(program(written), [words], [])
    assert code.splitlines()[1:-1] == [directed]
    assert any(note.reader == "past-the-goal" for note in notes)


@pytest.mark.parametrize("written", ["t = extend(t, 0.3, 'left')", "t = extend(t, direction='left')"])
def test_an_extension_with_its_own_direction_is_left_to_the_flags(written: str) -> None:
    code, _ = read_against_words(program(written), ["after the goal, carry on 0.3 to the right"], [])
    assert written in code


@pytest.mark.parametrize(
    "words",
    [
        "don't end where it ends now; proceed another 0.3 up",
        "keep driving an extra 0.3 upwards",
        "once the arm gets to its current goal, carry on 0.3 further up",
        "when you arrive at the present end point, press on a further 0.3 up",
    ],
)
def test_going_on_by_a_further_amount_is_past_the_goal(words: str) -> None:
    code, notes = read_against_words(program("t = extend(t, 0.3)"), [words], [])
    assert code.splitlines()[1:-1] == ["t = extend(t, 0.3, direction='up')"]
    assert any(note.reader == "past-the-goal" for note in notes)


@pytest.mark.parametrize(
    "words",
    [
        "continue more slowly near the vase",  # a pace, no further amount
        "keep going another 0.3 towards the vase",  # an object: not a plain going on
        "carry on along the same route",
        "continue for 3 more loops",  # a count, not a length
    ],
)
def test_going_on_without_a_further_amount_is_not_past_the_goal(words: str) -> None:
    assert after_goal(words, NAMES).clauses == ()


@pytest.mark.parametrize("shift", ["t = shift(t, 'left', 0.2)", "t = shift_goal(t, 'left')"])
def test_a_shift_the_way_only_the_going_on_says_is_the_extension_twice(shift: str) -> None:
    written = program("t = smooth(t)", shift, "t = extend(t, 0.2)")
    code, notes = read_against_words(
        written, ["smooth it out, and don't stop there: push on another 0.2 left"], []
    )
    assert code.splitlines()[1:-1] == ["t = smooth(t)", "t = extend(t, 0.2, direction='left')"]
    assert any("left out" in note.message for note in notes)


def test_a_shift_that_a_clause_before_the_goal_says_stays() -> None:
    written = program("t = shift(t, 'left', 0.1)", "t = extend(t, 0.2)")
    code, _ = read_against_words(
        written, ["move the whole path 0.1 left, then keep going an extra 0.2 left"], []
    )
    assert code.splitlines()[1:-1] == ["t = shift(t, 'left', 0.1)", "t = extend(t, 0.2, direction='left')"]

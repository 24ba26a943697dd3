"""A pause a clause asks for a count of timesteps, and no step that pauses (readers.asked_pauses)."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.asked_pauses import SOME_TIME_STEPS, add_asked_pauses, asked_pauses

NAMES = ["vase", "blue cup", "cup"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "place", "steps", "is_object"),
    [
        ("linger beside the vase for 4 timesteps", "vase", 4, True),
        ("halfway along, freeze for three time steps", "middle", 3, False),
        ("at the very beginning wait 6 steps", "start", 6, False),
        ("go near the blue cup and stay still there for 8 timesteps", "blue cup", 8, True),
        ("once at the destination, hold for nine timesteps", "goal", 9, False),
        # a length said without a count: SOME_TIME_STEPS; "idle", "dwell", "hang" are pause words
        ("idle beside the vase for a little while", "vase", SOME_TIME_STEPS, True),
        ("dwell briefly at the midpoint", "middle", SOME_TIME_STEPS, False),
        ("hang in the air by the blue cup for some moments", "blue cup", SOME_TIME_STEPS, True),
        # a length said with no "for", a short pause by its noun, a short stop that a verb adds
        ("hold it there a moment once level with the vase", "vase", SOME_TIME_STEPS, True),
        ("by the blue cup, a brief hover please", "blue cup", SOME_TIME_STEPS, True),
        ("put in a quick halt near the vase", "vase", SOME_TIME_STEPS, True),
        # the count in the clause after a pause with a place and no count
        ("come to a standstill next to the vase and then wait out 7 steps", "vase", 7, True),
        ("freeze at the start, dwell for two timesteps", "start", 2, False),
    ],
)  # fmt: skip
def test_a_pause_its_place_and_its_count(words: str, place: str, steps: int, is_object: bool) -> None:
    assert [(p.place, p.steps, p.is_object) for p in asked_pauses(words, NAMES)] == [
        (place, steps, is_object)
    ]


@pytest.mark.parametrize(
    "words",
    [
        "pause near the vase",  # no count: how long is not said
        "hold the height near the vase for a while",  # no word for stopping: a height held for a part
        "reduce the speed in steps near the vase",  # "in steps" counts nothing
        "lift the rest of the path for 5 timesteps",  # no word for stopping
        "stop for 5 timesteps",  # no place
        "wait 3 timesteps between the vase and the cup",  # two places
        "come to a quick stop at the vase",  # a quick stop with no verb that adds it ends the path
        "stop at the vase in a moment",  # when, not how long
        "halt by the vase after a while",
        "come down in a quick stop at the vase",
    ],
)
def test_no_count_no_pause_word_or_no_one_place_asks_no_pause(words: str) -> None:
    assert asked_pauses(words, NAMES) == []


def test_a_missing_pause_is_added_as_the_last_step() -> None:
    code, notes = add_asked_pauses(
        program("t = move_away(t, detect_objects('cup'))"),
        ["keep off the cup and halt mid-way for 5 steps"],
        NAMES,
    )
    assert code.splitlines()[-2] == "t = wait(t, 'middle', 5)"
    assert "no step pauses" in notes[0]


def test_a_stop_with_a_count_is_a_pause_and_the_path_goes_on() -> None:
    code, notes = add_asked_pauses(
        program("t = stop_at(t, detect_objects('vase'))"),
        ["come to a stop by the vase for 10 timesteps"],
        NAMES,
    )
    assert code.splitlines()[1] == "t = wait(t, detect_objects('vase'), 10)"
    assert "pauses, then goes on" in notes[0]


@pytest.mark.parametrize(
    "code",
    [
        program("t = wait(t, 'middle', 5)"),  # the model paused as asked
        "t = get_trajectory()\nt[5:] = t[5]\nmodified_trajectory = t",  # code the readers cannot follow
    ],
)
def test_code_that_pauses_or_cannot_be_followed_is_left_alone(code: str) -> None:
    assert add_asked_pauses(code, ["wait in the middle for 5 timesteps"], NAMES) == (code, [])


def test_shifts_nobody_asked_give_way_to_the_pause() -> None:
    """The pause is the step the words ask; the shifts in no said direction then serve no clause."""
    code, _ = read_against_words(
        program("t = shift(t, 'up', 'slightly')", "t = shift(t, 'right', 'slightly')"),
        ["keep the position at the path's midpoint for five timesteps"],
        NAMES,
    )
    assert code.splitlines()[1:-1] == ["t = wait(t, 'middle', 5)"]


def test_a_pause_that_points_back_takes_the_place_before() -> None:
    found = asked_pauses("when you reach the vase, remain still there for 7 steps", NAMES)
    assert [(p.place, p.steps, p.is_object) for p in found] == [("vase", 7, True)]


def test_a_wait_at_a_part_nobody_named_goes_to_the_object_the_pause_is_asked_at() -> None:
    words = ["when it gets alongside the vase, hold still for five waypoints"]
    code, notes = add_asked_pauses(program("t = wait(t, 'middle', 5)"), words, NAMES)
    assert code == program("t = wait(t, detect_objects('vase'), 5)") and "at the vase" in notes[0]
    halfway = ["halfway, by the vase, hold still for five waypoints"]  # the words say the middle too
    assert add_asked_pauses(program("t = wait(t, 'middle', 5)"), halfway, NAMES)[0] == program(
        "t = wait(t, 'middle', 5)"
    )


def test_a_brief_stop_is_a_pause_and_the_path_goes_on() -> None:
    code, _ = add_asked_pauses(
        program("t = stop_at(t, detect_objects('vase'))"),
        ["make a brief stop at the vase, then carry on"],
        NAMES,
    )
    assert code == program("t = wait(t, detect_objects('vase'), 10)")


def test_a_stop_that_only_begins_a_pause_leaves_beside_the_wait() -> None:
    code, notes = add_asked_pauses(
        program("t = stop_at(t, t[-2])", "t = wait(t, 'middle', 3)"),
        ["at the midpoint, halt and then linger there for 3 steps"],
        NAMES,
    )
    assert code == program("t = wait(t, 'middle', 3)")
    assert "only to pause" in notes[0]


@pytest.mark.parametrize(
    "words",
    [
        "come to a stop at the end, and wait 3 timesteps by the vase",  # a stop of its own
        "halt near the cup",  # no pause with a count
    ],
)
def test_a_stop_of_its_own_stays(words: str) -> None:
    code = program("t = stop_at(t, detect_objects('cup'))", "t = wait(t, detect_objects('vase'), 3)")
    assert add_asked_pauses(code, [words], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("words", "count"),
    [
        ("pause beside the vase for 6 timesteps", 6),
        ("when you reach the vase, stay still briefly", SOME_TIME_STEPS),
    ],
)
def test_the_one_wait_takes_the_one_pause_count(words: str, count: int) -> None:
    code, notes = add_asked_pauses(program("t = wait(t, detect_objects('vase'), 1)"), [words], NAMES)
    assert code.splitlines()[1] == f"t = wait(t, detect_objects('vase'), {count})" and notes


def test_a_wait_with_the_asked_count_or_two_pauses_stay() -> None:
    code = program("t = wait(t, detect_objects('vase'), 6)")
    assert add_asked_pauses(code, ["pause beside the vase for 6 timesteps"], NAMES) == (code, [])
    two = program("t = wait(t, detect_objects('vase'), 2)")
    words = "wait at the vase for 4 steps, then wait at the cup for 7 steps"
    assert add_asked_pauses(two, [words], NAMES) == (two, [])  # which wait is which pause: not read


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        ("hover in place for 3 waypoints as you pass the vase", 3),
        ("hang on beside the vase for a couple of waypoints", 2),
        ("idle by the vase for a few waypoints", 3),
    ],
)
def test_a_pause_may_be_counted_in_waypoints(words: str, steps: int) -> None:
    (pause,) = asked_pauses(words, NAMES)
    assert (pause.place, pause.steps) == ("vase", steps)


@pytest.mark.parametrize(
    ("words", "step"),
    [
        (
            "pause briefly beside the vase",
            "t = wait(t, detect_objects('vase'), 5)",
        ),  # a vague length read as 5
        (
            "halt at the vase for 4 steps",
            "t = wait(t, detect_objects('Vase'), 4)",
        ),  # the object, another case
    ],
)
def test_a_wait_as_asked_or_a_vague_length_read_its_own_way_stays(words: str, step: str) -> None:
    code = program(step)
    assert add_asked_pauses(code, [words], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("words", "count"),
    [
        ("linger for a couple of beats beside the vase, and keep away from the cup", 2),
        ("keep 0.3 from the cup; when you reach the vase, stay still briefly", 3),
    ],
)
def test_a_wait_at_another_object_goes_to_the_object_the_pause_is_asked_at(words: str, count: int) -> None:
    code, notes = add_asked_pauses(program("t = wait(t, detect_objects('cup'), 3)"), [words], NAMES)
    assert code == program(f"t = wait(t, detect_objects('vase'), {count})") and "at the vase" in notes[0]


def test_a_waypoint_named_as_a_place_is_no_count() -> None:
    (pause,) = asked_pauses("hover at the middle waypoint for 5 timesteps", NAMES)
    assert pause.steps == 5


def test_where_the_path_goes_on_to_after_the_pause_is_not_the_pause_place() -> None:
    (pause,) = asked_pauses("halt by the vase, then wait 4 steps before heading on to the goal", NAMES)
    assert (pause.place, pause.steps) == ("vase", 4)


@pytest.mark.parametrize(
    ("words", "place"),
    [
        ("before heading on, wait 3 steps at the vase", "vase"),
        ("pause for 3 steps before passing the vase", "vase"),
    ],
)
def test_words_before_the_pause_or_a_place_passed_still_place_it(words: str, place: str) -> None:
    (pause,) = asked_pauses(words, NAMES)
    assert (pause.place, pause.steps) == (place, 3)

"""A pace the words ask to run down to a stop or up from rest (readers.speed_profiles).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import pytest

from trajadapt.readers.speed_profiles import asked_profile, profile_paces

NAMES = ["box", "lamp"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "profile"),
    [
        ("glide forward, slowing down till it comes to a full stop", "decelerate"),
        ("brake gently down to zero", "decelerate"),
        ("decelerate until the speed reaches 0", "decelerate"),
        ("start from a standstill and speed up", "accelerate"),
        ("pick up the pace from rest", "accelerate"),
        ("drift to a standstill at the very end", "decelerate"),  # a stop with no word of slowing
        ("slow down near the box", None),  # a place, no stop
        ("speed up to a halt of the jitter", None),  # faster: no slowing
        ("bring the average speed down to 0.2 m/s", None),  # a speed, not zero
        ("never come to a stop", None),  # refused
        ("halfway, come to a stop for 5 steps, then carry on", None),  # a pause on the way
        ("let the velocity reach 0.05 at the goal", None),
        ("slow down until you stop at the box", None),  # a place to stop at
        ("go faster", None),
    ],
)  # fmt: skip
def test_a_slowing_to_a_stop_or_a_speeding_up_from_rest(words: str, profile: str | None) -> None:
    assert asked_profile(words, NAMES) == profile


def test_the_one_whole_path_scale_becomes_the_profile() -> None:
    code, notes = profile_paces(
        program("t = shift(t, 'front')", "t = scale_speed(t, 0.65)"),
        ["move forward and ease off to a standstill"],
        NAMES,
    )
    assert code == program("t = shift(t, 'front')", "t = speed_profile(t, 'decelerate', start=0.6)")
    assert "down to a stop" in notes[0]


@pytest.mark.parametrize(
    "steps",
    [
        ("t = scale_speed(t, 0.65, near=detect_objects('box'))",),  # placed: not the whole path
        ("t = scale_speed(t, 0.65)", "t = set_speed(t, 0.2)"),  # which one?
        ("t = speed_profile(t, 'decelerate')",),  # already the profile
    ],
)
def test_placed_several_or_profiled_paces_stay(steps: tuple[str, ...]) -> None:
    code = program(*steps)
    assert profile_paces(code, ["slow down to zero"], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        ("t = speed_profile(t, 'constant', start=0.6)", "lower the pace gently towards the end",
         "t = speed_profile(t, 'decelerate', start=0.6)"),
        ("t = speed_profile(t, 'decelerate')", "pick up speed as you go", "t = speed_profile(t, 'accelerate')"),
        # a pace turned down (not a direction), and where the slowing begins said as a closing share
        ("t = speed_profile(t, 'constant')", "ramp the speed down over the final quarter until it stops",
         "t = speed_profile(t, 'decelerate', start=0.75)"),
        ("t = speed_profile(t, 'accelerate')", "dial it back down through the last 40% of the route",
         "t = speed_profile(t, 'decelerate', start=0.6)"),
        ("t = speed_profile(t, 'constant', start=0.5)", "ramp the speed down in the last third",
         "t = speed_profile(t, 'decelerate', start=0.5)"),  # the model's own start stays
    ],
)  # fmt: skip
def test_a_profile_the_other_way_from_the_asked_pace_is_turned(step: str, words: str, expected: str) -> None:
    code, notes = profile_paces(program(step), [words], NAMES)
    assert code == program(expected)
    assert "pace" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = speed_profile(t, 'constant')", "slow down to a steady speed"),  # an even speed asked
        ("t = speed_profile(t, 'trapezoidal')", "slow down at both ends"),  # speeds up and slows down
        ("t = speed_profile(t, 'constant')", "slow near the box, hurry past the lamp"),  # both paces
    ],
)
def test_profiles_the_words_allow_stay(step: str, words: str) -> None:
    assert profile_paces(program(step), [words], NAMES) == (program(step), [])


def test_a_slowing_to_rest_stays_beside_words_that_ask_only_faster() -> None:
    code, notes = profile_paces(
        program("t = scale_speed(t, 1.4, part='start')", "t = speed_profile(t, 'decelerate', start=0.6)"),
        ["hurry through the first part, then be at rest when it reaches the goal"],
        [],
    )
    assert "'decelerate'" in code and not notes


@pytest.mark.parametrize(
    ("words", "step", "expected"),
    [
        # one pace for the whole path, answered with a profile (session 31; fresh-f's "30% slower overall")
        ("drive the whole route about 25% slower", "t = speed_profile(t, 'decelerate', start=0.7)",
         "t = scale_speed(t, 0.75)"),
        ("shift the last point 0.2 left and speed up a lot", "t = speed_profile(t, 'accelerate')",
         "t = scale_speed(t, 1.6)"),
    ],
)  # fmt: skip
def test_a_profile_for_one_pace_of_the_whole_path_is_a_scale(words: str, step: str, expected: str) -> None:
    assert expected in profile_paces(program(step), [words], NAMES)[0].splitlines()


@pytest.mark.parametrize(
    "words",
    [
        "slow down gradually",  # a pace that changes
        "slow down towards the end",  # an end
        "ease off in steps, one every 4 waypoints",
        "go slower; you're in the middle",  # a part said in a clause of its own
        "slow down near the lamp",  # an object
        "slow down until it stops",  # a stop
    ],
)
def test_a_profile_the_words_may_ask_stays(words: str) -> None:
    code = program("t = speed_profile(t, 'decelerate', start=0.6)")
    assert profile_paces(code, [words], NAMES)[0] == code


@pytest.mark.parametrize(
    "words",
    [
        "in the middle stay below 1.2 m, and fly a little slower overall",
        "keep above 0.4 through the middle section; also fly slower",
    ],
)
def test_a_part_where_a_height_is_held_is_not_the_pace_part(words: str) -> None:
    """The clause naming the middle asks a height of its own: the pace is the whole path's."""
    code = program("t = speed_profile(t, 'decelerate')")
    step = profile_paces(code, [words], NAMES)[0].splitlines()[1]
    assert step.startswith("t = scale_speed(t, 0.") and "part" not in step


@pytest.mark.parametrize(
    ("step", "words", "start"),
    [
        ("t = scale_speed(t, 0.5, part='second half')", "wind down to a full stop at the end", 0.5),
        ("t = set_speed(t, 0.2, part='end')", "drift to a standstill over the final quarter", 0.75),
        ("t = scale_speed(t, 0.65, part='final')", "ease it to a halt as it arrives", 0.7),
    ],
)
def test_a_scale_of_the_closing_part_becomes_the_profile_from_that_part(
    step: str, words: str, start: float
) -> None:
    code, notes = profile_paces(program(step), [words], NAMES)
    assert (
        code == program(f"t = speed_profile(t, 'decelerate', start={start:g})")
        and "down to a stop" in notes[0]
    )


@pytest.mark.parametrize(
    "step", ["t = scale_speed(t, 0.5, part='middle')", "t = scale_speed(t, 0.5, part='start')"]
)
def test_a_scale_of_another_part_stays_beside_a_stop_at_the_end(step: str) -> None:
    code = program(step)
    assert profile_paces(code, ["wind down to a full stop at the end"], NAMES) == (code, [])

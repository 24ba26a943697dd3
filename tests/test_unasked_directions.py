"""A shift in a direction the user never said becomes what the words ask for instead."""

from __future__ import annotations

import pytest

from trajadapt.readers.unasked_directions import replace_unasked_shifts

NAMES = ["Lamp", "sofa"]
CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        ("t = shift(t, 'down')", "drive a bit further from the lamp", "t = move_away(t, detect_objects('Lamp'), 'a bit')"),
        ("t = shift_goal(t, 'left')", "come closer to the sofa", "t = move_closer(t, detect_objects('sofa'))"),
        ("t = shift_part(t, 'right', part='middle')", "hurry in the middle", "t = scale_speed(t, 1.4, part='middle')"),
        ("t = shift(t, 'up')", "a lot slower towards the end", "t = scale_speed(t, 0.45, part='end')"),
        ("t = shift(t, 'up')", "move slower", "t = scale_speed(t, 0.65)"),
        ("t = shift_goal(t, 'down')", "over the final fifth bring the speed down to a stop",
         "t = speed_profile(t, 'decelerate', start=0.8)"),  # slowing to a stop: the profile
    ],
)  # fmt: skip
def test_the_one_unsaid_shift_becomes_the_asked_step_with_a_note(
    step: str, words: str, expected: str
) -> None:
    code, notes = replace_unasked_shifts(CODE.format(step=step), [words], NAMES)
    assert code.splitlines()[1] == expected
    assert "names no such direction" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = shift(t, 'down')", "go down and further from the lamp"),  # the words say down
        ("t = shift(t, 'up')\nt = shift(t, 'right')", "go left, further from the lamp"),  # which guesses?
        ("t = shift(t, 'up')\nt = move_away(t, detect_objects('lamp'))", "go up, further from the lamp"),
        ("t = shift(t, 'up')\nt = scale_speed(t, 1.4)", "move the end part and go faster"),  # a part moved
        ("t = shift(t, 'up')", "make the path smoother"),  # nothing else asked
    ],
)
def test_said_directions_several_guesses_or_nothing_asked_stay(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert replace_unasked_shifts(code, [words], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        ("t = shift_part(t, 'up', None, 'middle')", "speed up over the middle part",
         "t = scale_speed(t, 1.4, part='middle')"),
        ("t = shift(t, 'down')", "slow down a lot in the final part", "t = scale_speed(t, 0.45, part='final')"),
        ("t = shift_start(t, 'left', 'a lot')", "go much slower when you pass the lamp",
         "t = scale_speed(t, 0.45, near=detect_objects('Lamp'))"),
        ("t = shift(t, 'right')", "hurry when the sofa is close", "t = scale_speed(t, 1.4, near=detect_objects('sofa'))"),
    ],
)  # fmt: skip
def test_a_pace_is_no_direction_and_may_be_tied_to_one_object(step: str, words: str, expected: str) -> None:
    """'speed up' / 'calm down' name no direction (session 13); a pace near one object scales it there."""
    code, notes = replace_unasked_shifts(CODE.format(step=step), [words], NAMES)
    assert code.splitlines()[1] == expected
    assert "names no such direction" in notes[0]


def test_paces_near_two_objects_leave_the_shift_alone() -> None:
    code = CODE.format(step="t = shift(t, 'left')")
    assert replace_unasked_shifts(code, ["faster near the lamp and slower near the sofa"], NAMES) == (
        code,
        [],
    )


@pytest.mark.parametrize(
    ("steps", "words"),
    [
        ("t = shift(t, 'up')\nt = move_away(t, detect_objects('lamp'))", "further from the lamp"),
        ("t = shift(t, 'up')\nt = scale_speed(t, 1.4)", "go faster"),
        ("t = shift(t, 'up')\nt = scale_speed(t, 1.4, part='end')", "faster at the end"),  # a part, no move
        ("t = shift(t, 'left')\nt = wait(t, 'middle', 4)", "halfway along, hold still for 4 timesteps"),
        ("t = scale_speed(t, 0.45)\nt = shift(t, 'down', 'a bit')\nt = move_away(t, detect_objects('sofa'))",
         "reduce the speed a lot and keep more room from the sofa"),
    ],
)  # fmt: skip
def test_an_unsaid_shift_beside_steps_that_make_all_the_words_ask_is_left_out(steps: str, words: str) -> None:
    code, notes = replace_unasked_shifts(CODE.format(step=steps), [words], NAMES)
    assert "shift" not in code and code.count("\n") == steps.count("\n") + 1
    assert "names no direction" in notes[0]


@pytest.mark.parametrize(
    ("steps", "words", "expected"),
    [
        ("t = shift(t, 'up')\nt = shift(t, 'left')", "further from the lamp",
         ["t = move_away(t, detect_objects('Lamp'))"]),
        ("t = shift(t, 'up', 'slightly')\nt = shift(t, 'right', 'slightly')\nt = move_away(t, detect_objects('sofa'))",
         "ease off whenever the lamp is close and keep clear of the sofa",
         ["t = scale_speed(t, 0.65, near=detect_objects('Lamp'))", "t = move_away(t, detect_objects('sofa'))"]),
    ],
)  # fmt: skip
def test_several_guesses_where_the_words_say_no_direction_become_the_asked_steps(
    steps: str, words: str, expected: list[str]
) -> None:
    """The first unsaid shift becomes what no step makes; the rest serve no clause and are left out."""
    code, notes = replace_unasked_shifts(CODE.format(step=steps), [words], NAMES)
    assert code.splitlines()[1:-1] == expected
    assert len(notes) == steps.count("shift(")


def test_an_unsaid_shift_beside_shifts_that_make_every_said_direction_is_left_out() -> None:
    code, notes = replace_unasked_shifts(
        CODE.format(step="t = shift(t, 'back', 0.5)\nt = shift(t, 'up', 0.5)"),
        ["back the arm up by 0.5"],
        NAMES,
    )
    assert code == CODE.format(step="t = shift(t, 'back', 0.5)")
    assert "names no such direction" in notes[0]


def test_an_unsaid_shift_beside_an_extension_the_said_way_is_left_out() -> None:
    code, notes = replace_unasked_shifts(
        CODE.format(step="t = extend(t, 0.5, direction='left')\nt = shift(t, 'up')\nt = wait(t, 'goal', 2)"),
        ["go on 0.5 further to the left past the end, then hover there for two waypoints"],
        NAMES,
    )
    assert code == CODE.format(step="t = extend(t, 0.5, direction='left')\nt = wait(t, 'goal', 2)")
    assert "names no such direction" in notes[0]

"""A step that bends the path the other way from what the words ask (readers.curve_asks).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.readers.curve_asks import asked_curve, bend_as_asked
from trajadapt.skills.shape import exaggerate_curve, smooth


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "asked"),
    [
        ("exaggerate the bends of the route", "more"),
        ("give it a deeper arc", "more"),
        ("let the path bend quite a bit more", "more"),
        ("flatten the curve a little", "less"),
        ("take the bends out, make the route straight", "less"),
        ("curve it less near the goal", "less"),
        ("go straight to the vase", None),  # "straight" here is "directly"
        ("extend the path smoothly", None),  # "smoothly" says how
        ("bend more but straighten the end", None),  # both: unclear
    ],
)  # fmt: skip
def test_more_or_less_curve(words: str, asked: str | None) -> None:
    assert asked_curve(words) == asked


def test_smoothing_for_more_curve_becomes_the_exaggeration() -> None:
    code, notes = bend_as_asked(program("t = smooth(t, 0.8)", "t = scale_speed(t, 0.9)"), ["curve it more"])
    assert code == program("t = exaggerate_curve(t)", "t = scale_speed(t, 0.9)")
    assert "bend more" in notes[0]


@pytest.mark.parametrize("step", ["t = exaggerate_curve(t, 2.0)", "t = smooth(t)", "t = smooth(t, 0.9)"])
def test_exaggeration_or_smoothing_for_a_straighter_path_becomes_the_drawing_in(step: str) -> None:
    code, _ = bend_as_asked(program(step), ["make it straighter"])
    assert code == program("t = exaggerate_curve(t, 0.5)")


def test_smoothing_the_words_ask_too_stays_beside_a_straightening() -> None:
    code = program("t = smooth(t)", "t = exaggerate_curve(t, 0.6)")
    assert bend_as_asked(code, ["smooth it out and straighten it"]) == (code, [])


@pytest.mark.parametrize(
    "words", ["a less winding route please", "take a more direct way", "less meandering"]
)
def test_a_more_direct_way_asks_less_bend(words: str) -> None:
    assert asked_curve(words) == "less"


def test_the_asked_straightening_draws_a_wide_bend_in_where_smoothing_keeps_it() -> None:
    s = np.linspace(0.0, 1.0, 40)
    t = np.stack([s, np.sin(np.pi * s), np.zeros_like(s), np.ones_like(s)], axis=1)
    chord_gap = lambda path: float(np.abs(path[:, 1]).mean())  # noqa: E731 (start and goal at y = 0)
    straightened = exaggerate_curve(t.copy(), 0.5)
    assert chord_gap(straightened) < 0.6 * chord_gap(t)
    assert chord_gap(smooth(t.copy())) > 0.9 * chord_gap(t)


def test_a_step_that_agrees_stays() -> None:
    code = program("t = exaggerate_curve(t, 1.5)")
    assert bend_as_asked(code, ["more curved please"]) == (code, [])


@pytest.mark.parametrize(
    ("words", "step", "after"),
    [
        ("give the route a wider arc", "t = shift(t, 'up', 0.1)", "t = exaggerate_curve(t)"),
        ("flatten out the curve", "t = shift(t, 'left')", "t = exaggerate_curve(t, 0.5)"),
    ],
)
def test_a_shift_in_a_direction_nobody_said_stands_for_the_asked_bend(
    words: str, step: str, after: str
) -> None:
    code, notes = bend_as_asked(program(step), [words])
    assert code == program(after)
    assert "say no direction" in notes[0]


def test_a_said_direction_keeps_its_shift_and_the_bend_is_not_added_beside_steps() -> None:
    code = program("t = shift(t, 'left', 0.2)")
    assert bend_as_asked(code, ["curve it more and move it left by 0.2"]) == (code, [])


def test_a_program_of_no_step_gets_the_asked_bend() -> None:
    code, notes = bend_as_asked(program(), ["could the route bend a bit more?"])
    assert code == program("t = exaggerate_curve(t)")
    assert notes == ["added `t = exaggerate_curve(t)`: the words ask the path to bend more and no step does"]


@pytest.mark.parametrize(
    "steps",
    [
        ("t = scale_speed(t, 1.4, part='end')",),
        ("t = set_speed(t, 0.3)", "t = wait(t, 'goal', 2)"),
    ],
)
def test_steps_of_pace_alone_get_the_asked_bend_beside_them(steps: tuple[str, ...]) -> None:
    code, notes = bend_as_asked(program(*steps), ["let it arc out wider, and go faster at the end"])
    assert code == program(*steps, "t = exaggerate_curve(t)") and len(notes) == 1


def test_a_step_that_moves_the_path_may_be_the_bend_and_nothing_is_added() -> None:
    code = program("t = lift_middle(t, 'left')", "t = scale_speed(t, 1.4)")
    assert bend_as_asked(code, ["let it arc out wider, and go faster"]) == (code, [])


@pytest.mark.parametrize(
    "words",
    ["slow down where the path bends more sharply", "don't make it any curvier, just slow down"],
)
def test_a_bend_that_only_places_a_pace_or_is_refused_is_not_added(words: str) -> None:
    code = program("t = scale_speed(t, 0.65)")
    assert bend_as_asked(code, [words]) == (code, [])

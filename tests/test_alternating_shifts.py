"""Shifts the words ask to alternate in blocks of waypoints (readers.alternating_shifts).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.alternating_shifts import alternate_shifts, alternation


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "asked"),
    [
        ("offset the path up for the first 5 waypoints, down for the next 5, and so forth", ("up", 5)),
        ("alternate front and back every 8 points", ("front", 8)),
        ("switch sides in groups of 12: right, then left, then right again", ("right", 12)),
        ("points 1-6 go left, 7-12 go right, back and forth to the end", ("left", 6)),
        ("lower the first 4 points, raise the next 4, and repeat the pattern", ("down", 4)),
    ],
)  # fmt: skip
def test_alternating_shifts_their_first_direction_and_block(words: str, asked: tuple[str, int]) -> None:
    assert alternation(words) == asked


@pytest.mark.parametrize(
    "words",
    [
        "shift the first 10 points left, then the rest right",  # no alternation
        "alternate the speed every 5 points",  # no direction
        "go left for the first 10 points and so on",  # one direction
        "alternate left and up in blocks of 5",  # not opposite
        "alternate left and right",  # no block
    ],
)
def test_no_alternation_block_or_opposite_pair_asks_nothing(words: str) -> None:
    assert alternation(words) is None


def test_the_shifts_in_the_two_directions_become_one_alternating_shift() -> None:
    code, notes = alternate_shifts(
        program(
            "t = shift_part(t, 'up', amount=0.3, part=(0, 5))",
            "t = scale_speed(t, 0.8)",
            "t = shift(t, 'down', 0.3)",
        ),
        ["up for the first 5 waypoints, down for the next 5, and so forth, a bit slower"],
    )
    assert code == program("t = shift(t, 'up', 0.3, alternate=5)", "t = scale_speed(t, 0.8)")
    assert "every 5 waypoints" in notes[0]


def test_an_answer_with_no_shift_in_those_directions_stays() -> None:
    code = program("t = zigzag(t, 0.1)")
    assert alternate_shifts(code, ["alternate left and right every 10 points"]) == (code, [])


def test_in_the_stage_a_loop_of_opposite_shifts_becomes_the_wave() -> None:
    code, notes = read_against_words(
        program(*["t = shift(t, 'right', 0.05)", "t = shift(t, 'left', 0.05)"] * 3),
        ["nudge it right by 0.05 for waypoints 1 to 7, then left for the next 7, alternating"],
        [],
    )
    assert code == program("t = shift(t, 'right', 0.05, alternate=7)")
    assert notes[-1].reader == "alternating-shifts"

"""A weave or a loop a clause asks and no step makes gets its step (readers.asked_shapes).

Written from fresh-c (new instructions: "weave side to side", "throw in one full loop"); the
wordings here are none of any set's.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.asked_shapes import add_asked_shapes, asked_shape
from trajadapt.readers.direction_words import said_directions

NAMES = ["lamp", "king snake", "crate"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("clause", "step"),
    [
        ("slalom your way to the goal", "t = zigzag(t)"),
        ("sway from side to side while flying", "t = zigzag(t)"),
        ("make the route serpentine", "t = zigzag(t)"),
        ("sweep from side to side as you go", "t = zigzag(t)"),
        ("let the drone oscillate sideways on its way", "t = zigzag(t)"),
        ("meander towards the goal", "t = zigzag(t)"),
        ("give it a sinusoidal wobble", "t = zigzag(t)"),
        ("do three loops at some point", "t = spiral(t, turns=3)"),
        ("add a 360 on the way", "t = spiral(t)"),
        ("orbit the crate once before leaving", "t = circle_around(t, detect_objects('crate'), turns=1)"),
        ("go round the lamp in two full circles", "t = circle_around(t, detect_objects('lamp'), turns=2)"),
    ],
)  # fmt: skip
def test_the_step_a_shape_clause_asks(clause: str, step: str) -> None:
    shape = asked_shape(clause, NAMES)
    assert shape is not None and shape.step == step


@pytest.mark.parametrize(
    "clause",
    [
        "iron out the wiggles",  # a shape taken away
        "make it less wavy",
        "no rocking from side to side, please",
        "slow down near the oscillating fan",  # an adjective
        "keep the gripper level from side to side",  # no verb of swinging
        "go straight instead of weaving",
        "don't loop around the lamp",
        "pass close to the king snake",  # an object's name, not a weave
        "follow a half circle around the crate",  # an arc, not a loop
        "the path zigzags too much",  # how the path is now
    ],
)
def test_clauses_that_ask_no_shape(clause: str) -> None:
    assert asked_shape(clause, NAMES) is None


def test_a_dropped_weave_is_added_after_the_moves() -> None:
    code, notes = add_asked_shapes(
        program("t = move_away(t, detect_objects('crate'))", "t = scale_speed(t, 0.8)"),
        ["stay further from the crate, snake along the way and slow down a bit"],
        NAMES,
    )
    assert code.splitlines()[1:-1] == [
        "t = move_away(t, detect_objects('crate'))",
        "t = zigzag(t)",
        "t = scale_speed(t, 0.8)",
    ]
    assert "snake along the way" in notes[0]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("wiggle along the way", "t = zigzag(t, 0.05, cycles=6)"),
        ("wiggle along the way", "t = shift(t, 'left', 0.1, alternate=5)"),  # a shift in blocks weaves
        ("loop twice", "t = circle_around(t, detect_objects('lamp'))"),
        (
            "alternate 0.1 left and right in blocks of 5 points",
            "t = shift(t, 'left', 0.1)\nt = shift(t, 'right', 0.1)",
        ),
    ],
)
def test_a_shape_a_step_makes_is_left_alone(words: str, step: str) -> None:
    assert add_asked_shapes(program(step), [words], NAMES) == (program(step), [])


def test_whole_path_shifts_both_ways_with_no_blocks_weave_nowhere() -> None:
    """ "Weave side to side a few times" answered right, left, right, left: the shifts cancel out."""
    steps = ("t = shift(t, 'right', 'slightly')", "t = shift(t, 'left', 'slightly')")
    code, notes = add_asked_shapes(program(*steps), ["weave side to side a few times"], NAMES)
    assert code.splitlines()[1:-1] == [*steps, "t = zigzag(t)"] and "weave side to side" in notes[0]


def test_code_beyond_the_skills_is_left_alone() -> None:
    code = program("t[:, 0] += 0.1")
    assert add_asked_shapes(code, ["weave about"], NAMES) == (code, [])


@pytest.mark.parametrize("words", ["rock back and forth as you go", "drift to and fro", "swing side to side"])
def test_a_swing_both_ways_says_no_direction(words: str) -> None:
    assert said_directions(words) == set()


def test_the_stage_drops_a_made_up_shift_and_adds_the_weave() -> None:
    code, notes = read_against_words(
        program("t = shift(t, 'back')"), ["Zig-zag back and forth on the way."], NAMES
    )
    assert code.splitlines()[1:-1] == ["t = zigzag(t)"]
    assert any(note.reader == "asked-shapes" for note in notes)

"""A step about an object the words never name serves no clause (readers.unnamed_objects)."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.unnamed_objects import leave_out_unnamed

NAMES = ["lemon", "Siberian husky", "red marker", "cup"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("step", "words", "after"),
    [
        ("t = scale_speed(t, 1.4, near=detect_objects('lemon'))", "speed it up", "t = scale_speed(t, 1.4)"),
        ("t = set_speed(t, 0.2, near=detect_objects('cup'), radius=0.1)", "hold a speed of 0.2",
         "t = set_speed(t, 0.2)"),
        ("t = scale_speed(t, 0.6, near=midpoint(detect_objects('cup'), detect_objects('lemon')))",
         "slow the whole thing down", "t = scale_speed(t, 0.6)"),
        ("t = spiral(t, turns=3, at=detect_objects('cup'))", "after the goal make a spiral of 3 turns",
         "t = spiral(t, turns=3)"),
    ],
)  # fmt: skip
def test_a_place_at_an_unnamed_object_goes_and_the_step_stays(step: str, words: str, after: str) -> None:
    code, notes = leave_out_unnamed(program(step), [words], NAMES)
    assert code.splitlines()[1] == after
    assert "never name" in notes[0]


@pytest.mark.parametrize(
    "step",
    [
        "t = move_away(t, detect_objects('lemon'))",
        "t = move_closer(t, detect_objects('red marker'), 'a bit')",
        "t = avoid(t, detect_objects('cup'), 0.3)",
        "t = pass_over(t, [detect_objects('cup'), detect_objects('lemon')], 'a bit')",
    ],
)
def test_a_move_by_unnamed_objects_alone_is_left_out(step: str) -> None:
    code, notes = leave_out_unnamed(program("t = shift(t, 'right', 0.3)", step), ["go right by 0.3"], NAMES)
    assert code.splitlines()[1:-1] == ["t = shift(t, 'right', 0.3)"]
    assert notes == [f"left out `{step}`: the words never name " + notes[0].split("never name ")[1]]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        (
            "t = move_closer(t, detect_objects('Siberian husky'))",
            "get closer to the husky",
        ),  # one of its words
        ("t = move_away(t, detect_objects('RED MARKER'))", "keep away from the red marker"),  # any case
        (
            "t = pass_over(t, [detect_objects('cup'), detect_objects('lemon')])",
            "pass over the cup",
        ),  # one named
        ("t = move_away(t, detect_objects('lemon'))", "stay clear of every obstacle"),  # objects in general
        ("t = avoid(t, detect_objects('cup'), 0.2)", "keep 0.2 from anything in the scene"),
        ("t = wait(t, detect_objects('cup'), 5)", "pause in the middle for 5 steps"),  # no default place
        ("t = scale_speed(t, 1.4, part='middle')", "faster in the middle"),  # no object at all
    ],
)
def test_named_objects_objects_in_general_and_pauses_stay(step: str, words: str) -> None:
    code = program(step)
    assert leave_out_unnamed(code, [words], NAMES) == (code, [])


def test_a_move_by_an_unnamed_object_gives_way_to_the_asked_direction() -> None:
    """Left out, the program keeps the path; the clause's direction and number come back as a shift."""
    code, notes = read_against_words(
        program("t = pass_over(t, [detect_objects('cup'), detect_objects('lemon')], 'a bit')"),
        ["slide the route 0.3 over to the right"],
        NAMES,
    )
    assert code.splitlines()[1:-1] == ["t = shift(t, 'right', 0.3)"]
    assert [note.reader for note in notes][:1] == ["unnamed-objects"]

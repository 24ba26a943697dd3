"""A turn of the whole path takes the angle and the sense its clause says."""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.bench.judges import CheckContext, run_check
from trajadapt.model.geometry import PAPER_AXES
from trajadapt.readers import read_against_words
from trajadapt.readers.asked_turns import turn_as_asked
from trajadapt.skills.shape import rotate


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "written", "expected"),
    [
        ("rotate the whole path a quarter turn counter-clockwise as seen from above", 90, -90),
        ("pivot the route about 30 degrees anticlockwise", 30, -30),
        ("swivel it 45° clockwise", -45, 45),
        ("turn the path through a right angle to the left", 90, -90),
        ("turn everything a quarter of a turn to the right", -30, 90),
        ("rotate the route half a turn", -90, -180),  # no sense said: the model's sign stays
        ("rotate the path by 20 degrees", -30, -20),
        ("spin the trajectory counterclockwise", 45, -45),  # no size said: the model's size stays
    ],
)
def test_the_clause_gives_the_angle_and_its_sign(words: str, written: int, expected: int) -> None:
    code, notes = turn_as_asked(program(f"t = rotate(t, {written})"), [words])
    assert code.splitlines()[1] == f"t = rotate(t, {expected})" and len(notes) == 1


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        ("rotate it 30 degrees clockwise", ["t = rotate(t, 30)"]),  # already as said
        ("rotate it clockwise", ["t = rotate(t, degrees=15)"]),
        ("rotate it 30 degrees clockwise, then rotate it 10 more", ["t = rotate(t, 30)"]),  # two turns asked
        ("rotate it 30 degrees clockwise", ["t = rotate(t, 30)", "t = rotate(t, 10)"]),  # two turns written
        ("shift it left by 0.2", ["t = rotate(t, 30)"]),  # no turn asked: other readers' matter
        ("rotate the path 30 degrees about its left end", ["t = rotate(t, 30)"]),  # a place, no sense
        ("swing out to the left around the box", ["t = rotate(t, 10)"]),  # no verb of turning
        ("make a three quarter turn clockwise", ["t = rotate(t, 270)"]),  # not a quarter
    ],
)
def test_what_the_words_say_or_cannot_tell_is_left(words: str, steps: list[str]) -> None:
    assert turn_as_asked(program(*steps), [words]) == (program(*steps), [])


def test_a_keyword_angle_is_read_too() -> None:
    code, _ = turn_as_asked(program("t = rotate(t, degrees=60)"), ["rotate it 60 degrees anti-clockwise"])
    assert code.splitlines()[1] == "t = rotate(t, degrees=-60)"


@pytest.mark.parametrize("sense", ["counter-clockwise", "clockwise"])
def test_the_turn_made_is_the_one_the_judges_measure(sense: str) -> None:
    path = np.column_stack([np.zeros(20), np.linspace(0, 1, 20), np.full(20, 0.5), np.full(20, 0.2)])
    code, _ = read_against_words(program("t = rotate(t, 90)"), [f"rotate it a quarter turn {sense}"], [])
    degrees = float(code.splitlines()[1].split(", ")[1].rstrip(")"))
    asked = -90 if sense.startswith("counter") else 90
    context = CheckContext(path, rotate(path, degrees), {}, PAPER_AXES)
    assert run_check(context, {"kind": "rotated", "degrees": asked}).passed

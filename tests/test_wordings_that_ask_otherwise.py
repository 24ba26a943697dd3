"""Wordings close to those this session's readers read, that ask something else (a review's findings).

Each reading was built for one form ("the goal has to stay", "no more than 0.25 from X", "end
there", "the start is out of bounds: move it"); these are the near misses a review found, read
through all the readers, with the code that must come out.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words

NAMES = ["mug", "lamp"]


def steps_after(words: str, *steps: str, names: list[str] = NAMES) -> list[str]:
    code = "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])
    return read_against_words(code, [words], names)[0].splitlines()[1:-1]


@pytest.mark.parametrize(
    ("words", "steps", "expected"),
    [
        # a negative amount that already goes the asked way is no sign slip
        ("lower the path by 10 cm", ["t = shift(t, 'up', -0.1)"], ["t = shift(t, 'up', -0.1)"]),
        # "by 0.1 or more", "0.2 at least" of a move closer are no clearance
        ("move closer to the lamp by 10 cm or more", ["t = move_closer(t, detect_objects('lamp'), 0.1)"],
         ["t = move_closer(t, detect_objects('lamp'), 0.1)"]),
        ("bring the path nearer to the lamp, 20 cm at least", ["t = move_closer(t, detect_objects('lamp'), 0.2)"],
         ["t = move_closer(t, detect_objects('lamp'), 0.2)"]),
        # "no more than 0.1" of a move is no reach to come within
        ("move a bit closer to the lamp, by no more than 10 cm", ["t = move_closer(t, detect_objects('lamp'), 0.1)"],
         ["t = move_closer(t, detect_objects('lamp'), 0.1)"]),
        # "it" after an end said to be fine is the path
        ("the start looks fine. now raise it by 10 cm", ["t = shift(t, 'up', 0.1)"], ["t = shift(t, 'up', 0.1)"]),
        # a pause there, or a negated end there, ends nowhere
        ("go to the mug and park there for a few seconds", ["t = pass_through(t, detect_objects('mug'))"],
         ["t = pass_through(t, detect_objects('mug'))"]),
        ("swing over to the mug but don't finish there, carry on 20 cm further forward",
         ["t = pass_through(t, detect_objects('mug'))", "t = extend(t, 0.2, 'front')"],
         ["t = pass_through(t, detect_objects('mug'))", "t = extend(t, 0.2, 'front')"]),
        # a stretch after "after" is a time, not the part that moves
        ("move the path up 10 cm after the first half", ["t = shift(t, 'up', 0.1)"], ["t = shift(t, 'up', 0.1)"]),
        # "as fast as you can" is a request of its own
        ("go as fast as you can and slow down near the lamp",
         ["t = scale_speed(t, 1.4)", "t = scale_speed(t, 0.65, near=detect_objects('lamp'))"],
         ["t = scale_speed(t, 1.4)", "t = scale_speed(t, 0.65, near=detect_objects('lamp'))"]),
        # the stretch's own step with amount= gets no second amount
        ("bow the middle of the path about 15 cm to the left",
         ["t = shift(t, 'left', 0.15)", "t = lift_middle(t, 'left', amount=0.15)"],
         ["t = lift_middle(t, 'left', amount=0.15)"]),
        # "the goal should be put next to the lamp" moves the goal
        ("the goal should be put right next to the lamp", ["t = reach(t, detect_objects('lamp'))"],
         ["t = reach(t, detect_objects('lamp'))"]),
        # a factor equal to another clause's distance still goes where its pace is
        ("raise the path by 0.5 and go slower near the lamp", ["t = shift(t, 'up', 0.5)", "t = scale_speed(t, 0.5)"],
         ["t = shift(t, 'up', 0.5)", "t = scale_speed(t, 0.5, near=detect_objects('lamp'))"]),
        # coming to a quick stop is braking, no pause; a halt at an object keeps its speed 0
        ("come to a quick stop at the goal", ["t = speed_profile(t, 'decelerate', start=0.6)"],
         ["t = speed_profile(t, 'decelerate', start=0.6)"]),
        ("slow down and halt completely at the lamp", ["t = set_speed(t, 0, near=detect_objects('lamp'))"],
         ["t = set_speed(t, 0, near=detect_objects('lamp'))"]),
        # a brief stop where the path passes nearest is a pause, not the end
        ("stop briefly where it passes closest to the lamp", ["t = wait(t, detect_objects('lamp'), 10)"],
         ["t = wait(t, detect_objects('lamp'), 10)"]),
    ],
)  # fmt: skip
def test_a_near_miss_asks_what_it_says(words: str, steps: list[str], expected: list[str]) -> None:
    assert steps_after(words, *steps) == expected


def test_a_shape_word_is_no_other_name_of_an_object() -> None:
    assert steps_after("make the spiral wider", "t = spiral(t)", names=["coil", "lamp"]) == ["t = spiral(t)"]

"""A height given with its relation; a height step with the wrong relation gets the asked one."""

from __future__ import annotations

import pytest

from trajadapt.readers.height_asks import relate_heights
from trajadapt.readers.height_words import asked_heights

CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("words", "heights"),
    [
        ("fly at an altitude of 2.5 over the field", [("set_height", 2.5)]),
        ("hover at 1 near the lamp", [("set_height", 1.0)]),
        ("never go higher than 3", [("stay_below", 3.0)]),  # a negation turns the relation round
        ("do not exceed 3 and stay above 0.5", [("stay_below", 3.0), ("stay_above", 0.5)]),
        ("stay at least 0.2 over the floor", [("stay_above", 0.2)]),
        ("keep under 1.2", [("stay_below", 1.2)]),
        ("hold an elevation of 0.6", [("set_height", 0.6)]),  # a level with no "at"
        ("raise the height 0.2", []),  # no "at", no "of": not read as a level
        ("don't climb above z = 0.4", [("stay_below", 0.4)]),  # a height named by its axis
        ("keep over a z of 0.15", [("stay_above", 0.15)]),
        ("please never allow the gripper to sink under 0.7", [("stay_above", 0.7)]),  # negation words away
        ("don't slow down, and stay under 0.4", [("stay_below", 0.4)]),  # a negation of another clause
        ("hold at least 0.3 away from the vase, and stay over 0.1", [("stay_above", 0.1)]),  # a distance
        ("keep a height of at least 0.3 from the floor", [("stay_above", 0.3)]),  # a height from the floor
        ("cap its elevation at 0.9", [("stay_below", 0.9)]),  # a limit said as a cap
        ("respect a ceiling of 2.5", [("stay_below", 2.5)]),
        ("a minimum height of 0.25 throughout", [("stay_above", 0.25)]),
        ("allow a maximum of 3 loops", []),  # a maximum of something else
        ("cap the speed at 2", []),
        ("nothing along the route may rise above 0.6", [("stay_below", 0.6)]),  # a negative pronoun
        ("none of the waypoints should sink under 0.05", [("stay_above", 0.05)]),
        # a level said of the height itself (a height word first)
        ("the altitude over the floor has to be kept at 0.25", [("set_height", 0.25)]),
        ("fix the elevation at 0.4", [("set_height", 0.4)]),
        ("have the height set to 0.15", [("set_height", 0.15)]),
        ("keep the pace held at 0.4", []),  # a pace
    ],
)
def test_the_words_around_a_height_say_its_relation(words: str, heights: list[tuple[str, float]]) -> None:
    assert asked_heights(words) == heights


def test_a_height_step_with_the_asked_number_and_another_relation_is_replaced() -> None:
    code, notes = relate_heights(CODE.format(step="t = stay_below(t, 0.4)"), ["cruise at a height of 0.4"])
    assert "t = set_height(t, 0.4)" in code.splitlines()
    assert "asks for a height of 0.4" in notes[0]


@pytest.mark.parametrize(
    ("step", "words", "replaced"),
    [
        ("t = set_height(t, 0.4, keep_goal=False)", "stay below 0.4", "t = stay_below(t, 0.4)"),
        ("t = set_height(t, -0.2, keep_start=True, keep_goal=True)", "keep it above z = -0.2", "t = stay_above(t, -0.2)"),
    ],
)  # fmt: skip
def test_a_height_step_with_options_or_below_zero_takes_the_asked_relation(
    step: str, words: str, replaced: str
) -> None:
    assert replaced in relate_heights(CODE.format(step=step), [words])[0].splitlines()


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = stay_below(t, 0.4)", "stay below 0.4"),  # already right
        ("t = stay_below(t, 0.3)", "cruise at a height of 0.4"),  # another number
        ("t = stay_below(t, 0.4)", "fly at 0.4 and never under 0.2"),  # two heights
    ],
)
def test_right_relations_other_numbers_and_two_heights_stay(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert relate_heights(code, [words]) == (code, [])


@pytest.mark.parametrize(
    ("words", "step", "shift"),
    [  # wordings of a change in none of the sets
        ("sink the route by 0.15", "t = set_height(t, 0.15)", "t = shift(t, 'down', 0.15)"),
        ("elevate everything 0.3 and slow down", "t = stay_above(t, 0.3)", "t = shift(t, 'up', 0.3)"),
        (
            "go 0.05 higher near the cup",
            "t = set_height(t, 0.05, keep_goal=True)",
            "t = shift(t, 'up', 0.05)",
        ),
        ("bring it down 0.2 then speed up", "t = stay_below(t, 0.2)", "t = shift(t, 'down', 0.2)"),
    ],
)
def test_a_height_step_holding_the_amount_of_a_move_up_or_down_becomes_that_shift(
    words: str, step: str, shift: str
) -> None:
    code, notes = relate_heights(CODE.format(step=step), [words])
    assert shift in code.splitlines()
    assert "moves the path" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = set_height(t, 0.1)", "hold an altitude of 0.1 above the ground"),  # a level
        ("t = set_height(t, 0.1)", "stay 0.1 up from the floor"),  # a level over the floor
        ("t = set_height(t, 0.2)", "rise by 0.3"),  # another number
        ("t = set_height(t, 0.2)", "move 0.2 to the left"),  # not up or down
        ("t = set_height(t, 0.2)\nt = stay_below(t, 0.2)", "rise by 0.2"),  # two height steps
    ],
)
def test_levels_other_numbers_and_other_directions_keep_the_height_step(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert relate_heights(code, [words]) == (code, [])


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        ("t = avoid(t, [0, 0, 0], 0.3)", "cruise at an altitude of 0.3 above the floor", "t = set_height(t, 0.3)"),
        ("t = move_away(t, (0.0, 0.0, 0.0), 0.5)", "never go below 0.5, the rotors need room", "t = stay_above(t, 0.5)"),
        # a clearance from a named object or by another number is kept, and the height is added after it
        ("t = avoid(t, detect_objects('lamp'), 0.3)", "fly at a height of 0.3",
         "t = avoid(t, detect_objects('lamp'), 0.3)\nt = set_height(t, 0.3)"),
        ("t = avoid(t, [0, 0, 0], 0.2)", "fly at a height of 0.3", "t = avoid(t, [0, 0, 0], 0.2)\nt = set_height(t, 0.3)"),
    ],
)  # fmt: skip
def test_a_clearance_from_a_made_up_point_by_the_asked_height_becomes_the_height_step(
    step: str, words: str, expected: str
) -> None:
    code = f"t = get_trajectory()\n{step}\nmodified_trajectory = t"
    changed, notes = relate_heights(code, [words])
    assert changed == code.replace(step, expected)
    assert len(notes) == 1


@pytest.mark.parametrize(
    ("words", "added"),
    [
        ("never climb above 1.2, and hurry", "t = stay_below(t, 1.2)"),
        ("keep the altitude at least 0.4 the whole way", "t = stay_above(t, 0.4)"),
    ],
)
def test_a_height_no_step_keeps_is_added_last(words: str, added: str) -> None:
    code, notes = relate_heights(CODE.format(step="t = scale_speed(t, 1.4)"), [words])
    assert code.splitlines()[1:-1] == ["t = scale_speed(t, 1.4)", added]
    assert "no step keeps it" in notes[0]


@pytest.mark.parametrize(
    "words",
    [
        "keep more than 0.5 away from the box",  # a distance, not a height
        "stay at least 0.3 clear of the lamp",
    ],
)
def test_a_number_of_distance_adds_no_height(words: str) -> None:
    code = CODE.format(step="t = move_away(t, detect_objects('box'))")
    assert relate_heights(code, [words]) == (code, [])


def test_a_limit_no_step_keeps_is_added_beside_a_clearance() -> None:
    words = "Stay more than 0.2 away from the vase, and never let it climb above 0.6."
    step = "t = move_away(t, detect_objects('vase'), 0.2)"
    code, notes = relate_heights(CODE.format(step=step), [words])
    assert code.splitlines()[1:-1] == [step, "t = stay_below(t, 0.6)"]
    assert notes


@pytest.mark.parametrize(
    ("words", "added"),
    [
        ("mid-flight, hold it at least 0.5 off the floor", "t = stay_above(t, 0.5, keep_ends=True)"),
        ("in the middle of the run keep at least 0.25 m up", "t = stay_above(t, 0.25, keep_ends=True)"),
        ("let the middle section sag, at most z = 0.1 there", "t = stay_below(t, 0.1, keep_ends=True)"),
        ("never dip under 0.2 at any point", "t = stay_above(t, 0.2)"),
    ],
)
def test_a_limit_held_through_the_middle_keeps_the_ends(words: str, added: str) -> None:
    code, _ = relate_heights(CODE.format(step="t = scale_speed(t, 1.4)"), [words])
    assert code.splitlines()[1:-1] == ["t = scale_speed(t, 1.4)", added]


def test_the_models_limit_held_through_the_middle_gets_the_ends_kept() -> None:
    code, notes = relate_heights(
        CODE.format(step="t = stay_above(t, 0.3)"), ["through the midway stretch stay above 0.3"]
    )
    assert code.splitlines()[1] == "t = stay_above(t, 0.3, keep_ends=True)" and notes


@pytest.mark.parametrize(
    ("words", "heights"),
    [
        ("never let the gripper sink under 85 cm", [("stay_above", 0.85)]),
        ("keep it below 1200 mm the whole time", [("stay_below", 1.2)]),
        ("fly at a height of 2 m", [("set_height", 2.0)]),
    ],
)
def test_a_height_in_a_metric_unit_is_read_in_metres(words: str, heights: list[tuple[str, float]]) -> None:
    found = asked_heights(words)
    assert [skill for skill, _ in found] == [skill for skill, _ in heights]
    assert [height for _, height in found] == pytest.approx([height for _, height in heights])

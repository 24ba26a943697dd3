"""A move the words place on a part of the path (start, goal, past the goal, first N waypoints)."""

from __future__ import annotations

import pytest

from trajadapt.readers.part_scope import PartMove, part_moves, scope_to_parts

CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("words", "move"),
    [
        ("move the start point a bit to the right", PartMove("the start", "right", "a bit")),
        ("move the initial position up by 0.3", PartMove("the start", "up", 0.3)),
        ("put the end position further back", PartMove("the goal", "back", None)),
        ("after arriving at the goal go up by 2.5", PartMove("past the goal", "up", 2.5)),
        (
            "keep going further once you reach the destination",
            PartMove("past the goal", None, None, goes_on=True),
        ),
        ("shift the first 8 waypoints downwards", PartMove("the first 8 waypoints", "down", None, 8)),
        ("push the first five points left", PartMove("the first 5 waypoints", "left", None, 5)),
        ("nudge the initial 3 waypoints right", PartMove("the first 3 waypoints", "right", None, 3)),
        ("the opening four points should drop", PartMove("the first 4 waypoints", "down", None, 4)),
        ("lift the leading 7 waypoints", PartMove("the first 7 waypoints", "up", None, 7)),
        ("the end point: drop it by 0.1", PartMove("the goal", "down", 0.1)),  # a topic said first
        ("starting point: nudge it back", PartMove("the start", "back", None)),
        # "there" right after a clause naming the goal is the goal
        ("head for the goal as before; when it's there, drift 0.1 up", PartMove("past the goal", "up", 0.1)),
        # a stretch of the path (fresh-p): its own shift_part
        (
            "push the first half of the path 6 cm forward",
            PartMove("the first half", "front", 0.06, named="first half"),
        ),
        ("lower the second half by 0.1", PartMove("the second half", "down", 0.1, named="second half")),
        ("drag the middle of the route a bit left", PartMove("the middle", "left", "a bit", named="middle")),
        # "it" right after a clause whose subject is an end is that end
        ("the start is out of bounds: move it 1 m to the left", PartMove("the start", "left", 1.0)),
        ("the goal sits too close to the wall, so pull it back by 0.2", PartMove("the goal", "back", 0.2)),
    ],
)
def test_a_clause_that_names_a_part_and_a_direction_asks_to_move_that_part(
    words: str, move: PartMove
) -> None:
    assert part_moves(words) == [move]


@pytest.mark.parametrize(
    "words",
    [
        "go left keeping the goal position where it is",  # the goal is kept, the path moves
        "slow down before the goal position",  # about speed
        "go left and reach the goal",  # the direction's clause names no part
        "start going up by 0.2",  # 'start' as a verb
        "lower the speed near the end point",
        "shift the start point up-left",  # two directions: which part moves where?
        "go past the lamp; once there, drift 0.1 up",  # "there" is the lamp: no goal before it
    ],
)
def test_clauses_that_keep_a_part_or_say_no_move_of_it_ask_nothing(words: str) -> None:
    assert part_moves(words) == []


def test_a_whole_path_shift_becomes_a_shift_of_the_start_and_keeps_its_amount() -> None:
    code, notes = scope_to_parts(
        CODE.format(step="t = shift(t, 'front', 0.4)"), ["nudge the starting position forward by 0.4"]
    )
    assert "t = shift_start(t, 'front', 0.4)" in code.splitlines()
    assert "moves the start, not the whole path" in notes[0]


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        ("t = shift_goal(t, 'left', 0.5)", "drive left by 0.5 after the goal", "t = extend(t, 0.5, 'left')"),
        ("t = move_closer(t, detect_objects('goal'))", "after reaching the goal go up by 1", "t = extend(t, 1.0, 'up')"),
        ("t = move_away(t, detect_objects('goal'))", "continue further past the goal", "t = extend(t)"),
        ("t = move_away(t, detect_objects('goal'), 'a bit')", "the goal point a little lower", "t = shift_goal(t, 'down', 'a little')"),
        ("t = shift(t, 'down')", "the first 4 waypoints go lower", "t = shift_part(t, 'down', part=(0, 4))"),
        ("t = shift_goal(t, 'up', 0.3)", "hoist everything up 0.3, a bit nearer the box", "t = shift(t, 'up', 0.3)"),
        ("t = shift_start(t, 'left')", "bear left", "t = shift(t, 'left')"),  # no part named: all of it
        ("t = shift_start(t, 'back')", "upon reaching the goal, retreat back a bit", "t = extend(t, 'a bit', 'back')"),
        ("t = extend(t, 0.3, 'up')\nt = stop_at(t, detect_objects('goal'))", "once at the end, rise 0.3",
         "t = extend(t, 0.3, 'up')"),  # the stop at the goal cut the extension off
        ("t = shift_part(t, 'up', part='end')", "head for the upper region", "t = shift(t, 'up')"),
        ("t = shift_part(t, 'down', 0.1, part='end')", "sink into the lower part by 0.1", "t = shift(t, 'down', 0.1)"),
        ("t = move_closer(t, detect_objects('goal'))", "once at the goal, keep moving for another 0.4", "t = extend(t, 0.4)"),
        # past the goal, a shift nobody's words say stands for the move ("back up" is back)
        ("t = shift(t, 'down', 0.7)", "when it's reached the end, pull back 0.7", "t = extend(t, 0.7, 'back')"),
        ("t = shift(t, 'up', 2)", "once you're at the destination, back up by 2", "t = extend(t, 2, 'back')"),
    ],
)  # fmt: skip
def test_the_step_written_for_the_part_is_replaced(step: str, words: str, expected: str) -> None:
    code, notes = scope_to_parts(CODE.format(step=step), [words])
    assert expected in code.splitlines() and len(notes) == 1


@pytest.mark.parametrize(
    ("steps", "words", "expected"),
    [
        ("t = shift(t, 'left', 0.15)\nt = lift_middle(t, 'left')", "bow the middle about 0.15 to the left",
         ["t = lift_middle(t, 'left', 0.15)"]),
        ("t = shift(t, 'up', 0.1)\nt = shift_part(t, 'up', 0.1, part='second half')", "raise the second half by 0.1",
         ["t = shift_part(t, 'up', 0.1, part='second half')"]),
    ],
)  # fmt: skip
def test_a_stretch_already_moved_that_way_loses_the_whole_shift(
    steps: str, words: str, expected: list[str]
) -> None:
    """One clause read twice: a whole-path shift beside the stretch's own move leaves, its amount kept."""
    code, notes = scope_to_parts(CODE.format(step=steps), [words])
    assert code.splitlines()[1:-1] == expected and "move only" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        (
            "t = shift(t, 'left')\nt = extend(t, 0.2, 'left')",
            "go left by 0.2 after the goal",
        ),  # already goes on
        ("t = shift(t, 'left')\nt = shift(t, 'left', 0.1)", "shift the start to the left"),  # which one?
        ("t = shift(t, 'up')", "shift the start to the left"),  # no step in that direction
        (
            "t = move_closer(t, detect_objects('box'))",
            "move the goal position left",
        ),  # an object, not a landmark
    ],
)
def test_steps_that_already_do_it_or_are_ambiguous_stay(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert scope_to_parts(code, [words]) == (code, [])


@pytest.mark.parametrize(
    "words",
    [
        "the new goal is halfway between the lamp and the box",
        "finish at the lamp",
        "the goal should be the lamp",
        "take the lamp as the new destination, arriving there smoothly",  # named before "new"
        "change the destination to the lamp",  # a verb that sets the goal
        "please move the goal point onto the lamp",
        "use the lamp as the goal and curve in gently",
    ],
)
def test_a_new_goal_makes_the_path_end_at_the_point_instead_of_passing_it(words: str) -> None:
    code, notes = scope_to_parts(CODE.format(step="t = pass_through(t, detect_objects('lamp'))"), [words])
    assert "t = reach(t, detect_objects('lamp'))" in code.splitlines()
    assert "gives a new goal" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = pass_through(t, detect_objects('lamp'))", "pass through the lamp"),  # no new goal
        (
            "t = pass_through(t, detect_objects('lamp'))\nt = reach(t, detect_objects('box'))",
            "finish at the box",
        ),
        ("t = move_closer(t, detect_objects('goal'))", "the new goal is further left"),  # the path's own end
    ],
)
def test_passing_by_an_existing_reach_or_the_old_goal_stay(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert scope_to_parts(code, [words]) == (code, [])


def test_going_on_past_the_goal_with_no_direction_takes_the_shift_in_a_direction_nobody_said() -> None:
    code, _ = scope_to_parts(
        CODE.format(step="t = shift_goal(t, 'right', 0.1)"), ["go further by 0.1 after the goal"]
    )
    assert "t = extend(t, 0.1)" in code.splitlines()
    said = CODE.format(step="t = shift(t, 'right', 0.1)")  # a direction said is the path's own move
    code, _ = scope_to_parts(said, ["go right, then further after the goal"])
    assert code.splitlines()[1:-1] == ["t = shift(t, 'right', 0.1)", "t = extend(t)"]


def test_a_goal_moved_against_the_whole_paths_shift_ends_on_the_other_side_and_the_middle_keeps_it() -> None:
    step = "t = shift(t, 'left', 0.2)\nt = shift(t, 'right', 0.1)"
    code, notes = scope_to_parts(
        CODE.format(step=step), ["go left by 0.2 but the goal position right by 0.1"]
    )
    assert code.splitlines()[1:-1] == [
        "t = shift(t, 'left', 0.2)",
        "t = shift_part(t, 'right', 0.2, part='end')",
        "t = shift_part(t, 'right', 0.1, part='end')",
    ]
    assert "against the rest's shift" in notes[0]


@pytest.mark.parametrize(
    ("step", "words"),
    [
        ("t = shift(t, 'left')", "go left from the start"),  # the start is a place, the path moves
        ("t = shift(t, 'up')", "go up until the goal position"),
        ("t = move_closer(t, detect_objects('box'))", "go closer to the box and end at the goal"),
    ],
)
def test_a_part_named_as_a_place_or_a_goal_without_the_object_is_not_a_move_of_it(
    step: str, words: str
) -> None:
    code = CODE.format(step=step)
    assert scope_to_parts(code, [words]) == (code, [])


@pytest.mark.parametrize(
    ("words", "step", "expected"),
    [  # written for this reader, in words none of the benchmark sets has
        ("Pull the first 4 waypoints toward the cup", "t = move_closer(t, detect_objects('cup'))",
         "t = move_closer(t, detect_objects('cup'), part=(0, 4))"),
        ("the first ten points should keep further away from the vase",
         "t = move_away(t, detect_objects('vase'), 'a bit')",
         "t = move_away(t, detect_objects('vase'), 'a bit', part=(0, 10))"),
        ("go left, and bring the first 3 points nearer the lamp", "t = move_closer(t, detect_objects('lamp'), 'a lot')",
         "t = move_closer(t, detect_objects('lamp'), 'a lot', part=(0, 3))"),
    ],
)  # fmt: skip
def test_an_object_move_of_the_first_waypoints_is_made_on_them(words: str, step: str, expected: str) -> None:
    code, notes = scope_to_parts(CODE.format(step=step), [words])
    assert expected in code.splitlines()
    assert "moves the first" in notes[-1]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("bring the path closer to the cup", "t = move_closer(t, detect_objects('cup'))"),  # no part named
        (
            "the first 4 waypoints closer to the cup",
            "t = move_closer(t, detect_objects('mug'))",
        ),  # another object
        (
            "the first 4 waypoints closer to the cup",
            "t = move_away(t, detect_objects('cup'))",
        ),  # the other way
        ("the first 4 waypoints closer to the cup", "t = move_closer(t, detect_objects('cup'), part='end')"),
    ],
)
def test_object_moves_the_clause_does_not_place_on_the_first_waypoints_stay(words: str, step: str) -> None:
    assert scope_to_parts(CODE.format(step=step), [words]) == (CODE.format(step=step), [])


@pytest.mark.parametrize("words", ["finish precisely at the lamp", "terminate directly on the lamp"])
def test_stopping_where_the_path_passes_an_object_said_as_its_end_is_a_new_goal(words: str) -> None:
    code, notes = scope_to_parts(CODE.format(step="t = stop_at(t, detect_objects('lamp'))"), [words])
    assert code.splitlines()[1:-1] == ["t = reach(t, detect_objects('lamp'))"]
    assert "gives a new goal" in notes[0]


def test_a_stop_at_an_object_with_no_new_goal_stays() -> None:
    code = CODE.format(step="t = stop_at(t, detect_objects('lamp'))")
    assert scope_to_parts(code, ["stop when you get near the lamp"]) == (code, [])


def test_a_whole_path_shift_beside_the_part_move_it_repeats_leaves() -> None:
    code = "t = get_trajectory()\nt = shift_part(t, 'up', 0.1, 'end')\nt = shift(t, 'up', 0.1)\nmodified_trajectory = t"
    read, notes = scope_to_parts(code, ["raise the end of the path 0.1, keeping the start where it is"])
    assert "t = shift(t, 'up', 0.1)" not in read.splitlines() and notes
    both = scope_to_parts(code, ["move everything up 0.1 and the end up another 0.1"])[0]
    assert both == code  # a clause with no part says up too
    other = code.replace("shift(t, 'up', 0.1)", "shift(t, 'up', 0.2)")
    words = ["raise the whole path 0.2 from start to end, and lift the end a further 0.1"]
    assert scope_to_parts(other, words)[0] == other  # another amount: another clause's step


def test_a_whole_path_shift_beside_the_going_on_it_repeats_leaves() -> None:
    code = "t = get_trajectory()\nt = extend(t, 0.5, direction='left')\nt = shift(t, 'left', 0.5)\nmodified_trajectory = t"
    read, notes = scope_to_parts(code, ["carry the route on half a metre to the left past its end"])
    assert "t = shift(t, 'left', 0.5)" not in read.splitlines() and notes
    both = ["shift everything 0.5 left, then go on another 0.5 left past the goal"]
    assert scope_to_parts(code, both)[0] == code  # a clause with no part says left too


@pytest.mark.parametrize(
    ("words", "expected"),
    [
        ("raise the entire route by 0.3", "t = shift(t, 'up', 0.3)"),  # the whole path, ends included
        ("bring all of the trajectory down 0.3", "t = lift_middle(t, 'up', 0.3)"),  # another direction: left
        ("raise the route in an arc by 0.3", "t = lift_middle(t, 'up', 0.3)"),  # no whole path said
        ("raise the whole path by 0.3, keeping the start and goal", "t = lift_middle(t, 'up', 0.3)"),
        # every point of the path (session 37: fresh-aa's "lift every point of the trajectory")
        ("move each waypoint 0.3 higher", "t = shift(t, 'up', 0.3)"),
        ("raise all the points by 0.3", "t = shift(t, 'up', 0.3)"),
        ("raise the middle points by 0.3", "t = lift_middle(t, 'up', 0.3)"),
        ("raise every point by 0.3 and wait for 4 waypoints by the box", "t = shift(t, 'up', 0.3)"),
        (
            "raise each waypoint near the box by 0.3",
            "t = lift_middle(t, 'up', 0.3)",
        ),  # a place: no whole path
    ],
)
def test_a_lift_of_the_middle_is_the_whole_path_s_shift_where_the_words_say_the_whole_path(
    words: str, expected: str
) -> None:
    code, _ = scope_to_parts(CODE.format(step="t = lift_middle(t, 'up', 0.3)"), [words])
    assert code == CODE.format(step=expected)


@pytest.mark.parametrize(
    "words", ["for the first steps, go 10 cm left", "move the final ten waypoints 10 cm left"]
)
def test_waypoints_or_steps_that_name_a_part_are_no_pause_length(words: str) -> None:
    code = CODE.format(step="t = shift_part(t, 'left', 0.1, part='end')")
    assert "shift_part" in scope_to_parts(code, [words])[0]

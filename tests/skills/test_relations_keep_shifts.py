"""A shift and a closer/further step in one program keep both promises (issue #24, item 4).

"Go up by 0.2 and a bit closer to the table" with the table below: run one after the other, the
closer step pulled the path down again and the shift lost half its amount. Measured from the
original path (``reference``), the relation step reaches its distance across the shift instead.
"""

import ast

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.rewrite import measure_from_original
from trajadapt.sandbox.runner import ExecutionOptions
from trajadapt.skills import bind_skills
from trajadapt.skills.objects import _fraction, _weight, move_away, move_closer

SKILL = bind_skills()


def arc(n: int = 41, height: float = 1.0) -> np.ndarray:
    """A path going front along a shallow arc at ``height``, speed 1."""
    s = np.linspace(0.0, 1.0, n)
    return np.c_[0.2 * np.sin(np.pi * s), s, np.full(n, height), np.ones(n)]


points = st.tuples(st.floats(-1.0, 1.0), st.floats(-0.5, 1.5), st.floats(-1.0, 2.0))


@settings(max_examples=100, deadline=None)
@given(points, st.sampled_from([None, "a bit", "a lot", 0.5]))
def test_without_a_reference_closer_is_the_straight_move_towards_the_point(point, amount):
    before = arc()
    target = np.asarray(point)
    weight = _fraction(amount) * _weight(before, target)
    expected = before[:, :3] + weight[:, None] * (target - before[:, :3])
    assert np.allclose(move_closer(before, target, amount)[:, :3], expected, atol=1e-9)


@settings(max_examples=100, deadline=None)
@given(
    points,
    st.sampled_from(["up", "down", "left", "front"]),
    st.floats(0.05, 0.4),
    st.sampled_from(["a bit", None]),
)
def test_closer_after_a_shift_keeps_the_shift_and_never_ends_further(point, direction, amount, closer):
    original = arc()
    target = np.asarray(point)
    shifted = SKILL["shift"](original, direction, amount)
    after = move_closer(shifted, target, closer, reference=original)
    change = shifted[:, :3] - original[:, :3]
    moved = after[:, :3] - shifted[:, :3]
    assert np.allclose(np.sum(moved * change, axis=1), 0.0, atol=1e-9)  # nothing along the shift
    distance = np.linalg.norm(after[:, :3] - target, axis=1)
    assert np.all(distance <= np.linalg.norm(shifted[:, :3] - target, axis=1) + 1e-9)


def test_up_and_closer_to_a_table_below_does_both():
    original = arc()
    table = np.array([1.2, 0.5, 0.6])
    shifted = SKILL["shift"](original, "up", 0.2)
    after = move_closer(shifted, table, "a bit", reference=original)
    middle = len(original) // 2
    assert after[middle, 2] - original[middle, 2] == pytest.approx(0.2, abs=1e-9)
    assert np.linalg.norm(after[middle, :3] - table) < np.linalg.norm(original[middle, :3] - table) - 0.05
    plain = move_closer(shifted, table, "a bit")  # the old composition lost part of the rise
    assert plain[middle, 2] - original[middle, 2] < 0.15


def test_away_after_a_rise_towards_the_object_still_ends_further_than_the_original():
    original = arc()
    lamp = np.array([-0.3, 0.5, 1.4])
    shifted = SKILL["shift"](original, "up", 0.1)
    after = move_away(shifted, lamp, 0.1, reference=original)
    middle = len(original) // 2
    assert after[middle, 2] - original[middle, 2] == pytest.approx(0.1, abs=1e-9)
    assert np.linalg.norm(after[middle, :3] - lamp) > np.linalg.norm(original[middle, :3] - lamp) + 0.05


def test_a_reference_of_another_length_is_ignored():
    original = arc()
    point = np.array([0.5, 0.5, 1.0])
    assert np.allclose(move_closer(original, point, reference=arc(11)), move_closer(original, point))


def rewritten(code: str) -> tuple[str, list[str]]:
    tree = ast.parse(code)
    notes = measure_from_original(tree)
    return ast.unparse(tree), notes


def test_the_relation_step_runs_after_the_shift_measured_from_the_original():
    code, notes = rewritten(
        "t = get_trajectory()\n"
        "t = move_closer(t, detect_objects('table'), 'a bit')\n"
        "table = detect_objects('table')\n"
        "t = shift(t, 'up', 0.2)\n"
        "modified_trajectory = t\n"
    )
    assert code.splitlines() == [
        "t = get_trajectory()",
        "table = detect_objects('table')",
        "t = shift(t, 'up', 0.2)",
        "t = move_closer(t, detect_objects('table'), 'a bit', reference=get_trajectory())",
        "modified_trajectory = t",
    ]
    assert len(notes) == 1 and "move_closer" in notes[0]


@pytest.mark.parametrize(
    "code",
    [
        "t = get_trajectory()\nt = move_closer(t, detect_objects('box'))\nmodified_trajectory = t\n",
        "t = get_trajectory()\nt = shift(t, 'up', 0.2)\nt = scale_speed(t, 0.5)\n",
        "t = get_trajectory()\nt = move_away(t, detect_objects('box'))\nt = wait(t, 'goal', 5)\nt = shift(t, 'up')\n",
        "t = get_trajectory()\nt = shift(t, 'up')\nt = move_away(t, detect_objects('box'), reference=t)\n",
        "t = get_trajectory()\nt = shift(t, 'up')\nu = move_away(t, detect_objects('box'))\n",
    ],
    ids=["no-shift", "no-relation", "a-step-between", "reference-given", "another-variable"],
)
def test_other_programs_are_left_as_written(code):
    assert rewritten(code) == (ast.unparse(ast.parse(code)), [])


def test_in_the_sandbox_a_rise_and_a_closer_step_both_hold(sandbox):
    original = arc()
    scene = Scene((SceneObject("table", 1.2, 0.5, 0.6),))
    code = (
        "t = get_trajectory()\n"
        "t = move_closer(t, detect_objects('table'), 'a bit')\n"
        "t = shift(t, 'up', 0.2)\n"
        "modified_trajectory = t\n"
    )
    result = sandbox.run(code, Trajectory(original), scene, ExecutionOptions(skills=True))
    assert result.ok, result.error
    after = np.asarray(result.rows)
    middle = len(original) // 2
    assert after[middle, 2] - original[middle, 2] == pytest.approx(0.2, abs=1e-6)
    assert np.linalg.norm(after[middle, :3] - [1.2, 0.5, 0.6]) < np.linalg.norm(
        original[middle, :3] - [1.2, 0.5, 0.6]
    )
    assert any("measured from the original path" in note for note in result.notes)


def test_the_path_up_and_the_goal_down_ends_below_the_old_goal_with_the_middle_still_up():
    original = arc()
    raised = SKILL["shift"](original, "up", 0.1)
    after = SKILL["shift_goal"](raised, "down", 0.1, reference=original)
    assert after[-1, 2] - original[-1, 2] == pytest.approx(-0.1, abs=1e-9)
    assert after[len(original) // 2, 2] - original[len(original) // 2, 2] > 0.04
    assert np.allclose(after[0], original[0])
    plain = SKILL["shift_goal"](raised, "down", 0.1)  # before: the two cancelled at the goal
    assert plain[-1, 2] == pytest.approx(original[-1, 2], abs=1e-9)


def test_an_end_moved_the_same_way_as_the_path_adds_up():
    original = arc()
    raised = SKILL["shift"](original, "up", 0.1)
    after = SKILL["shift_start"](raised, "up", 0.1, reference=original)
    assert np.allclose(after, SKILL["shift_start"](raised, "up", 0.1))


def test_an_end_step_beside_a_shift_is_measured_from_the_original():
    code, notes = rewritten(
        "t = get_trajectory()\nt = shift_goal(t, 'down', 'a little')\nt = shift(t, 'up', 'a little')\n"
    )
    assert code.splitlines()[1:] == [
        "t = shift(t, 'up', 'a little')",
        "t = shift_goal(t, 'down', 'a little', reference=get_trajectory())",
    ]
    assert "shift_goal" in notes[0]

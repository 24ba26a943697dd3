"""A limit step runs after the moves written after it, so that its limit still holds (sandbox.rewrite)."""

from __future__ import annotations

import ast

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.rewrite import limits_last
from trajadapt.sandbox.runner import ExecutionOptions


def rewritten(code: str) -> tuple[list[str], list[str]]:
    tree = ast.parse(code)
    notes = limits_last(tree)
    return ast.unparse(tree).splitlines(), notes


def test_a_clearance_runs_after_a_move_towards_another_object():
    lines, notes = rewritten(
        "t = get_trajectory()\n"
        "t = avoid(t, detect_objects('bottle'), 1.0)\n"
        "t = move_closer(t, detect_objects('table'))\n"
        "t = scale_speed(t, 0.8)\n"
        "modified_trajectory = t\n"
    )
    assert lines[1:4] == [
        "t = move_closer(t, detect_objects('table'))",
        "t = scale_speed(t, 0.8)",
        "t = avoid(t, detect_objects('bottle'), 1.0)",
    ]
    assert len(notes) == 1 and "its limit still holds" in notes[0]


@pytest.mark.parametrize(
    "code",
    [
        # the move names the object kept clear of: the two contradict each other, left as written
        "t = get_trajectory()\nt = avoid(t, detect_objects('box'), 0.5)\nt = move_closer(t, detect_objects('box'))\n",
        # an end at a point after the limit is the program's own business
        "t = get_trajectory()\nt = stay_below(t, 0.4)\nt = reach(t, detect_objects('box'))\n",
        "t = get_trajectory()\nt = shift(t, 'up')\nt = stay_below(t, 0.4)\n",  # already last
    ],
    ids=["same-object", "an-end-after", "already-last"],
)
def test_other_programs_are_left_as_written(code):
    assert rewritten(code) == (ast.unparse(ast.parse(code)).splitlines(), [])


def line(n: int = 41) -> np.ndarray:
    """A straight path going front at height 0.5, speed 1."""
    s = np.linspace(0.0, 1.0, n)
    return np.c_[np.zeros(n), 2 * s, np.full(n, 0.5), np.ones(n)]


@settings(max_examples=20, deadline=None)
@given(st.floats(0.3, 0.8), st.sampled_from(["left", "right", "up"]), st.floats(0.05, 0.4))
def test_in_the_sandbox_the_clearance_holds_after_the_move(sandbox, clearance, direction, amount):
    scene = Scene((SceneObject("bottle", 0.1, 1.0, 0.5), SceneObject("table", 1.5, 1.0, 0.5)))
    code = (
        "t = get_trajectory()\n"
        f"t = avoid(t, detect_objects('bottle'), {clearance:.3f})\n"
        f"t = shift(t, {direction!r}, {amount:.3f})\n"
        "modified_trajectory = t\n"
    )
    result = sandbox.run(code, Trajectory(line()), scene, ExecutionOptions(skills=True))
    assert result.ok, result.error
    nearest = np.linalg.norm(np.asarray(result.rows)[:, :3] - np.array([0.1, 1.0, 0.5]), axis=1).min()
    assert nearest >= round(clearance, 3) - 1e-6


@settings(max_examples=10, deadline=None)
@given(st.floats(0.3, 0.8), st.floats(0.2, 1.0))
def test_a_clearance_holds_after_a_smoothing_written_after_it(sandbox, clearance, strength):
    scene = Scene((SceneObject("bottle", 0.1, 1.0, 0.5),))
    code = (
        "t = get_trajectory()\n"
        f"t = avoid(t, detect_objects('bottle'), {clearance:.3f})\n"
        f"t = smooth(t, strength={strength:.3f})\n"
        "modified_trajectory = t\n"
    )
    result = sandbox.run(code, Trajectory(line()), scene, ExecutionOptions(skills=True))
    assert result.ok, result.error
    nearest = np.linalg.norm(np.asarray(result.rows)[:, :3] - np.array([0.1, 1.0, 0.5]), axis=1).min()
    assert nearest >= round(clearance, 3) - 1e-6


@settings(max_examples=10, deadline=None)
@given(
    st.floats(0.3, 0.6),
    st.sampled_from(
        ["t = scale_about(t, detect_objects('bottle'), 0.5)", "t = rotate(t, 20)", "t = exaggerate_curve(t)"]
    ),
)
def test_a_height_cap_holds_after_a_reshaping_written_after_it(sandbox, cap, reshaping):
    scene = Scene((SceneObject("bottle", 0.1, 1.0, 1.5),))
    code = f"t = get_trajectory()\nt = stay_below(t, {cap:.3f})\n{reshaping}\nmodified_trajectory = t\n"
    result = sandbox.run(code, Trajectory(line()), scene, ExecutionOptions(skills=True))
    assert result.ok, result.error
    assert np.asarray(result.rows)[:, 2].max() <= round(cap, 3) + 1e-6

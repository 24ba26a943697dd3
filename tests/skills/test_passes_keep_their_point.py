"""A step that puts the path through a point keeps it when moves are written after it (issue #24, item 4).

"Fly over the cycle, then finish 0.3 further right" came back as ``pass_over`` then ``shift_goal``:
run as written, the goal's move dragged the pass off the cycle. ``passes_last`` runs the passes after
the moves beside them, so both promises hold.
"""

import ast

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.rewrite import passes_last
from trajadapt.sandbox.runner import ExecutionOptions


def arc(n: int = 41) -> np.ndarray:
    """A path going front along a shallow arc at height 1, speed 1."""
    s = np.linspace(0.0, 1.0, n)
    return np.c_[0.2 * np.sin(np.pi * s), s, np.ones(n), np.ones(n)]


def rewritten(code: str) -> tuple[list[str], list[str]]:
    tree = ast.parse(code)
    notes = passes_last(tree)
    return ast.unparse(tree).splitlines(), notes


def test_a_pass_runs_after_the_moves_written_after_it():
    lines, notes = rewritten(
        "t = get_trajectory()\n"
        "t = pass_over(t, detect_objects('cycle'))\n"
        "t = scale_speed(t, 0.5)\n"
        "t = shift_goal(t, 'right', 0.3)\n"
        "modified_trajectory = t\n"
    )
    assert lines == [
        "t = get_trajectory()",
        "t = scale_speed(t, 0.5)",
        "t = shift_goal(t, 'right', 0.3)",
        "t = pass_over(t, detect_objects('cycle'))",
        "modified_trajectory = t",
    ]
    assert len(notes) == 1 and "pass_over() runs after the moves" in notes[0]


@pytest.mark.parametrize(
    "code",
    [
        "t = get_trajectory()\nt = shift(t, 'up')\nt = pass_through(t, detect_objects('box'))\n",
        "t = get_trajectory()\nt = pass_through(t, detect_objects('box'))\nt = scale_speed(t, 0.5)\n",
        "t = get_trajectory()\nt = pass_through(t, detect_objects('box'))\nt = spiral(t)\nt = shift(t, 'up')\n",
        "t = get_trajectory()\nt = pass_through(t, detect_objects('box'))\nu = shift(t, 'up')\n",
    ],
    ids=["already-last", "only-a-speed-after", "an-event-between", "another-variable"],
)
def test_other_programs_are_left_as_written(code):
    assert rewritten(code) == (ast.unparse(ast.parse(code)).splitlines(), [])


@settings(max_examples=25, deadline=None)
@given(
    st.tuples(st.floats(-0.3, 0.3), st.floats(0.2, 0.8), st.floats(0.8, 1.3)),
    st.sampled_from(["shift_goal", "shift_start", "shift", "lift_middle"]),
    st.sampled_from(["left", "right", "up", "front"]),
)
def test_in_the_sandbox_the_path_still_passes_the_point(sandbox, point, move, direction):
    scene = Scene((SceneObject("box", *point),))
    code = (
        "t = get_trajectory()\n"
        "t = pass_through(t, detect_objects('box'))\n"
        f"t = {move}(t, {direction!r}, 0.2)\n"
        "modified_trajectory = t\n"
    )
    result = sandbox.run(code, Trajectory(arc()), scene, ExecutionOptions(skills=True))
    assert result.ok, result.error
    closest = np.linalg.norm(np.asarray(result.rows)[:, :3] - np.asarray(point), axis=1).min()
    assert closest < 1e-6

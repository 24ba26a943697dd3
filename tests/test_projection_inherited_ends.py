"""The projection leaves alone a limit the original path already broke at its start or goal (issue #24).

A case's own path may start below its floor or inside an object's clearance; when the adapted path
breaks something new elsewhere, the projection used to move that start onto the limit too, and the
result then moved a start nobody asked to move.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.checks.constraints import Constraints, find_violations
from trajadapt.checks.projection import project
from trajadapt.model.scene import Scene, SceneObject

FLOOR = Constraints(lower=(-math.inf, -math.inf, 0.0), upper=(0.5, math.inf, math.inf))


def line(count: int, start_z: float, end_z: float) -> np.ndarray:
    s = np.linspace(0.0, 1.0, count)
    return np.c_[np.zeros(count), 2 * s, start_z + (end_z - start_z) * s, np.ones(count)]


@settings(max_examples=30, deadline=None)
@given(
    st.integers(12, 60),
    st.floats(-0.3, -0.01),
    st.floats(-0.3, -0.01),
    st.floats(0.55, 1.5),
)
def test_ends_that_already_broke_a_bound_stay_where_they_were(
    count: int, start_z: float, end_z: float, too_far: float
) -> None:
    original = line(count, start_z, end_z)
    adapted = original.copy()
    adapted[1:-1, 0] += too_far  # the middle now breaks x <= 0.5: a new violation
    result = project(adapted, original, Scene(()), FLOOR)
    assert np.allclose(result.trajectory[[0, -1], :3], original[[0, -1], :3])
    assert result.trajectory[1:-1, 0].max() <= 0.5 + 1e-6  # the new violation is still projected away


def test_a_start_inside_an_objects_clearance_stays_and_the_rest_keeps_clear() -> None:
    original = line(40, 0.5, 0.5)
    scene = Scene((SceneObject("box", 0.0, 0.05, 0.5),))  # the original starts 0.05 from the box
    limits = Constraints(min_clearance=0.3, upper=(0.5, math.inf, math.inf))
    adapted = original.copy()
    adapted[10:30, 0] += 1.0  # a bulge past x = 0.5
    result = project(adapted, original, scene, limits)
    assert np.allclose(result.trajectory[0, :3], original[0, :3])
    assert result.trajectory[:, 0].max() <= 0.5 + 1e-6


def test_an_end_the_code_moved_is_still_projected() -> None:
    original = line(30, 0.2, 0.2)
    adapted = original.copy()
    adapted[0, 2] = -0.2  # the code itself moved the start below the floor: that is new, and fixed
    result = project(adapted, original, Scene(()), FLOOR)
    assert result.trajectory[0, 2] >= -1e-6
    assert not find_violations(result.trajectory, original, Scene(()), FLOOR)


def test_the_note_says_which_limits_were_left_as_the_original_has_them() -> None:
    original = line(30, -0.1, 0.2)
    adapted = original.copy()
    adapted[5:25, 0] += 1.0
    result = project(adapted, original, Scene(()), FLOOR)
    assert result.remaining == ()
    assert len(result.as_original) == 1 and "z below 0" in result.as_original[0]
    assert "left as the original has them (at an end, or outside the room): " in result.describe()


@settings(max_examples=30, deadline=None)
@given(st.floats(-0.45, 0.45), st.floats(0.3, 1.2), st.floats(0.51, 0.9))
def test_an_end_the_code_moved_within_the_limits_stays_where_the_code_put_it(
    goal_shift: float, bulge: float, too_far: float
) -> None:
    original = line(40, 0.2, 0.2)
    adapted = original.copy()
    adapted[:, 0] += goal_shift * np.linspace(0.0, 1.0, 40) ** 2  # the goal moved sideways, within x <= 0.5
    adapted[15:25, 0] += too_far * np.sin(np.linspace(0.0, np.pi, 10)) * bulge  # a bulge that breaks x <= 0.5
    result = project(adapted, original, Scene(()), FLOOR)
    np.testing.assert_allclose(result.trajectory[[0, -1], :3], adapted[[0, -1], :3], atol=1e-9)
    assert not find_violations(result.trajectory, original, Scene(()), FLOOR)

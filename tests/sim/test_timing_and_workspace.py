"""Waypoint timing from speeds and the map into a robot's workspace (no pybullet needed)."""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.sim.reference import build_reference, waypoint_times
from trajadapt.sim.workspace import WorkspaceBox, fit_workspace


def test_times_follow_distance_over_speed() -> None:
    points = np.c_[np.arange(5.0), np.zeros(5), np.zeros(5)]
    times = waypoint_times(points, np.full(5, 2.0))
    assert np.allclose(times, [0, 0.5, 1.0, 1.5, 2.0])


def test_a_start_at_rest_and_a_pause_get_finite_times() -> None:
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 0, 0], [2, 0, 0]], dtype=float)
    times = waypoint_times(points, np.array([0.0, 1.0, 0.0, 1.0]))
    assert np.all(np.diff(times) > 0) and np.isfinite(times).all()
    assert np.isclose(times[2] - times[1], times[1] - times[0])  # the pause lasts one nominal step


def test_no_speed_at_all_is_refused() -> None:
    with pytest.raises(ValueError, match="speed 0"):
        waypoint_times(np.eye(3), np.zeros(3))


def test_reference_interpolates_in_time() -> None:
    reference = build_reference(np.array([[0, 0, 0], [2, 0, 0]], dtype=float), np.array([1.0, 1.0]))
    assert np.allclose(reference.position(1.0), [1, 0, 0])
    assert np.allclose(reference.velocity(1.0), [1, 0, 0])
    assert np.allclose(reference.position(99.0), [2, 0, 0])


def test_fit_shrinks_never_enlarges_and_centres() -> None:
    box = WorkspaceBox(centre=(0.5, 0.0, 0.4), size=(0.4, 0.4, 0.4))
    big = np.array([[-10, -10, 0], [10, 10, 5]], dtype=float)
    mapping = fit_workspace(big, box)
    assert np.isclose(mapping.scale, 0.02)
    assert np.allclose(mapping.to_robot(big).mean(axis=0), box.centre)
    small = np.array([[0, 0, 0], [0.1, 0.1, 0.1]])
    assert fit_workspace(small, box).scale == 1.0
    assert np.allclose(mapping.to_case(mapping.to_robot(big)), big)
    mirrored = fit_workspace(big, box, mirror_x=True)  # the paper's +X left is the robot's -x
    assert (
        mirrored.to_robot(np.array([[10.0, 0, 0]]))[0, 0] < mirrored.to_robot(np.array([[-10.0, 0, 0]]))[0, 0]
    )
    assert np.allclose(mirrored.to_case(mirrored.to_robot(big)), big)
    flat = fit_workspace(big, box, flat_z=0.0)
    assert flat.offset[2] == 0.0 and "x case" in flat.describe()

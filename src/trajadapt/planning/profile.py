"""From a planner's polyline to a trajectory: even spacing, rounded corners, a speed profile."""

from __future__ import annotations

import numpy as np

from trajadapt.planning.obstacles import Array


def resample_rounded(points: Array, count: int, window: int = 5) -> Array:
    """``count`` points evenly spaced along the polyline, corners rounded by a moving average.

    The ends stay exactly where they were.
    """
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    total = float(steps.sum())
    if total <= 0:
        return np.repeat(points[:1], count, axis=0)
    s = np.concatenate([[0.0], np.cumsum(steps)]) / total
    target = np.linspace(0.0, 1.0, count)
    dense = np.stack([np.interp(target, s, points[:, k]) for k in range(points.shape[1])], axis=1)
    half = window // 2
    padded = np.pad(dense, ((half, half), (0, 0)), mode="edge")
    kernel = np.ones(window) / window
    rounded = np.stack(
        [np.convolve(padded[:, k], kernel, mode="valid") for k in range(points.shape[1])], axis=1
    )
    rounded[[0, -1]] = dense[[0, -1]]
    return rounded


def trapezoidal_speeds(count: int, top: float, ramp: float = 0.15) -> Array:
    """Speed rising over the first ``ramp`` of the waypoints, cruising at ``top``, falling to 0 at the goal.

    The first waypoint gets a tiny positive speed so the trajectory can be timed from rest.
    """
    s = np.linspace(0.0, 1.0, count)
    speeds = top * np.clip(np.minimum(s, 1.0 - s) / ramp, 0.0, 1.0)
    speeds[0] = max(speeds[1] * 0.1, 1e-3 * top)
    return speeds

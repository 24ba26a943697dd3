"""Waypoints placed evenly again over a stretch where a step grew far longer than the original's longest.

A 1.5 m clearance pushed round a fan, or a path scaled twice about an object, keeps its number of
waypoints: the steps across the detour grow to 4-6 times the original's longest, which a controller
meets as a jump (``review.JUMP_FACTOR``). The waypoints of the stretch around each long step are
placed again at equal distances along a smooth curve through the stretch's own waypoints
(Catmull-Rom); the stretch's two ends and every waypoint outside it stay where they are, speeds stay
with their waypoints, and a stretch never takes in a pause (waypoints at one position).
"""

from __future__ import annotations

import numpy as np

from trajadapt.checks.review import JUMP_FACTOR
from trajadapt.model.geometry import Array

EVEN_SHARE = 0.5
"""A stretch grows until its mean step is at most this share of the longest step allowed."""
SAMPLES = 64  # points of the curve per step of the stretch, to measure its length


def evened_steps(trajectory: Array, original: Array) -> Array | None:
    """``trajectory`` with the stretches around its too-long steps evened out, or None where none is.

    Too long: more than ``JUMP_FACTOR`` times the original's longest step. None also where evening
    out leaves the longest step no shorter.
    """
    allowed = JUMP_FACTOR * float(_steps(original).max(initial=0.0))
    steps = _steps(trajectory)
    if allowed <= 0 or steps.max(initial=0.0) <= allowed:
        return None
    evened = trajectory.copy()
    for first, last in _stretches(steps, EVEN_SHARE * allowed):
        evened[first : last + 1, :3] = _even_along(trajectory[:, :3], first, last)
    return evened if _steps(evened).max() < steps.max() else None


def _steps(trajectory: Array) -> Array:
    lengths: Array = np.linalg.norm(np.diff(trajectory[:, :3], axis=0), axis=1)
    return lengths


def _stretches(steps: Array, mean_step: float) -> list[tuple[int, int]]:
    """(first, last) of each stretch: round a long step, grown until its mean step is ``mean_step``."""
    paused = steps <= 1e-12 * max(float(steps.max()), 1.0)
    stretches: list[tuple[int, int]] = []
    for step in np.flatnonzero(steps > 2 * mean_step):
        if stretches and step < stretches[-1][1]:
            continue  # inside the stretch already made
        first, last = int(step), int(step) + 1
        while steps[first:last].sum() > mean_step * (last - first):
            grow_back = first > 0 and not paused[first - 1]
            grow_on = last < len(steps) and not paused[last]
            if not (grow_back or grow_on):
                break
            if grow_back and (not grow_on or steps[first - 1] <= steps[last]):
                first -= 1
            else:
                last += 1
        if stretches and first <= stretches[-1][1]:
            first = stretches.pop()[0]
        stretches.append((first, last))
    return stretches


def _even_along(points: Array, first: int, last: int) -> Array:
    """Waypoints ``first``..``last`` at equal distances along a Catmull-Rom curve through them."""
    through = points[max(first - 1, 0) : last + 2]
    offset = 1 if first > 0 else 0
    segments = [_segment(through, k) for k in range(offset, offset + last - first)]
    curve = np.vstack([segments[0][:1], *(segment[1:] for segment in segments)])
    length = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(curve, axis=0), axis=1))]
    wanted = np.linspace(0.0, length[-1], last - first + 1)
    placed = np.stack([np.interp(wanted, length, curve[:, axis]) for axis in range(3)], axis=1)
    placed[[0, -1]] = points[[first, last]]
    return placed


def _segment(points: Array, k: int) -> Array:
    """The Catmull-Rom curve from ``points[k]`` to ``points[k + 1]`` (at the ends, tangents from the ends)."""
    before, start, end = points[max(k - 1, 0)], points[k], points[k + 1]
    after = points[min(k + 2, len(points) - 1)]
    s = np.linspace(0.0, 1.0, SAMPLES + 1)[:, None]
    out_tangent, in_tangent = (end - before) / 2, (after - start) / 2
    curve: Array = (
        (2 * s**3 - 3 * s**2 + 1) * start
        + (s**3 - 2 * s**2 + s) * out_tangent
        + (-2 * s**3 + 3 * s**2) * end
        + (s**3 - s**2) * in_tangent
    )
    return curve

"""Skills that add or remove waypoints: stop, wait, extend past the goal, go on to a point, spirals, loops."""

from __future__ import annotations

from typing import Any

import numpy as np

from trajadapt.model.geometry import PAPER_AXES, Array, Axes, extent, progress
from trajadapt.skills.core import (
    DirectionArg,
    DistanceArg,
    PointArg,
    TrajectoryArg,
    WaypointArg,
    as_point,
    as_trajectory,
    nearest_index,
    resolve_amount,
)

POSITION_WORDS = ("start", "beginning", "middle", "center", "goal", "end")
"""Words that name a waypoint of the path."""


def _index(t: Array, at: Any) -> int:
    """A waypoint index from an index, 'start'/'middle'/'goal', or a point (its nearest waypoint)."""
    if isinstance(at, str):
        last, middle = len(t) - 1, len(t) // 2
        words = dict(zip(POSITION_WORDS, (0, 0, middle, middle, last, last), strict=True))
        if at.strip().lower() not in words:
            raise ValueError(
                f"unknown position {at!r}; use an index, a point (for an object: detect_objects({at!r})), "
                f"or one of {', '.join(words)}"
            )
        return words[at.strip().lower()]
    if isinstance(at, int | np.integer):
        return int(at) % len(t)
    return nearest_index(t, at)


BESIDE_GAP = 0.07
"""How far from an object (a share of the path's size) an end beside it stops."""
WITHIN_SHARE = 0.8
"""How much of a stated distance an end within it stops at ("within 0.4 of the person": 0.32 at most)."""


def stop_at(
    trajectory: TrajectoryArg, point: PointArg, *, beside: bool = False, within: float | None = None
) -> Array:
    """End the trajectory at the waypoint nearest to point (later waypoints removed, velocity 0 there).

    ``beside`` (set by the readers for "end next to the sofa", "park right beside it"): where that
    waypoint is further than ``BESIDE_GAP`` of the path's size from the point, the path then goes
    on in a straight line to that distance from it, on the side it comes from. ``within`` (set by the
    readers for "come to rest within 0.4 of the person"): where that waypoint is further than the
    distance, on to beside it and at most ``WITHIN_SHARE`` of the distance from it.
    """
    t = as_trajectory(trajectory)
    k = max(nearest_index(t, point), 1)
    stopped = t[: k + 1].copy()
    if beside or within is not None:
        centre, gap = as_point(point), BESIDE_GAP * extent(t)
        offset = stopped[-1, :3] - centre
        distance = float(np.linalg.norm(offset))
        if within is not None and float(within) > 0:  # the nearest pass within it is enough
            gap = distance if distance <= float(within) else min(gap, WITHIN_SHARE * float(within))
        step = float(np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).mean())
        if distance > gap and step > 1e-12:  # spaced as the path, at most its length; on at the speed it had
            count = int(np.clip(np.ceil((distance - gap) / step), 2, len(t)))
            return append_segment(stopped, centre + offset / distance * gap, count)
    stopped[-1, 3] = 0.0
    return stopped


def wait(trajectory: TrajectoryArg, at: WaypointArg, steps: int) -> Array:
    """Pause steps timesteps at a waypoint (an index, 'start', 'middle', 'goal', or a point).

    Pause for steps timesteps at a waypoint (an index, 'start', 'middle', 'goal', or a point): inserts
    that many copies of it with velocity 0.
    """
    t = as_trajectory(trajectory)
    if _is_count(at) and not _is_count(steps):
        at, steps = steps, at  # wait(t, 7, 'goal'): the count came first
    k = _index(t, at)
    pause = np.repeat(t[k : k + 1], max(int(steps), 0), axis=0)
    pause[:, 3] = 0.0
    return np.vstack([t[: k + 1], pause, t[k + 1 :]])


def _is_count(value: Any) -> bool:
    """Whether value is a whole number (not a word, a position or a bool)."""
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


# Direction words that mean "keep going the way the path ends" rather than a fixed axis.
HEADING_WORDS = frozenset({"", "goal", "heading", "straight", "along", "same", "onward", "onwards"})


def extend(
    trajectory: TrajectoryArg,
    distance: DistanceArg = None,
    direction: DirectionArg | None = None,
    count: int = 10,
    *,
    axes: Axes = PAPER_AXES,
) -> Array:
    """Continue past the goal by distance, along the final heading or in a direction word.

    Continue past the goal by distance (default 20% of the path's size), along the final heading or in a
    direction ('left', 'back', 'up', ...), adding count waypoints.
    """
    t = as_trajectory(trajectory)
    length = resolve_amount(distance, t, default_word="large") if distance is not None else 0.2 * extent(t)
    along = direction is None or str(direction).strip().lower() in HEADING_WORDS
    heading = _final_heading(t) if along else axes.vector(str(direction))
    return append_segment(t, t[-1, :3] + heading * length, count)


def _final_heading(t: Array) -> Array:
    for k in range(len(t) - 1, 0, -1):
        step = t[k, :3] - t[k - 1, :3]
        norm = np.linalg.norm(step)
        if norm > 1e-12:
            return step / norm
    raise ValueError("the trajectory does not move, so it has no final heading; give a direction")


def append_segment(trajectory: TrajectoryArg, point: PointArg, count: int = 10) -> Array:
    """After the goal, go on in a straight line to point, adding count waypoints (the robot stops there).

    The added waypoints keep the pace of ``going_on_pace``; the old goal no longer rests.
    """
    t = as_trajectory(trajectory)
    target = as_point(point)
    count = max(int(count), 1)
    fractions = np.linspace(1.0 / count, 1.0, count)[:, None]
    pace = going_on_pace(t)
    segment = np.hstack([t[-1, :3] + fractions * (target - t[-1, :3]), np.full((count, 1), pace)])
    segment[-1, 3] = 0.0
    moving = t.copy()
    moving[-1, 3] = pace
    return np.vstack([moving, segment])


APPROACH_SHARE = 0.2
"""How far back (share of the path) the pace a path arrives with is looked for: a path slowing the
whole way would otherwise go on at its top speed, and one slowing over its last waypoints at a crawl."""


def going_on_pace(trajectory: Array) -> float:
    """The pace a path goes on at past its goal: its speed at the goal, or the pace it arrives with.

    A path that comes to rest at its goal goes on at the speed its final slowing began with, looked
    for at most ``APPROACH_SHARE`` of the path back from its last moving waypoint (not its top speed
    elsewhere, nor the crawl of its last waypoint); one with no moving waypoint, at its top speed.
    """
    speeds = trajectory[:, 3]
    if speeds[-1] > 0:
        return float(speeds[-1])
    moving = np.flatnonzero(speeds[:-1] > 0)
    if not moving.size:
        return float(speeds.max())
    s = progress(trajectory)
    k = int(moving[-1])
    while k > 0 and speeds[k - 1] >= speeds[k] and s[moving[-1]] - s[k - 1] <= APPROACH_SHARE:
        k -= 1
    return float(speeds[k])


def spiral(
    trajectory: TrajectoryArg,
    max_radius: DistanceArg = None,
    turns: float = 3.0,
    at: WaypointArg = "goal",
    count: int = 60,
    *,
    axes: Axes = PAPER_AXES,
) -> Array:
    """Add a horizontal spiral (max_radius, turns) at the goal, or at the waypoint nearest 'at'.

    A horizontal spiral growing to max_radius over turns, at the goal (appended) or at the waypoint
    nearest a point/object (inserted: spirals out and back in, then the path continues).
    """
    t = as_trajectory(trajectory)
    radius = resolve_amount(max_radius, t, default_word="a bit")
    k = _index(t, at)
    grow = np.linspace(0.0, 1.0, int(count))
    profile = grow if k == len(t) - 1 else np.sin(np.pi * grow)
    loop = _horizontal_loop(t[k, :3], radius * profile, turns * 2 * np.pi * grow, axes)
    return _insert_loop(t, k, loop)


def circle_around(
    trajectory: TrajectoryArg,
    center: PointArg,
    radius: DistanceArg = None,
    turns: float = 1.0,
    count: int = 40,
    *,
    axes: Axes = PAPER_AXES,
) -> Array:
    """Circle turns times around center (e.g. an object), then continue the path.

    Leave the path at the waypoint nearest center, circle around center turns times at radius (default:
    the current distance), and come back to continue the path.
    """
    t = as_trajectory(trajectory)
    middle = as_point(center, "center")
    k = nearest_index(t, middle)
    up = axes.vector("up")
    offset = t[k, :3] - middle
    offset -= (offset @ up) * up
    start_radius = float(np.linalg.norm(offset))
    size = resolve_amount(radius, t) if radius is not None else max(start_radius, 0.05 * extent(t))
    phase = (
        np.arctan2(offset @ axes.vector("front"), offset @ axes.vector("right"))
        if start_radius > 1e-12
        else 0.0
    )
    angles = phase + np.linspace(0.0, 2 * np.pi * float(turns), int(count))
    blend = np.sin(np.linspace(0.0, np.pi, int(count)))
    radii = start_radius + (size - start_radius) * np.minimum(1.0, 3 * blend)
    loop = _circle_points(middle + (t[k, :3] - middle) @ up * up, radii, angles, axes)
    return _insert_loop(t, k, loop)


def _horizontal_loop(center: Array, radii: Array, angles: Array, axes: Axes) -> Array:
    return (
        _circle_points(center, radii, angles, axes)
        - _circle_points(center, radii[:1], angles[:1], axes)
        + center
    )


def _circle_points(center: Array, radii: Array, angles: Array, axes: Axes) -> Array:
    right, front = axes.vector("right"), axes.vector("front")
    return center + radii[:, None] * (np.cos(angles)[:, None] * right + np.sin(angles)[:, None] * front)


def _insert_loop(t: Array, k: int, loop: Array) -> Array:
    speed = float(t[k, 3] if t[k, 3] > 0 else max(t[:, 3].max(), 1e-3))
    rows = np.hstack([loop, np.full((len(loop), 1), speed)])
    if k == len(t) - 1:
        head = t.copy()
        head[-1, 3] = speed
        rows[-1, 3] = 0.0 if t[-1, 3] == 0 else t[-1, 3]
        return np.vstack([head, rows[1:]])
    return np.vstack([t[: k + 1], rows[1:-1], t[k:]])

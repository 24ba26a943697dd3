"""Skills that move the path itself: shifts, heights, sides, rotation, scaling, zig-zag, smoothing.

Every function takes a trajectory (N, 4) and returns a new one; lengths are in the trajectory's
own units; directions are words ('left', 'front', 'up', ...) read in the prompt's axis convention.
Changes blend in smoothly, and the start stays where it is unless the function is about moving it.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from trajadapt.model.geometry import PAPER_AXES, Array, Axes, extent, progress
from trajadapt.skills.core import (
    DirectionArg,
    DistanceArg,
    HeightArg,
    PartArg,
    PointArg,
    TrajectoryArg,
    as_point,
    as_trajectory,
    bump,
    part_mask,
    resolve_amount,
    smoothstep,
)

BLEND_IN = 0.15  # fraction of the path over which a shift is blended in (latte-dev: better than 0.25)


def shift(
    trajectory: TrajectoryArg,
    direction: DirectionArg,
    amount: DistanceArg = None,
    *,
    axes: Axes = PAPER_AXES,
    alternate: int = 0,
) -> Array:
    """Move the path in a direction by amount, keeping the start (blended in over the first 15%).

    Args:
        trajectory: (N, 4) rows x, y, z, velocity.
        direction: 'left', 'right', 'front', 'back', 'up', 'down' (or 'higher', 'top', 'bottom', ...).
        amount: a distance, or a word ('slightly', 'a bit', 'a lot'); default 15% of the path's size.
        axes: the axis convention (bound by the sandbox).
        alternate: N > 0 flips the direction every N waypoints from the first one, start included
            ("the first 10 points left, the next 10 right, and so on"); set by a reader, not shown
            in the prompt.
    """
    t = as_trajectory(trajectory)
    offset = axes.vector(direction) * resolve_amount(amount, t)
    if alternate > 0:
        t[:, :3] += alternating_signs(len(t), int(alternate))[:, None] * offset
        return t
    t[:, :3] += smoothstep(progress(t) / BLEND_IN)[:, None] * offset
    return t


def alternating_signs(count: int, block: int) -> Array:
    """+1 for the first ``block`` of ``count`` waypoints, -1 for the next, and so on.

    The two waypoints on either side of a flip take half their sign, so the path crosses over in
    three steps (a half, a whole, a half of the double offset) instead of jumping in one.
    """
    index = np.arange(count)
    signs = np.where((index // block) % 2 == 0, 1.0, -1.0)
    eased = signs.copy()
    for edge in range(block, count, block):
        eased[edge - 1] = 0.5 * signs[edge - 1]
        eased[edge] = 0.5 * signs[edge]
    return eased


def shift_goal(
    trajectory: TrajectoryArg,
    direction: DirectionArg,
    amount: DistanceArg = None,
    *,
    axes: Axes = PAPER_AXES,
    reference: Any = None,
) -> Array:
    """Move the goal in a direction by amount; the start stays and the path bends smoothly towards it.

    With ``reference`` (the path before other steps moved it), the goal ends amount beyond the
    reference's goal in that direction even where other steps moved it the other way ("the path up a
    little, the goal down a little": the goal ends below where it was); what they moved is undone over
    the last 15%, as ``shift`` blends in over the first.
    """
    t = as_trajectory(trajectory)
    unit = axes.vector(direction)
    s = progress(t)
    undo = _moved_against(t, reference, -1, unit) * smoothstep((s - 1.0 + BLEND_IN) / BLEND_IN)
    t[:, :3] += (smoothstep(s) * resolve_amount(amount, t) + undo)[:, None] * unit
    return t


def shift_start(
    trajectory: TrajectoryArg,
    direction: DirectionArg,
    amount: DistanceArg = None,
    *,
    axes: Axes = PAPER_AXES,
    reference: Any = None,
) -> Array:
    """Move the start in a direction by amount; the goal stays and the change fades out along the path.

    ``reference``: as for ``shift_goal``, for the start (undone over the first 15%).
    """
    t = as_trajectory(trajectory)
    unit = axes.vector(direction)
    s = progress(t)
    undo = _moved_against(t, reference, 0, unit) * (1.0 - smoothstep(s / BLEND_IN))
    t[:, :3] += ((1.0 - smoothstep(s)) * resolve_amount(amount, t) + undo)[:, None] * unit
    return t


def _moved_against(t: Array, reference: Any, index: int, unit: Array) -> float:
    """How far other steps moved waypoint ``index`` against ``unit`` since ``reference`` (0 if none)."""
    if reference is None:
        return 0.0
    before = as_trajectory(reference)
    if len(before) != len(t):
        return 0.0
    return max(0.0, -float((t[index, :3] - before[index, :3]) @ unit))


def shift_part(
    trajectory: TrajectoryArg,
    direction: DirectionArg,
    amount: DistanceArg = None,
    part: PartArg = "middle",
    *,
    axes: Axes = PAPER_AXES,
) -> Array:
    """Move one part of the path ('start', 'middle', 'end', a fraction pair or index pair) smoothly."""
    t = as_trajectory(trajectory)
    offset = axes.vector(direction) * resolve_amount(amount, t)
    t[:, :3] += part_mask(t, part)[:, None] * offset
    return t


def set_height(
    trajectory: TrajectoryArg, height: HeightArg, keep_start: bool = True, keep_goal: bool = True
) -> Array:
    """Fly the path at a constant height z, blending from/to the start and goal if they are kept."""
    t = as_trajectory(trajectory)
    t[:, 2] += _away_from_the_ends(t, keep_start, keep_goal) * (float(height) - t[:, 2])
    return t


def _away_from_the_ends(t: Array, keep_start: bool, keep_goal: bool, over: float = 0.15) -> Array:
    """A weight 0 at each kept end that rises smoothly to 1 over the share ``over`` of the path."""
    s = progress(t)
    weight = np.ones(len(t))
    if keep_start:
        weight *= smoothstep(s / over)
    if keep_goal:
        weight *= smoothstep((1.0 - s) / over)
    return weight


LIMIT_FADE = 0.1
"""The share of the path at each end over which a height limit that keeps the ends fades in."""


def keep_side(
    trajectory: TrajectoryArg,
    side: DirectionArg,
    point: PointArg,
    margin: float = 0.0,
    *,
    axes: Axes = PAPER_AXES,
) -> Array:
    """Keep every waypoint on one side ('left', 'right', 'front', 'back', 'up', 'down') of a point.

    Example: "do not go left of the bottle" -> keep_side(traj, 'right', detect_objects('bottle')).
    """
    t = as_trajectory(trajectory)
    normal = axes.vector(side)
    boundary = float(as_point(point) @ normal) + float(margin)
    along = t[:, :3] @ normal
    t[:, :3] += np.maximum(boundary - along, 0.0)[:, None] * normal
    return t


def stay_above(trajectory: TrajectoryArg, height: HeightArg, *, keep_ends: bool = False) -> Array:
    """Raise any waypoint below height z up to it.

    With ``keep_ends`` (set by a reader where the words hold the limit through the middle of the path:
    "stay at least 0.3 off the ground through the middle of the flight") the start and the goal stay
    and the limit fades in over the first and last 10% of the path (``LIMIT_FADE``).
    """
    t = as_trajectory(trajectory)
    weight = _away_from_the_ends(t, keep_ends, keep_ends, LIMIT_FADE)
    t[:, 2] += weight * (np.maximum(t[:, 2], float(height)) - t[:, 2])
    return t


def stay_below(trajectory: TrajectoryArg, height: HeightArg, *, keep_ends: bool = False) -> Array:
    """Lower any waypoint above height z down to it.

    With ``keep_ends``, as ``stay_above``'s: the limit holds away from the start and the goal.
    """
    t = as_trajectory(trajectory)
    weight = _away_from_the_ends(t, keep_ends, keep_ends, LIMIT_FADE)
    t[:, 2] += weight * (np.minimum(t[:, 2], float(height)) - t[:, 2])
    return t


def rotate(
    trajectory: TrajectoryArg, degrees: float, center: PointArg = None, *, axes: Axes = PAPER_AXES
) -> Array:
    """Turn the path by degrees about a vertical axis; positive is clockwise seen from above.

    Turn the path about the vertical axis through center (default: the start); positive is clockwise
    seen from above.
    """
    t = as_trajectory(trajectory)
    pivot = t[0, :3] if center is None else as_point(center, "center")
    right, front = axes.vector("right"), axes.vector("front")
    relative = t[:, :3] - pivot
    r, f = relative @ right, relative @ front
    angle = np.radians(float(degrees))
    new_r = r * np.cos(angle) + f * np.sin(angle)
    new_f = -r * np.sin(angle) + f * np.cos(angle)
    t[:, :3] += (new_r - r)[:, None] * right + (new_f - f)[:, None] * front
    return t


def scale_about(trajectory: TrajectoryArg, point: PointArg, factor: float, keep_ends: bool = True) -> Array:
    """Multiply each waypoint's distance from point by factor (2 = twice as far), ends kept by default."""
    t = as_trajectory(trajectory)
    center = as_point(point)
    weight = _ends_fade(t) if keep_ends else np.ones(len(t))
    t[:, :3] += weight[:, None] * (float(factor) - 1.0) * (t[:, :3] - center)
    return t


def exaggerate_curve(trajectory: TrajectoryArg, factor: float = 1.5) -> Array:
    """Scale how far the path bends away from the straight start-goal line (factor > 1: more curved)."""
    t = as_trajectory(trajectory)
    start, goal = t[0, :3], t[-1, :3]
    s = progress(t)[:, None]
    chord = start + s * (goal - start)
    t[:, :3] = chord + float(factor) * (t[:, :3] - chord)
    return t


def zigzag(
    trajectory: TrajectoryArg, amplitude: DistanceArg = None, cycles: int = 4, *, axes: Axes = PAPER_AXES
) -> Array:
    """Add a sideways zig-zag (triangle wave) across the direction of travel; start and goal stay."""
    t = as_trajectory(trajectory)
    size = resolve_amount(amplitude, t, default_word="a bit")
    s = progress(t)
    wave = 2.0 * np.abs(2.0 * ((s * cycles) % 1.0) - 1.0) - 1.0
    t[:, :3] += (size * wave * _ends_fade(t))[:, None] * _sideways(t, axes)
    return t


def _sideways(t: Array, axes: Axes) -> Array:
    """Unit vectors in the horizontal plane, across the local direction of travel."""
    up = axes.vector("up")
    heading = np.gradient(t[:, :3], axis=0)
    across = np.cross(heading, up)
    norms = np.linalg.norm(across, axis=1, keepdims=True)
    fallback = np.broadcast_to(axes.vector("left"), across.shape)
    return np.where(norms > 1e-12, across / np.maximum(norms, 1e-12), fallback)


SMOOTHING_SPAN = 10.0
"""At strength 1 the smoothing kernel's sigma is one waypoint in this many (2 of 40 at the default 0.5).
With one in twenty, a wiggle 8 waypoints long kept three quarters of its roughness at the default, and
"smooth out the wiggles" came back barely smoother."""


def smooth(trajectory: TrajectoryArg, strength: float = 0.5) -> Array:
    """Round off sharp turns and jitter (strength 0..1); start and goal stay; speeds smoothed too.

    A pause (waypoints at rest beside their twin) stays where it is, a standstill.
    """
    t = as_trajectory(trajectory)
    sigma = max(float(strength), 0.0) * max(len(t) / SMOOTHING_SPAN, 1.0)
    if sigma <= 0:
        return t
    radius = int(np.ceil(3 * sigma))
    kernel = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    kernel /= kernel.sum()
    padded = np.pad(t, ((radius, radius), (0, 0)), mode="reflect", reflect_type="odd")
    smoothed = np.stack([np.convolve(padded[:, k], kernel, mode="valid") for k in range(4)], axis=1)
    smoothed[:, 3] = np.maximum(smoothed[:, 3], 0.0)
    smoothed[[0, -1]] = t[[0, -1]]
    paused = _paused(t)
    smoothed[paused] = t[paused]
    return smoothed


def _paused(t: Array) -> npt.NDArray[np.bool_]:
    """Waypoints of a pause: at rest where a neighbour stands at the same place."""
    same = np.all(np.isclose(t[1:, :3], t[:-1, :3]), axis=1)
    beside = np.r_[same, False] | np.r_[False, same]
    paused: npt.NDArray[np.bool_] = (t[:, 3] <= 0) & beside
    return paused


def resample(trajectory: TrajectoryArg, count: int) -> Array:
    """The same path with count waypoints, evenly spaced along it (positions and speeds interpolated)."""
    t = as_trajectory(trajectory)
    count = int(count)
    if count < 2:
        raise ValueError(f"count must be at least 2, got {count}")
    s = progress(t)
    target = np.linspace(0.0, 1.0, count)
    return np.stack([np.interp(target, s, t[:, k]) for k in range(4)], axis=1)


def add_noise(trajectory: TrajectoryArg, scale: DistanceArg = "tiny", seed: int = 0) -> Array:
    """Add small random (Gaussian) offsets to the positions; start and goal stay."""
    t = as_trajectory(trajectory)
    sigma = resolve_amount(scale, t)
    noise = np.random.default_rng(seed).normal(0.0, sigma, size=(len(t), 3))
    t[:, :3] += noise * _ends_fade(t)[:, None]
    return t


def _ends_fade(t: Array) -> Array:
    """1 along the path, easing to 0 at the start and the goal (first and last 10%)."""
    s = progress(t)
    return smoothstep(s / 0.1) * smoothstep((1.0 - s) / 0.1)


def lift_middle(
    trajectory: TrajectoryArg, direction: DirectionArg, amount: DistanceArg = None, *, axes: Axes = PAPER_AXES
) -> Array:
    """Bow the middle of the path in a direction (start and goal stay), e.g. 'go to the top part'."""
    t = as_trajectory(trajectory)
    offset = axes.vector(direction) * resolve_amount(amount, t)
    t[:, :3] += bump(t)[:, None] * offset
    return t


def path_size(trajectory: TrajectoryArg) -> float:
    """The largest side of the path's bounding box, to express amounts relative to the path."""
    return extent(as_trajectory(trajectory))

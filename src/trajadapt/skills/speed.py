"""Skills that change velocity only: scale or set it globally, near an object, in a part; profiles.

Positions never change here. Changes near an object or in a part blend in and out smoothly, and
velocities stay >= 0.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from trajadapt.model.geometry import Array, extent, progress
from trajadapt.skills.core import (
    FactorArg,
    PartArg,
    PointArg,
    ProfileArg,
    TrajectoryArg,
    as_point,
    as_trajectory,
    part_mask,
    proximity,
    within,
)

PROFILES = ("constant", "trapezoidal", "accelerate", "decelerate")

SPEED_FACTORS = {
    "faster": {"a bit": 1.25, "": 1.4, "a lot": 1.6},
    "slower": {"a bit": 0.75, "": 0.65, "a lot": 0.45},
}
"""The factor of "a bit faster", "faster", "a lot faster" (and slower): the prompt's phrase table."""

NEAR_REACH = 0.4  # how far (fraction of the path's size) "near an object" reaches beyond the closest pass
# (calibrated on latte-dev with the factors of the prompt's phrase table: 0.2 before)


HELD_SHARE = 0.2  # a held pace holds over the share of waypoints nearest the object ...
HELD_BEYOND = 0.1  # ... but not beyond this much (of the path's size) past the closest pass
HELD_FADE = 0.3  # and fades out within this much (of the path's size) past that stretch


NEAR_RULES = ("zone", "latte")
"""What "near an object" means to a speed change: ``zone`` (the default: the whole change at the
path's closest pass, fading within ``NEAR_REACH`` beyond it, wherever the object is) or ``latte``
(LaTTe's data generator: a change falling linearly from the object to nothing at a reach the
generator draws per case, here its expectation over that range, so a path that never comes near
the object keeps its speed)."""

LATTE_REACH = (0.5, 1.5)
"""The generator's reach as shares of the path's size: uniform in 0.3..0.9 in scenes whose paths
span 0.6 (LaTTe's ``locality_factor``; not fitted to any case)."""


def checked_near_rule(near_rule: str) -> str:
    """``near_rule`` itself, when it is one of ``NEAR_RULES``.

    Raises:
        ValueError: any other value, with the rules that exist.
    """
    if near_rule not in NEAR_RULES:
        raise ValueError(f"near_rule must be one of {', '.join(NEAR_RULES)}, got {near_rule!r}")
    return near_rule


def speed_weight(
    trajectory: Any,
    near: Any = None,
    radius: float | None = None,
    part: Any = None,
    near_rule: str = "zone",
    held: bool = False,
) -> Array:
    """Where a speed change applies: a weight 0..1 per waypoint.

    Where a speed change applies, 0..1 per waypoint: near a point (as ``near_rule`` reads near),
    within a radius of it, in a part of the path ('start', 'middle', 'end', a fraction or index
    pair), or everywhere.

    Raises:
        ValueError: a near_rule not in ``NEAR_RULES``.
    """
    t = as_trajectory(trajectory)
    weight = np.ones(len(t))
    if near is not None:
        point = as_point(near, "near")
        if radius is not None:
            weight *= within(t, point, float(radius), blend=0.25 * float(radius))
        elif held:
            weight *= held_zone(t, point)
        elif checked_near_rule(near_rule) == "latte":
            weight *= latte_field(t, point)
        else:
            weight *= proximity(t, point, NEAR_REACH * extent(t))
    if part is not None:
        weight *= part_mask(t, part)
    return weight


def held_zone(trajectory: Array, point: Array) -> Array:
    """1 over the stretch nearest ``point``, fading to 0 beyond it: where a stated pace holds.

    The stretch is the ``HELD_SHARE`` of waypoints nearest the point, cut at ``HELD_BEYOND`` of the
    path's size past its closest pass; the weight fades as ``proximity`` fades within ``HELD_FADE``
    of the size past the stretch.
    """
    distance = np.linalg.norm(trajectory[:, :3] - point, axis=1)
    size = extent(trajectory)
    edge = min(float(np.sort(distance)[int(HELD_SHARE * len(distance))]), distance.min() + HELD_BEYOND * size)
    return proximity(trajectory, point, HELD_FADE * size, edge)


def latte_field(trajectory: Array, point: Array) -> Array:
    """LaTTe's speed field around ``point``, 0..1 per waypoint, averaged over the generator's reach.

    For a reach r the field is max(0, 1 - d / r) at distance d; with r uniform in ``LATTE_REACH``
    (times the path's size) its mean is ((b - m) - d ln(b / m)) / (b - a), m = max(a, d), for d < b.
    """
    low, high = (share * extent(trajectory) for share in LATTE_REACH)
    distance = np.linalg.norm(trajectory[:, :3] - point, axis=1)
    lower = np.clip(distance, low, None)
    inside = distance < high
    mean = np.zeros(len(distance))
    d, m = distance[inside], lower[inside]
    mean[inside] = ((high - m) - d * np.log(high / m)) / (high - low)
    return np.clip(mean, 0.0, 1.0)  # rounding leaves -1e-16 at the reach's edge


def scale_speed(
    trajectory: TrajectoryArg,
    factor: FactorArg,
    near: PointArg = None,
    radius: float | None = None,
    part: PartArg = None,
    *,
    near_rule: str = "zone",
    held: bool = False,
) -> Array:
    """Multiply velocity by factor (0.5 half, 2 double): everywhere, near a point, or in a part.

    Multiply the velocity by factor (0.5 = half as fast, 2 = twice as fast), everywhere or only near a
    point / within radius of it / in a part. ``near_rule`` (bound by the sandbox from the user's
    settings) says what near means: see ``NEAR_RULES``. ``held`` (set by the readers where the words
    state the factor near the object) holds the factor over the stretch nearest it: ``held_zone``.
    """
    t = as_trajectory(trajectory)
    if float(factor) < 0:
        raise ValueError(f"factor must be >= 0, got {factor}")
    weight = speed_weight(t, near, radius, part, near_rule, held)
    t[:, 3] *= 1.0 + (float(factor) - 1.0) * weight
    return t


def set_speed(
    trajectory: TrajectoryArg,
    speed: float,
    near: PointArg = None,
    radius: float | None = None,
    part: PartArg = None,
    *,
    near_rule: str = "zone",
) -> Array:
    """Set the velocity to speed, everywhere or only near a point / within radius of it / in a part.

    ``near_rule`` (bound by the sandbox from the user's settings) says what near means: see
    ``NEAR_RULES``.
    """
    t = as_trajectory(trajectory)
    if float(speed) < 0:
        raise ValueError(f"speed must be >= 0, got {speed}")
    weight = speed_weight(t, near, radius, part, near_rule)
    t[:, 3] += (float(speed) - t[:, 3]) * weight
    return t


def speed_profile(
    trajectory: TrajectoryArg, kind: ProfileArg, peak: float | None = None, start: float = 0.0
) -> Array:
    """Velocity profile 'constant', 'trapezoidal', 'accelerate' or 'decelerate' from fraction start.

    Replace the velocity by a profile: 'constant', 'trapezoidal' (speed up, cruise, slow down),
    'accelerate' (uniformly up to peak) or 'decelerate' (uniformly down to 0 at the goal), applied from
    fraction start of the path on; peak defaults to the current top speed. Decelerating never makes a
    waypoint faster than it was, accelerating never slower; accelerating a path already at its top
    speed goes up to the phrase table's "faster" factor of it, and decelerating a path that already
    slows scales its own speeds down by the same uniform ramp, never rising. A path at rest on the
    way (at its start, or a stop) speeds up from its last rest as it did until it meets a ramp from
    its fastest speed after that rest down to 0 at the goal, so that it still moves and slows
    gradually to a stop at the goal.
    """
    t = as_trajectory(trajectory)
    s = progress(t)
    begin = float(np.clip(start, 0.0, 0.99))
    rest = _last_rest(t, s, begin) if str(kind).strip().lower() == "decelerate" else None
    if rest is not None:
        t[:, 3] = _slowed_after_a_rest(t, s, rest)
        return t
    local = np.clip((s - begin) / (1.0 - begin), 0.0, 1.0)
    entry = float(np.interp(begin, s, t[:, 3]))
    top = float(peak) if peak is not None else float(t[:, 3].max())
    if peak is None and top <= entry * (1.0 + 1e-6):
        top = entry * SPEED_FACTORS["faster"][""]
    profiles: dict[str, Array] = {
        "constant": np.full(len(t), top),
        "trapezoidal": top * np.minimum(1.0, np.minimum(local, 1.0 - local) / 0.2),
        "accelerate": entry + (top - entry) * local,
        "decelerate": np.minimum(t[:, 3], entry) * (1.0 - local),  # a slowing path slows more
    }
    key = str(kind).strip().lower()
    if key not in PROFILES:
        raise ValueError(f"unknown profile {kind!r}; use one of: {', '.join(PROFILES)}")
    after = s >= begin
    speeds = np.maximum(profiles[key][after], 0.0)
    if key == "decelerate":
        speeds = np.minimum.accumulate(speeds)  # never rising
    elif key == "accelerate":
        speeds = np.maximum(speeds, t[after, 3])
    t[after, 3] = speeds
    return t


def _last_rest(t: Array, s: Array, begin: float) -> int | None:
    """The index of the path's last waypoint at rest at ``begin`` or after it, before its goal, if any.

    "At ``begin``" allows for rounding: a ramp starting 5e-324 along a path at rest at its start began
    from that rest's speed, 0, and held the whole path at 0.
    """
    resting = np.flatnonzero((s >= begin - 1e-9) & (t[:, 3] <= 1e-9))
    resting = resting[resting < len(t) - 1]
    return int(resting[-1]) if len(resting) else None


def _slowed_after_a_rest(t: Array, s: Array, rest: int) -> Array:
    """The speeds of a path that rests at waypoint ``rest`` (its start, or a stop), slowed to 0 at the goal.

    A slowing from the rest itself would hold the path at 0 from there on. Instead the speeds after
    the rest are capped by a uniform ramp from the fastest speed after it down to 0 at the goal: the
    path speeds up from the rest as it did until it meets the ramp, then slows along it, never rising
    again ("decelerate gradually to rest at the goal" on a path that speeds up from its start all the
    way slows over its whole second part, not at its last waypoint).
    """
    first = float(min(s[rest], 0.99))
    local = np.clip((s - first) / (1.0 - first), 0.0, 1.0)
    top = float(t[rest:, 3].max())
    speeds = t[:, 3].copy()
    after = np.arange(len(t)) >= rest
    speeds[after] = np.minimum(t[after, 3], top * (1.0 - local[after]))
    peak = rest + int(np.argmax(speeds[rest:]))
    speeds[peak:] = np.minimum.accumulate(speeds[peak:])
    return np.maximum(speeds, 0.0)

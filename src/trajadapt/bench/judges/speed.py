"""Checks of how fast the path is taken: speed near an object, overall, profiles and pauses."""

from __future__ import annotations

from typing import Any

import numpy as np

from trajadapt.bench.judges.core import (
    NEAR_FRACTION,
    CheckContext,
    check,
    distances_to,
)
from trajadapt.model.geometry import Array, progress


def _speed_near(trajectory: Array, target: Array, radius: float | None = None) -> tuple[float, float]:
    """Mean speed of the waypoints near the target (within radius, or the nearest quarter) and of the rest."""
    distances = distances_to(trajectory, target)
    if radius is not None and (distances <= radius).any():
        near, far = np.flatnonzero(distances <= radius), np.flatnonzero(distances > radius)
    else:
        order = np.argsort(distances)
        count = max(2, int(NEAR_FRACTION * len(trajectory)))
        near, far = order[:count], order[count:]
    return float(trajectory[near, 3].mean()), float(trajectory[far, 3].mean()) if far.size else 0.0


@check("speed_near")
def _speed_near_check(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Speed near an object is 'lower' / 'higher' (by factor if given) or 'equal' value; elsewhere kept."""
    target = ctx.point(p)
    radius = float(p["radius"]) if "radius" in p else None
    near_before, far_before = _speed_near(ctx.original, target, radius)
    near_after, far_after = _speed_near(ctx.adapted, target, radius)
    ok, detail = _compare_speed(p, near_before, near_after)
    if p.get("elsewhere_kept", True) and far_before > 0:
        kept = abs(far_after - far_before) <= 0.15 * far_before + 0.25 * abs(near_after - near_before)
        ok = ok and kept
        detail += f"; elsewhere {far_before:.3g} -> {far_after:.3g}"
    return ok, "near: " + detail


@check("speed")
def _speed(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Mean speed over the path (or a 'part': start/middle/end) is lower / higher / equal to a value."""
    part = p.get("part")
    bounds = {"start": (0.0, 0.3), "middle": (0.3, 0.7), "end": (0.7, 1.0), None: (0.0, 1.0)}[part]

    def mean_speed(t: Array) -> float:
        s = progress(t)
        return float(t[(s >= bounds[0]) & (s <= bounds[1]), 3].mean())

    return _compare_speed(p, mean_speed(ctx.original), mean_speed(ctx.adapted))


def _compare_speed(p: dict[str, Any], before: float, after: float) -> tuple[bool, str]:
    relation = p["relation"]
    detail = f"speed {before:.3g} -> {after:.3g}"
    if relation == "lower":
        return after < before * (1 - float(p.get("by", 0.05))), detail
    if relation == "higher":
        return after > before * (1 + float(p.get("by", 0.05))), detail
    if relation == "equal":
        value = float(p["value"])
        return abs(after - value) <= float(p.get("tolerance", 0.1)) * max(
            value, 1e-9
        ), detail + f" (asked {value})"
    raise ValueError(f"unknown speed relation {relation!r}")


@check("constant_speed")
def _constant_speed(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """All (moving) waypoints at one speed, the given value if any."""
    speeds = ctx.adapted[1:-1, 3]
    spread = float(np.ptp(speeds))
    value = p.get("value")
    ok = spread <= 0.05 * max(float(speeds.mean()), 1e-9)
    if value is not None:
        ok = ok and abs(float(np.median(speeds)) - float(value)) <= 0.1 * float(value)
    return ok, f"speeds {speeds.min():.3g}..{speeds.max():.3g}"


@check("decelerates")
def _decelerates(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Speed falls towards the goal: the last part is slower than before, ending near 'final' if given."""
    tail = ctx.adapted[progress(ctx.adapted) >= float(p.get("after", 0.6)), 3]
    falling = bool(np.all(np.diff(tail) <= 1e-9)) and tail[-1] < tail[0]
    final = p.get("final")
    ok = falling and (final is None or abs(tail[-1] - float(final)) <= 0.05 * max(tail[0], 1e-9))
    return ok, f"last part speeds {tail[0]:.3g} -> {tail[-1]:.3g}"


@check("pause")
def _pause(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The robot stands still (repeated position, speed 0) for 'steps' waypoints, near 'object' if given."""
    still = (np.linalg.norm(np.diff(ctx.adapted[:, :3], axis=0), axis=1) <= 1e-9 * ctx.size) & (
        ctx.adapted[1:, 3] <= 1e-9
    )
    longest, run, end = 0, 0, 0
    for index, flag in enumerate(still):
        run = run + 1 if flag else 0
        if run > longest:
            longest, end = run, index + 1
    ok = longest >= int(p["steps"])
    if ok and "object" in p:
        ok = (
            float(np.linalg.norm(ctx.adapted[end, :3] - ctx.point(p)))
            <= 1.5 * float(distances_to(ctx.original, ctx.point(p)).min()) + 0.05 * ctx.size
        )
    return ok, f"longest stop {longest} steps (asked {p['steps']})"

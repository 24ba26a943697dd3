"""Checks of where the path goes: shifts, distances, ends, loops, heights, sides, shape."""

from __future__ import annotations

from typing import Any

import numpy as np

from trajadapt.bench.judges.core import (
    REAL_CHANGE,
    CheckContext,
    at_progress,
    check,
    distances_to,
    near_mean,
)
from trajadapt.model.geometry import Array, progress


@check("shift")
def _shift(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path (or its 'goal' / 'start' / 'middle' part) moved in a direction, by an amount if given."""
    direction = ctx.axes.vector(p["direction"])
    part = p.get("part", "path")
    fractions = {"goal": [1.0], "start": [0.0], "middle": [0.4, 0.5, 0.6], "path": np.linspace(0.5, 1.0, 11)}[
        part
    ]
    before, after = (
        at_progress(ctx.original, np.asarray(fractions)),
        at_progress(ctx.adapted, np.asarray(fractions)),
    )
    along = float(np.median((after[:, :3] - before[:, :3]) @ direction))
    if "amount" in p:
        tolerance = float(p.get("tolerance", 0.25)) * float(p["amount"])
        return abs(
            along - float(p["amount"])
        ) <= tolerance, f"{part} moved {along:.3g} {p['direction']} (asked {p['amount']})"
    return (
        along > REAL_CHANGE * ctx.size,
        f"{part} moved {along:.3g} {p['direction']} (needs > {REAL_CHANGE * ctx.size:.3g})",
    )


@check("start_kept")
def _start_kept(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    moved = float(np.linalg.norm(ctx.adapted[0, :3] - ctx.original[0, :3]))
    return moved <= float(p.get("tolerance", 0.01)) * ctx.size, f"start moved {moved:.3g}"


@check("goal_kept")
def _goal_kept(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    moved = float(np.linalg.norm(ctx.adapted[-1, :3] - ctx.original[-1, :3]))
    return moved <= float(p.get("tolerance", 0.01)) * ctx.size, f"goal moved {moved:.3g}"


@check("distance")
def _distance(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Distance to an object: 'decreased' / 'increased' near it, or 'at_least' value everywhere."""
    target = ctx.point(p)
    relation = p["relation"]
    if "first" in p:  # only the first n waypoints count ("shift the first 6 points closer")
        count = int(p["first"])
        ctx = CheckContext(ctx.original[:count], ctx.adapted[:count], ctx.objects, ctx.axes)
    if relation == "at_least":
        closest = float(distances_to(ctx.adapted, target).min())
        return closest >= float(p["value"]) * (
            1 - float(p.get("tolerance", 0.02))
        ), f"closest {closest:.3g} (asked >= {p['value']})"
    before, after = near_mean(ctx.original, target), near_mean(ctx.adapted, target)
    change = after - before
    needed = REAL_CHANGE * ctx.size
    if relation == "decreased":
        return change < -needed, f"near distance {before:.3g} -> {after:.3g}"
    if relation == "increased":
        factor = float(p.get("factor", 0))
        ok = after >= factor * before * 0.9 if factor else change > needed
        return ok, f"near distance {before:.3g} -> {after:.3g}"
    raise ValueError(f"unknown distance relation {relation!r}")


@check("passes_near")
def _passes_near(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path comes within tolerance (fraction of the size) of a point or object."""
    closest = float(distances_to(ctx.adapted, ctx.point(p)).min())
    limit = float(p.get("tolerance", 0.05)) * ctx.size
    return closest <= limit, f"closest {closest:.3g} (needs <= {limit:.3g})"


@check("ends_near")
def _ends_near(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path ends at the point of the original nearest to the object (or within tolerance of it)."""
    target = ctx.point(p)
    nearest = ctx.original[int(np.argmin(distances_to(ctx.original, target))), :3]
    gap = float(np.linalg.norm(ctx.adapted[-1, :3] - (target if p.get("at_object") else nearest)))
    limit = float(p.get("tolerance", 0.05)) * ctx.size
    stopped = not p.get("stopped", False) or ctx.adapted[-1, 3] <= 1e-6
    return gap <= limit and stopped, f"ends {gap:.3g} from the target, final speed {ctx.adapted[-1, 3]:.3g}"


@check("extends")
def _extends(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path goes on past the original goal, by at least 'distance' if given (or a real amount)."""
    gap = float(np.linalg.norm(ctx.adapted[-1, :3] - ctx.original[-1, :3]))
    passes_goal = float(distances_to(ctx.adapted, ctx.original[-1, :3]).min()) <= 0.05 * ctx.size
    needed = float(p.get("distance", REAL_CHANGE * 5 * ctx.size)) * (1 - float(p.get("tolerance", 0.2)))
    ok = passes_goal and gap >= needed
    if "direction" in p:
        step = (ctx.adapted[-1, :3] - ctx.original[-1, :3]) @ ctx.axes.vector(p["direction"])
        ok = ok and bool(step >= needed)
    return ok, f"ends {gap:.3g} beyond the old goal (needs {needed:.3g}), passes it: {passes_goal}"


def _turning(trajectory: Array) -> float:
    xy = trajectory[:, :2]
    steps = np.diff(xy, axis=0)
    steps = steps[np.linalg.norm(steps, axis=1) > 1e-9]
    if len(steps) < 2:
        return 0.0
    angles = np.unwrap(np.arctan2(steps[:, 1], steps[:, 0]))
    return float(np.abs(np.diff(angles)).sum())


@check("loop")
def _loop(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """A spiral or circle was added: the horizontal heading turns at least 'turns' more full turns."""
    extra = (_turning(ctx.adapted) - _turning(ctx.original)) / (2 * np.pi)
    needed = float(p.get("turns", 1)) * 0.8
    return extra >= needed, f"{extra:.2f} extra turns (needs {needed:.2f})"


@check("waypoints")
def _waypoints(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The waypoint count is 'more', 'fewer', or changed by exactly 'delta'."""
    before, after = len(ctx.original), len(ctx.adapted)
    relation = p["relation"]
    ok = {"more": after > before, "fewer": after < before, "delta": after - before == int(p.get("delta", 0))}[
        relation
    ]
    return ok, f"{before} -> {after} waypoints"


@check("height")
def _height(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Heights z of the (middle part of the) path stay within [min, max]."""
    z = ctx.adapted[:, 2]
    if p.get("middle_only"):
        s = progress(ctx.adapted)
        z = z[(s > 0.2) & (s < 0.8)]
    low, high = float(p.get("min", -np.inf)), float(p.get("max", np.inf))
    slack = 1e-6 + float(p.get("tolerance", 0.0))
    return bool((z >= low - slack).all() and (z <= high + slack).all()), f"z {z.min():.3g}..{z.max():.3g}"


@check("side")
def _side(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Every waypoint stays on one 'side' of an object (not beyond it in the opposite direction)."""
    normal = ctx.axes.vector(p["side"])
    margin = (ctx.adapted[:, :3] - ctx.point(p)) @ normal
    return bool((margin >= -1e-6).all()), f"worst {margin.min():.3g} beyond the object"


@check("smooth")
def _smooth(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """No step between waypoints longer than 'factor' (default 3) times the original's longest step."""
    longest = float(np.linalg.norm(np.diff(ctx.adapted[:, :3], axis=0), axis=1).max())
    limit = float(p.get("factor", 3.0)) * float(
        np.linalg.norm(np.diff(ctx.original[:, :3], axis=0), axis=1).max()
    )
    return longest <= limit, f"longest step {longest:.3g} (limit {limit:.3g})"


@check("zigzag")
def _zigzag(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path weaves sideways: its lateral offset changes sign at least 'swings' times."""
    if len(ctx.adapted) == len(ctx.original):  # same waypoints: compare them one by one
        before, after = ctx.original[:, :3], ctx.adapted[:, :3]
    else:
        s = np.linspace(0.0, 1.0, 200)
        before, after = at_progress(ctx.original, s)[:, :3], at_progress(ctx.adapted, s)[:, :3]
    across = np.cross(np.gradient(before, axis=0), ctx.axes.vector("up"))
    across /= np.maximum(np.linalg.norm(across, axis=1, keepdims=True), 1e-12)
    lateral = np.sum((after - before) * across, axis=1)
    largest = float(np.abs(lateral).max())
    significant = np.abs(lateral) > max(0.25 * largest, 0.002 * ctx.size)
    signs = np.sign(lateral[significant])
    swings = int(np.sum(signs[1:] != signs[:-1]))
    return swings >= int(p.get("swings", 4)), f"{swings} sideways swings (largest offset {largest:.3g})"


@check("changed")
def _changed(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Anything changed at all: positions or speeds differ by a real amount, or the count differs."""
    if len(ctx.adapted) != len(ctx.original):
        return True, "waypoint count changed"
    moved = float(np.abs(ctx.adapted[:, :3] - ctx.original[:, :3]).max())
    speed = float(np.abs(ctx.adapted[:, 3] - ctx.original[:, 3]).max())
    top = max(float(ctx.original[:, 3].max()), 1e-9)
    return (
        moved > REAL_CHANGE * ctx.size or speed > 0.05 * top,
        f"moved {moved:.3g}, speed change {speed:.3g}",
    )


@check("rotated")
def _rotated(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The start-to-goal heading turned by 'degrees' (clockwise from above is positive), within 20."""
    right, front = ctx.axes.vector("right"), ctx.axes.vector("front")

    def heading(t: Array) -> float:
        chord = t[-1, :3] - t[0, :3]
        return float(np.degrees(np.arctan2(chord @ right, chord @ front)))

    turned = (heading(ctx.adapted) - heading(ctx.original) + 180) % 360 - 180
    return abs(
        turned - float(p["degrees"])
    ) <= 20, f"turned {turned:.0f} degrees clockwise (asked {p['degrees']})"


def _chord_deviation(trajectory: Array) -> float:
    start, goal = trajectory[0, :3], trajectory[-1, :3]
    s = progress(trajectory)[:, None]
    return float(np.linalg.norm(trajectory[:, :3] - (start + s * (goal - start)), axis=1).mean())


@check("bend")
def _bend(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path bends more (relation 'more') or less ('less') away from its start-goal line."""
    before, after = _chord_deviation(ctx.original), _chord_deviation(ctx.adapted)
    more = after > before * 1.05 + 1e-9
    return more if p.get(
        "relation", "more"
    ) == "more" else after < before * 0.95, f"mean bend {before:.3g} -> {after:.3g}"


@check("smoother")
def _smoother(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """The path is smoother: its mean second difference (per unit of path length) shrank."""

    def rough(t: Array) -> float:
        steps = np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).sum()
        return float(np.linalg.norm(np.diff(t[:, :3], n=2, axis=0), axis=1).sum() / max(steps, 1e-12))

    before, after = rough(ctx.original), rough(ctx.adapted)
    return after < before * 0.98, f"roughness {before:.3g} -> {after:.3g}"


@check("passes_above")
def _passes_above(ctx: CheckContext, p: dict[str, Any]) -> tuple[bool, str]:
    """Over each object (the waypoint horizontally nearest to it), the path is higher than the object."""
    results = []
    for name in p.get("objects") or [p["object"]]:
        target = ctx.objects[str(name).strip().casefold()]
        horizontal = np.linalg.norm(ctx.adapted[:, :2] - target[:2], axis=1)
        k = int(np.argmin(horizontal))
        results.append(
            (
                ctx.adapted[k, 2] > target[2] and horizontal[k] <= 0.1 * ctx.size,
                f"{name}: z {ctx.adapted[k, 2]:.3g} vs {target[2]:.3g}, off by {horizontal[k]:.3g}",
            )
        )
    return all(ok for ok, _ in results), "; ".join(text for _, text in results)

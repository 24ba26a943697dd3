"""Skills relative to objects and points: closer, further, keep a distance, pass through or over, reach.

Points are positions [x, y, z], e.g. ``detect_objects('box')``; None (an object not found) is
refused with a message that says so.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from trajadapt.model.geometry import Array, extent, progress
from trajadapt.skills.bends import bend_sigma, inner_room_to_bend, room_to_bend
from trajadapt.skills.core import (
    DistanceArg,
    FractionArg,
    PartArg,
    PointArg,
    PointsArg,
    TrajectoryArg,
    as_point,
    as_trajectory,
    nearest_index,
    part_mask,
    proximity,
    resolve_amount,
    smoothstep,
)

CLOSER_FRACTIONS = {
    "tiny": 0.15, "slightly": 0.2, "a little": 0.2, "a bit": 0.2, "little": 0.2, "bit": 0.2,
    "": 0.35, "default": 0.35, "much": 0.5, "a lot": 0.5, "lot": 0.5, "very": 0.5, "very much": 0.6,
}  # fmt: skip
"""Share of the way to the object; calibrated on latte-dev (0.3 / 0.5 / 0.75 before overshot)."""
INFLUENCE = 0.5  # how far along the path (fraction of its size) an object-centred change reaches
FAR_FROM = (0.4, 0.3)  # move_away fades out for an object already this far (fraction of the path's size)
# from the path, to nothing at the sum: "further away" from something far asks for little (latte-dev:
# dist MSE 0.00099 -> 0.00095, DFD 0.0924 -> 0.0874; ovita-dev unchanged)


def _fraction(amount: Any) -> float:
    if amount is None:
        return CLOSER_FRACTIONS[""]
    if isinstance(amount, str):
        key = amount.strip().lower()
        if key not in CLOSER_FRACTIONS:
            words = ", ".join(k for k in CLOSER_FRACTIONS if k)
            raise ValueError(f"unknown amount {amount!r}; use a fraction 0..1 or one of: {words}")
        return CLOSER_FRACTIONS[key]
    return float(np.clip(float(amount), 0.0, 1.0))


def _weight(t: Array, point: Array) -> Array:
    """Strongest at the waypoint nearest the object, fading along the path; 0 at start and goal."""
    return proximity(t, point, INFLUENCE * extent(t)) * _away_from_the_ends(t)


ENDS_FADE = 0.1  # the share of the path at each end over which a move by an object fades in


def _away_from_the_ends(t: Array) -> Array:
    """0 at the start and the goal, rising smoothly to 1 within ``ENDS_FADE`` of the path."""
    s = progress(t)
    return smoothstep(s / ENDS_FADE) * smoothstep((1.0 - s) / ENDS_FADE)


def _where(t: Array, point: Array, part: PartArg) -> Array:
    """How much each waypoint of an object-centred move takes: around the nearest pass, or a part."""
    return _weight(t, point) if part is None else part_mask(t, part)


def move_closer(
    trajectory: TrajectoryArg,
    point: PointArg,
    amount: FractionArg = None,
    *,
    reference: Any = None,
    part: PartArg = None,
) -> Array:
    """Bring the path closer to a point; amount is a fraction 0..1 or 'a bit' / 'a lot'.

    Bring the path closer to a point: the nearest part moves amount (fraction 0..1, or 'a bit', 'a lot')
    of the way towards it; start and goal stay. With ``part`` (as ``scale_speed``'s: a word, a
    fraction pair or a waypoint index pair, "the first 6 points" is ``(0, 6)``) that part moves
    instead, all of it, ends included. With ``reference`` (the path before other steps moved
    it, of the same length), the distances are promised from the reference, and each waypoint reaches
    its distance across what the other steps did, so that their moves stay (see ``to_distances``).
    """
    t = as_trajectory(trajectory)
    target = as_point(point)
    before = _reference(t, reference)
    weight = _fraction(amount) * _where(before, target, part)
    asked = (1.0 - weight) * np.linalg.norm(before[:, :3] - target, axis=1)
    if reference is not None:  # never further than the other steps left it
        asked = np.minimum(asked, np.linalg.norm(t[:, :3] - target, axis=1))
    return to_distances(t, before, target, asked)


def move_away(
    trajectory: TrajectoryArg,
    point: PointArg,
    amount: DistanceArg = None,
    *,
    reference: Any = None,
    part: PartArg = None,
) -> Array:
    """Push the path away from a point by amount (a distance, or 'a bit' / 'a lot').

    Push the path away from a point by amount (a distance, or 'a bit', 'a lot'); the nearest part moves
    most; start and goal stay. A vague amount shrinks when the path already passes far from the point.
    ``reference`` and ``part``: as for ``move_closer``.
    """
    t = as_trajectory(trajectory)
    source = as_point(point)
    before = _reference(t, reference)
    distance = resolve_amount(amount, before)
    if amount is None or isinstance(amount, str):
        distance *= _still_near(before, source)
    asked = np.linalg.norm(before[:, :3] - source, axis=1) + distance * _where(before, source, part)
    if reference is not None:  # never nearer than the other steps left it
        asked = np.maximum(asked, np.linalg.norm(t[:, :3] - source, axis=1))
    return to_distances(t, before, source, asked)


def _reference(t: Array, reference: Any) -> Array:
    """The path the distances are promised from: ``reference`` when given with t's length, else t."""
    if reference is None:
        return t
    before = as_trajectory(reference)
    return before if len(before) == len(t) else t


def to_distances(t: Array, reference: Array, point: Array, distances: Array) -> Array:
    """Each waypoint of t moved to its distance from the point, keeping what moved it from the reference.

    A waypoint that other steps moved (t differs from the reference there) keeps its move along that
    change and reaches the distance across it; as close as it can when the change alone is further. An
    unmoved waypoint goes straight towards or away from the point.
    """
    offset = t[:, :3] - point
    change = t[:, :3] - reference[:, :3]
    size = np.linalg.norm(change, axis=1, keepdims=True)
    along = np.where(size > 1e-9 * max(extent(t), 1e-12), change / np.maximum(size, 1e-300), 0.0)
    held = np.sum(offset * along, axis=1, keepdims=True) * along
    across = offset - held
    length = np.linalg.norm(across, axis=1)
    wanted = np.sqrt(np.maximum(distances**2 - np.sum(held**2, axis=1), 0.0))
    scale = np.where(length > 1e-12, wanted / np.maximum(length, 1e-300), 1.0)
    t[:, :3] = point + held + across * scale[:, None]
    return t


def _still_near(t: Array, point: Array) -> float:
    """1 when the path passes within FAR_FROM[0] of the point, easing to 0 over FAR_FROM[1] beyond."""
    gap = float(np.linalg.norm(t[:, :3] - point, axis=1).min()) / extent(t)
    start, width = FAR_FROM
    return 1.0 - float(smoothstep(np.asarray((gap - start) / width)))


EXACT_ROUNDS = 20
"""How often the exact clearance pushes go round the points at most: a push out of one point's
clearance can land a waypoint in another's where two overlap (two rounds sufficed where measured)."""


def avoid(
    trajectory: TrajectoryArg,
    points: PointsArg,
    clearance: float,
    iterations: int = 50,
    *,
    far_side: bool = False,
) -> Array:
    """Give a point or a list of points a clearance: every waypoint at least clearance away.

    Make every waypoint at least clearance away from each point (one point or a list of points),
    spreading the correction smoothly over neighbouring waypoints. Waypoints already further away stay.

    ``far_side``: take the path round each point on the other side from the one it passes now (where
    a wall or a bound leaves no room on its own side).
    """
    t = as_trajectory(trajectory)
    centres = _points(points)
    minimum = float(clearance)
    sides = [-passing_side(t, centre, minimum) if far_side else None for centre in centres]
    for _ in range(int(iterations)):
        pushes = [clearance_push(t, c, minimum * 1.02, side=s) for c, s in zip(centres, sides, strict=True)]
        push = np.sum(pushes, axis=0)
        if not np.any(push):
            break
        t[:, :3] += _spread(push)
    for _ in range(EXACT_ROUNDS):  # exact guarantee after the smooth passes, for all points together
        for centre in centres:
            t[:, :3] += clearance_push(t, centre, minimum, sideways=False)
        if all(np.linalg.norm(t[:, :3] - c, axis=1).min() >= minimum * (1 - 1e-9) for c in centres):
            break
    return t


def _points(points: Any) -> list[Array]:
    if points is None or isinstance(points, str):
        return [as_point(points)]
    array = np.asarray(points, dtype=object if _ragged(points) else np.float64)
    if array.dtype != object and array.ndim == 1:
        return [as_point(array)]
    return [as_point(p, f"points[{i}]") for i, p in enumerate(points)]


def _ragged(points: Any) -> bool:
    try:
        np.asarray(points, dtype=np.float64)
    except (ValueError, TypeError):
        return True
    return False


def clearance_push(
    t: Array, centre: Array, minimum: float, sideways: bool = True, side: Array | None = None
) -> Array:
    """Displacements that bring waypoints within ``minimum`` of ``centre`` out to it.

    Sideways (across the direction of travel) when possible, so that a path running straight at
    the object bends around it instead of bunching up; radially otherwise. ``side``: the direction
    from the centre to push towards (across each heading), through the centre if need be; by default
    the side the waypoints inside are on.
    """
    offset = t[:, :3] - centre
    inside = np.linalg.norm(offset, axis=1) < minimum
    if not inside.any():
        return np.zeros((len(t), 3))
    if not sideways:
        direction = _unit(offset, _fallback(t))
    elif side is None:
        direction = sideways_from(t, offset, inside)
    else:
        direction = _across_heading(t, side)
    along = np.sum(offset * direction, axis=1)
    gap = along**2 - (np.sum(offset * offset, axis=1) - minimum**2)
    distance = -along + np.sqrt(np.maximum(gap, 0.0))
    return np.where(inside[:, None], np.maximum(distance, 0.0)[:, None] * direction, 0.0)


def _unit(vectors: Array, fallback: Array) -> Array:
    norm = np.linalg.norm(vectors, axis=1, keepdims=True)
    return np.where(norm > 1e-12, vectors / np.maximum(norm, 1e-12), fallback)


def passing_side(t: Array, centre: Array, minimum: float) -> Array:
    """The direction from ``centre`` to the side the path passes it on, across its heading (0 if clear)."""
    offset = t[:, :3] - np.asarray(centre, dtype=np.float64)
    inside = np.linalg.norm(offset, axis=1) < minimum
    return _shared_side(t, _heading(t), offset, inside) if inside.any() else np.zeros(3)


def sideways_from(t: Array, offset: Array, inside: Array) -> Array:
    """One shared sideways direction per obstacle, perpendicular to each waypoint's heading."""
    heading = _heading(t)
    return _across_heading(t, _shared_side(t, heading, offset, inside), heading)


def _heading(t: Array) -> Array:
    """Each waypoint's unit direction of travel (+y where the path does not move)."""
    return _unit(np.gradient(t[:, :3], axis=0), np.array([[0.0, 1.0, 0.0]]))


def _shared_side(t: Array, heading: Array, offset: Array, inside: Array) -> Array:
    """The sum of the inside waypoints' offsets across their heading: the side they pass on."""
    perpendicular = offset - np.sum(offset * heading, axis=1, keepdims=True) * heading
    shared: Array = perpendicular[inside].sum(axis=0)
    if np.linalg.norm(shared) < 1e-9:
        shared = _fallback(t)[inside].sum(axis=0)
    return shared


def _across_heading(t: Array, shared: Array, heading: Array | None = None) -> Array:
    """``shared`` made perpendicular to each waypoint's heading, as unit vectors."""
    heading = _heading(t) if heading is None else heading
    local = shared - np.sum(shared * heading, axis=1, keepdims=True) * heading
    return _unit(local, _fallback(t))


def _fallback(t: Array) -> Array:
    """Horizontal unit vectors across the heading (for points straight ahead of an obstacle)."""
    heading = np.gradient(t[:, :3], axis=0)
    side = np.stack([-heading[:, 1], heading[:, 0], np.zeros(len(t))], axis=1)
    norm = np.linalg.norm(side, axis=1, keepdims=True)
    return np.where(norm > 1e-12, side / np.maximum(norm, 1e-12), np.array([[1.0, 0.0, 0.0]]))


def _spread(push: Array) -> Array:
    """Blend a correction into neighbouring waypoints (Gaussian over the index), keeping its peak."""
    sigma = max(len(push) / 30.0, 1.0)
    radius = int(3 * sigma)
    kernel = np.exp(-0.5 * (np.arange(-radius, radius + 1) / sigma) ** 2)
    spread = np.stack([np.convolve(push[:, k], kernel / kernel.max(), mode="same") for k in range(3)], axis=1)
    peak = np.linalg.norm(push, axis=1).max()
    largest = np.linalg.norm(spread, axis=1).max()
    return spread * (peak / largest) if largest > 0 else spread


def pass_through(
    trajectory: TrajectoryArg, point: PointArg, index: int | None = None, width: float = 0.25
) -> Array:
    """Bend the path so that it passes exactly through point (e.g. an object or a midpoint).

    Bend the path so that it passes exactly through point, at the given waypoint index (default: the
    nearest one); width (fraction of the path) sets how far the bend reaches.
    """
    t = as_trajectory(trajectory)
    target = as_point(point)
    if index is not None and np.size(index) != 1:
        raise ValueError(
            "index must be a waypoint number; to pass through two points call pass_through once for each "
            "(t = pass_through(t, a); t = pass_through(t, b)), or use pass_through(t, midpoint(a, b)) "
            "for the point between them"
        )
    k = room_to_bend(t, target, nearest_index(t, target)) if index is None else int(index) % len(t)
    s = progress(t)
    weight = np.exp(-0.5 * ((s - s[k]) / bend_sigma(t, target - t[k, :3], width)) ** 2)
    # the start and the goal stay: a window that is 1 at k and falls smoothly to 0 at each end
    # (subtracting the ends' weights instead, then dividing by the weight at k, blew a bend near an
    # end up many times over)
    before, after = s <= s[k], s > s[k]
    window = np.ones_like(s)
    if k != 0:
        window[before] = smoothstep(s[before] / max(s[k], 1e-12))
    if k != len(t) - 1:
        window[after] = smoothstep((1.0 - s[after]) / max(1.0 - s[k], 1e-12))
    t[:, :3] += (weight * window)[:, None] * (target - t[k, :3])
    return t


OVER_CLEARANCE = 0.1  # how far above an object pass_over goes by default (fraction of the path's size)
OVER_ROUNDS = 4
"""Rounds of bends over several points: each round puts back what the neighbours' bends moved."""


def pass_over(trajectory: TrajectoryArg, points: PointsArg, clearance: DistanceArg = None) -> Array:
    """Bend the path so that it passes over a point or each of a list of points, clearance above it.

    Bend the path so that it passes right over each point (horizontally through it, clearance above
    it; default a tenth of the path's size), e.g. to hop over objects. Start and goal stay. Without a
    stated clearance the pass is never lower than the path already flies there: a path raised
    before ("raise the whole flight by 30 cm, fly over the keyboard") keeps its height; with one, no
    waypoint above the point comes nearer it than that, away from the ends.
    """
    t = as_trajectory(trajectory)
    height = OVER_CLEARANCE * extent(t) if clearance is None else resolve_amount(clearance, t)
    tops = [centre + np.array([0.0, 0.0, height]) for centre in _points(points)]
    if clearance is None:
        tops = [_no_lower_than_the_path(t, top) for top in tops]
    for _ in range(OVER_ROUNDS if len(tops) > 1 else 1):  # each bend nudges the others' passes
        for top in tops:
            t = pass_through(t, top, inner_room_to_bend(t, top))
    if clearance is not None:  # a stated gap is kept all the way over, not only at the top
        t = _over_the_domes(t, _points(points), height)
    return t


def _over_the_domes(t: Array, centres: list[Array], clearance: float) -> Array:
    """``t`` with each inner waypoint above a centre and nearer than ``clearance`` lifted onto its dome.

    The bend passes ``clearance`` above the point, but its shoulders, lower and horizontally near it,
    came closer ("go over the toad, leaving a gap of at least 100 mm" passed at 0.093). The lift fades
    out within ``ENDS_FADE`` of each end, which stays where it is.
    """
    out = t.copy()
    fade = _away_from_the_ends(t)  # no cliff beside a kept end inside a dome
    for centre in centres:
        across = np.linalg.norm(out[:, :2] - centre[:2], axis=1)
        dome = centre[2] + np.sqrt(np.clip(clearance**2 - across**2, 0.0, None))
        lift = np.where(
            (across < clearance) & (out[:, 2] >= centre[2]), np.clip(dome - out[:, 2], 0.0, None), 0.0
        )
        out[:, 2] += lift * fade
    return out


def _no_lower_than_the_path(t: Array, top: Array) -> Array:
    """``top`` raised to the height of the waypoint horizontally nearest it, where that is higher."""
    nearest = int(np.argmin(np.linalg.norm(t[:, :2] - top[:2], axis=1)))
    return np.array([top[0], top[1], max(float(top[2]), float(t[nearest, 2]))])


def reach(trajectory: TrajectoryArg, point: PointArg) -> Array:
    """Make the path end at point instead of the old goal; the start stays and the path bends smoothly."""
    t = as_trajectory(trajectory)
    offset = as_point(point) - t[-1, :3]
    t[:, :3] += smoothstep(progress(t))[:, None] * offset
    return t


def midpoint(first: PointArg, second: PointArg) -> Array:
    """The point halfway between two points (e.g. two objects)."""
    return (as_point(first, "first") + as_point(second, "second")) / 2.0


def closest_waypoint(trajectory: TrajectoryArg, point: PointArg) -> int:
    """The index of the waypoint nearest to point."""
    return nearest_index(as_trajectory(trajectory), point)

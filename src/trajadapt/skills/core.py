"""Shared pieces of the skill library: array checks, direction and amount words, smooth blends.

Everything here is pure numpy, so the library also loads inside the sandbox child.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Annotated, Any

import numpy as np

from trajadapt.model.geometry import PART_WORDS, Array, extent, progress


@dataclass(frozen=True)
class ArgKind:
    """What a skill parameter accepts, beyond its Python type: read by the answer grammar.

    Kinds: trajectory, point, points, direction, distance (a number or an amount word), fraction
    (0..1 or a closeness word), part (a word or a pair), waypoint (an index, a word or a point),
    profile (a speed-profile name), height (an absolute z), factor (a speed multiplier). Plain
    ``float``, ``int`` and ``bool`` parameters need no kind.
    """

    name: str


TrajectoryArg = Annotated[Any, ArgKind("trajectory")]
PointArg = Annotated[Any, ArgKind("point")]
PointsArg = Annotated[Any, ArgKind("points")]
DirectionArg = Annotated[str, ArgKind("direction")]
DistanceArg = Annotated[Any, ArgKind("distance")]
FractionArg = Annotated[Any, ArgKind("fraction")]
PartArg = Annotated[Any, ArgKind("part")]
WaypointArg = Annotated[Any, ArgKind("waypoint")]
ProfileArg = Annotated[str, ArgKind("profile")]
HeightArg = Annotated[float, ArgKind("height")]
FactorArg = Annotated[float, ArgKind("factor")]

# Vague amount words, as fractions of the trajectory's size (largest side of its bounding box).
# Calibrated on latte-dev's targets with benchmarks/latte_oracle.py (README, "Calibrated amounts"):
# the amounts before were 0.08 / 0.15 / 0.3 and overshot LaTTe's generator by a third or more.
AMOUNT_WORDS = {
    "tiny": 0.03, "very slightly": 0.03, "slightly": 0.06, "a little": 0.06, "little": 0.06,
    "a bit": 0.06, "bit": 0.06, "small": 0.06, "somewhat": 0.09, "default": 0.12, "": 0.12,
    "moderately": 0.12, "much": 0.2, "a lot": 0.2, "lot": 0.2, "very": 0.2, "far": 0.2,
    "large": 0.2, "significantly": 0.2, "very much": 0.25,
}  # fmt: skip

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?")


def as_trajectory(trajectory: Any) -> Array:
    """A float copy of ``trajectory`` checked to be (N, 4) with N >= 2.

    Raises:
        ValueError: with the shape found and what is expected.
    """
    array = np.array(trajectory, dtype=np.float64, copy=True)
    if array.ndim != 2 or array.shape[1] != 4 or array.shape[0] < 2:
        raise ValueError(
            f"expected a trajectory of shape (N, 4) with rows (x, y, z, velocity), got shape {array.shape}; "
            "pass the array from get_trajectory() or from another skill"
        )
    return array


def as_point(point: Any, name: str = "point") -> Array:
    """A 3-vector from a position, an object position from detect_objects, or an (x, y, z, v) row.

    Raises:
        ValueError: None (an object that was not found) or a value that is not a position.
    """
    if point is None:
        raise ValueError(
            f"{name} is None: detect_objects() did not find that object; check its name in the "
            "ENVIRONMENT DESCRIPTION"
        )
    if isinstance(point, str):
        raise ValueError(
            f"{name} must be a position [x, y, z] (for an object use detect_objects('{point}')), "
            f"not the word {point!r}"
        )
    array = np.asarray(point, dtype=np.float64).reshape(-1)
    if array.size == 1:
        raise ValueError(
            f"{name} must be a position [x, y, z], got the single number {point!r}: detect_objects('name') "
            "already returns [x, y, z], pass it whole (do not index it)"
        )
    if array.size not in (3, 4):
        raise ValueError(f"{name} must be a position [x, y, z], got {point!r}")
    return array[:3].copy()


def resolve_amount(amount: Any, trajectory: Array, default_word: str = "") -> float:
    """A distance from a number or a vague word ('a bit', 'a lot'), relative to the trajectory's size.

    None and 0 both mean the default word's amount; a text holding one number ('at least 0.5') is that number.

    Raises:
        ValueError: an unknown word, listing the known ones.
    """
    if amount is None or (isinstance(amount, (int, float)) and not isinstance(amount, bool) and amount == 0):
        amount = default_word  # a move "by 0" is never what was asked: read it as "by the default amount"
    if isinstance(amount, str):
        key = amount.strip().lower()
        numbers = NUMBER.findall(key)
        if key not in AMOUNT_WORDS and len(numbers) == 1:
            return float(numbers[0])  # 'at least 0.5', '0.2 m': the one number given
        if key not in AMOUNT_WORDS:
            words = ", ".join(sorted(w for w in AMOUNT_WORDS if w))
            raise ValueError(f"unknown amount {amount!r}; give a number or one of: {words}")
        return AMOUNT_WORDS[key] * extent(trajectory)
    return float(amount)


def smoothstep(x: Array) -> Array:
    """0 below 0, 1 above 1, a smooth S in between (zero slope at both ends)."""
    t = np.clip(x, 0.0, 1.0)
    return t * t * t * (t * (6.0 * t - 15.0) + 10.0)


def bump(trajectory: Array) -> Array:
    """A weight that is 0 at start and goal and 1 in the middle, smooth (sin^2 of the progress)."""
    return np.sin(np.pi * progress(trajectory)) ** 2


def proximity(trajectory: Array, point: Array, radius: float, edge: float | None = None) -> Array:
    """1 at the waypoint nearest to ``point``, falling smoothly to 0 over ``radius`` beyond that.

    ``edge``: the distance from ``point`` within which the weight is 1 (the closest pass if None).
    """
    distance = np.linalg.norm(trajectory[:, :3] - point, axis=1)
    start = distance.min() if edge is None else edge
    relative = np.clip(distance - start, 0.0, None) / max(radius, 1e-12)
    weight: Array = np.exp(-(relative**2) * 3.0)
    return weight


def within(trajectory: Array, point: Array, radius: float, blend: float | None = None) -> Array:
    """1 for waypoints within ``radius`` of ``point``, easing to 0 over ``blend`` beyond it."""
    distance = np.linalg.norm(trajectory[:, :3] - point, axis=1)
    width = blend if blend is not None else 0.5 * radius
    return 1.0 - smoothstep((distance - radius) / max(width, 1e-12))


def part_mask(trajectory: Array, part: Any, blend: float = 0.1) -> Array:
    """A smooth 0..1 weight selecting a part of the path.

    ``part`` is a word ('all', 'start', 'middle', 'end', 'first half', 'second half'), a pair of
    fractions of the path (0.2, 0.6), or a pair of waypoint indices (5, 20) (end exclusive).

    Raises:
        ValueError: an unknown word or a malformed pair.
    """
    low, high, by_index = _part_bounds(trajectory, part)
    if by_index:
        weights = np.zeros(len(trajectory))
        weights[int(low) : int(high)] = 1.0
        return weights
    s = progress(trajectory)
    rise = smoothstep((s - low) / blend + 0.5) if low > 0 else np.ones_like(s)
    fall = 1.0 - smoothstep((s - high) / blend + 0.5) if high < 1 else np.ones_like(s)
    return rise * fall


def _part_bounds(trajectory: Array, part: Any) -> tuple[float, float, bool]:
    if part is None:
        return 0.0, 1.0, False
    if isinstance(part, str):
        key = part.strip().lower()
        if key not in PART_WORDS:
            raise ValueError(
                f"unknown part {part!r}; use one of {', '.join(PART_WORDS)} or a pair (start, end)"
            )
        low, high = PART_WORDS[key]
        return low, high, False
    if isinstance(part, Sequence | np.ndarray) and len(part) == 2:
        low, high = float(part[0]), float(part[1])
        is_index = isinstance(part[0], int | np.integer) and isinstance(part[1], int | np.integer)
        if is_index:
            return max(low, 0), min(high, len(trajectory)), True
        return low, high, False
    raise ValueError(f"part must be a word or a pair (start, end), got {part!r}")


def nearest_index(trajectory: Array, point: Any) -> int:
    """Index of the waypoint closest to ``point``."""
    return int(np.argmin(np.linalg.norm(trajectory[:, :3] - as_point(point), axis=1)))

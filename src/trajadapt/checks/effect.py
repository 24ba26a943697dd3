"""What an adaptation actually did, measured on the two trajectories.

``measure_effect`` compares the original and the adapted trajectory: start and goal moved (how far,
which way in the stated axis convention), the largest and mean displacement and where along the
path, the closest distance to each object, the mean distance and the speed near it (its nearest
quarter of waypoints) before and after, mean speed, path length, waypoint count and time to
traverse; where the result was projected onto constraints, which constraint moved which waypoints.
What the effect contradicts in the user's words is read in ``checks.contradictions``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import asdict, dataclass

import numpy as np
import numpy.typing as npt

from trajadapt.checks.constraints import ConstraintMove
from trajadapt.model.geometry import Axes, extent, progress
from trajadapt.model.scene import SceneObject
from trajadapt.model.trajectory import Trajectory

Array = npt.NDArray[np.float64]
NEAR_SHARE = 0.25  # the share of waypoints nearest an object whose speed counts as "near" it
NOTICEABLE = 0.02  # of the original's size: smaller changes read as "no change"


@dataclass(frozen=True)
class ObjectEffect:
    """Closest distance to one object, the mean distance and speed near it, before and after.

    "Near" is the ``NEAR_SHARE`` of waypoints nearest the object, on each path.
    """

    name: str
    closest_before: float
    closest_after: float
    speed_near_before: float
    speed_near_after: float
    near_before: float
    near_after: float


@dataclass(frozen=True)
class Effect:
    """The measured change between two trajectories; lengths in the trajectory's units."""

    size: float
    start_moved: float
    start_direction: str
    goal_moved: float
    goal_direction: str
    largest_displacement: float
    largest_at: float
    mean_displacement: float
    mean_shift: tuple[float, float, float]
    mean_shift_direction: str
    speed_before: float
    speed_after: float
    length_before: float
    length_after: float
    waypoints_before: int
    waypoints_after: int
    duration_before: float | None
    duration_after: float | None
    objects: tuple[ObjectEffect, ...]
    constraint_moves: tuple[ConstraintMove, ...] = ()

    def to_dict(self) -> dict[str, object]:
        """The result file's ``effect`` field."""
        return asdict(self)

    def describe(self) -> list[str]:
        """The effect in words, one line per fact, for the reviewer."""
        lines = [
            f"start {_moved(self.start_moved, self.start_direction, self.size)}, "
            f"goal {_moved(self.goal_moved, self.goal_direction, self.size)}",
            f"largest displacement {self.largest_displacement:.3g} at {self.largest_at:.0%} of the path, "
            f"mean {self.mean_displacement:.3g} (mostly {self.mean_shift_direction})",
            f"mean speed {self.speed_before:.3g} -> {self.speed_after:.3g}; path length "
            f"{self.length_before:.3g} -> {self.length_after:.3g}; waypoints "
            f"{self.waypoints_before} -> {self.waypoints_after}"
            + (
                f"; time {self.duration_before:.3g} -> {self.duration_after:.3g}"
                if self.duration_before is not None and self.duration_after is not None
                else ""
            ),
        ]
        lines += [
            f"{o.name}: closest {o.closest_before:.3g} -> {o.closest_after:.3g}, speed near it "
            f"{o.speed_near_before:.3g} -> {o.speed_near_after:.3g}"
            for o in self.objects
        ]
        lines += [f"projected: {move.describe()}" for move in self.constraint_moves]
        return lines


def _moved(distance: float, direction: str, size: float) -> str:
    return "kept" if distance <= 1e-6 * max(size, 1e-12) else f"moved {distance:.3g} {direction}"


def direction_words(vector: Array, axes: Axes) -> str:
    """The named directions a displacement points along, largest first ('left and up')."""
    parts = []
    for word in ("left", "front", "up"):
        component = float(vector @ axes.vector(word))
        if abs(component) > 0.25 * float(np.linalg.norm(vector)) and abs(component) > 1e-12:
            opposite = {"left": "right", "front": "back", "up": "down"}[word]
            parts.append((abs(component), word if component > 0 else opposite))
    return " and ".join(word for _, word in sorted(parts, reverse=True)) or "nowhere"


def _matched(original: Array, adapted: Array) -> Array:
    """The adapted positions at the original's progress points (paths of different lengths compare)."""
    if len(original) == len(adapted):
        return adapted
    s, target = progress(adapted), progress(original)
    return np.stack([np.interp(target, s, adapted[:, k]) for k in range(4)], axis=1)


def _duration(t: Array) -> float | None:
    steps = np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1)
    speeds = 0.5 * (t[1:, 3] + t[:-1, 3])
    moving = steps > 1e-12
    if np.any(moving & (speeds <= 1e-12)):
        return None  # a zero speed on a moving step: no finite time
    return float(np.sum(steps[moving] / speeds[moving]))


def _object_effect(obj: SceneObject, original: Array, adapted: Array) -> ObjectEffect:
    point = np.array([obj.x, obj.y, obj.z])

    def nearest(t: Array) -> tuple[Array, npt.NDArray[np.intp]]:
        distance = np.linalg.norm(t[:, :3] - point, axis=1)
        return distance, np.argsort(distance)[: max(2, int(NEAR_SHARE * len(t)))]

    (before, near), (after, near_adapted) = nearest(original), nearest(adapted)
    return ObjectEffect(
        obj.name,
        closest_before=float(before.min()),
        closest_after=float(after.min()),
        speed_near_before=float(original[near, 3].mean()),
        speed_near_after=float(adapted[near_adapted, 3].mean()),
        near_before=float(before[near].mean()),
        near_after=float(after[near_adapted].mean()),
    )


def measure_effect(
    original: Trajectory, adapted: Trajectory, objects: Sequence[SceneObject] = (), axes: Axes | None = None
) -> Effect:
    """Measure what changed from ``original`` to ``adapted`` (see the module docstring)."""
    axes = axes or Axes()
    before, after = original.array, adapted.array
    matched = _matched(before, after)
    displacement = matched[:, :3] - before[:, :3]
    norms = np.linalg.norm(displacement, axis=1)
    largest = int(np.argmax(norms))
    mean_shift = displacement.mean(axis=0)
    start, goal = after[0, :3] - before[0, :3], after[-1, :3] - before[-1, :3]
    return Effect(
        size=extent(before),
        start_moved=float(np.linalg.norm(start)),
        start_direction=direction_words(start, axes),
        goal_moved=float(np.linalg.norm(goal)),
        goal_direction=direction_words(goal, axes),
        largest_displacement=float(norms[largest]),
        largest_at=float(progress(before)[largest]),
        mean_displacement=float(norms.mean()),
        mean_shift=(float(mean_shift[0]), float(mean_shift[1]), float(mean_shift[2])),
        mean_shift_direction=direction_words(mean_shift, axes),
        speed_before=float(before[:, 3].mean()),
        speed_after=float(after[:, 3].mean()),
        length_before=original.path_length(),
        length_after=adapted.path_length(),
        waypoints_before=len(before),
        waypoints_after=len(after),
        duration_before=_duration(before),
        duration_after=_duration(after),
        objects=tuple(_object_effect(obj, before, after) for obj in objects),
    )

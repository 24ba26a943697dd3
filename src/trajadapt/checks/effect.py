"""What an adaptation actually did, measured on the two trajectories, and what contradicts the words.

``measure_effect`` compares the original and the adapted trajectory: start and goal moved (how far,
which way in the stated axis convention), the largest and mean displacement and where along the
path, the closest distance to each object and the speed near it before and after, mean speed, path
length, waypoint count and time to traverse; where the result was projected onto constraints, which
constraint moved which waypoints. ``contradictions`` reads the instruction for the few
things that can be checked without an LLM (an object named whose distance did not change, "slower"
while the speed rose, "left" while the path moved right) and flags them for the reviewer.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import asdict, dataclass

import numpy as np
import numpy.typing as npt

from trajadapt.checks.constraints import ConstraintMove
from trajadapt.model.geometry import DIRECTIONS, OPPOSITE_DIRECTIONS, Axes, extent, progress
from trajadapt.model.scene import SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.readers.words import AWAY, CLOSER, FASTER, SLOWER, said_directions

Array = npt.NDArray[np.float64]
NEAR_SHARE = 0.25  # the share of waypoints nearest an object whose speed counts as "near" it
NOTICEABLE = 0.02  # of the original's size: smaller changes read as "no change"


@dataclass(frozen=True)
class ObjectEffect:
    """Closest distance to one object and the mean speed near it, before and after."""

    name: str
    closest_before: float
    closest_after: float
    speed_near_before: float
    speed_near_after: float


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

    def near_speed(t: Array) -> float:
        distance = np.linalg.norm(t[:, :3] - point, axis=1)
        nearest = np.argsort(distance)[: max(2, int(NEAR_SHARE * len(t)))]
        return float(t[nearest, 3].mean())

    return ObjectEffect(
        obj.name,
        float(np.linalg.norm(original[:, :3] - point, axis=1).min()),
        float(np.linalg.norm(adapted[:, :3] - point, axis=1).min()),
        near_speed(original),
        near_speed(adapted),
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


AVOIDED = re.compile(r"\b(?:avoid\w*|clear of)\b", re.I)
"""Words that ask a clearance: the flags read them as asking away (the readers leave them to ``avoid``)."""


def _asks_away(text: str) -> bool:
    """Whether the words ask to keep further from something (``AWAY``, or a clearance: ``AVOIDED``)."""
    return bool(AWAY.search(text) or AVOIDED.search(text))


def contradictions(instruction: str, effect: Effect, axes: Axes | None = None) -> list[str]:
    """What the measured effect contradicts in the instruction's words; [] when nothing can be read."""
    text = instruction.lower()
    noticeable = NOTICEABLE * effect.size
    flags = _speed_flags(text, effect)
    for obj in effect.objects:
        if obj.name.lower() in text:
            flags += _object_flags(text, obj, noticeable)
    flags += _direction_flags(text, effect, noticeable, axes or Axes())
    return flags


def _speed_flags(text: str, effect: Effect) -> list[str]:
    change = effect.speed_after - effect.speed_before
    tiny = 1e-9 * max(effect.speed_before, 1.0)
    slower, faster = bool(SLOWER.search(text)), bool(FASTER.search(text))
    before_after = f"({effect.speed_before:.3g} -> {effect.speed_after:.3g})"
    if slower and not faster and change > tiny:
        return [f"the instruction asks for slower, but the mean speed rose {before_after}"]
    if faster and not slower and change < -tiny:
        return [f"the instruction asks for faster, but the mean speed fell {before_after}"]
    return []


def _object_flags(text: str, obj: ObjectEffect, noticeable: float) -> list[str]:
    change = obj.closest_after - obj.closest_before
    distances = f"({obj.closest_before:.3g} -> {obj.closest_after:.3g})"
    speed_changed = abs(obj.speed_near_after - obj.speed_near_before) > 1e-6 * max(obj.speed_near_before, 1)
    if abs(change) <= noticeable and not speed_changed:
        return [f"the instruction names the {obj.name}, but neither the distance to it {distances} "
                "nor the speed near it changed"]  # fmt: skip
    away = _asks_away(text)
    if CLOSER.search(text) and not away and change > noticeable:
        return [
            f"the instruction asks to get closer to the {obj.name}, but the closest distance grew {distances}"
        ]
    if away and not CLOSER.search(text) and change < -noticeable:
        return [f"the instruction asks to keep away from the {obj.name}, but the distance shrank {distances}"]
    return []


def _direction_flags(text: str, effect: Effect, noticeable: float, axes: Axes) -> list[str]:
    words = said_directions(text)  # "slow down" says no direction
    named = [w for w in DIRECTIONS if w in words]
    if len(named) != 1 or OPPOSITE_DIRECTIONS[named[0]] in words or CLOSER.search(text) or _asks_away(text):
        return []  # several directions, or relative to an object: no single expected sign
    along = float(np.asarray(effect.mean_shift) @ axes.vector(named[0]))
    if along < -noticeable:
        return [
            f"the instruction says {named[0]}, but the path moved {effect.mean_shift_direction} on average"
        ]
    return []

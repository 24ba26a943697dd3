"""Constraints a result must respect: workspace bounds, clearance from objects, speed, fixed ends.

They come from the case's constraints text (the forms OVITA's cases use: axis ranges of a cuboid,
min/max x and y of a room, a fixed z, a minimum distance from all objects) and from the user's flags.
``find_violations`` measures a trajectory against them; the messages carry the numbers so that the
repair round can use them.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

import numpy as np

from trajadapt.scene import Scene
from trajadapt.skills.core import Array

AXES = "xyz"
NUMBER = r"(-?\d+(?:\.\d+)?)"


@dataclass(frozen=True)
class Constraints:
    """Limits on an adapted trajectory. ``None`` means not constrained."""

    lower: tuple[float, float, float] = (-math.inf, -math.inf, -math.inf)
    upper: tuple[float, float, float] = (math.inf, math.inf, math.inf)
    min_clearance: float | None = None
    clearance_objects: tuple[str, ...] = ()
    max_speed: float | None = None
    keep_start: bool = False
    keep_goal: bool = False
    sources: tuple[str, ...] = field(default=())

    @property
    def empty(self) -> bool:
        """True when nothing is constrained."""
        unbounded = all(math.isinf(v) for v in self.lower + self.upper)
        return (
            unbounded
            and self.min_clearance is None
            and self.max_speed is None
            and not (self.keep_start or self.keep_goal)
        )


def parse_constraints_text(text: str) -> Constraints:
    """Read the bounds and clearance stated in a case's constraints text; unknown sentences are ignored.

    >>> parse_constraints_text("The x-axis range is -2 to 2, and the z-axis range is 0 to 2.").upper
    (2.0, inf, 2.0)
    """
    lower, upper = [-math.inf] * 3, [math.inf] * 3
    sources = []
    for axis, low, high in re.findall(
        rf"\b([xyz])(?:-axis)?\s+(?:range is|ranges from)\s+{NUMBER}\s+to\s+{NUMBER}", text, re.I
    ):
        k = AXES.index(axis.lower())
        lower[k], upper[k] = float(low), float(high)
        sources.append(f"{axis} in [{low}, {high}]")
    for word, axis, value in re.findall(rf"\b(maximum|minimum)\s+([xyz])\s+of\s+{NUMBER}", text, re.I):
        k = AXES.index(axis.lower())
        if word.lower() == "maximum":
            upper[k] = float(value)
        else:
            lower[k] = float(value)
        sources.append(f"{word.lower()} {axis} {value}")
    if re.search(r"z-coordinate is (?:always|fixed at) 0\b", text, re.I):
        lower[2], upper[2] = 0.0, 0.0
        sources.append("z = 0")
    clearance = re.search(rf"minimum distance of\s+{NUMBER}\s+from the boundaries of all objects", text, re.I)
    return Constraints(
        lower=(lower[0], lower[1], lower[2]),
        upper=(upper[0], upper[1], upper[2]),
        min_clearance=float(clearance.group(1)) if clearance else None,
        sources=tuple(sources) + ((f"clearance {clearance.group(1)} from all objects",) if clearance else ()),
    )


def constraints_for(scene: Scene, extra: Constraints | None = None) -> Constraints:
    """The scene's constraints text merged with the user's: the user's values win where both are set."""
    parsed = parse_constraints_text(scene.constraints)
    if extra is None:
        return parsed
    lower = tuple(e if not math.isinf(e) else p for e, p in zip(extra.lower, parsed.lower, strict=True))
    upper = tuple(e if not math.isinf(e) else p for e, p in zip(extra.upper, parsed.upper, strict=True))
    return replace(
        extra,
        lower=(lower[0], lower[1], lower[2]),
        upper=(upper[0], upper[1], upper[2]),
        min_clearance=extra.min_clearance if extra.min_clearance is not None else parsed.min_clearance,
        sources=parsed.sources + extra.sources,
    )


@dataclass(frozen=True)
class Violation:
    """One broken constraint, measured; ``key`` names the exact limit (e.g. 'bounds:x:above')."""

    key: str
    message: str


def new_violations(
    trajectory: Array, original: Array, scene: Scene, constraints: Constraints
) -> list[Violation]:
    """The violations of ``trajectory`` that the original trajectory did not already have."""
    inherited = {v.key for v in find_violations(original, original, scene, constraints)}
    return [v for v in find_violations(trajectory, original, scene, constraints) if v.key not in inherited]


def find_violations(
    trajectory: Array, original: Array, scene: Scene, constraints: Constraints
) -> list[Violation]:
    """Every constraint ``trajectory`` breaks, with the measured numbers (tolerance 1e-6 of the scale)."""
    slack = 1e-6 * max(float(np.ptp(original[:, :3], axis=0).max()), 1.0)
    found = _bound_violations(trajectory, constraints, slack)
    found += _clearance_violations(trajectory, scene, constraints, slack)
    if constraints.max_speed is not None and trajectory[:, 3].max() > constraints.max_speed + slack:
        found.append(
            Violation(
                "speed",
                f"top speed {trajectory[:, 3].max():.4g} is above the limit {constraints.max_speed:.4g}",
            )
        )
    if constraints.keep_start and np.linalg.norm(trajectory[0, :3] - original[0, :3]) > slack:
        found.append(
            Violation(
                "start",
                f"the start moved by {np.linalg.norm(trajectory[0, :3] - original[0, :3]):.4g}; it must stay",
            )
        )
    if constraints.keep_goal and np.linalg.norm(trajectory[-1, :3] - original[-1, :3]) > slack:
        found.append(
            Violation(
                "goal",
                f"the goal moved by {np.linalg.norm(trajectory[-1, :3] - original[-1, :3]):.4g}; keep it",
            )
        )
    return found


def _bound_violations(trajectory: Array, constraints: Constraints, slack: float) -> list[Violation]:
    found = []
    for k, axis in enumerate(AXES):
        values = trajectory[:, k]
        low, high = constraints.lower[k], constraints.upper[k]
        below, above = values < low - slack, values > high + slack
        if below.any():
            found.append(
                Violation(
                    f"bounds:{axis}:below",
                    f"{int(below.sum())} waypoint(s) have {axis} below {low:g} (lowest {values.min():.4g})",
                )
            )
        if above.any():
            found.append(
                Violation(
                    f"bounds:{axis}:above",
                    f"{int(above.sum())} waypoint(s) have {axis} above {high:g} (highest {values.max():.4g})",
                )
            )
    return found


def _clearance_violations(
    trajectory: Array, scene: Scene, constraints: Constraints, slack: float
) -> list[Violation]:
    if constraints.min_clearance is None:
        return []
    names = set(constraints.clearance_objects)
    found = []
    for obj in scene.objects:
        if names and obj.name not in names:
            continue
        closest = float(np.linalg.norm(trajectory[:, :3] - np.asarray(obj.position), axis=1).min())
        if closest < constraints.min_clearance - slack:
            found.append(
                Violation(
                    f"clearance:{obj.name}",
                    f"the path comes within {closest:.4g} of {obj.name}; keep {constraints.min_clearance:g}",
                )
            )
    return found

"""Constraints a result must respect: workspace, reach, clearance from objects, speed, fixed ends.

They come in three layers, later ones winning where both set a value: a robot's limits
(``robot_limits``: a box for the drone and the ground robot, the arm's reach around its base, a top
speed), the case's constraints text (the forms OVITA's cases use: axis ranges of a cuboid, min/max x
and y of a room, a fixed z, a minimum distance from all objects) and the user's flags.
``find_violations`` measures a trajectory against them; each violation names the waypoints that break
it and carries the numbers, so that the repair round and the reviewer can use them.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import TypeVar

import numpy as np

from trajadapt.model.geometry import Array
from trajadapt.model.scene import Scene, SceneObject, name_key
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import names_in

_T = TypeVar("_T")

AXES = "xyz"
NUMBER = r"(-?\d+(?:\.\d+)?)"


@dataclass(frozen=True)
class Reach:
    """The shell an arm's end effector can reach: between ``minimum`` and ``maximum`` from ``base``."""

    base: tuple[float, float, float]
    minimum: float
    maximum: float

    def describe(self) -> str:
        """The shell in words."""
        x, y, z = self.base
        return f"reach {self.minimum:g} to {self.maximum:g} from the base at ({x:g}, {y:g}, {z:g})"


@dataclass(frozen=True)
class Constraints:
    """Limits on an adapted trajectory. ``None`` means not constrained.

    Clearance applies to the objects in ``clearance_objects`` (empty: every object) except those in
    ``approached`` (objects the instruction asks to come near; see ``approached_objects``). It is
    measured from an object's box when its dimensions are known (OVITA: "from the boundaries of all
    objects"), else from its centre; the projection keeps it from the sphere that holds the box.
    """

    lower: tuple[float, float, float] = (-math.inf, -math.inf, -math.inf)
    upper: tuple[float, float, float] = (math.inf, math.inf, math.inf)
    min_clearance: float | None = None
    clearance_objects: tuple[str, ...] = ()
    approached: tuple[str, ...] = ()
    max_speed: float | None = None
    reach: Reach | None = None
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
            and self.reach is None
            and not (self.keep_start or self.keep_goal)
        )

    def keeps_clear_of(self, name: str) -> bool:
        """True when the clearance applies to the object called ``name``."""
        if self.min_clearance is None or name_key(name) in {name_key(n) for n in self.approached}:
            return False
        return not self.clearance_objects or name_key(name) in {name_key(n) for n in self.clearance_objects}

    def merged_with(self, over: Constraints) -> Constraints:
        """These limits with ``over``'s wherever ``over`` sets one (bounds per axis and side)."""
        lower = tuple(o if not math.isinf(o) else b for o, b in zip(over.lower, self.lower, strict=True))
        upper = tuple(o if not math.isinf(o) else b for o, b in zip(over.upper, self.upper, strict=True))
        return Constraints(
            lower=(lower[0], lower[1], lower[2]),
            upper=(upper[0], upper[1], upper[2]),
            min_clearance=_either(over.min_clearance, self.min_clearance),
            clearance_objects=over.clearance_objects or self.clearance_objects,
            approached=tuple(dict.fromkeys(self.approached + over.approached)),
            max_speed=_either(over.max_speed, self.max_speed),
            reach=_either(over.reach, self.reach),
            keep_start=self.keep_start or over.keep_start,
            keep_goal=self.keep_goal or over.keep_goal,
            sources=tuple(dict.fromkeys(self.sources + over.sources)),
        )


def _either(preferred: _T | None, fallback: _T | None) -> _T | None:
    return preferred if preferred is not None else fallback


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


def constraints_for(
    scene: Scene, extra: Constraints | None = None, robot: Constraints | None = None, instruction: str = ""
) -> Constraints:
    """The robot's limits < the scene's constraints text < the user's; clearance spares approached objects.

    ``instruction`` (every instruction of the session so far) names the objects the user asks to come
    near; the clearance does not apply to them.
    """
    merged = (robot or Constraints()).merged_with(parse_constraints_text(scene.constraints))
    if extra is not None:
        merged = merged.merged_with(extra)
    approached = approached_objects(instruction, scene.names()) if merged.min_clearance is not None else ()
    return replace(merged, approached=tuple(dict.fromkeys(merged.approached + approached)))


APPROACH_WORDS = re.compile(
    r"\b(?:approach\w*|closer|close to|near(?:er|by)?|next to|toward[s]?|reach\w*|touch\w*|visit\w*"
    r"|land\w* on|go(?:es)? to|move to|fly to|drive to|pick\w*|grab\w*|over|above|through)\b",
    re.I,
)
AWAY_WORDS = re.compile(r"\b(?:away|avoid\w*|far\w*|clear of|distance from|keep off)\b", re.I)


def approached_objects(instruction: str, names: Sequence[str]) -> tuple[str, ...]:
    """The objects a clause of ``instruction`` asks to come near ('slow down near the box').

    A clause that also says away, avoid or farther does not count.

    >>> approached_objects("approach the cup, then avoid the box", ["cup", "box"])
    ('cup',)
    """
    found = []
    for clause in split_clauses(instruction, names):
        if not APPROACH_WORDS.search(clause) or AWAY_WORDS.search(clause):
            continue
        found += names_in(clause, names)
    return tuple(dict.fromkeys(found))


@dataclass(frozen=True)
class Violation:
    """One broken constraint, measured; ``key`` names the exact limit (e.g. 'bounds:x:above').

    ``waypoints`` are the indices of the waypoints that break it (empty for the whole path's).
    """

    key: str
    message: str
    waypoints: tuple[int, ...] = ()


@dataclass(frozen=True)
class ConstraintMove:
    """What projecting onto one constraint did: which waypoints moved and by how much at most.

    ``largest_change`` is a distance in the trajectory's units, or for the speed limit the largest
    cut in speed.
    """

    constraint: str
    waypoints: tuple[int, ...]
    largest_change: float

    def describe(self) -> str:
        """One line for the reviewer: 'x above 2: waypoints 12-18 moved by up to 0.31'."""
        what = "slowed by up to" if self.constraint == "speed limit" else "moved by up to"
        return f"{self.constraint}: waypoints {index_ranges(self.waypoints)} {what} {self.largest_change:.3g}"


def index_ranges(indices: Sequence[int]) -> str:
    """Indices as ranges: [1, 2, 3, 7] -> '1-3, 7'.

    >>> index_ranges([1, 2, 3, 7, 9, 10])
    '1-3, 7, 9-10'
    """
    parts: list[str] = []
    for index in sorted(set(indices)):
        if parts and index == int(parts[-1].split("-")[-1]) + 1:
            parts[-1] = f"{parts[-1].split('-')[0]}-{index}"
        else:
            parts.append(str(index))
    return ", ".join(parts) or "none"


def new_violations(
    trajectory: Array, original: Array, scene: Scene, constraints: Constraints
) -> list[Violation]:
    """The violations of ``trajectory`` that the original trajectory did not already have."""
    inherited = {v.key for v in find_violations(original, original, scene, constraints)}
    return [v for v in find_violations(trajectory, original, scene, constraints) if v.key not in inherited]


def find_violations(
    trajectory: Array, original: Array, scene: Scene, constraints: Constraints
) -> list[Violation]:
    """Every constraint ``trajectory`` breaks, with the measured numbers (tolerance ``violation_slack``)."""
    slack = violation_slack(original)
    found = _bound_violations(trajectory, constraints, slack)
    found += _reach_violations(trajectory, constraints, slack)
    found += _clearance_violations(trajectory, scene, constraints, slack)
    fast = np.flatnonzero(trajectory[:, 3] > (constraints.max_speed or math.inf) + slack)
    if fast.size:
        found.append(
            Violation(
                "speed",
                f"top speed {trajectory[:, 3].max():.4g} is above the limit {constraints.max_speed:.4g}",
                tuple(int(i) for i in fast),
            )
        )
    for key, index, keep in (("start", 0, constraints.keep_start), ("goal", -1, constraints.keep_goal)):
        moved = float(np.linalg.norm(trajectory[index, :3] - original[index, :3]))
        if keep and moved > slack:
            found.append(
                Violation(key, f"the {key} moved by {moved:.4g}; it must stay", (index % len(trajectory),))
            )
    return found


def violation_slack(original: Array) -> float:
    """How far past a limit still keeps it: 1e-6 of the original's extent (at least 1e-6)."""
    return 1e-6 * max(float(np.ptp(original[:, :3], axis=0).max()), 1.0)


def _reach_violations(trajectory: Array, constraints: Constraints, slack: float) -> list[Violation]:
    reach = constraints.reach
    if reach is None:
        return []
    distance = np.linalg.norm(trajectory[:, :3] - np.asarray(reach.base), axis=1)
    found = []
    for key, broken, words in (
        ("reach:far", distance > reach.maximum + slack, f"farther than {reach.maximum:g} from the base"),
        ("reach:near", distance < reach.minimum - slack, f"nearer than {reach.minimum:g} to the base"),
    ):
        if broken.any():
            found.append(
                Violation(
                    key,
                    f"{int(broken.sum())} waypoint(s) are {words} (the arm's reach; "
                    f"range {distance.min():.4g} to {distance.max():.4g})",
                    tuple(int(i) for i in np.flatnonzero(broken)),
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
                    tuple(int(i) for i in np.flatnonzero(below)),
                )
            )
        if above.any():
            found.append(
                Violation(
                    f"bounds:{axis}:above",
                    f"{int(above.sum())} waypoint(s) have {axis} above {high:g} (highest {values.max():.4g})",
                    tuple(int(i) for i in np.flatnonzero(above)),
                )
            )
    return found


def distance_to(trajectory: Array, obj: SceneObject) -> Array:
    """Each waypoint's distance to the object: to its box when its dimensions are known, else its centre."""
    offsets = np.abs(trajectory[:, :3] - np.asarray(obj.position))
    if obj.dimensions is not None:
        offsets = np.maximum(offsets - np.asarray(obj.dimensions) / 2, 0.0)
    distances: Array = np.linalg.norm(offsets, axis=1)
    return distances


def enclosing_radius(obj: SceneObject) -> float:
    """Half the diagonal of the object's box (0 without dimensions): a sphere that holds the box."""
    return 0.0 if obj.dimensions is None else float(np.linalg.norm(obj.dimensions) / 2)


def _clearance_violations(
    trajectory: Array, scene: Scene, constraints: Constraints, slack: float
) -> list[Violation]:
    if constraints.min_clearance is None:
        return []
    found = []
    for obj in scene.objects:
        if not constraints.keeps_clear_of(obj.name):
            continue
        distance = distance_to(trajectory, obj)
        close = distance < constraints.min_clearance - slack
        if close.any():
            found.append(
                Violation(
                    f"clearance:{obj.name}",
                    f"the path comes within {distance.min():.4g} of {obj.name}; "
                    f"keep {constraints.min_clearance:g}",
                    tuple(int(i) for i in np.flatnonzero(close)),
                )
            )
    return found

"""The planning problem: scene objects as spheres (circles on the ground) inside a bounding box."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from trajadapt.errors import PlanningError
from trajadapt.model.scene import Scene

Array = npt.NDArray[np.float64]
DEFAULT_CLEARANCE_FRACTION = 0.08  # of the box's largest side, when objects have no size


@dataclass(frozen=True)
class PlanningProblem:
    """Start, goal, bounds and round obstacles, in case units."""

    start: Array
    goal: Array
    low: Array
    high: Array
    centres: Array  # (K, 3)
    radii: Array  # (K,)
    planar: bool = False

    def dimensions(self) -> int:
        """2 for a ground robot (x, y), else 3."""
        return 2 if self.planar else 3

    def is_free(self, point: Array) -> bool:
        """True when ``point`` (2 or 3 coordinates) is inside the bounds and clear of every obstacle."""
        d = self.dimensions()
        if np.any(point[:d] < self.low[:d]) or np.any(point[:d] > self.high[:d]):
            return False
        if not len(self.centres):
            return True
        gaps = np.linalg.norm(self.centres[:, :d] - point[:d], axis=1)
        return bool(np.all(gaps > self.radii))


def build_problem(
    scene: Scene,
    start: Array,
    goal: Array,
    clearance: float | None = None,
    bounds: tuple[Array, Array] | None = None,
    planar: bool = False,
) -> PlanningProblem:
    """Obstacles from the scene's objects, bounds from everything with a 25% margin unless given.

    Raises:
        PlanningError: the start or goal lies inside an obstacle or outside the bounds.
    """
    start, goal = np.asarray(start, dtype=np.float64), np.asarray(goal, dtype=np.float64)
    centres = np.array([o.position for o in scene.objects]).reshape(-1, 3)
    if bounds is None:
        everything = np.vstack([centres, start, goal])
        low, high = everything.min(axis=0), everything.max(axis=0)
        margin = 0.25 * max(float((high - low).max()), 1e-6)
        bounds = (low - margin, high + margin)
    low, high = (np.asarray(b, dtype=np.float64) for b in bounds)
    if clearance is None:
        clearance = DEFAULT_CLEARANCE_FRACTION * float((high - low).max())
    radii = np.array([_radius(o.dimensions, clearance) for o in scene.objects])
    problem = PlanningProblem(start, goal, low, high, centres, radii, planar)
    for label, point in (("start", start), ("goal", goal)):
        if not problem.is_free(point):
            raise PlanningError(
                f"the {label} {point.tolist()} is inside an obstacle or outside the bounds; "
                "move it or give a smaller --clearance"
            )
    return problem


def _radius(dimensions: tuple[float, float, float] | None, clearance: float) -> float:
    if dimensions is None:
        return clearance
    return float(np.linalg.norm(dimensions) / 2 + clearance / 2)

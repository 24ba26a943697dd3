"""Initial trajectories from planners, so the loop plan -> adapt -> simulate starts from nothing.

``plan_case(scene, start, goal, planner)`` returns a :class:`~trajadapt.model.case.Case` whose trajectory
avoids the scene's objects: ``rrt`` (ompl, 2-D or 3-D) or ``astar`` (a grid in the plane, for a ground
robot), resampled evenly with rounded corners and a trapezoidal speed profile.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from trajadapt.errors import PlanningError
from trajadapt.model.case import Case
from trajadapt.model.scene import Scene
from trajadapt.model.trajectory import Trajectory
from trajadapt.planning.astar import plan_astar
from trajadapt.planning.obstacles import Array, PlanningProblem, build_problem
from trajadapt.planning.profile import resample_rounded, trapezoidal_speeds
from trajadapt.planning.rrt import plan_rrt

PLANNERS: dict[str, Callable[[PlanningProblem], Array]] = {"rrt": plan_rrt, "astar": plan_astar}


def plan_case(
    scene: Scene,
    start: Array,
    goal: Array,
    planner: str = "rrt",
    count: int = 50,
    speed: float = 1.0,
    clearance: float | None = None,
    instruction: str = "",
    name: str = "planned",
) -> Case:
    """Plan a path from ``start`` to ``goal`` around the scene's objects and return it as a case.

    ``astar`` plans in the plane (z kept at the start's height); ``rrt`` plans in 3-D unless start and
    goal share a height, then in the plane too.

    Raises:
        PlanningError: unknown planner, start/goal blocked, or no path found.
        DependencyNotInstalled: ``rrt`` without ompl.
    """
    if planner not in PLANNERS:
        raise PlanningError(f"unknown planner {planner!r}; choose one of: {', '.join(PLANNERS)}")
    if count < 2:
        raise PlanningError(f"count must be at least 2, got {count}")
    start, goal = np.asarray(start, dtype=np.float64), np.asarray(goal, dtype=np.float64)
    planar = planner == "astar" or abs(float(start[2] - goal[2])) < 1e-9
    problem = build_problem(scene, start, goal, clearance, planar=planar)
    polyline = PLANNERS[planner](problem)
    points = resample_rounded(polyline, count)
    trajectory = Trajectory(np.c_[points, trapezoidal_speeds(count, speed)])
    return Case(name=name, trajectory=trajectory, scene=scene, instruction=instruction)


__all__ = ["PLANNERS", "PlanningProblem", "build_problem", "plan_astar", "plan_case", "plan_rrt"]

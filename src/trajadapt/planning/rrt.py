"""RRT through ompl (2.0.1 wheels), in 2-D for a ground robot or 3-D, with path simplification."""

from __future__ import annotations

from typing import Any

import numpy as np

from trajadapt.errors import DependencyNotInstalled, PlanningError
from trajadapt.planning.obstacles import Array, PlanningProblem

_SEEDED: list[int] = []


def _seed_once(ou: Any, seed: int) -> None:
    """Ompl's generator takes a seed only before its first use in a process; later plans go on from it."""
    if not _SEEDED:
        ou.RNG.setSeed(seed)
        _SEEDED.append(seed)


def plan_rrt(problem: PlanningProblem, seed: int = 7, time_limit_s: float = 5.0) -> Array:
    """An RRT path from start to goal avoiding the obstacles, simplified by ompl, as waypoints.

    Raises:
        DependencyNotInstalled: ompl is not installed.
        PlanningError: no path was found within the time limit.
    """
    try:
        from ompl import base as ob
        from ompl import geometric as og
        from ompl import util as ou
    except ImportError as exc:
        raise DependencyNotInstalled("the RRT planner needs ompl: pip install 'trajadapt[plan]'") from exc
    dims = problem.dimensions()
    ou.setLogLevel(ou.LOG_ERROR)
    _seed_once(ou, seed)
    space = ob.RealVectorStateSpace(dims)
    limits = ob.RealVectorBounds(dims)
    for axis in range(dims):
        limits.setLow(axis, float(problem.low[axis]))
        limits.setHigh(axis, float(problem.high[axis]))
    space.setBounds(limits)
    setup = og.SimpleSetup(space)

    def valid(state: Any) -> bool:
        return problem.is_free(np.array([state[i] for i in range(dims)]))

    setup.setStateValidityChecker(valid)
    start, goal = space.allocState(), space.allocState()
    for axis in range(dims):
        start[axis], goal[axis] = float(problem.start[axis]), float(problem.goal[axis])
    setup.setStartAndGoalStates(start, goal)
    setup.setPlanner(og.RRT(setup.getSpaceInformation()))
    if not setup.solve(time_limit_s) or not setup.haveExactSolutionPath():
        raise PlanningError(
            f"RRT found no path in {time_limit_s:.0f} s; give a smaller --clearance or wider bounds"
        )
    setup.simplifySolution()
    path = setup.getSolutionPath()
    points = np.array([[path.getState(i)[a] for a in range(dims)] for i in range(path.getStateCount())])
    if dims == 2:
        points = np.c_[points, np.full(len(points), problem.start[2])]
    return points

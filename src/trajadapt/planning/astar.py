"""Grid A* in the plane for a ground robot: 8-connected cells, obstacles inflated by the clearance."""

from __future__ import annotations

import heapq
import math

import numpy as np

from trajadapt.errors import PlanningError
from trajadapt.planning.obstacles import Array, PlanningProblem

MOVES = [(dx, dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1) if dx or dy]


def plan_astar(problem: PlanningProblem, cells: int = 120) -> Array:
    """The shortest free grid path from start to goal in x, y (z kept at the start's), as waypoints.

    Raises:
        PlanningError: no free path exists on the grid.
    """
    size = float((problem.high[:2] - problem.low[:2]).max()) / cells
    shape = tuple(int(math.ceil(v)) + 1 for v in (problem.high[:2] - problem.low[:2]) / size)
    free = _free_grid(problem, shape, size)
    start, goal = _cell(problem.start, problem, size), _cell(problem.goal, problem, size)
    free[start] = free[goal] = True
    came_from = _search(free, start, goal)
    cells_path = [goal]
    while cells_path[-1] != start:
        cells_path.append(came_from[cells_path[-1]])
    xy = np.array([problem.low[:2] + size * np.array(c, dtype=np.float64) for c in reversed(cells_path)])
    xy[0], xy[-1] = problem.start[:2], problem.goal[:2]
    return np.asarray(np.c_[xy, np.full(len(xy), problem.start[2])])


def _free_grid(problem: PlanningProblem, shape: tuple[int, ...], size: float) -> np.ndarray:
    xs = problem.low[0] + size * np.arange(shape[0])
    ys = problem.low[1] + size * np.arange(shape[1])
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    free = np.ones(shape, dtype=bool)
    for centre, radius in zip(problem.centres, problem.radii, strict=True):
        free &= np.hypot(gx - centre[0], gy - centre[1]) > radius
    return free


def _cell(point: Array, problem: PlanningProblem, size: float) -> tuple[int, int]:
    index = np.rint((point[:2] - problem.low[:2]) / size).astype(int)
    return int(index[0]), int(index[1])


def _search(
    free: np.ndarray, start: tuple[int, int], goal: tuple[int, int]
) -> dict[tuple[int, int], tuple[int, int]]:
    came_from: dict[tuple[int, int], tuple[int, int]] = {}
    cost = {start: 0.0}
    frontier = [(math.dist(start, goal), start)]
    while frontier:
        _, current = heapq.heappop(frontier)
        if current == goal:
            return came_from
        for dx, dy in MOVES:
            nxt = (current[0] + dx, current[1] + dy)
            if not (0 <= nxt[0] < free.shape[0] and 0 <= nxt[1] < free.shape[1]) or not free[nxt]:
                continue
            new_cost = cost[current] + math.hypot(dx, dy)
            if new_cost < cost.get(nxt, math.inf):
                cost[nxt], came_from[nxt] = new_cost, current
                heapq.heappush(frontier, (new_cost + math.dist(nxt, goal), nxt))
    raise PlanningError("A* found no free path between start and goal; give a smaller --clearance")

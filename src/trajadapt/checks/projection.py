"""Project a trajectory that breaks its constraints onto them with a small, smooth least-squares solve.

The quadratic program (solved with OSQP, ``pip install "trajadapt[qp]"``) stays as close as possible
to the LLM's trajectory while keeping its shape smooth:

    minimise  |p - a|^2 + w |D2 p|^2   over positions p (N x 3), a = the adapted positions,
    subject to  lower <= p <= upper, fixed start/goal where asked,
                n_i . (p_i - c) >= d for waypoints near each object (clearance, linearised at a),
                r_min <= n_i . (p_i - b) <= r_max for waypoints near the edge of an arm's reach.

Clearance and the inner reach are not convex, so the linearised problem is solved again from its
own answer a few times; what the linearisation leaves is closed by a direct push, which is smoothed
once more and kept only if the smoothed path breaks nothing new. Speeds are not changed (they are
clipped to ``max_speed`` if one is set). The clearances the program itself keeps at its close
(``kept``: ``avoid(t, detect_objects('fan'), 1)``, from ``closing_limits.kept_clearances``) get rows
of their own, measured from the object's centre as the step measures them: pulling a path back
inside its bounds must not bring it back beside the object the words keep it from; unlike a
constraint, one the projection cannot keep is no violation. ``Projection.moves`` says which
constraint moved which waypoints; the rest of the moved waypoints moved to keep the path smooth.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from trajadapt.checks.constraints import (
    ConstraintMove,
    Constraints,
    enclosing_radius,
    find_violations,
    new_violations,
)
from trajadapt.checks.projection_ends import (
    broken_at_ends,
    broken_by_the_code,
    ends_where_the_program_put_them,
    held_as_original,
    holding_kept_ends,
    matched_original,
    outside_as_original,
)
from trajadapt.checks.projection_moves import constraint_moves
from trajadapt.errors import DependencyNotInstalled
from trajadapt.model.geometry import Array
from trajadapt.model.scene import Scene
from trajadapt.skills.objects import avoid, sideways_from

SMOOTHING_WEIGHT = 4.0
ROUNDS = 4
REACH_MARGIN = 0.9  # waypoints beyond this share of the outer reach (or inside 1/share of the inner) get rows
KEPT_MARGIN = 1.02  # a kept clearance's rows hold a little more, as ``avoid`` does: the linearisation moves
Kept = Sequence[tuple[Sequence[float], float]]
"""Clearances the program keeps: (a point, the least distance from it)."""


@dataclass(frozen=True)
class Projection:
    """The projected trajectory and what changed: per constraint, and what is still broken.

    ``as_original``: limits the original path itself broke at its start or goal, which the
    projection left as they were (the code did not move that end), and bounds the original runs
    outside of, left where it does.
    """

    trajectory: Array
    largest_move: float
    remaining: tuple[str, ...]
    moves: tuple[ConstraintMove, ...] = ()
    as_original: tuple[str, ...] = ()
    far_sides: tuple[str, ...] = ()
    """The objects whose kept clearance the path keeps by going round their other side."""

    def describe(self) -> str:
        """One line for the reviewer."""
        tail = f"; still violated: {'; '.join(self.remaining)}" if self.remaining else ""
        if self.far_sides:
            far = ", ".join(self.far_sides)
            tail += f"; taken round the other side of {far}: no room for its clearance on the near side"
        if self.as_original:
            kept = "; ".join(self.as_original)
            tail += f"; left as the original has them (at an end, or outside the room): {kept}"
        return f"projected onto the constraints: waypoints moved by at most {self.largest_move:.4g}{tail}"


def project(
    trajectory: Array, original: Array, scene: Scene, constraints: Constraints, kept: Kept = ()
) -> Projection:
    """Return the nearest smooth trajectory that satisfies ``constraints``.

    A pause (consecutive waypoints at one position) stays a pause: the problem is solved on one
    waypoint per run of equal positions and the answer is spread back over the run.

    Raises:
        DependencyNotInstalled: osqp or scipy is missing.
    """
    inherited = broken_at_ends(original, original, scene, constraints)
    broken_ends = broken_by_the_code(trajectory, original, scene, constraints, inherited)
    constraints = holding_kept_ends(trajectory, original, constraints, broken_ends)
    runs = _runs_of_equal_positions(trajectory)
    firsts = np.flatnonzero(np.r_[True, np.diff(runs) > 0])
    ends = ends_where_the_program_put_them(trajectory, constraints, broken_ends)
    compact, rounded = _keeping_what_it_can(
        trajectory[firsts], original, Problem(scene, constraints, tuple(kept), ends)
    )
    projected = trajectory.copy()
    projected[:, :3] = compact[runs, :3]
    if constraints.max_speed is not None:
        projected[:, 3] = np.minimum(projected[:, 3], constraints.max_speed)
    left = find_violations(projected, original, scene, constraints)
    held = held_as_original(left, len(projected), inherited, constraints) | outside_as_original(
        left, projected, original
    )
    remaining = tuple(v.message for v in left if v.key not in held)
    as_original = tuple(v.message for v in left if v.key in held)
    largest = float(np.linalg.norm(projected[:, :3] - trajectory[:, :3], axis=1).max())
    broken = new_violations(trajectory, original, scene, constraints)
    moves = constraint_moves(trajectory, projected, broken)
    far_sides = tuple(_named(scene, point) for point, _ in rounded)
    return Projection(projected, largest, remaining, moves, as_original, far_sides)


@dataclass(frozen=True)
class Problem:
    """What a projection keeps: the scene, the constraints and the program's own clearances."""

    scene: Scene
    constraints: Constraints
    kept: Kept = ()
    ends: tuple[tuple[int, tuple[float, float, float]], ...] = ()
    """Ends held where the program put them: (0 or -1, position)."""

    def pins(self, original: Array) -> list[tuple[int, Array]]:
        """The ends held fixed, (0 or -1, position): those kept at the original's, those the program put."""
        kept = ((0, self.constraints.keep_start), (-1, self.constraints.keep_goal))
        return [(end, original[end, :3]) for end, keep in kept if keep] + [
            (end, np.asarray(position)) for end, position in self.ends
        ]

    def bounds(self, count: int, original: Array) -> tuple[Array, Array]:
        """Lower and upper bounds per waypoint of ``count`` (count x 3), as far out as the original goes.

        Where the original itself lies outside the room (a path that enters it from outside), the
        waypoint at the same share of the path may lie as far out as the original does there: the
        projection is for what the program broke, and pulling that stretch inside while its end
        stays where it was would make a jump.
        """
        lower = np.array([_finite(v, -1e9) for v in self.constraints.lower], dtype=np.float64)
        upper = np.array([_finite(v, 1e9) for v in self.constraints.upper], dtype=np.float64)
        matched = matched_original(original, count)
        return np.minimum(lower, matched), np.maximum(upper, matched)

    def broken(self, trajectory: Array, original: Array) -> int:
        """How many constraints and kept clearances ``trajectory`` breaks."""
        return self.limits_broken(trajectory, original) + self.kept_broken(trajectory)

    def limits_broken(self, trajectory: Array, original: Array) -> int:
        """How many constraints ``trajectory`` breaks."""
        return len(find_violations(trajectory, original, self.scene, self.constraints))

    def kept_broken(self, trajectory: Array) -> int:
        """How many of the program's clearances ``trajectory`` breaks."""
        return sum(_nearest(trajectory, point) < distance - 1e-9 for point, distance in self.kept)


def _named(scene: Scene, point: Sequence[float]) -> str:
    """The scene object at ``point``, or the point itself."""
    at = [o.name for o in scene.objects if np.allclose(o.position, point)]
    return f"the {at[0]}" if at else f"({', '.join(f'{c:.3g}' for c in point)})"


def _nearest(trajectory: Array, point: Sequence[float]) -> float:
    return float(np.linalg.norm(trajectory[:, :3] - np.asarray(point, dtype=np.float64), axis=1).min())


def _runs_of_equal_positions(trajectory: Array) -> np.ndarray:
    """For each waypoint, the number of its run of consecutive waypoints at the same position."""
    scale = max(float(np.ptp(trajectory[:, :3], axis=0).max()), 1.0)
    moved = np.linalg.norm(np.diff(trajectory[:, :3], axis=0), axis=1) > 1e-12 * scale
    runs: np.ndarray = np.r_[0, np.cumsum(moved)]
    return runs


def _keeping_what_it_can(trajectory: Array, original: Array, problem: Problem) -> tuple[Array, Kept]:
    """The projection keeping the program's clearances too, where that is no worse; else the plain one.

    No worse: it holds them, breaks no more limits than the projection onto the limits alone, and
    stays as smooth. Where the limits leave no room on the side the path passes (an object 0.5 from
    a wall, kept 0.8 from), the path is taken round the object's other side, kept if that is no worse
    too; it must not be pulled across the scene. Also returned: the clearances taken round the far side.
    """
    plain = _project_distinct(trajectory, original, replace(problem, kept=()))
    plain_limits = problem.limits_broken(plain, original)
    if not problem.kept or plain_limits + problem.kept_broken(plain) == 0:
        return plain, ()
    rounded = tuple(
        (point, distance) for point, distance in problem.kept if _nearest(plain, point) < distance - 1e-9
    )
    candidates = [(trajectory, ())] + ([(_round_the_far_side(plain, rounded), rounded)] if rounded else [])
    for candidate, far in candidates:
        keeping = _project_distinct(candidate, original, problem)
        smooth_enough = _longest_step(keeping) <= 1.5 * max(_longest_step(trajectory), _longest_step(plain))
        no_worse = (
            problem.kept_broken(keeping) == 0 and problem.limits_broken(keeping, original) <= plain_limits
        )
        if smooth_enough and no_worse:
            return keeping, far
    return plain, ()


def _round_the_far_side(trajectory: Array, clearances: Kept) -> Array:
    """``trajectory`` taken round each point on the side away from the one it passes, at its clearance."""
    for point, distance in clearances:
        trajectory = avoid(trajectory, [list(point)], distance * KEPT_MARGIN, far_side=True)
    return trajectory


def _longest_step(trajectory: Array) -> float:
    return float(np.linalg.norm(np.diff(trajectory[:, :3], axis=0), axis=1).max(initial=0.0))


def _project_distinct(trajectory: Array, original: Array, problem: Problem) -> Array:
    """The projection of a trajectory without repeated positions (see ``project``)."""
    positions = trajectory[:, :3].copy()
    for _ in range(ROUNDS):
        positions = _solve(positions, trajectory[:, :3], original, problem)
        projected = np.c_[positions, trajectory[:, 3]]
        if not problem.broken(projected, original):
            break
    if problem.broken(projected, original):
        projected = _finish(projected, trajectory, original, problem)
    for index, position in problem.pins(original):
        projected[index, :3] = position  # exactly: the solver holds them to 1e-9
    result: Array = projected
    return result


def _finish(projected: Array, target: Array, original: Array, problem: Problem) -> Array:
    """Close what the linearisation left with a direct push; smooth that once more if it stays valid."""
    pushed = _push_into(projected, original, problem)
    smoothed = np.c_[_solve(pushed[:, :3], target[:, :3], original, problem), pushed[:, 3]]
    smoothed = _push_into(smoothed, original, problem)
    still = problem.broken(pushed, original)
    return smoothed if problem.broken(smoothed, original) <= still else pushed


def _push_into(trajectory: Array, original: Array, problem: Problem) -> Array:
    """Push waypoints out of objects' clearance, into the reach shell and the bounds; keep fixed ends."""
    scene, constraints = problem.scene, problem.constraints
    fixed = trajectory.copy()
    for point, distance in problem.kept:
        fixed = avoid(fixed, [list(point)], distance)
    if constraints.min_clearance is not None:
        for obj in (o for o in scene.objects if constraints.keeps_clear_of(o.name)):
            fixed = avoid(
                fixed, [np.asarray(obj.position)], constraints.min_clearance + enclosing_radius(obj)
            )
    if constraints.reach is not None:
        base = np.asarray(constraints.reach.base)
        offsets = fixed[:, :3] - base
        distance = np.maximum(np.linalg.norm(offsets, axis=1, keepdims=True), 1e-12)
        wanted = np.clip(distance, constraints.reach.minimum, constraints.reach.maximum)
        fixed[:, :3] = base + offsets * wanted / distance
    fixed[:, :3] = np.clip(fixed[:, :3], *problem.bounds(len(fixed), original))
    for index, position in problem.pins(original):
        fixed[index, :3] = position
    return fixed


def _solve(around: Array, target: Array, original: Array, problem: Problem) -> Array:
    try:
        import osqp
        from scipy import sparse
    except ImportError as exc:
        raise DependencyNotInstalled(
            'projection needs osqp and scipy; run: pip install "trajadapt[qp]"'
        ) from exc
    count = len(target)
    size = 3 * count
    second = sparse.diags([1.0, -2.0, 1.0], [0, 1, 2], shape=(max(count - 2, 1), count))
    smoothing = sparse.kron(second.T @ second, sparse.eye(3))
    cost = sparse.csc_matrix(sparse.eye(size) + SMOOTHING_WEIGHT * smoothing)
    linear = -target.reshape(-1)
    rows, low, high = _constraint_rows(around, original, problem)
    solver = osqp.OSQP()
    solver.setup(P=sparse.triu(cost, format="csc"), q=linear, A=rows, l=low, u=high,
                 verbose=False, eps_abs=1e-9, eps_rel=1e-9, max_iter=20000, polishing=True)  # fmt: skip
    solution = solver.solve(raise_error=False)
    if solution.x is None or not np.all(np.isfinite(solution.x)):
        return around
    return np.asarray(solution.x, dtype=np.float64).reshape(count, 3)


def _constraint_rows(around: Array, original: Array, problem: Problem) -> tuple[Any, np.ndarray, np.ndarray]:
    from scipy import sparse

    constraints = problem.constraints

    count = len(around)
    rows: list[Any] = [sparse.eye(3 * count, format="csr")]
    low, high = [], []
    lower, upper = (bound.reshape(-1) for bound in problem.bounds(count, original))
    for end, position in problem.pins(original):  # the result may have another number of waypoints
        index = 0 if end == 0 else count - 1
        lower[3 * index : 3 * index + 3] = upper[3 * index : 3 * index + 3] = position
    low.append(lower)
    high.append(upper)
    for row, bound in _clearance_rows(around, problem.scene, constraints) + _kept_rows(around, problem.kept):
        rows.append(sparse.csr_matrix(row[None, :]))
        low.append(np.array([bound]))
        high.append(np.array([1e9]))
    for row, row_low, row_high in _reach_rows(around, constraints):
        rows.append(sparse.csr_matrix(row[None, :]))
        low.append(np.array([row_low]))
        high.append(np.array([row_high]))
    return sparse.vstack(rows, format="csc"), np.concatenate(low), np.concatenate(high)


def _clearance_rows(around: Array, scene: Scene, constraints: Constraints) -> list[tuple[np.ndarray, float]]:
    """Half-space rows keeping waypoints that pass beside an object at least the clearance sideways."""
    if constraints.min_clearance is None:
        return []
    rows = []
    for obj in scene.objects:
        if constraints.keeps_clear_of(obj.name):
            # a margin: the linearisation moves with the path; the sphere holds the object's box
            clearance = (constraints.min_clearance + enclosing_radius(obj)) * 1.05
            rows += _beside_rows(around, np.asarray(obj.position), clearance)
    return rows


def _kept_rows(around: Array, kept: Kept) -> list[tuple[np.ndarray, float]]:
    """Rows for the clearances the program keeps, from each point itself (``avoid`` measures so)."""
    return [
        row
        for point, distance in kept
        for row in _beside_rows(around, np.asarray(point), distance * KEPT_MARGIN)
    ]


def _beside_rows(around: Array, centre: Array, clearance: float) -> list[tuple[np.ndarray, float]]:
    """Half-space rows keeping waypoints that pass beside ``centre`` at least ``clearance`` sideways.

    A waypoint whose offset along its heading is ``a`` must be ``sqrt(d^2 - a^2)`` off to the side
    (one shared side per point, across the direction of travel). Waypoints ahead of or behind the
    point by more than d are clear anyway; constraining them radially would bunch the path up.
    """
    heading = np.gradient(around, axis=0)
    heading /= np.maximum(np.linalg.norm(heading, axis=1, keepdims=True), 1e-12)
    offsets = around - centre
    along = np.sum(offsets * heading, axis=1)
    beside = (np.abs(along) < clearance) & (np.linalg.norm(offsets, axis=1) < 1.5 * clearance)
    if not beside.any():
        return []
    side = sideways_from(np.c_[around, np.zeros(len(around))], offsets, beside)
    rows = []
    for index in np.flatnonzero(beside):
        row = np.zeros(3 * len(around))
        row[3 * index : 3 * index + 3] = side[index]
        rows.append((row, float(side[index] @ centre + np.sqrt(clearance**2 - along[index] ** 2))))
    return rows


def _reach_rows(around: Array, constraints: Constraints) -> list[tuple[np.ndarray, float, float]]:
    """Rows keeping waypoints near the edge of the reach shell inside it, along their direction from the base.

    Along the unit vector n from the base to a waypoint, r_min <= n . (p - b) <= r_max: the outer
    side is the tangent plane of a ball (it holds the ball), the inner side a plane outside the
    inner ball; both are solved again from the new positions.
    """
    reach = constraints.reach
    if reach is None:
        return []
    base = np.asarray(reach.base)
    offsets = around - base
    distance = np.linalg.norm(offsets, axis=1)
    near_edge = (distance > REACH_MARGIN * reach.maximum) | (distance < reach.minimum / REACH_MARGIN)
    rows = []
    for index in np.flatnonzero(near_edge & (distance > 1e-12)):
        direction = offsets[index] / distance[index]
        row = np.zeros(3 * len(around))
        row[3 * index : 3 * index + 3] = direction
        rows.append((row, float(direction @ base + reach.minimum), float(direction @ base + reach.maximum)))
    return rows


def _finite(value: float, fallback: float) -> float:
    return fallback if math.isinf(value) else value

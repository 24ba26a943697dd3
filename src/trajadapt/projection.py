"""Project a trajectory that breaks its constraints onto them with a small, smooth least-squares solve.

The quadratic program (solved with OSQP, ``pip install "trajadapt[qp]"``) stays as close as possible
to the LLM's trajectory while keeping its shape smooth:

    minimise  |p - a|^2 + w |D2 p|^2   over positions p (N x 3), a = the adapted positions,
    subject to  lower <= p <= upper, fixed start/goal where asked,
                n_i . (p_i - c) >= d for waypoints near each object (clearance, linearised at a).

Clearance is not convex, so the linearised problem is solved again from its own answer a few times.
Speeds are not changed (they are clipped to ``max_speed`` if one is set).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from trajadapt.constraints import Constraints, find_violations
from trajadapt.errors import DependencyNotInstalled
from trajadapt.scene import Scene
from trajadapt.skills.core import Array
from trajadapt.skills.objects import avoid, sideways_from

SMOOTHING_WEIGHT = 4.0
ROUNDS = 4


@dataclass(frozen=True)
class Projection:
    """The projected trajectory and what changed."""

    trajectory: Array
    largest_move: float
    remaining: tuple[str, ...]

    def describe(self) -> str:
        """One line for the reviewer."""
        tail = f"; still violated: {'; '.join(self.remaining)}" if self.remaining else ""
        return f"projected onto the constraints: waypoints moved by at most {self.largest_move:.4g}{tail}"


def project(trajectory: Array, original: Array, scene: Scene, constraints: Constraints) -> Projection:
    """Return the nearest smooth trajectory that satisfies ``constraints``.

    Raises:
        DependencyNotInstalled: osqp or scipy is missing.
    """
    positions = trajectory[:, :3].copy()
    for _ in range(ROUNDS):
        positions = _solve(positions, trajectory[:, :3], original, scene, constraints)
        projected = np.c_[positions, trajectory[:, 3]]
        if not find_violations(projected, original, scene, constraints):
            break
    if constraints.min_clearance is not None and find_violations(projected, original, scene, constraints):
        projected = _finish_clearance(projected, scene, constraints)
    if constraints.max_speed is not None:
        projected[:, 3] = np.minimum(projected[:, 3], constraints.max_speed)
    remaining = tuple(v.message for v in find_violations(projected, original, scene, constraints))
    largest = float(np.linalg.norm(projected[:, :3] - trajectory[:, :3], axis=1).max())
    return Projection(projected, largest, remaining)


def _finish_clearance(trajectory: Array, scene: Scene, constraints: Constraints) -> Array:
    """Close the last small clearance gaps the linearisation left, then clip to the bounds."""
    names = set(constraints.clearance_objects)
    centres = [np.asarray(o.position) for o in scene.objects if not names or o.name in names]
    assert constraints.min_clearance is not None
    fixed = avoid(trajectory, centres, constraints.min_clearance)
    lower = np.array(constraints.lower)
    upper = np.array(constraints.upper)
    fixed[:, :3] = np.clip(fixed[:, :3], lower, upper)
    return fixed


def _solve(around: Array, target: Array, original: Array, scene: Scene, constraints: Constraints) -> Array:
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
    rows, low, high = _constraint_rows(around, original, scene, constraints)
    solver = osqp.OSQP()
    solver.setup(P=sparse.triu(cost, format="csc"), q=linear, A=rows, l=low, u=high,
                 verbose=False, eps_abs=1e-9, eps_rel=1e-9, max_iter=20000, polishing=True)  # fmt: skip
    solution = solver.solve(raise_error=False)
    if solution.x is None or not np.all(np.isfinite(solution.x)):
        return around
    return np.asarray(solution.x, dtype=np.float64).reshape(count, 3)


def _constraint_rows(
    around: Array, original: Array, scene: Scene, constraints: Constraints
) -> tuple[Any, np.ndarray, np.ndarray]:
    from scipy import sparse

    count = len(around)
    rows: list[Any] = [sparse.eye(3 * count, format="csr")]
    low, high = [], []
    lower = np.tile([_finite(v, -1e9) for v in constraints.lower], count)
    upper = np.tile([_finite(v, 1e9) for v in constraints.upper], count)
    for index, keep in ((0, constraints.keep_start), (count - 1, constraints.keep_goal)):
        if keep:
            lower[3 * index : 3 * index + 3] = upper[3 * index : 3 * index + 3] = original[index, :3]
    low.append(lower)
    high.append(upper)
    for row, bound in _clearance_rows(around, scene, constraints):
        rows.append(sparse.csr_matrix(row[None, :]))
        low.append(np.array([bound]))
        high.append(np.array([1e9]))
    return sparse.vstack(rows, format="csc"), np.concatenate(low), np.concatenate(high)


def _clearance_rows(around: Array, scene: Scene, constraints: Constraints) -> list[tuple[np.ndarray, float]]:
    """Half-space rows keeping waypoints that pass beside an object at least the clearance sideways.

    A waypoint whose offset along its heading is ``a`` must be ``sqrt(d^2 - a^2)`` off to the side
    (one shared side per object, across the direction of travel). Waypoints ahead of or behind the
    object by more than d are clear anyway; constraining them radially would bunch the path up.
    """
    if constraints.min_clearance is None:
        return []
    clearance = constraints.min_clearance * 1.05  # a margin: the linearisation moves with the path
    names = set(constraints.clearance_objects)
    track = np.c_[around, np.zeros(len(around))]
    heading = np.gradient(around, axis=0)
    heading /= np.maximum(np.linalg.norm(heading, axis=1, keepdims=True), 1e-12)
    rows = []
    for obj in scene.objects:
        if names and obj.name not in names:
            continue
        centre = np.asarray(obj.position)
        offsets = around - centre
        along = np.sum(offsets * heading, axis=1)
        beside = (np.abs(along) < clearance) & (np.linalg.norm(offsets, axis=1) < 1.5 * clearance)
        if not beside.any():
            continue
        side = sideways_from(track, offsets, beside)
        for index in np.flatnonzero(beside):
            row = np.zeros(3 * len(around))
            row[3 * index : 3 * index + 3] = side[index]
            rows.append((row, float(side[index] @ centre + np.sqrt(clearance**2 - along[index] ** 2))))
    return rows


def _finite(value: float, fallback: float) -> float:
    return fallback if math.isinf(value) else value

"""Which constraint moved which waypoints of a projected path, for the effect report."""

from __future__ import annotations

import numpy as np

from trajadapt.checks.constraints import ConstraintMove, Violation
from trajadapt.model.geometry import Array


def constraint_moves(before: Array, after: Array, broken: list[Violation]) -> tuple[ConstraintMove, ...]:
    """Which constraint moved which waypoints, and how far; the other moved ones kept the path smooth."""
    moved = np.linalg.norm(after[:, :3] - before[:, :3], axis=1)
    slowed = before[:, 3] - after[:, 3]
    tolerance = 1e-6 * max(float(np.ptp(before[:, :3], axis=0).max()), 1.0)
    moves, attributed = [], set()
    for violation in broken:
        indices = tuple(i for i in violation.waypoints if i < len(after))
        if not indices:
            continue
        change = slowed if violation.key == "speed" else moved
        name = "speed limit" if violation.key == "speed" else _constraint_name(violation)
        moves.append(ConstraintMove(name, indices, float(change[list(indices)].max())))
        attributed |= set(indices) if violation.key != "speed" else set()
    others = tuple(int(i) for i in np.flatnonzero(moved > tolerance) if int(i) not in attributed)
    if others:
        moves.append(
            ConstraintMove(
                "smoothness (neighbours of moved waypoints)", others, float(moved[list(others)].max())
            )
        )
    return tuple(moves)


def _constraint_name(violation: Violation) -> str:
    """'bounds:x:above' -> 'x upper bound'; 'clearance:box' -> 'clearance from box'; others as keyed."""
    kind, _, rest = violation.key.partition(":")
    if kind == "bounds":
        axis, _, side = rest.partition(":")
        return f"{axis} {'upper' if side == 'above' else 'lower'} bound"
    if kind == "clearance":
        return f"clearance from {rest}"
    if kind == "reach":
        return f"arm reach ({'outer' if rest == 'far' else 'inner'})"
    return f"fixed {kind}"

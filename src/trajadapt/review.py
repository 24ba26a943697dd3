"""Checks on what generated code returns: validity (errors) and what a reviewer should notice."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from trajadapt.errors import InvalidTrajectory
from trajadapt.geometry import extent
from trajadapt.trajectory import MAX_MAGNITUDE, Trajectory

JUMP_FACTOR = 3.0


def validate_result(rows: Any) -> Trajectory:
    """Turn the sandbox's raw rows into a Trajectory: N x 4, N >= 2, finite, v >= 0.

    Raises:
        InvalidTrajectory: saying what is wrong in words the repair prompt can pass on.
    """
    array = np.asarray(rows, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 4:
        raise InvalidTrajectory(
            f"modified_trajectory has shape {array.shape}; it must be (N, 4) with rows (x, y, z, velocity)"
        )
    if array.shape[0] < 2:
        raise InvalidTrajectory(
            f"modified_trajectory has {array.shape[0]} waypoint(s); at least 2 are needed"
        )
    bad = np.argwhere(~np.isfinite(array))
    if bad.size:
        row, column = (int(v) for v in bad[0])
        raise InvalidTrajectory(
            f"modified_trajectory has {len(bad)} non-finite value(s) (NaN or inf), first at "
            f"row {row}, column {'xyzv'[column]}"
        )
    huge = np.argwhere(np.abs(array) > MAX_MAGNITUDE)
    if huge.size:
        row, column = (int(v) for v in huge[0])
        raise InvalidTrajectory(
            f"modified_trajectory has {len(huge)} value(s) beyond ±{MAX_MAGNITUDE:.0e}, first at row {row}, "
            f"column {'xyzv'[column]} ({array[row, column]:.3g}); keep the trajectory in the scene's units"
        )
    negative = np.flatnonzero(array[:, 3] < 0)
    if negative.size:
        raise InvalidTrajectory(
            f"modified_trajectory has {negative.size} negative velocity value(s), first at row "
            f"{int(negative[0])} ({array[negative[0], 3]:.3g}); velocities must be >= 0"
        )
    return Trajectory(array)


@dataclass(frozen=True)
class ReviewNote:
    """Something the reviewer should look at; not an error."""

    code: str
    message: str


def review_notes(original: Trajectory, adapted: Trajectory) -> list[ReviewNote]:
    """Start moved, waypoints added or removed, jumps far larger than the original's largest step."""
    notes = []
    scale = extent(original.array)
    start_shift = float(np.linalg.norm(adapted.positions[0] - original.positions[0]))
    if start_shift > 1e-6 * scale:
        notes.append(ReviewNote("start-moved", f"the start moved by {start_shift:.3g}"))
    if len(adapted) != len(original):
        change = "added" if len(adapted) > len(original) else "removed"
        count = abs(len(adapted) - len(original))
        notes.append(
            ReviewNote(
                f"points-{change}",
                f"{count} waypoint(s) {change} ({len(original)} -> {len(adapted)})",
            )
        )
    original_step = float(original.step_lengths().max())
    adapted_step = float(adapted.step_lengths().max())
    if adapted_step > JUMP_FACTOR * max(original_step, 1e-9 * scale):
        notes.append(
            ReviewNote(
                "large-jump",
                f"largest step between waypoints is {adapted_step:.3g}, "
                f"{adapted_step / max(original_step, 1e-12):.1f}x the original's {original_step:.3g}",
            )
        )
    return notes

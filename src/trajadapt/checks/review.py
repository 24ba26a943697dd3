"""Checks on what generated code returns: validity (errors) and what a reviewer should notice."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from trajadapt.errors import InvalidTrajectory, InvalidWaypoints
from trajadapt.model.geometry import extent
from trajadapt.model.trajectory import Trajectory

JUMP_FACTOR = 3.0


def validate_result(rows: Any) -> Trajectory:
    """Turn the sandbox's raw rows into a Trajectory (the rule is the Trajectory's own).

    Raises:
        InvalidTrajectory: saying what is wrong in words the repair prompt can pass on.
    """
    try:
        array = np.asarray(rows, dtype=np.float64)
    except (ValueError, TypeError):
        raise InvalidTrajectory(
            "modified_trajectory is not a table of numbers; it must be (N, 4) with rows (x, y, z, velocity)"
        ) from None
    try:
        return Trajectory(array)
    except InvalidWaypoints as exc:
        raise InvalidTrajectory(f"modified_trajectory {str(exc).removeprefix('the trajectory ')}") from None


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

"""What a projection does at the path's ends: hold them, or leave a limit the original broke there.

A projection is for what the program broke. An end the user keeps (``keep_start`` / ``keep_goal``)
or the program left at the original's stays there; one the program moved and broke nothing at
stays where the program put it; a limit the original itself broke at an end is left as it was, and
so is a bound along a stretch the original itself runs outside of (``matched_original``).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from trajadapt.checks.constraints import AXES, Constraints, Violation, find_violations, violation_slack
from trajadapt.model.geometry import Array
from trajadapt.model.scene import Scene


def broken_by_the_code(
    trajectory: Array,
    original: Array,
    scene: Scene,
    constraints: Constraints,
    inherited: set[tuple[str, int]],
) -> set[int]:
    """The ends (0, -1) where ``trajectory`` breaks a limit the original did not break there."""
    return {end for _, end in broken_at_ends(trajectory, original, scene, constraints) - inherited}


def holding_kept_ends(
    trajectory: Array, original: Array, constraints: Constraints, broken: set[int]
) -> Constraints:
    """Also hold the start / goal where the code left them (at the original's), unless it broke a limit there.

    The smoothing would otherwise move an end nobody asked to move (a curve made rounder, then lifted
    back above the floor, started 0.04 away from where it started). A limit the original itself
    broke at that end (a path that starts below its floor, or beside an object closer than the
    clearance) is left alone: the projection is for what the code broke (``broken``, from
    ``broken_by_the_code``).
    """
    tolerance = 1e-9 * max(float(np.ptp(original[:, :3], axis=0).max()), 1.0)
    kept = [
        float(np.linalg.norm(trajectory[index, :3] - original[index, :3])) <= tolerance
        and index not in broken
        for index in (0, -1)
    ]
    return replace(
        constraints, keep_start=constraints.keep_start or kept[0], keep_goal=constraints.keep_goal or kept[1]
    )


def ends_where_the_program_put_them(
    trajectory: Array, constraints: Constraints, broken: set[int]
) -> tuple[tuple[int, tuple[float, float, float]], ...]:
    """The ends the program moved and left within every limit: held there.

    "Finish 30 cm further back than the current goal" moved the goal 0.3; one waypoint 0.001 past
    the floor's edge elsewhere had the smoothing carry the goal 0.185 further. The projection is
    for what the code broke: an end it placed and broke nothing at stays where it is.
    """
    held = ((0, constraints.keep_start), (-1, constraints.keep_goal))
    return tuple(
        (index, (float(trajectory[index, 0]), float(trajectory[index, 1]), float(trajectory[index, 2])))
        for index, keep in held
        if not keep and index not in broken
    )


def held_as_original(
    left: list[Violation], count: int, inherited: set[tuple[str, int]], constraints: Constraints
) -> set[str]:
    """The limits of ``left`` broken only at ends where the original broke them too.

    Only the ends the projection kept at the original's position count (``constraints.keep_start``
    / ``keep_goal``); ``count`` is the number of waypoints ``left`` was measured on.
    """
    kept = {end for end, keep in ((0, constraints.keep_start), (-1, constraints.keep_goal)) if keep}
    held = set()
    for violation in left:
        ends = {_end_of(i, count) for i in violation.waypoints}
        if ends and ends <= kept and all((violation.key, end) in inherited for end in ends):
            held.add(violation.key)
    return held


def broken_at_ends(
    trajectory: Array, original: Array, scene: Scene, constraints: Constraints
) -> set[tuple[str, int]]:
    """(limit, end) for each limit ``trajectory`` breaks at its start (end 0) or its goal (end -1)."""
    return {
        (v.key, end)
        for v in find_violations(trajectory, original, scene, constraints)
        for i in v.waypoints
        if (end := _end_of(i, len(trajectory))) is not None
    }


def _end_of(index: int, count: int) -> int | None:
    """0 for the first of ``count`` waypoints, -1 for the last (negative indices too), else None."""
    position = index % count
    return 0 if position == 0 else -1 if position == count - 1 else None


def matched_original(original: Array, count: int) -> Array:
    """The original's positions at the same shares of the path as each of ``count`` waypoints (count x 3)."""
    matched: Array = original[np.rint(np.linspace(0, len(original) - 1, count)).astype(int), :3]
    return matched


def outside_as_original(left: list[Violation], trajectory: Array, original: Array) -> set[str]:
    """The bounds of ``left`` broken only where the original lies at least as far outside them."""
    matched = matched_original(original, len(trajectory))
    slack = violation_slack(original)  # as far past a bound as find_violations lets it be
    held = set()
    for violation in left:
        kind, axis, side = (violation.key.split(":") + ["", ""])[:3]
        if kind != "bounds" or axis not in AXES:
            continue
        at, k = list(violation.waypoints), AXES.index(axis)
        beyond = trajectory[at, k] - matched[at, k]
        if np.all(beyond >= -slack if side == "below" else beyond <= slack):
            held.add(violation.key)
    return held

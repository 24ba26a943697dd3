"""Each robot's limits in the trajectory's own units: where it can go and how fast.

The defaults are those of OVITA's constraint module (the paper's successor), in the units of its
cases: the drone flies in a box 20 x 20 x 5 above the floor, the ground robot drives on the floor
(z = 0) in an 8 x 6 room, the arm reaches 0.15 to 1.2 from its base at (-0.5, 0, 0.6). Top speeds:
3 for the drone and the ground robot, 0.8 for the arm. A user's own robot overrides them with the
``--workspace``, ``--reach-base``/``--reach`` and ``--max-speed`` flags (or the page's fields); the
case's constraints text is applied on top of the robot's limits.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from trajadapt.checks.constraints import Constraints, Reach
from trajadapt.errors import InputError


@dataclass(frozen=True)
class RobotLimits:
    """A named robot's default limits and a line that says what they are."""

    name: str
    description: str
    constraints: Constraints


ROBOT_LIMITS: dict[str, RobotLimits] = {
    "none": RobotLimits(
        "none", "no robot limits (only the case's constraints and your flags)", Constraints()
    ),
    "arm": RobotLimits(
        "arm",
        "a 7-DoF arm reaching 0.15 to 1.2 from its base at (-0.5, 0, 0.6), speed at most 0.8",
        Constraints(
            reach=Reach((-0.5, 0.0, 0.6), 0.15, 1.2),
            max_speed=0.8,
            sources=("arm reach 0.15 to 1.2 from (-0.5, 0, 0.6)", "arm speed at most 0.8"),
        ),
    ),
    "drone": RobotLimits(
        "drone",
        "x and y in [-10, 10], z in [0, 5], speed at most 3",
        Constraints(
            lower=(-10.0, -10.0, 0.0),
            upper=(10.0, 10.0, 5.0),
            max_speed=3.0,
            sources=("drone box x, y in [-10, 10], z in [0, 5]", "drone speed at most 3"),
        ),
    ),
    "ground": RobotLimits(
        "ground",
        "x in [-4, 4], y in [-3, 3], on the floor (z = 0), speed at most 3",
        Constraints(
            lower=(-4.0, -3.0, 0.0),
            upper=(4.0, 3.0, 0.0),
            max_speed=3.0,
            sources=("ground robot room x in [-4, 4], y in [-3, 3], z = 0", "ground robot speed at most 3"),
        ),
    ),
}
ROBOT_NAMES = tuple(ROBOT_LIMITS)


def robot_constraints(name: str) -> Constraints:
    """The limits of the robot called ``name`` ('none' for none).

    Raises:
        InputError: no robot has that name.
    """
    if name not in ROBOT_LIMITS:
        raise InputError(f"no robot limits called {name!r}; known: {', '.join(ROBOT_NAMES)}")
    return ROBOT_LIMITS[name].constraints


def user_constraints(
    *,
    workspace: tuple[float, float, float, float, float, float] | None = None,
    reach_base: tuple[float, float, float] | None = None,
    reach: tuple[float, float] | None = None,
    clearance: float | None = None,
    max_speed: float | None = None,
    fixed_ends: str = "none",
) -> Constraints:
    """The limits a user gives with flags or the page's fields, checked.

    Args:
        workspace: x_min, x_max, y_min, y_max, z_min, z_max.
        reach_base: the arm's base; given with ``reach``.
        reach: the least and the most distance from the base the arm reaches.
        clearance: distance kept from every object the instruction does not ask to approach.
        max_speed: the top speed.
        fixed_ends: 'none', 'start', 'goal' or 'both' stay where they are.

    Raises:
        InputError: a bound or distance that cannot hold (min above max, negative, not finite).
    """
    _check_numbers(workspace, reach_base, reach, clearance, max_speed)
    lower, upper = (-math.inf,) * 3, (math.inf,) * 3
    if workspace is not None:
        if any(workspace[2 * k] > workspace[2 * k + 1] for k in range(3)):
            raise InputError(f"--workspace {_numbers(workspace)}: each minimum must be at most its maximum")
        lower, upper = (workspace[0], workspace[2], workspace[4]), (workspace[1], workspace[3], workspace[5])
    if (reach_base is None) != (reach is None):
        raise InputError("give --reach-base X Y Z and --reach MIN MAX together (the arm's base and reach)")
    shell = None
    if reach_base is not None and reach is not None:
        if not 0 <= reach[0] < reach[1]:
            raise InputError(f"--reach {_numbers(reach)}: need 0 <= MIN < MAX")
        shell = Reach(reach_base, reach[0], reach[1])
    if fixed_ends not in ("none", "start", "goal", "both"):
        raise InputError(f"fixed ends {fixed_ends!r} is not one of none, start, goal, both")
    if (clearance is not None and clearance < 0) or (max_speed is not None and max_speed <= 0):
        raise InputError("--clearance must be at least 0 and --max-speed above 0")
    sources = tuple(
        text
        for text, given in (
            (f"your workspace {_numbers(workspace or ())}", workspace),
            (shell.describe() if shell else "", shell),
            (f"your clearance {clearance:g}" if clearance is not None else "", clearance),
            (f"your speed limit {max_speed:g}" if max_speed is not None else "", max_speed),
        )
        if given is not None
    )
    return Constraints(
        lower=lower,
        upper=upper,
        reach=shell,
        min_clearance=clearance,
        max_speed=max_speed,
        keep_start=fixed_ends in ("start", "both"),
        keep_goal=fixed_ends in ("goal", "both"),
        sources=sources,
    )


def _check_numbers(*groups: object) -> None:
    for group in groups:
        values = group if isinstance(group, tuple) else (group,)
        if any(isinstance(v, float | int) and not math.isfinite(v) for v in values):
            raise InputError("limits must be finite numbers")


def _numbers(values: tuple[float, ...]) -> str:
    return " ".join(f"{v:g}" for v in values)

"""The reference a controller follows: waypoint times from the trajectory's speeds, then sampling.

Each waypoint carries a speed v (case units per second). The time between two waypoints is their
distance over the mean of their speeds; speeds near zero (a start at rest) use a floor of 5% of the
fastest speed, and a repeated waypoint (a pause) lasts one nominal timestep. Positions in between are
interpolated linearly in time.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]

SPEED_FLOOR_FRACTION = 0.05


@dataclass(frozen=True)
class Reference:
    """Waypoints in the robot frame with the time each is due."""

    points: Array  # (N, 3)
    times: Array  # (N,), starts at 0

    @property
    def duration(self) -> float:
        """Seconds from the first waypoint to the last."""
        return float(self.times[-1])

    def position(self, t: float) -> Array:
        """The reference position at time ``t`` (held at the ends)."""
        return np.array([np.interp(t, self.times, self.points[:, k]) for k in range(3)])

    def velocity(self, t: float, dt: float = 1e-2) -> Array:
        """The reference velocity at ``t`` by a central difference."""
        return (self.position(t + dt) - self.position(t - dt)) / (2 * dt)

    def acceleration(self, t: float, dt: float = 5e-2) -> Array:
        """The reference acceleration at ``t`` (smoothed over ``dt``)."""
        return (self.velocity(t + dt) - self.velocity(t - dt)) / (2 * dt)


def waypoint_times(points: Array, speeds: Array) -> Array:
    """Cumulative arrival time of each waypoint, from distances and the mean speed of each segment.

    Raises:
        ValueError: every speed is zero, so no time can be given.
    """
    speeds = np.abs(np.asarray(speeds, dtype=np.float64))
    top = float(speeds.max()) if len(speeds) else 0.0
    if top <= 0:
        raise ValueError("every waypoint has speed 0, so the trajectory has no timing; set a speed first")
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    mean_speed = np.maximum((speeds[:-1] + speeds[1:]) / 2, SPEED_FLOOR_FRACTION * top)
    durations = steps / mean_speed
    moving = durations[steps > 1e-12]
    nominal = float(np.median(moving)) if len(moving) else 1.0
    durations[steps <= 1e-12] = nominal  # a pause: one timestep at the same place
    return np.concatenate([[0.0], np.cumsum(durations)])


def build_reference(points: Array, speeds: Array, speed_scale: float = 1.0) -> Reference:
    """The reference for robot-frame ``points`` whose case speeds are multiplied by ``speed_scale``."""
    return Reference(
        np.asarray(points, dtype=np.float64), waypoint_times(points, np.asarray(speeds) * speed_scale)
    )

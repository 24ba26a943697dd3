"""The simulated robots by name: ``arm`` (KUKA iiwa), ``drone`` (Crazyflie-like), ``ground`` (Husky)."""

from __future__ import annotations

from trajadapt.sim.robots.arm import Arm
from trajadapt.sim.robots.base import CameraPose, Problem, Robot
from trajadapt.sim.robots.drone import Drone
from trajadapt.sim.robots.ground import Ground

ROBOTS: dict[str, type[Robot]] = {robot.name: robot for robot in (Arm, Drone, Ground)}

__all__ = ["ROBOTS", "Arm", "CameraPose", "Drone", "Ground", "Problem", "Robot"]

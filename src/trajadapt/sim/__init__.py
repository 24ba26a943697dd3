"""Execute trajectories on simulated robots (pybullet): a KUKA arm, a Crazyflie-like drone, a Husky.

``simulate(trajectory, scene, robot)`` maps the case units into the robot's workspace (the map is
explicit in the report), times the waypoints from their speeds, follows them with the robot's own
controller in pybullet (DIRECT mode unless asked for a window) and reports the tracking error, the
problems found per waypoint and, on request, a picture and an animated GIF.
"""

from __future__ import annotations

from trajadapt.sim.report import SimulationReport, Tracking
from trajadapt.sim.robots import ROBOTS
from trajadapt.sim.run import SimulationOptions, simulate
from trajadapt.sim.workspace import WorkspaceMap, fit_workspace

__all__ = [
    "ROBOTS",
    "SimulationOptions",
    "SimulationReport",
    "Tracking",
    "WorkspaceMap",
    "fit_workspace",
    "simulate",
]

"""Clearpath Husky (pybullet_data), differential drive, following the path in the plane (z ignored)."""

from __future__ import annotations

import math

import numpy as np

from trajadapt.sim.reference import Reference
from trajadapt.sim.robots.base import Array, CameraPose, Problem, Robot
from trajadapt.sim.workspace import WorkspaceBox

WHEEL_RADIUS = 0.1651  # m
TRACK = 0.555  # m between left and right wheels
SKID_FACTOR = 1.6  # four skidding wheels turn less than two ideal ones would: effective track multiplier
WHEEL_FORCE = 60.0  # N m
LOOKAHEAD_S = 0.6  # the carrot is the reference this far ahead in time
MIN_LOOKAHEAD = 0.25  # m
HEADING_GAIN = 2.5  # 1/s for turning on the spot
TURN_IN_PLACE = math.radians(70)


class Ground(Robot):
    """Husky with four velocity-controlled wheels steered by pure pursuit of a timed carrot."""

    name = "ground"
    description = "Clearpath Husky (pybullet_data), skid-steer differential drive, pure pursuit"
    workspace = WorkspaceBox(centre=(0.0, 0.0, 0.0), size=(10.0, 10.0, 0.0))
    max_speed = 1.0
    camera = CameraPose(distance=2.0, yaw=0.0, pitch=-70.0)
    planar = True
    marker_radius = 0.2

    def setup(self, reference: Reference) -> None:
        """Load the Husky on the first waypoint facing along the path."""
        start = reference.points[0]
        ahead = reference.position(min(reference.duration, 1.0)) - start
        yaw = math.atan2(ahead[1], ahead[0]) if np.linalg.norm(ahead[:2]) > 1e-9 else 0.0
        self.body = self.world.load_urdf("husky/husky.urdf", position=(start[0], start[1], 0.1), yaw=yaw)
        names = [
            self.world.call("getJointInfo", self.body, j)[1].decode() for j in range(self._joint_count())
        ]
        self.left = [j for j, n in enumerate(names) if n.endswith("left_wheel")]
        self.right = [j for j, n in enumerate(names) if n.endswith("right_wheel")]

    def _joint_count(self) -> int:
        return int(self.world.call("getNumJoints", self.body))

    def position(self) -> Array:
        """The base's position on the floor (z set to 0)."""
        xyz = np.asarray(self.world.call("getBasePositionAndOrientation", self.body)[0], dtype=np.float64)
        return np.array([xyz[0], xyz[1], 0.0])

    def _yaw(self) -> float:
        quaternion = self.world.call("getBasePositionAndOrientation", self.body)[1]
        return float(self.world.pb.getEulerFromQuaternion(quaternion)[2])

    def check(self, points: Array) -> list[Problem]:
        """A ground robot cannot follow heights: say so once (index -1) if the path has any."""
        spread = float(np.ptp(points[:, 2]))
        if spread <= 1e-6:
            return []
        return [
            Problem(
                -1, "height_ignored", f"the path's height varies by {spread:.3g} m; the robot drives it flat"
            )
        ]

    def control(self, t: float, reference: Reference) -> None:
        """Set wheel speeds that steer towards the carrot and keep pace with the reference."""
        here = self.position()
        carrot = reference.position(t + LOOKAHEAD_S)
        offset = (carrot - here)[:2]
        distance = float(np.linalg.norm(offset))
        angle = _wrap(math.atan2(offset[1], offset[0]) - self._yaw())
        if distance < 0.02:
            forward, turn = 0.0, 0.0
        elif abs(angle) > TURN_IN_PLACE:
            forward, turn = 0.0, HEADING_GAIN * angle
        else:
            forward = min(self.max_speed, distance / LOOKAHEAD_S)
            turn = 2.0 * forward * math.sin(angle) / max(distance, MIN_LOOKAHEAD)
        self._drive(forward, turn)

    def _drive(self, forward: float, turn: float) -> None:
        half = SKID_FACTOR * TRACK / 2
        for joints, speed in ((self.left, forward - turn * half), (self.right, forward + turn * half)):
            self.world.call(
                "setJointMotorControlArray", self.body, joints, self.world.pb.VELOCITY_CONTROL,
                targetVelocities=[speed / WHEEL_RADIUS] * len(joints), forces=[WHEEL_FORCE] * len(joints),
            )  # fmt: skip


def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2 * math.pi) - math.pi

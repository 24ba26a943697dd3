"""KUKA iiwa (pybullet_data) whose end effector follows the waypoints through inverse kinematics."""

from __future__ import annotations

import math

import numpy as np

from trajadapt.sim.reference import Reference
from trajadapt.sim.robots.base import Array, CameraPose, Problem, Robot
from trajadapt.sim.workspace import WorkspaceBox

END_EFFECTOR = 6
REACH_TOLERANCE = 0.01  # m between a waypoint and where the best joint solution puts the end effector
LIMIT_MARGIN = 0.03  # rad from a joint limit that is reported
MOTOR_FORCE = 300.0


class Arm(Robot):
    """KUKA LBR iiwa 7 on a fixed base at the origin, gripper pointing down where it can."""

    name = "arm"
    description = "KUKA iiwa arm (pybullet_data), end effector by inverse kinematics"
    workspace = WorkspaceBox(centre=(0.55, 0.0, 0.45), size=(0.4, 0.6, 0.4))
    max_speed = 1.0
    camera = CameraPose(distance=1.2, yaw=50.0, pitch=-25.0)
    marker_radius = 0.025
    anchors = ((0.0, 0.0, 0.0), (0.0, 0.0, 1.0))

    def setup(self, reference: Reference) -> None:
        """Load the arm and put its joints at the first waypoint's solution."""
        self.body = self.world.load_urdf("kuka_iiwa/model.urdf", fixed=True)
        joints = range(self.world.call("getNumJoints", self.body))
        infos = [self.world.call("getJointInfo", self.body, j) for j in joints]
        self.joints = [
            j for j, info in zip(joints, infos, strict=True) if info[2] != self.world.pb.JOINT_FIXED
        ]
        self.lower = np.array([infos[j][8] for j in self.joints])
        self.upper = np.array([infos[j][9] for j in self.joints])
        self.down = self.world.pb.getQuaternionFromEuler([0, -math.pi, 0])
        self._set_joints(self._solve(reference.points[0]))

    def _set_joints(self, angles: Array) -> None:
        for joint, angle in zip(self.joints, angles, strict=True):
            self.world.call("resetJointState", self.body, joint, float(angle))

    def _inverse_kinematics(
        self, target: Array, rest: list[float], iterations: int, threshold: float, orientation: bool = True
    ) -> Array:
        """Joint angles from pybullet's IK for ``target``, seeded by the current state, within the limits."""
        extra = {"targetOrientation": self.down} if orientation else {}
        angles = self.world.call(
            "calculateInverseKinematics", self.body, END_EFFECTOR, list(target),
            lowerLimits=list(self.lower), upperLimits=list(self.upper),
            jointRanges=list(self.upper - self.lower), restPoses=rest,
            maxNumIterations=iterations, residualThreshold=threshold, **extra,
        )[: len(self.joints)]  # fmt: skip
        return np.asarray(np.clip(np.asarray(angles, dtype=np.float64), self.lower, self.upper))

    def _solve(self, target: Array, orientation: bool = True) -> Array:
        """Joint angles for ``target`` from the current state (a few refining passes, joints set there)."""
        angles = np.zeros(len(self.joints))
        for _ in range(3):
            angles = self._inverse_kinematics(target, [0.0] * len(self.joints), 200, 1e-6, orientation)
            self._set_joints(angles)
        return angles

    def position(self) -> Array:
        """The end effector's world position."""
        state = self.world.call("getLinkState", self.body, END_EFFECTOR, computeForwardKinematics=True)
        return np.asarray(state[4], dtype=np.float64)

    def check(self, points: Array) -> list[Problem]:
        """Solve every waypoint in order; report misses over 1 cm and joints at their limits."""
        saved = [self.world.call("getJointState", self.body, j)[0] for j in self.joints]
        problems = []
        for index, point in enumerate(points):
            angles = self._solve(point)
            miss = float(np.linalg.norm(self.position() - point))
            if miss > REACH_TOLERANCE:
                angles = self._solve(point, orientation=False)
                miss = float(np.linalg.norm(self.position() - point))
            if miss > REACH_TOLERANCE:
                problems.append(Problem(index, "unreachable", f"the arm gets only within {miss:.3f} m"))
            near = np.minimum(angles - self.lower, self.upper - angles) < LIMIT_MARGIN
            for joint in np.flatnonzero(near):
                problems.append(Problem(index, "joint_limit", f"joint {joint + 1} at its limit"))
        self._set_joints(np.asarray(saved))
        return problems

    def control(self, t: float, reference: Reference) -> None:
        """Position-control the joints to the inverse-kinematics solution of the reference point."""
        current = [self.world.call("getJointState", self.body, j)[0] for j in self.joints]
        angles = self._inverse_kinematics(reference.position(t), current, 50, 1e-5)
        self.world.call(
            "setJointMotorControlArray", self.body, self.joints, self.world.pb.POSITION_CONTROL,
            targetPositions=list(angles), forces=[MOTOR_FORCE] * len(self.joints),
        )  # fmt: skip

"""A quadrotor with the Crazyflie 2.x's mass and inertia under a position and attitude controller.

gym-pybullet-drones is not on PyPI, so the body and the controller are written here: a rigid body
(27 g; inertia 1.4e-5, 1.4e-5, 2.17e-5 kg m^2) gets a collective thrust along its own z axis and three
body torques each physics step. The controller is the usual cascade on SO(3): a PD position loop with
the reference's velocity and acceleration fed forward gives the wanted thrust vector; the attitude loop
turns the body towards it (yaw held at 0). Thrust and torques are clipped to what four Crazyflie motors
give.
"""

from __future__ import annotations

import numpy as np

from trajadapt.sim.reference import Reference
from trajadapt.sim.robots.base import Array, CameraPose, Problem, Robot
from trajadapt.sim.workspace import WorkspaceBox

MASS = 0.027  # kg
INERTIA = np.array([1.4e-5, 1.4e-5, 2.17e-5])  # kg m^2
GRAVITY = 9.81
MAX_THRUST = 0.6  # N, four motors (thrust to weight about 2.3)
MAX_TORQUE = np.array([6e-3, 6e-3, 1.5e-3])  # N m
MAX_TILT_ACCEL = GRAVITY * np.tan(np.radians(35))  # horizontal acceleration the tilt limit allows
POSITION_GAIN, VELOCITY_GAIN = 36.0, 11.0  # 1/s^2, 1/s
ATTITUDE_GAIN, RATE_GAIN = INERTIA * 900.0, INERTIA * 54.0  # natural frequency 30 rad/s
MIN_HEIGHT = 0.05  # m above the floor


def _vee(matrix: Array) -> Array:
    return np.array([matrix[2, 1], matrix[0, 2], matrix[1, 0]])


class Drone(Robot):
    """Crazyflie-sized quadrotor (27 g), geometric position/attitude control written here."""

    name = "drone"
    description = "quadrotor with Crazyflie mass and inertia, cascade PD/SO(3) controller"
    workspace = WorkspaceBox(centre=(0.0, 0.0, 1.0), size=(2.0, 2.0, 1.2))
    max_speed = 1.0
    camera = CameraPose(distance=0.8, yaw=40.0, pitch=-30.0)
    marker_radius = 0.05

    def setup(self, reference: Reference) -> None:
        """Create the body hovering at the first waypoint."""
        pb = self.world.pb
        collision = self.world.call("createCollisionShape", pb.GEOM_BOX, halfExtents=[0.046, 0.046, 0.012])
        visual = self.world.call(
            "createVisualShape",
            pb.GEOM_BOX,
            halfExtents=[0.046, 0.046, 0.012],
            rgbaColor=[0.15, 0.15, 0.15, 1],
        )
        self.body = self.world.call(
            "createMultiBody", baseMass=MASS, baseCollisionShapeIndex=collision,
            baseVisualShapeIndex=visual, basePosition=list(reference.points[0]),
        )  # fmt: skip
        self.world.call(
            "changeDynamics",
            self.body,
            -1,
            localInertiaDiagonal=list(INERTIA),
            linearDamping=0.0,
            angularDamping=0.0,
        )

    def position(self) -> Array:
        """The body's centre."""
        return np.asarray(self.world.call("getBasePositionAndOrientation", self.body)[0], dtype=np.float64)

    def check(self, points: Array) -> list[Problem]:
        """Waypoints at or below the floor."""
        return [
            Problem(int(i), "below_floor", f"z = {points[i, 2]:.3f} m, under the {MIN_HEIGHT} m floor margin")
            for i in np.flatnonzero(points[:, 2] < MIN_HEIGHT)
        ]

    def control(self, t: float, reference: Reference) -> None:
        """Apply this step's thrust and torque."""
        position, quaternion = self.world.call("getBasePositionAndOrientation", self.body)
        velocity, rate_world = self.world.call("getBaseVelocity", self.body)
        rotation = np.asarray(self.world.pb.getMatrixFromQuaternion(quaternion)).reshape(3, 3)
        wanted = self._wanted_acceleration(t, reference, np.asarray(position), np.asarray(velocity))
        thrust = float(np.clip(MASS * wanted @ rotation[:, 2], 0.0, MAX_THRUST))
        torque = self._attitude_torque(wanted, rotation, rotation.T @ np.asarray(rate_world))
        pb = self.world.pb
        self.world.call("applyExternalForce", self.body, -1, [0, 0, thrust], [0, 0, 0], pb.LINK_FRAME)
        self.world.call("applyExternalTorque", self.body, -1, list(rotation @ torque), pb.WORLD_FRAME)

    @staticmethod
    def _wanted_acceleration(t: float, reference: Reference, position: Array, velocity: Array) -> Array:
        error = reference.position(t) - position
        wanted = (
            reference.acceleration(t)
            + POSITION_GAIN * error
            + VELOCITY_GAIN * (reference.velocity(t) - velocity)
        )
        horizontal = float(np.linalg.norm(wanted[:2]))
        if horizontal > MAX_TILT_ACCEL:
            wanted[:2] *= MAX_TILT_ACCEL / horizontal
        wanted[2] = max(wanted[2] + GRAVITY, 0.2 * GRAVITY)
        return np.asarray(wanted)

    @staticmethod
    def _attitude_torque(wanted: Array, rotation: Array, rate_body: Array) -> Array:
        z_axis = wanted / np.linalg.norm(wanted)
        y_axis = np.cross(z_axis, [1.0, 0.0, 0.0])
        y_axis /= np.linalg.norm(y_axis)
        desired = np.column_stack([np.cross(y_axis, z_axis), y_axis, z_axis])
        error = 0.5 * _vee(desired.T @ rotation - rotation.T @ desired)
        torque = -ATTITUDE_GAIN * error - RATE_GAIN * rate_body + np.cross(rate_body, INERTIA * rate_body)
        return np.asarray(np.clip(torque, -MAX_TORQUE, MAX_TORQUE))

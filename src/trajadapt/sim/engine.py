"""One pybullet world per simulation: its own client (never the module-global one), quiet by default.

pybullet prints its build time and URDF warnings from C straight to file descriptors 1 and 2; they are
silenced here so that the CLI's output and JSON stay clean.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from types import ModuleType
from typing import Any

import numpy as np

from trajadapt.errors import DependencyNotInstalled

PHYSICS_HZ = 240
OBJECT_COLOURS = ((0.95, 0.6, 0.1, 1.0), (0.2, 0.7, 0.3, 1.0), (0.6, 0.3, 0.8, 1.0), (0.9, 0.8, 0.1, 1.0))


@contextlib.contextmanager
def quiet_native_output() -> Iterator[None]:
    """Send what C code writes to stdout/stderr to /dev/null for the duration of the block."""
    saved = [os.dup(1), os.dup(2)]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        yield
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (*saved, devnull):
            os.close(fd)


def import_pybullet() -> tuple[ModuleType, str]:
    """The pybullet module and the folder of pybullet_data's robot models.

    Raises:
        DependencyNotInstalled: naming the extra that installs pybullet.
    """
    try:
        with quiet_native_output():
            import pybullet
            import pybullet_data
    except ImportError as exc:
        raise DependencyNotInstalled(
            "the simulators need pybullet: pip install 'trajadapt[sim]' (or scripts/setup.sh)"
        ) from exc
    return pybullet, str(pybullet_data.getDataPath())


class World:
    """A pybullet physics client with a ground plane, gravity and helpers to add scene markers."""

    def __init__(self, gui: bool = False) -> None:
        """Connect (DIRECT unless ``gui``) and load the ground plane."""
        self.pb, self.data_path = import_pybullet()
        with quiet_native_output():
            self.client = self.pb.connect(self.pb.GUI if gui else self.pb.DIRECT)
        if self.client < 0:
            raise DependencyNotInstalled("pybullet could not open a GUI window; run without --gui")
        self.call("setAdditionalSearchPath", self.data_path)
        self.call("setGravity", 0, 0, -9.81)
        self.call("setTimeStep", 1.0 / PHYSICS_HZ)
        self.load_urdf("plane.urdf")

    def call(self, name: str, *args: Any, **kwargs: Any) -> Any:
        """Call ``pybullet.<name>`` on this world's client."""
        return getattr(self.pb, name)(*args, physicsClientId=self.client, **kwargs)

    def load_urdf(self, path: str, position: Any = (0, 0, 0), yaw: float = 0.0, fixed: bool = False) -> int:
        """Load a model from pybullet_data (warnings silenced) and return its body id."""
        orientation = self.pb.getQuaternionFromEuler([0, 0, yaw])
        with quiet_native_output():
            return int(self.call("loadURDF", path, list(position), orientation, useFixedBase=fixed))

    def add_marker(self, position: Any, radius: float, index: int, label: str) -> int:
        """A visual-only sphere (robots pass through it; clearance is reported instead) with a label."""
        colour = OBJECT_COLOURS[index % len(OBJECT_COLOURS)]
        shape = self.call("createVisualShape", self.pb.GEOM_SPHERE, radius=radius, rgbaColor=colour)
        body = int(
            self.call("createMultiBody", baseMass=0, baseVisualShapeIndex=shape, basePosition=list(position))
        )
        self.call("addUserDebugText", label, list(np.asarray(position) + [0, 0, radius * 1.5]), [0, 0, 0])
        return body

    def step(self) -> None:
        """Advance the physics by one step (1/240 s)."""
        self.call("stepSimulation")

    def close(self) -> None:
        """Disconnect this client."""
        with contextlib.suppress(Exception):
            self.pb.disconnect(physicsClientId=self.client)

    def __enter__(self) -> World:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

"""What every simulated robot provides: a workspace, a start, a controller step and a pre-run check."""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import numpy.typing as npt

from trajadapt.sim.engine import World
from trajadapt.sim.reference import Reference
from trajadapt.sim.workspace import WorkspaceBox

Array = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Problem:
    """Something about one waypoint the robot cannot do as asked (index -1: the whole path)."""

    index: int
    kind: str
    detail: str

    def to_dict(self) -> dict[str, object]:
        """JSON form."""
        return {"index": self.index, "kind": self.kind, "detail": self.detail}


@dataclass(frozen=True)
class CameraPose:
    """The direction the renderer looks from, and its least distance (it backs off to see everything)."""

    distance: float
    yaw: float
    pitch: float


class Robot(ABC):
    """A robot in a :class:`World` that follows a :class:`Reference` one physics step at a time."""

    name: ClassVar[str]
    description: ClassVar[str]
    workspace: ClassVar[WorkspaceBox]
    max_speed: ClassVar[float]  # m/s the controller is tuned for; faster references are slowed down
    camera: ClassVar[CameraPose]
    planar: ClassVar[bool] = False  # ground robots: z is ignored
    marker_radius: ClassVar[float] = 0.03
    anchors: ClassVar[tuple[tuple[float, float, float], ...]] = ()  # robot points every picture shows

    def __init__(self, world: World) -> None:
        """Keep the world; nothing is loaded until :meth:`setup`."""
        self.world = world

    @abstractmethod
    def setup(self, reference: Reference) -> None:
        """Load the robot at the reference's first waypoint, ready to go."""

    @abstractmethod
    def check(self, points: Array) -> list[Problem]:
        """Waypoints (robot frame) the robot cannot reach or hold, found before running."""

    @abstractmethod
    def control(self, t: float, reference: Reference) -> None:
        """Send this physics step's commands for time ``t``."""

    @abstractmethod
    def position(self) -> Array:
        """The tracked point now: end effector, body centre or base."""

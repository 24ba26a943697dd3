"""The map from case units to a robot's workspace: one uniform scale and an offset, always explicit.

OVITA's cases are in about [-0.3, 0.3], the paper's ground-robot map is 100 x 100, a drone room
may be in metres. ``fit_workspace`` shrinks (never enlarges) the scene to fit the robot's box and
centres it there; users can give their own scale and offset instead.

Simulators are right-handed with the robot facing +y, so its left is -x. In the paper's convention
(+X left) the case's x is therefore mirrored, so that "go left" moves the robot to its physical
left; in OVITA's (+X right) it is not.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]


@dataclass(frozen=True)
class WorkspaceBox:
    """An axis-aligned box in the robot's world frame (metres) where paths are placed."""

    centre: tuple[float, float, float]
    size: tuple[float, float, float]


@dataclass(frozen=True)
class WorkspaceMap:
    """``robot = scale * (mirrored) case + offset`` for positions; speeds scale by ``scale`` too."""

    scale: float
    offset: tuple[float, float, float]
    mirror_x: bool = False

    @property
    def _signs(self) -> Array:
        return _axis_signs(self.mirror_x)

    def to_robot(self, points: Array) -> Array:
        """Case-unit positions (N, 3) in the robot's frame."""
        scaled = np.asarray(points, dtype=np.float64) * self._signs * self.scale
        return np.asarray(scaled + np.asarray(self.offset))

    def to_case(self, points: Array) -> Array:
        """Robot-frame positions (N, 3) back in case units."""
        return np.asarray(
            (np.asarray(points, dtype=np.float64) - np.asarray(self.offset)) / self.scale * self._signs
        )

    def describe(self) -> str:
        """One line a user can check: ``robot = 0.5 x case (x mirrored) + (0.55, 0, 0.4) m``."""
        offset = ", ".join(f"{v:.4g}" for v in self.offset)
        mirrored = " (x mirrored: +X is left)" if self.mirror_x else ""
        return f"robot = {self.scale:.4g} x case{mirrored} + ({offset}) m"


def fit_workspace(
    points: Array, box: WorkspaceBox, flat_z: float | None = None, mirror_x: bool = False
) -> WorkspaceMap:
    """Scale ``points`` down (never up) to fit ``box`` and centre them in it.

    Args:
        points: every case-unit position that must fit (trajectories and objects), shape (N, 3).
        box: the robot's workspace box.
        flat_z: for a ground robot, ignore z when fitting and put the paths at this height.
        mirror_x: the case's +X is the robot's left (the paper's convention).
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3) * _axis_signs(mirror_x)
    low, high = points.min(axis=0), points.max(axis=0)
    extent = high - low
    size = np.asarray(box.size, dtype=np.float64)
    axes = [0, 1] if flat_z is not None else [0, 1, 2]
    ratios = [size[k] / extent[k] for k in axes if extent[k] > 1e-12]
    scale = float(min([1.0, *ratios]))
    offset = np.asarray(box.centre) - scale * (low + high) / 2
    if flat_z is not None:
        offset[2] = flat_z
    return WorkspaceMap(scale, (float(offset[0]), float(offset[1]), float(offset[2])), mirror_x)


def _axis_signs(mirror_x: bool) -> Array:
    """Multipliers that turn case axes into robot axes (x flipped when mirrored)."""
    return np.array([-1.0 if mirror_x else 1.0, 1.0, 1.0])

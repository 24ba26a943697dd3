"""Pictures of a run from pybullet's CPU renderer, with the paths and labels drawn over them.

pybullet's tiny renderer does not draw debug lines or text, so paths (original blue, executed red) and
object labels are projected with the camera's own matrices and drawn with Pillow.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt
from PIL import Image, ImageDraw

from trajadapt.files.atomic_files import write_bytes_atomic
from trajadapt.sim.engine import World
from trajadapt.sim.robots.base import CameraPose

Array = npt.NDArray[np.float64]
BLUE, RED, BLACK = (31, 119, 180), (214, 39, 40), (0, 0, 0)
FIELD_OF_VIEW = 50.0  # degrees, vertical


@dataclass(frozen=True)
class Overlay:
    """What is drawn over every frame."""

    original: Array  # (N, 3) robot frame
    labels: tuple[tuple[str, tuple[float, float, float]], ...]
    caption: str


class Camera:
    """A fixed camera around a target point, with the projection from world to pixels."""

    def __init__(self, world: World, content: Array, pose: CameraPose, size: tuple[int, int] = (480, 360)):
        """Look from ``pose``'s direction at the centre of ``content``, far enough to see all of it."""
        self.world, self.size = world, size
        low, high = content.min(axis=0), content.max(axis=0)
        reach = float(np.linalg.norm(high - low)) / 2
        distance = max(pose.distance, 1.2 * reach / np.tan(np.radians(FIELD_OF_VIEW / 2)))
        target = list((low + high) / 2)
        self.view = world.pb.computeViewMatrixFromYawPitchRoll(target, distance, pose.yaw, pose.pitch, 0, 2)
        self.projection = world.pb.computeProjectionMatrixFOV(FIELD_OF_VIEW, size[0] / size[1], 0.02, 200)
        matrix = np.asarray(self.projection).reshape(4, 4).T @ np.asarray(self.view).reshape(4, 4).T
        self._matrix = matrix

    def pixels(self, points: Array) -> list[tuple[float, float]]:
        """Image coordinates of world points (N, 3)."""
        rows = np.asarray(points).reshape(-1, 3)
        homogeneous = np.c_[rows, np.ones(len(rows))]
        clip = homogeneous @ self._matrix.T
        ndc = clip[:, :3] / clip[:, 3:4]
        width, height = self.size
        return [(float((x + 1) / 2 * width), float((1 - y) / 2 * height)) for x, y in ndc[:, :2]]

    def frame(self) -> Image.Image:
        """The scene now, from the CPU renderer."""
        width, height = self.size
        _, _, rgba, _, _ = self.world.call(
            "getCameraImage",
            width,
            height,
            self.view,
            self.projection,
            renderer=self.world.pb.ER_TINY_RENDERER,
        )
        return Image.fromarray(np.asarray(rgba, dtype=np.uint8).reshape(height, width, 4)[:, :, :3])

    def annotated(self, overlay: Overlay, executed: Array) -> Image.Image:
        """A frame with the original path, the executed path so far, labels and the caption."""
        image = self.frame()
        draw = ImageDraw.Draw(image)
        for points, colour, width in ((overlay.original, BLUE, 5), (executed, RED, 2)):
            if len(points) > 1:
                draw.line(self.pixels(points), fill=colour, width=width)
        for label, position in overlay.labels:
            x, y = self.pixels(np.asarray(position))[0]
            draw.text((x + 4, y - 12), label, fill=BLACK)
        draw.text((6, 4), overlay.caption, fill=BLACK)
        draw.text((6, self.size[1] - 16), "blue: original   red: executed", fill=BLACK)
        return image


def save_png(image: Image.Image, path: Path) -> None:
    """Write a PNG atomically."""
    write_bytes_atomic(path, _encode(image, "PNG", optimize=True))


def save_gif(frames: list[Image.Image], path: Path, frame_ms: int) -> None:
    """Write an animated GIF (looping) atomically."""
    if not frames:
        raise ValueError("no frames to write")
    encoded = _encode(frames[0], "GIF", save_all=True, append_images=frames[1:], duration=frame_ms, loop=0)
    write_bytes_atomic(path, encoded)


def _encode(image: Image.Image, kind: str, **options: Any) -> bytes:
    buffer = io.BytesIO()
    image.save(buffer, format=kind, **options)
    return buffer.getvalue()

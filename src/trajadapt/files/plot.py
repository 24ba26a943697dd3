"""Plots of an adapted trajectory against the original: PNG files through matplotlib's Agg."""

from __future__ import annotations

import io
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.axes import Axes  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from mpl_toolkits.mplot3d import Axes3D  # noqa: E402

from trajadapt.files.atomic_files import write_bytes_atomic  # noqa: E402
from trajadapt.model.geometry import AxisConvention  # noqa: E402
from trajadapt.model.scene import Scene, SceneObject  # noqa: E402
from trajadapt.model.trajectory import Trajectory  # noqa: E402

ORIGINAL_COLOUR = "tab:blue"
ADAPTED_COLOUR = "tab:red"
FLAT_TOLERANCE = 1e-9


def is_planar(*trajectories: Trajectory) -> bool:
    """True when every trajectory keeps one height (a ground robot): a top view says it all."""
    heights = np.concatenate([t.positions[:, 2] for t in trajectories])
    return bool(np.ptp(heights) <= FLAT_TOLERANCE)


def plot_comparison(
    original: Trajectory,
    adapted: Trajectory | None,
    scene: Scene,
    path: Path,
    axes: AxisConvention,
    title: str = "",
) -> None:
    """Write a PNG: original in blue, adapted in red, objects labelled; 3-D or top view as fits."""
    shown = [t for t in (original, adapted) if t is not None]
    figure = plt.figure(figsize=(7, 6), dpi=100)
    try:
        if is_planar(*shown):
            _draw_top_view(figure.add_subplot(), original, adapted, scene, axes)
        else:
            _draw_3d(figure.add_subplot(projection="3d"), original, adapted, scene)
        figure.suptitle(title[:90] or "trajectory adaptation", fontsize=10)
        figure.tight_layout()
        write_bytes_atomic(path, _png_bytes(figure))
    finally:
        plt.close(figure)


def _png_bytes(figure: Figure) -> bytes:
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png")
    return buffer.getvalue()


MAX_LABELS = 30
"""Objects named on a plot: the ones nearest the original path (thousands of labels take minutes)."""


def labelled(scene: Scene, original: Trajectory) -> list[SceneObject]:
    """The objects to name on the plot: all of them, or the ``MAX_LABELS`` nearest the original path."""
    if len(scene.objects) <= MAX_LABELS:
        return list(scene.objects)
    positions = original.positions
    distance = [
        float(np.min(np.linalg.norm(positions - np.asarray(obj.position), axis=1))) for obj in scene.objects
    ]
    nearest = sorted(range(len(scene.objects)), key=lambda i: distance[i])[:MAX_LABELS]
    return [scene.objects[i] for i in sorted(nearest)]


def _draw_top_view(
    ax: Axes, original: Trajectory, adapted: Trajectory | None, scene: Scene, axes: AxisConvention
) -> None:
    for trajectory, colour, label in (
        (original, ORIGINAL_COLOUR, "original"),
        (adapted, ADAPTED_COLOUR, "adapted"),
    ):
        if trajectory is None:
            continue
        xy = trajectory.positions[:, :2]
        ax.plot(xy[:, 0], xy[:, 1], "-o", color=colour, markersize=2, label=label)
        ax.scatter(xy[0, 0], xy[0, 1], color=colour, marker="s", s=40)
        ax.scatter(xy[-1, 0], xy[-1, 1], color=colour, marker="*", s=90)
    if scene.objects:
        where = np.array([obj.position for obj in scene.objects])
        ax.scatter(where[:, 0], where[:, 1], color="black", marker="^")
    for obj in labelled(scene, original):
        ax.annotate(obj.name, (obj.x, obj.y), textcoords="offset points", xytext=(4, 4), fontsize=8)
    if axes.positive_x == "left":
        ax.invert_xaxis()  # seen from above with front up, +X left must point left
    ax.set_xlabel(f"x (+ is {axes.positive_x})")
    ax.set_ylabel(f"y (+ is {axes.positive_y})")
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(loc="best", fontsize=8, title="square: start, star: goal", title_fontsize=7)


def _draw_3d(ax: Axes3D, original: Trajectory, adapted: Trajectory | None, scene: Scene) -> None:
    for trajectory, colour, label in (
        (original, ORIGINAL_COLOUR, "original"),
        (adapted, ADAPTED_COLOUR, "adapted"),
    ):
        if trajectory is None:
            continue
        p = trajectory.positions
        ax.plot(p[:, 0], p[:, 1], p[:, 2], "-o", color=colour, markersize=2, label=label)
        ax.scatter(*p[0], color=colour, marker="s", s=40)
        ax.scatter(*p[-1], color=colour, marker="*", s=90)
    if scene.objects:
        where = np.array([obj.position for obj in scene.objects])
        ax.scatter(where[:, 0], where[:, 1], where[:, 2], color="black", marker="^")
    for obj in labelled(scene, original):
        ax.text(obj.x, obj.y, obj.z, obj.name, fontsize=8)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.legend(loc="best", fontsize=8, title="square: start, star: goal", title_fontsize=7)

"""Run a trajectory on a simulated robot: map it into the workspace, time it, follow it, report."""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from trajadapt.errors import SimulationError
from trajadapt.model.scene import Scene
from trajadapt.model.trajectory import Trajectory
from trajadapt.sim.engine import PHYSICS_HZ, World
from trajadapt.sim.reference import Reference, build_reference
from trajadapt.sim.render import Camera, Overlay, save_gif, save_png
from trajadapt.sim.report import Array, SimulationReport, measure_tracking
from trajadapt.sim.robots import ROBOTS, Robot
from trajadapt.sim.workspace import WorkspaceMap, fit_workspace

SETTLE_S = 1.5  # simulated time after the last waypoint is due
MAX_SIMULATED_S = 600.0
GIF_MAX_FRAMES = 80
GIF_FRAME_MS = 100


@dataclass(frozen=True)
class SimulationOptions:
    """How to run: window, mapping override, files to write."""

    gui: bool = False
    scale: float | None = None  # with offset: the user's own map from case units to metres
    offset: tuple[float, float, float] | None = None
    image: Path | None = None
    animation: Path | None = None
    realtime: bool = False  # sleep to wall-clock pace (with the GUI)
    positive_x: str = "left"  # the case's axis convention: paper (+X left, mirrored) or ovita (+X right)


def simulate(
    trajectory: Trajectory,
    scene: Scene,
    robot: str,
    options: SimulationOptions = SimulationOptions(),
    original: Trajectory | None = None,
    progress: Callable[[float], None] | None = None,
) -> SimulationReport:
    """Execute ``trajectory`` on ``robot`` ('arm', 'drone', 'ground') and measure how it followed.

    ``original`` (the trajectory before adaptation) is drawn in blue in the pictures; without it the
    input itself is. ``progress`` gets the fraction of simulated time done.

    Raises:
        SimulationError: unknown robot, a trajectory with no timing, or a run that cannot start.
    """
    robot_class = ROBOTS.get(robot)
    if robot_class is None:
        raise SimulationError(f"unknown robot {robot!r}; choose one of: {', '.join(ROBOTS)}")
    reference_original = original if original is not None else trajectory
    mapping = _mapping(robot_class, trajectory, reference_original, scene, options)
    raw_points = mapping.to_robot(trajectory.positions)
    points = _flat(raw_points, robot_class.planar)
    reference, notes = _timed_reference(robot_class, points, trajectory, mapping)
    with World(gui=options.gui) as world:
        machine = robot_class(world)
        machine.setup(reference)
        problems = machine.check(raw_points)
        labels = _place_objects(world, machine, scene, mapping)
        original_points = _flat(mapping.to_robot(reference_original.positions), robot_class.planar)
        camera = Camera(world, _content(points, original_points, labels, robot_class), robot_class.camera)
        overlay = Overlay(original_points, labels, mapping.describe())
        run = _Run(world, machine, reference, camera, overlay, options, progress)
        executed, executed_times, wall, frames, render_s = run.execute()
    tracking = measure_tracking(points, reference.times, executed, executed_times)
    report = SimulationReport(
        robot=robot, robot_description=robot_class.description, mapping=mapping.describe(),
        waypoints=len(points), simulated_s=float(executed_times[-1]), wall_s=wall, tracking=tracking,
        problems=problems, notes=notes, executed=executed,
    )  # fmt: skip
    _write_pictures(report, options, frames, run.last_image, render_s)
    return report


def _mapping(
    robot_class: type[Robot],
    trajectory: Trajectory,
    original: Trajectory,
    scene: Scene,
    options: SimulationOptions,
) -> WorkspaceMap:
    mirror = options.positive_x == "left"
    if options.scale is not None:
        return WorkspaceMap(float(options.scale), options.offset or (0.0, 0.0, 0.0), mirror)
    everything = [trajectory.positions, original.positions]
    if scene.objects:
        everything.append(np.array([o.position for o in scene.objects]))
    flat_z = 0.0 if robot_class.planar else None
    return fit_workspace(np.concatenate(everything), robot_class.workspace, flat_z=flat_z, mirror_x=mirror)


def _timed_reference(
    robot_class: type[Robot], points: Array, trajectory: Trajectory, mapping: WorkspaceMap
) -> tuple[Reference, list[str]]:
    try:
        reference = build_reference(points, trajectory.speeds, mapping.scale)
    except ValueError as exc:
        raise SimulationError(f"cannot time the trajectory: {exc}") from exc
    notes = []
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    fastest = float(np.max(steps / np.maximum(np.diff(reference.times), 1e-9))) if len(steps) else 0.0
    if fastest > robot_class.max_speed:
        stretch = fastest / robot_class.max_speed
        reference = Reference(points, reference.times * stretch)
        notes.append(
            f"slowed down {stretch:.2f}x: the path asks for {fastest:.2f} m/s, the {robot_class.name} "
            f"is run at up to {robot_class.max_speed:.2f} m/s"
        )
    if reference.duration > MAX_SIMULATED_S:
        raise SimulationError(
            f"the trajectory lasts {reference.duration:.0f} s at its speeds (limit {MAX_SIMULATED_S:.0f} s); "
            "raise its speeds or give a smaller --scale"
        )
    return reference, notes


def _content(
    points: Array,
    original: Array,
    labels: tuple[tuple[str, tuple[float, float, float]], ...],
    robot: type[Robot],
) -> Array:
    """Every point a picture must show: both paths, the objects and the robot's anchors."""
    extra = [np.asarray(position) for _, position in labels] + [np.asarray(a) for a in robot.anchors]
    return np.vstack([points, original, *extra])


def _flat(points: Array, planar: bool) -> Array:
    if planar:
        points = points.copy()
        points[:, 2] = 0.0
    return points


def _place_objects(
    world: World, machine: Robot, scene: Scene, mapping: WorkspaceMap
) -> tuple[tuple[str, tuple[float, float, float]], ...]:
    labels = []
    for index, obj in enumerate(scene.objects):
        position = _flat(mapping.to_robot(np.array([obj.position])), machine.planar)[0]
        world.add_marker(position, machine.marker_radius, index, obj.name)
        top = position + [0, 0, machine.marker_radius]
        labels.append((obj.name, (float(top[0]), float(top[1]), float(top[2]))))
    return tuple(labels)


class _Run:
    """The stepping loop: control, physics, samples and animation frames."""

    def __init__(
        self, world: World, machine: Robot, reference: Reference, camera: Camera, overlay: Overlay,
        options: SimulationOptions, progress: Callable[[float], None] | None,
    ) -> None:  # fmt: skip
        self.world, self.machine, self.reference = world, machine, reference
        self.camera, self.overlay, self.options, self.progress = camera, overlay, options, progress
        self.last_image: Image.Image | None = None

    def execute(self) -> tuple[Array, Array, float, list[Image.Image], float]:
        total_steps = int(np.ceil((self.reference.duration + SETTLE_S) * PHYSICS_HZ))
        frame_every = max(1, total_steps // GIF_MAX_FRAMES)
        progress_every = max(1, total_steps // 10)
        samples: list[Array] = []
        times: list[float] = []
        frames: list[Image.Image] = []
        render_s, wall = 0.0, 0.0
        for step in range(total_steps + 1):
            started = time.perf_counter()
            t = step / PHYSICS_HZ
            samples.append(self.machine.position())
            times.append(t)
            if step < total_steps:
                self.machine.control(t, self.reference)
                self.world.step()
            wall += time.perf_counter() - started
            if self.options.animation is not None and step % frame_every == 0:
                render_s += self._add_frame(frames, np.asarray(samples))
            if self.options.realtime:
                time.sleep(max(0.0, 1.0 / PHYSICS_HZ - (time.perf_counter() - started)))
            if self.progress is not None and step % progress_every == 0:
                self.progress(step / total_steps)
        executed = np.asarray(samples)
        if self.options.image is not None:
            started = time.perf_counter()
            self.last_image = self.camera.annotated(self.overlay, executed)
            render_s += time.perf_counter() - started
        return executed, np.asarray(times), wall, frames, render_s

    def _add_frame(self, frames: list[Image.Image], executed: Array) -> float:
        started = time.perf_counter()
        frames.append(self.camera.annotated(self.overlay, executed))
        return time.perf_counter() - started


def _write_pictures(
    report: SimulationReport,
    options: SimulationOptions,
    frames: list[Image.Image],
    image: Image.Image | None,
    render_s: float,
) -> None:
    if options.image is not None and image is not None:
        save_png(image, options.image)
        report.image = options.image
    if options.animation is not None and frames:
        started = time.perf_counter()
        save_gif(frames, options.animation, GIF_FRAME_MS)
        report.animation = options.animation
        report.animation_s = render_s + time.perf_counter() - started

"""``trajadapt simulate`` and ``trajadapt plan``: run a trajectory on a robot, plan one from nothing."""

from __future__ import annotations

from pathlib import Path

import click
import numpy as np

from trajadapt.errors import InputError
from trajadapt.files.atomic_files import sibling_file, write_json_atomic
from trajadapt.model.case import load_scene
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.settings import load_settings
from trajadapt.sim.inputs import load_run_input

ROBOT_NAMES = ("arm", "drone", "ground")


@click.command()
@click.argument("result_file", type=click.Path(path_type=Path))
@click.option(
    "--robot", type=click.Choice(ROBOT_NAMES), required=True, help="arm (KUKA iiwa), drone or ground (Husky)."
)
@click.option(
    "--gif",
    "gif_file",
    type=click.Path(path_type=Path),
    default=None,
    help="Write an animated GIF of the run.",
)
@click.option(
    "--image",
    "image_file",
    type=click.Path(path_type=Path),
    default=None,
    help="Scene picture (default: <result>.<robot>.png).",
)
@click.option(
    "--report",
    "report_file",
    type=click.Path(path_type=Path),
    default=None,
    help="JSON report (default: <result>.<robot>.sim.json).",
)
@click.option(
    "--axes",
    type=click.Choice(sorted(AXIS_CONVENTIONS)),
    default=None,
    help="The case's convention: paper (+X left; mirrored onto the robot) or ovita (+X right). "
    "Default: the one the result was adapted in, else TRAJADAPT_AXES / config.toml (paper).",
)
@click.option(
    "--gui", is_flag=True, help="Open pybullet's window and run at wall-clock pace (needs a display)."
)
@click.option(
    "--scale", type=float, default=None, help="Metres per case unit (default: fit the robot's workspace)."
)
@click.option(
    "--offset", type=float, nargs=3, default=None, help="Robot-frame offset X Y Z in metres (with --scale)."
)
def simulate(
    result_file: Path, robot: str, gif_file: Path | None, image_file: Path | None, report_file: Path | None,
    axes: str | None, gui: bool, scale: float | None, offset: tuple[float, float, float] | None,
) -> None:  # fmt: skip
    """Execute RESULT_FILE (a result from 'adapt' or a case file) on a simulated robot.

    The case units are mapped into the robot's workspace by one scale and offset (printed; set them
    with --scale/--offset); with --axes paper (+X left) x is mirrored so that "left" is the robot's
    left. Reports the tracking error, waypoints the robot cannot reach, and writes a
    picture (original blue, executed red), a JSON report and, with --gif, an animation.
    """
    run_and_report(result_file, robot, image_file, report_file, gif_file, gui, scale, offset, axes)


def run_and_report(
    source: Path, robot: str, image: Path | None = None, report_file: Path | None = None,
    gif: Path | None = None, gui: bool = False, scale: float | None = None,
    offset: tuple[float, float, float] | None = None, axes: str | None = None,
) -> None:  # fmt: skip
    """Simulate ``source`` and print and write the report (shared by 'simulate' and 'adapt --simulate').

    ``axes`` (None: the result's own, else the settings') says which way +X points.
    The picture and report default to ``<source stem>.<robot>.png`` and ``.<robot>.sim.json`` beside it.
    """
    image = image or sibling_file(source, f".{robot}.png")
    report_file = report_file or sibling_file(source, f".{robot}.sim.json")
    from trajadapt.cli.console import Progress
    from trajadapt.sim import SimulationOptions, simulate

    if offset is not None and scale is None:
        raise InputError("--offset needs --scale (without both, the map is fitted to the workspace)")
    run = load_run_input(source)
    positive_x = AXIS_CONVENTIONS[axes or run.axes or load_settings().axes].positive_x
    options = SimulationOptions(
        gui=gui, scale=scale, offset=offset, image=image, animation=gif, realtime=gui, positive_x=positive_x
    )
    with Progress() as progress:
        progress.update(f"simulating on the {robot}")
        report = simulate(
            run.trajectory, run.scene, robot, options, original=run.original,
            progress=lambda done: progress.update(f"simulating on the {robot}: {done:.0%}"),
        )  # fmt: skip
    write_json_atomic(report_file, report.to_dict())
    for line in report.summary_lines():
        click.echo(line)
    click.echo(f"report: {report_file}")


@click.command()
@click.option(
    "--scene",
    "scene_file",
    type=click.Path(path_type=Path),
    required=True,
    help="Scene file (objects, Env_descp).",
)
@click.option("--start", type=float, nargs=3, required=True, help="Start X Y Z.")
@click.option("--goal", type=float, nargs=3, required=True, help="Goal X Y Z.")
@click.option(
    "--planner",
    type=click.Choice(["rrt", "astar"]),
    default="rrt",
    show_default=True,
    help="rrt (ompl; 2-D or 3-D) or astar (grid, ground plane).",
)
@click.option(
    "--count", type=click.IntRange(2, 10_000), default=50, show_default=True, help="Waypoints in the result."
)
@click.option(
    "--speed", type=float, default=1.0, show_default=True, help="Cruise speed of the trapezoidal profile."
)
@click.option(
    "--clearance", type=float, default=None, help="Distance kept from each object (default: 8% of the scene)."
)
@click.option("--instruction", "-i", default="", help="Instruction to store in the case (for 'adapt').")
@click.option("--out", type=click.Path(path_type=Path), required=True, help="Case file to write.")
def plan(
    scene_file: Path, start: tuple[float, float, float], goal: tuple[float, float, float], planner: str,
    count: int, speed: float, clearance: float | None, instruction: str, out: Path,
) -> None:  # fmt: skip
    """Plan an initial trajectory around the scene's objects and write it as a case file.

    The case can be adapted with 'trajadapt adapt OUT' and executed with 'trajadapt simulate'.
    """
    from trajadapt.planning import plan_case

    if speed <= 0:
        raise InputError(f"--speed must be positive, got {speed}")
    scene = load_scene(scene_file)
    case = plan_case(
        scene, np.array(start), np.array(goal), planner, count, speed, clearance, instruction, name=out.stem
    )
    write_json_atomic(out, case.to_dict())
    length = float(np.linalg.norm(np.diff(case.trajectory.positions, axis=0), axis=1).sum())
    click.echo(f"{planner}: {count} waypoints, path length {length:.3g}, written to {out}")

"""``trajadapt adapt``: one case, reviewed in the terminal: plan, code, approve or correct, result."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from trajadapt.backends.base import Backend
from trajadapt.chain import AdaptationChain
from trajadapt.checks.constraints import Constraints
from trajadapt.cli.common import (
    backend_option,
    examples_option,
    grammar_option,
    isolation_of,
    limits_options,
    make_backend,
    near_rule_option,
    option_option,
)
from trajadapt.cli.console import Progress, show_plan, show_result
from trajadapt.cli.robots import ROBOT_NAMES, run_and_report
from trajadapt.errors import InputError, SessionStateError
from trajadapt.files.atomic_files import sibling_file, write_json_atomic
from trajadapt.files.plot import plot_comparison
from trajadapt.files.rosbag_io import is_bag, read_bag_trajectory
from trajadapt.files.store import Store
from trajadapt.memory import MemoryBank
from trajadapt.model.case import Case, load_case, load_case_from_parts
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.model.trajectory import Trajectory
from trajadapt.prompts import PROMPT_MODES
from trajadapt.safe_text import safe_text
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationResult, AdaptationSession, SessionSettings
from trajadapt.settings import Settings, load_settings


@click.command()
@click.argument("case_file", required=False, type=click.Path(path_type=Path))
@click.option("--instruction", "-i", default=None, help="Instruction (replaces the case's own).")
@click.option(
    "--trajectory",
    "trajectory_file",
    type=click.Path(path_type=Path),
    default=None,
    help="Trajectory file (JSON, CSV with columns x,y,z,v, or a ROS recording: .bag, .mcap, .db3 or a "
    "ROS 2 bag folder, with --topic) instead of a case file.",
)
@click.option(
    "--topic",
    default=None,
    help="The recording's topic holding the trajectory (nav_msgs/Path, geometry_msgs/PoseStamped or "
    "trajectory_msgs/MultiDOFJointTrajectory).",
)
@click.option(
    "--waypoints",
    type=click.IntRange(2, 10000),
    default=None,
    help="Waypoints to resample a PoseStamped stream to (default 50).",
)
@click.option(
    "--scene",
    "scene_file",
    type=click.Path(path_type=Path),
    default=None,
    help="Scene file with 'objects' (and optional Env_descp, constraints), with --trajectory.",
)
@backend_option
@option_option
@click.option(
    "--model-path",
    type=click.Path(path_type=Path, dir_okay=False),
    default=None,
    help="A GGUF model file of your own for the local backend (instead of the embedded one).",
)
@click.option("--yes", "-y", is_flag=True, help="Approve the first plan without asking.")
@click.option(
    "--out",
    type=click.Path(path_type=Path),
    default=None,
    help="Result file (default: ./<case>.result.json).",
)
@click.option(
    "--plot",
    "plot_file",
    type=click.Path(path_type=Path),
    default=None,
    help="PNG plot of original (blue) vs adapted (red) (default: next to --out).",
)
@click.option(
    "--axes",
    type=click.Choice(sorted(AXIS_CONVENTIONS)),
    default=None,
    help="Coordinate convention stated in the prompt: paper (+X left) or ovita (+X right).",
)
@near_rule_option
@click.option(
    "--repairs",
    type=click.IntRange(0, 10),
    default=None,
    help="Automatic repair rounds when the code fails (default 2).",
)
@click.option(
    "--mode",
    type=click.Choice(PROMPT_MODES),
    default=None,
    help="Prompt mode: skills (default; the skill library) or paper (the paper's prompt).",
)
@examples_option
@grammar_option
@click.option(
    "--temperature", type=float, default=None, help="Sampling temperature (default 0: deterministic)."
)
@click.option("--seed", type=int, default=None, help="Sampling seed (default 0).")
@click.option(
    "--project/--no-project",
    "project_onto",
    default=None,
    help="Project a result that breaks the stated constraints onto them (the default; smooth least "
    "squares, needs [qp]), or send it back for repair (--no-project).",
)
@limits_options
@click.option("--no-log", is_flag=True, help="Do not log the exchanges to the SQLite log.")
@click.option("--no-memory", is_flag=True,
              help="Neither recall earlier approved answers as examples nor remember this one "
              "(TRAJADAPT_MEMORY=false does the same; see 'trajadapt examples').")  # fmt: skip
@click.option(
    "--simulate",
    "simulate_on",
    type=click.Choice(ROBOT_NAMES),
    default=None,
    help="After approval, execute the result on a simulated robot (arm, drone or ground).",
)
def adapt(
    case_file: Path | None,
    instruction: str | None,
    trajectory_file: Path | None,
    topic: str | None,
    waypoints: int | None,
    scene_file: Path | None,
    backend: str | None,
    options: tuple[tuple[str, str], ...],
    model_path: Path | None,
    yes: bool,
    out: Path | None,
    plot_file: Path | None,
    axes: str | None,
    near_rule: str | None,
    repairs: int | None,
    mode: str | None,
    examples: int | None,
    grammar: bool | None,
    temperature: float | None,
    seed: int | None,
    project_onto: bool | None,
    robot: str | None,
    limits: Constraints,
    no_log: bool,
    no_memory: bool,
    simulate_on: str | None,
) -> None:
    """Adapt the trajectory of CASE_FILE (OVITA case format) to its instruction.

    Shows the plan and code, then asks: approve, give feedback (a new plan follows), or quit.
    """
    overrides = {"backend": backend, "axes": axes, "near_rule": near_rule, "repair_attempts": repairs,
                 "mode": mode, "seed": seed, "project": project_onto, "examples": examples,
                 "grammar": grammar, "robot": robot}  # fmt: skip
    settings = load_settings({**overrides, "log": False if no_log else None, "temperature": temperature,
                              "memory": False if no_memory else None})  # fmt: skip
    case = _load_case(case_file, trajectory_file, scene_file, instruction, (topic, waypoints))
    chosen = make_backend(settings, options, model_path)
    out = out or Path(f"{case.name}.result.json")
    plot_file = plot_file or sibling_file(out, ".png")
    result, record = _run_session(case, chosen, settings, yes, limits)
    _save(result, record, out, plot_file, settings)
    if not result.ok:
        raise click.exceptions.Exit(1)
    if simulate_on is not None:
        run_and_report(out, simulate_on, axes=settings.axes)


def _load_case(
    case_file: Path | None,
    trajectory_file: Path | None,
    scene_file: Path | None,
    instruction: str | None,
    bag_topic: tuple[str | None, int | None] = (None, None),
) -> Case:
    if case_file is not None and trajectory_file is not None:
        raise InputError("give either a CASE_FILE or --trajectory, not both")
    if case_file is not None:
        case = load_case(case_file)
    elif trajectory_file is not None:
        case = load_case_from_parts(
            trajectory_file, scene_file, instruction or "", _bag_trajectory(trajectory_file, *bag_topic)
        )
    else:
        raise InputError("give a CASE_FILE, or --trajectory FILE [--scene FILE] --instruction TEXT")
    if instruction is not None:
        case = case.with_instruction(instruction)
    if not case.instruction:
        raise InputError(
            f"{case.source or case.name}: the case has no instruction; give one with --instruction"
        )
    return case


def _bag_trajectory(path: Path, topic: str | None, waypoints: int | None) -> Trajectory | None:
    """The trajectory of a ROS recording's topic, said where it came from; None for other files."""
    if not is_bag(path):
        if topic is not None:
            raise InputError(
                f"--topic is for ROS recordings (.bag, .mcap, .db3, a bag folder); {path} is not one"
            )
        return None
    read = read_bag_trajectory(path, topic, waypoints)
    click.echo(
        f"Read {len(read.trajectory)} waypoints from {read.topic} ({read.msgtype}), frame '{read.frame}'"
    )
    for note in read.notes:
        click.echo(f"  note: {note}")
    return read.trajectory


def _run_session(
    case: Case, backend: Backend, settings: Settings, yes: bool, limits: Constraints
) -> tuple[AdaptationResult, dict[str, Any]]:
    """Draft, review, approve; then, interactively, corrections on the result or the original."""
    store = Store(settings.log_path) if settings.log else None
    session_settings = SessionSettings.from_settings(settings, limits)
    try:
        with Sandbox(isolation=isolation_of(settings)) as sandbox, Progress() as progress:
            memory = MemoryBank(settings.memory_path) if settings.memory else None
            chain = AdaptationChain(case, backend, sandbox, session_settings, store, progress.update, memory)
            click.echo(f"Case {case.name}: {case.instruction}")
            show_plan(chain.draft())
            while True:
                while not yes and not _review(chain.session):
                    pass
                result = chain.approve()
                show_result(result)
                if yes or not _correct(chain):
                    break
    finally:
        backend.close()
        if store is not None:
            store.close()
    return result, chain.to_dict(result)


def _correct(chain: AdaptationChain) -> bool:
    """Ask for a correction of the result; True when one was given (a new plan is shown)."""
    try:
        text = click.prompt(
            "Enter keeps this result; 'c: text' changes it further, 'o: text' re-plans from the original",
            default="",
            show_default=False,
        ).strip()
    except click.Abort:  # the input ended (a pipe, Ctrl-D): keep the result
        return False
    if not text:
        return False
    kind, _, words = text.partition(":")
    if kind.strip().lower() not in ("c", "o") or not words.strip():
        click.echo("Write 'c: what to change' (on this result) or 'o: what to change' (from the original).")
        return _correct(chain)
    show_plan(chain.feedback(words.strip(), on="current" if kind.strip().lower() == "c" else "original"))
    return True


def _review(session: AdaptationSession) -> bool:
    """Ask approve / feedback / quit once; True when the plan is approved."""
    choice = click.prompt(
        "[a]pprove, [f]eedback, [e]xplain or [q]uit",
        type=click.Choice(["a", "f", "e", "q"]),
        show_choices=False,
    )
    if choice == "e":
        explanation = session.explain()
        source = (
            "from the skills it calls"
            if explanation.source == "skills"
            else "the model's reading, not checked"
        )
        click.secho(f"What the code does ({source}):", bold=True)
        for line in explanation.lines:
            click.echo(f"  {line}")
        return False
    if choice == "q":
        raise SessionStateError("quit without approving; nothing was written")
    if choice == "a":
        return True
    text = click.prompt("Feedback on the plan")
    show_plan(session.feedback(text))
    return False


def _save(
    result: AdaptationResult, record: dict[str, Any], out: Path, plot_file: Path, settings: Settings
) -> None:
    write_json_atomic(out, record)
    click.echo(f"Result written to {out} (status {result.status})")
    if not result.ok:
        return
    try:
        original = Trajectory.from_rows(record["original_trajectory"])  # the first step's input
        plot_comparison(
            original, result.trajectory, result.case.scene, plot_file,
            AXIS_CONVENTIONS[settings.axes], title=record["instruction"],
        )  # fmt: skip
    except Exception as exc:  # noqa: BLE001 - a picture that cannot be drawn must not fail a written result
        click.echo(f"Warning: the plot could not be drawn ({type(exc).__name__}: {safe_text(exc, 300)}); "
                   "the result file is complete", err=True)  # fmt: skip
        return
    click.echo(f"Plot written to {plot_file}")

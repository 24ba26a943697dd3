"""Prompts: template files with named fields, rendered into chat messages.

The fixed part (role, functions, coordinate system, rules, output format, examples) is the system
message and comes first, byte-identical from one request to the next, so that a local model can
reuse its cached state; what changes (environment, trajectory, instruction) follows it.
"""

from __future__ import annotations

from collections.abc import Sequence
from importlib import resources
from string import Template

import numpy as np

from trajadapt.backends.base import ChatMessage
from trajadapt.llm.example_bank import Example
from trajadapt.memory import RememberedExample, Retrieval, choose_examples
from trajadapt.model.case import Case
from trajadapt.model.geometry import AxisConvention
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.api import CONTRACT, RESULT_VARIABLE
from trajadapt.skills import describe_skills

PROMPT_MODES = ("skills", "paper")


def load_template(name: str) -> Template:
    """Read the template file ``prompts/<name>.md`` shipped with the package."""
    text = resources.files("trajadapt.prompts").joinpath(f"{name}.md").read_text(encoding="utf-8")
    return Template(text)


def render(name: str, **fields: str) -> str:
    """Render template ``name``; every named field must be given.

    Raises:
        KeyError: a field of the template was not given.
    """
    return load_template(name).substitute(fields).strip() + "\n"


def render_functions(mode: str = "paper") -> str:
    """The FUNCTIONS AVAILABLE section, built from the sandbox contract (and the skill library)."""
    contract = "\n".join(f"- {fn.signature}: {fn.description}" for fn in CONTRACT)
    return contract if mode == "paper" else contract + "\n" + describe_skills()


def system_prompt(axes: AxisConvention, mode: str = "skills") -> str:
    """The fixed part of every conversation, for prompt mode ``skills`` or ``paper``.

    Raises:
        ValueError: an unknown mode.
    """
    if mode not in PROMPT_MODES:
        raise ValueError(f"unknown prompt mode {mode!r}; use one of: {', '.join(PROMPT_MODES)}")
    return render(
        f"system_{mode}",
        functions=render_functions(mode),
        coordinate_system=axes.describe(),
        result_variable=RESULT_VARIABLE,
    )


def describe_environment(case: Case) -> str:
    """Objects with positions, then the scene description and constraints when given."""
    lines = [f"- {obj.name}: [{obj.x:.4g}, {obj.y:.4g}, {obj.z:.4g}]" for obj in case.scene.objects]
    parts = ["Objects (name: [x, y, z]):\n" + ("\n".join(lines) if lines else "- none")]
    if case.scene.description:
        parts.append(case.scene.description)
    if case.scene.constraints:
        parts.append("Constraints: " + case.scene.constraints)
    return "\n".join(parts)


def summarize_trajectory(trajectory: Trajectory) -> str:
    """Count, start, goal, extent, length and speed range: what the model needs, in few tokens."""
    positions, speeds = trajectory.positions, trajectory.speeds
    low, high = positions.min(axis=0), positions.max(axis=0)
    extent = ", ".join(f"{axis} {lo:.3g}..{hi:.3g}" for axis, lo, hi in zip("xyz", low, high, strict=True))
    return "\n".join(
        [
            f"- {len(trajectory)} waypoints, path length {trajectory.path_length():.3g}",
            f"- start {_point(positions[0])}, goal {_point(positions[-1])}",
            f"- extent: {extent}",
            f"- velocity {speeds.min():.3g}..{speeds.max():.3g} (mean {speeds.mean():.3g})",
        ]
    )


def _point(xyz: np.ndarray) -> str:
    return "[" + ", ".join(f"{value:.3g}" for value in xyz) + "]"


def list_waypoints(trajectory: Trajectory) -> str:
    """Every waypoint as ``[x, y, z, v]`` with 3 significant digits, one per line."""
    return "\n".join("[" + ", ".join(f"{value:.3g}" for value in row) + "]" for row in trajectory.array)


def chosen_examples(
    case: Case,
    mode: str,
    count: int,
    remembered: Sequence[RememberedExample] = (),
    by: Retrieval = "words",
) -> tuple[Example, ...]:
    """The examples the first prompt shows, best first (none in paper mode, whose prompt is fixed).

    They are the ``count`` nearest to the instruction from the shipped bank and the user's
    ``remembered`` answers, chosen ``by`` clauses or by words (``memory.choose_examples``).
    """
    if mode != "skills":
        return ()
    return tuple(choose_examples(case.instruction, count, case.scene.names(), remembered, by))


def render_examples(chosen: Sequence[Example]) -> str:
    """The chosen examples, nearest last, as a prompt section ('' for none)."""
    if not chosen:
        return ""
    body = "\n\n".join(example.render() for example in reversed(chosen))
    return f"EXAMPLES CLOSE TO THIS INSTRUCTION (their objects are not in this scene):\n{body}\n\n"


def task_prompt(case: Case, waypoints: bool = False, chosen: Sequence[Example] = ()) -> str:
    """The per-request part: chosen examples, environment, trajectory summary, instruction."""
    trajectory = summarize_trajectory(case.trajectory)
    if waypoints:
        trajectory += "\n- waypoints [x, y, z, velocity]:\n" + list_waypoints(case.trajectory)
    return render(
        "task",
        examples=render_examples(chosen),
        environment=describe_environment(case),
        trajectory=trajectory,
        instruction=case.instruction,
    )


def first_messages(
    case: Case,
    axes: AxisConvention,
    mode: str = "skills",
    waypoints: bool = False,
    examples: int = 0,
    remembered: Sequence[RememberedExample] = (),
    chosen: Sequence[Example] | None = None,
) -> tuple[ChatMessage, ...]:
    """The opening conversation for ``case``.

    ``waypoints`` adds every waypoint to the summary. The examples before the environment are
    ``chosen`` when given (a session chooses them once and keeps the choice), else
    ``chosen_examples(case, mode, examples, remembered)``.
    """
    if chosen is None:
        chosen = chosen_examples(case, mode, examples, remembered)
    return (
        ChatMessage("system", system_prompt(axes, mode)),
        ChatMessage("user", task_prompt(case, waypoints, chosen)),
    )

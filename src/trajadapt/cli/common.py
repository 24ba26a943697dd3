"""Pieces several commands share: the backend options and building a prepared backend."""

from __future__ import annotations

import functools
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import click

from trajadapt.backends.base import Backend
from trajadapt.backends.registry import get_backend
from trajadapt.checks.robot_limits import ROBOT_LIMITS, ROBOT_NAMES, user_constraints
from trajadapt.cli.console import PrepareBar
from trajadapt.errors import InputError
from trajadapt.sandbox.runner import Isolation
from trajadapt.settings import CHOICES, Settings

backend_option = click.option(
    "--backend", "-b", default=None, help="Backend name (see 'trajadapt backends'); default: local."
)
option_option = click.option(
    "--option", "-o", "options", type=(str, str), multiple=True, metavar="KEY VALUE",
    help="Backend option, e.g. -o base_url http://127.0.0.1:11434/v1 -o model qwen2.5-coder.",
)  # fmt: skip
examples_option = click.option(
    "--examples", type=click.IntRange(0, 12), default=None, metavar="K",
    help="Worked examples nearest to the instruction put into the prompt (skills mode; default 3).",
)  # fmt: skip
grammar_option = click.option(
    "--grammar/--free-decoding", "grammar", default=None,
    help="Constrain a local model's answer to the skill calls and object names of the scene (skills "
    "mode; the default), or let it write any code.",
)  # fmt: skip

near_rule_option = click.option(
    "--near-rule", type=click.Choice(CHOICES["near_rule"]), default=None,
    help="What 'near an object' means to a speed change: zone (the default: the whole change where "
    "the path passes closest, fading soon beyond) or latte (LaTTe's data generator: falling off "
    "with distance from the object, none where the path stays far; for LaTTe-style data).",
)  # fmt: skip

Command = TypeVar("Command", bound=Callable[..., Any])
LIMIT_FLAGS = ("workspace", "reach_base", "reach", "clearance", "max_speed", "fixed_ends")


def limits_options(command: Command) -> Command:
    """Add the robot and constraint flags; the command gets ``robot`` and ``limits`` (a Constraints)."""
    robots = "; ".join(f"{name}: {limits.description}" for name, limits in ROBOT_LIMITS.items())
    flags = [
        click.option("--robot", type=click.Choice(ROBOT_NAMES), default=None,
                     help=f"Whose limits every result keeps (default none). {robots}."),
        click.option("--workspace", type=(float,) * 6, default=None,
                     metavar="XMIN XMAX YMIN YMAX ZMIN ZMAX", help="A box every waypoint stays in."),
        click.option("--reach-base", type=(float,) * 3, default=None, metavar="X Y Z",
                     help="Your arm's base (with --reach)."),
        click.option("--reach", type=(float,) * 2, default=None, metavar="MIN MAX",
                     help="How near and how far from --reach-base the arm reaches."),
        click.option("--clearance", type=float, default=None,
                     help="Distance kept from every object the instruction does not ask to approach."),
        click.option("--max-speed", type=float, default=None, help="Highest allowed velocity."),
        click.option("--fixed-ends", type=click.Choice(["none", "start", "goal", "both"]), default="none",
                     show_default=True, help="Keep the start, the goal or both where they are."),
    ]  # fmt: skip

    @functools.wraps(command)
    def run(**kwargs: Any) -> Any:
        given = {name: kwargs.pop(name) for name in LIMIT_FLAGS}
        return command(limits=user_constraints(**given), **kwargs)

    for flag in reversed(flags):
        run = flag(run)
    return run  # type: ignore[return-value]


def backend_options(pairs: tuple[tuple[str, str], ...]) -> dict[str, str]:
    """``-o KEY VALUE`` pairs as a dict."""
    return {key: value for key, value in pairs}


def make_backend(
    settings: Settings, pairs: tuple[tuple[str, str], ...], model_path: Path | None = None
) -> Backend:
    """The configured backend with the command line's options, prepared (model assembled/loaded)."""
    options = dict(settings.backend_options) if settings.backend_options else {}
    options.update(backend_options(pairs))
    if model_path is not None:
        options["model_path"] = str(model_path)
    backend = get_backend(settings.backend, options)
    backend.prepare(PrepareBar())
    return backend


def isolation_of(settings: Settings) -> Isolation:
    """The sandbox isolation the settings ask for.

    Raises:
        InputError: an unknown isolation name.
    """
    if settings.isolation not in ("auto", "bwrap", "process"):
        raise InputError(f"isolation must be auto, bwrap or process, not {settings.isolation!r}")
    return settings.isolation

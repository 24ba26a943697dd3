"""The ``trajadapt`` group: every command, and our errors as one clear line."""

from __future__ import annotations

import logging
from typing import Any

import click

from trajadapt.cli.adapt import adapt
from trajadapt.cli.backends import backends
from trajadapt.cli.bench import bench
from trajadapt.cli.examples import examples
from trajadapt.cli.logs import logs
from trajadapt.cli.robots import plan, simulate
from trajadapt.cli.ros import export
from trajadapt.cli.serve import serve
from trajadapt.errors import TrajadaptError


class TrajadaptGroup(click.Group):
    """Turns every TrajadaptError into one clear line and exit code 1 (tracebacks with --debug)."""

    def invoke(self, ctx: click.Context) -> Any:
        """Run the command, mapping our errors to click's."""
        try:
            return super().invoke(ctx)
        except TrajadaptError as exc:
            if ctx.params.get("debug"):
                raise
            raise click.ClickException(f"{type(exc).__name__}: {exc}") from exc


@click.group(cls=TrajadaptGroup)
@click.option("--debug", is_flag=True, help="Show tracebacks and debug logging.")
@click.version_option(package_name="trajadapt")
def cli(debug: bool) -> None:
    """Adapt robot trajectories to natural-language instructions.

    An LLM answers an instruction with a numbered plan and Python code; you approve the plan or
    give feedback; the approved code runs in a sandbox on the trajectory; the result is written
    as JSON and plotted against the original.
    """
    logging.basicConfig(level=logging.DEBUG if debug else logging.WARNING)


for command in (adapt, bench, backends, logs, examples, simulate, plan, serve, export):
    cli.add_command(command)

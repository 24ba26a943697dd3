"""``trajadapt backends``: the registered backends, and a tiny request to each with --check."""

from __future__ import annotations

import click

from trajadapt.backends.registry import backend_class, get_backend, registered_backends
from trajadapt.cli.common import (
    backend_option,
    backend_options,
    option_option,
)
from trajadapt.errors import TrajadaptError
from trajadapt.settings import load_settings


@click.command()
@click.option("--check", is_flag=True, help="Also send each configured backend a tiny request.")
@backend_option
@option_option
def backends(check: bool, backend: str | None, options: tuple[tuple[str, str], ...]) -> None:
    """List the registered backends (built-in and plugins); with --check, try them."""
    settings = load_settings({"backend": backend})
    names = [backend] if backend else sorted(registered_backends())
    for name in names:
        marker = "*" if name == settings.backend else " "
        try:
            doc = (backend_class(name).__doc__ or "").strip().splitlines()[0]
        except TrajadaptError as exc:
            click.echo(f"{marker} {name:10s} unavailable: {exc}")
            continue
        click.echo(f"{marker} {name:10s} {doc}")
        if check:
            click.echo("    " + _check_backend(name, backend_options(options) if backend else {}))


def _check_backend(name: str, options: dict[str, str]) -> str:
    from trajadapt.backends.conformance import probe_backend

    try:
        return probe_backend(get_backend(name, options))
    except TrajadaptError as exc:
        return f"FAILED: {type(exc).__name__}: {exc}"

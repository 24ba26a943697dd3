"""``trajadapt serve``: the review page on a local web server."""

from __future__ import annotations

import ipaddress
import os
import secrets
from pathlib import Path
from typing import TYPE_CHECKING

import click

from trajadapt.checks.constraints import Constraints
from trajadapt.cli.common import (
    backend_option,
    isolation_of,
    limits_options,
    make_backend,
    near_rule_option,
    option_option,
)
from trajadapt.errors import DependencyNotInstalled, InputError
from trajadapt.files.store import Store
from trajadapt.memory import MemoryBank
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import PROMPT_MODES
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import SessionSettings
from trajadapt.settings import Settings, load_settings

if TYPE_CHECKING:
    from fastapi import FastAPI

TOKEN_ENV = "TRAJADAPT_TOKEN"


@click.command()
@click.option("--host", default="127.0.0.1", show_default=True, help="Address to bind (loopback by default).")
@click.option("--port", default=8765, show_default=True, type=click.IntRange(1, 65535), help="Port.")
@click.option("--cases", "cases_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              help="Folder of case files the page can pick from.")  # fmt: skip
@click.option("--allow-remote", is_flag=True, help="Allow binding to a non-loopback address (needs a token).")
@click.option("--token", default=None, help=f"Access token (default: ${TOKEN_ENV}, or a new random one).")
@click.option("--allowed-host", "allowed_hosts", multiple=True, metavar="NAME",
              help="Another host name the page may be opened under (e.g. the machine's DNS name with "
                   "--allow-remote); loopback names and the bound address are always allowed.")  # fmt: skip
@backend_option
@option_option
@click.option("--model-path", type=click.Path(dir_okay=False, path_type=Path), default=None,
              help="Use this GGUF file with the local backend.")  # fmt: skip
@click.option("--mode", type=click.Choice(PROMPT_MODES), default=None, help="Prompt mode (default skills).")
@click.option("--axes", type=click.Choice(sorted(AXIS_CONVENTIONS)), default=None, help="Axis convention.")
@near_rule_option
@click.option("--no-log", is_flag=True, help="Do not log sessions (and list no earlier ones).")
@click.option("--no-memory", is_flag=True,
              help="Neither recall approved answers as examples nor remember new ones.")  # fmt: skip
@limits_options
def serve(
    host: str, port: int, cases_dir: Path | None, allow_remote: bool, token: str | None,
    allowed_hosts: tuple[str, ...], backend: str | None, options: tuple[tuple[str, str], ...],
    model_path: Path | None, mode: str | None, axes: str | None, near_rule: str | None, no_log: bool,
    no_memory: bool, robot: str | None, limits: Constraints,
) -> None:  # fmt: skip
    """Serve the review page: load a case, read the plan and code, see the paths, approve or correct.

    Sessions are logged to the same SQLite log as 'adapt', so a restarted server lists earlier ones
    (not with --no-log or TRAJADAPT_LOG=false: then nothing is written).
    Binds to 127.0.0.1; another address needs --allow-remote, and then every request needs the token.
    The server answers only to loopback names, the bound address and --allowed-host names (a guard
    against DNS rebinding), and reads no request body over 8 MB. The robot and limit flags are the
    page's defaults; its Limits fields change them per session.
    """
    token = _access_token(host, allow_remote, token)
    overrides = {
        "backend": backend,
        "mode": mode,
        "axes": axes,
        "near_rule": near_rule,
        "robot": robot,
        "log": False if no_log else None,
        "memory": False if no_memory else None,
    }
    settings = load_settings(overrides)
    app = _build_app(settings, cases_dir, options, model_path, limits, token, (host, *allowed_hosts))
    import uvicorn

    query = f"/?token={token}" if token else "/"
    click.echo(f"trajadapt review page: http://{host}:{port}{query}  (Ctrl-C to stop)")
    uvicorn.run(app, host=host, port=port, log_level="warning")


def _access_token(host: str, allow_remote: bool, token: str | None) -> str | None:
    if _is_loopback(host):
        return token or os.environ.get(TOKEN_ENV) or None
    if not allow_remote:
        raise InputError(
            f"binding to {host} exposes the server beyond this machine; "
            "add --allow-remote (a token is then required)"
        )
    return token or os.environ.get(TOKEN_ENV) or secrets.token_urlsafe(18)


def _is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def _build_app(
    settings: Settings,
    cases_dir: Path | None,
    options: tuple[tuple[str, str], ...],
    model_path: Path | None,
    limits: Constraints,
    token: str | None,
    allowed_hosts: tuple[str, ...],
) -> FastAPI:
    try:
        from trajadapt.web.app import create_app
        from trajadapt.web.services import Services, pybullet_simulator
    except ImportError as exc:
        raise DependencyNotInstalled(
            "the review page needs fastapi, uvicorn and plotly: pip install 'trajadapt[web]'"
        ) from exc
    if cases_dir is not None and not cases_dir.is_dir():
        raise InputError(f"--cases {cases_dir}: not a folder")
    convention = AXIS_CONVENTIONS[settings.axes]
    session_settings = SessionSettings.from_settings(settings, limits)
    services = Services(
        backend=make_backend(settings, options, model_path),
        sandbox=Sandbox(isolation=isolation_of(settings)),
        store=Store(settings.log_path) if settings.log else None,
        settings=session_settings,
        work_dir=settings.home / "web",
        cases_dir=cases_dir,
        simulator=pybullet_simulator(convention.positive_x),
        memory=MemoryBank(settings.memory_path) if settings.memory else None,
    )
    return create_app(services, token, allowed_hosts)

"""``trajadapt logs``: the logged exchanges from the SQLite log."""

from __future__ import annotations

import json
from datetime import datetime

import click

from trajadapt.files.store import Store
from trajadapt.settings import load_settings


@click.command()
@click.option("--limit", "-n", default=20, show_default=True, help="How many exchanges to show.")
@click.option("--session", "session_id", default=None, help="Show one session (id or prefix).")
@click.option("--json", "as_json", is_flag=True, help="Print the records as JSON lines.")
def logs(limit: int, session_id: str | None, as_json: bool) -> None:
    """Show logged exchanges (prompts, answers, plans, code, results) from the SQLite log."""
    settings = load_settings()
    if not settings.log_path.exists():
        click.echo(f"No log yet at {settings.log_path}")
        return
    store = Store(settings.log_path)
    try:
        records = store.recent_exchanges(limit, session_id)
    finally:
        store.close()
    for record in records:
        if as_json:
            click.echo(json.dumps(record.__dict__))
            continue
        when = datetime.fromtimestamp(record.created).strftime("%Y-%m-%d %H:%M:%S")
        status = f"ERROR {record.error}" if record.error else "ok"
        click.secho(f"#{record.id} {when} session {record.session_id} {record.kind} "
                    f"[{record.backend}/{record.model}] {status}", bold=True)  # fmt: skip
        click.echo(f"  instruction: {record.instruction}")
        if record.plan:
            click.echo("  plan: " + record.plan.replace("\n", "\n        "))

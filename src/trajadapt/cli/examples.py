"""``trajadapt examples``: the answers you approved, kept as examples for your next requests."""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

import click

from trajadapt.errors import InputError
from trajadapt.memory import MemoryBank, RememberedExample
from trajadapt.settings import load_settings


def _bank() -> MemoryBank:
    return MemoryBank(load_settings().memory_path)


def _found(bank: MemoryBank, example_id: str) -> RememberedExample:
    """The example whose id starts with ``example_id`` (one only)."""
    matches = [e for e in bank.examples() if e.id.startswith(example_id)]
    if len(matches) != 1:
        what = "no example" if not matches else f"{len(matches)} examples"
        raise InputError(
            f"{what} with id {example_id!r} in {bank.path}; 'trajadapt examples list' shows them"
        )
    return matches[0]


@click.group()
def examples() -> None:
    """The answers you approved, remembered as examples for your next requests.

    Each approval (adapt, the review page, AdaptationSession.approve) keeps the instruction and the
    final program in TRAJADAPT_HOME/memory.jsonl, with the scene's object names as <object k>, and
    later requests in the same words (or nearly) are shown it first. Turn it off with --no-memory or
    TRAJADAPT_MEMORY=false; bench never uses it unless given --memory.
    """


@examples.command("list")
def list_examples() -> None:
    """Every remembered example: id, when, and the instruction."""
    bank = _bank()
    remembered = bank.examples()
    if not remembered:
        click.echo(f"No remembered examples in {bank.path}")
        return
    for example in remembered:
        when = datetime.fromtimestamp(example.created).strftime("%Y-%m-%d %H:%M")
        click.echo(f"{example.id}  {when}  {example.instruction}")


@examples.command()
@click.argument("example_id")
def show(example_id: str) -> None:
    """The instruction, its clauses, the plan and the program of one example (an id prefix will do)."""
    example = _found(_bank(), example_id)
    click.echo(f"id: {example.id} (from {example.origin})\ninstruction: {example.instruction}")
    for clause in example.clauses:
        click.echo(f"  clause: {clause}")
    click.echo(f"plan:\n{example.plan}\ncode:\n{example.code}")


@examples.command()
@click.argument("example_id")
def remove(example_id: str) -> None:
    """Forget one example: it is never recalled again."""
    bank = _bank()
    example = _found(bank, example_id)
    bank.forget(example.id)
    click.echo(f"Forgot {example.id}: {example.instruction}")


@examples.command("export")
@click.argument("target", type=click.Path(path_type=Path, dir_okay=False))
def export_examples(target: Path) -> None:
    """Write every remembered example to TARGET (a new file), to import on another machine."""
    count = _bank().export(target)
    click.echo(f"Wrote {count} example(s) to {target}")


@examples.command("import")
@click.argument("source", type=click.Path(path_type=Path, dir_okay=False))
def import_examples(source: Path) -> None:
    """Add the examples of SOURCE (written by 'export'), with new ids and names as placeholders.

    The whole file is checked first; a damaged or foreign file adds nothing.
    """
    added = _bank().import_file(source)
    click.echo(f"Imported {len(added)} example(s) from {source}")

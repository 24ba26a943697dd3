"""Terminal output for the CLI: a progress spinner and the plan, code and result as people read them."""

from __future__ import annotations

import itertools
import shutil
import sys
import threading
import time
from types import TracebackType
from typing import TextIO

import click

from trajadapt.llm.answer import Plan
from trajadapt.session import AdaptationResult
from trajadapt.skills.explain import explain_code


class Progress:
    """Shows what is going on while the LLM works: a live spinner on a terminal, plain lines otherwise."""

    def __init__(self, stream: TextIO | None = None) -> None:
        self.stream = stream or sys.stderr
        self.live = self.stream.isatty()
        self._message = ""
        self._since = time.monotonic()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def __enter__(self) -> Progress:
        if self.live:
            self._thread = threading.Thread(target=self._spin, daemon=True)
            self._thread.start()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
            self.stream.write("\r\033[K")
            self.stream.flush()

    def update(self, message: str) -> None:
        """Show ``message`` as the current activity."""
        self._message, self._since = message, time.monotonic()
        if not self.live:
            click.echo(f"... {message}", file=self.stream)

    def _spin(self) -> None:
        for frame in itertools.cycle("|/-\\"):
            if self._stop.wait(0.15):
                return
            elapsed = f" ({time.monotonic() - self._since:.0f} s)"
            room = shutil.get_terminal_size((100, 20)).columns - len(elapsed) - 3
            message = self._message if len(self._message) <= room else "…" + self._message[-(room - 1) :]
            self.stream.write(f"\r\033[K{frame} {message}{elapsed}")
            self.stream.flush()


def show_plan(plan: Plan) -> None:
    """Print the numbered plan and the code."""
    click.secho("High-level plan:", bold=True)
    click.echo(plan.numbered() or "(the answer gave no plan steps)")
    click.secho("Code:", bold=True)
    for number, line in enumerate(plan.code.rstrip("\n").splitlines(), start=1):
        click.echo(f"{number:3d}  {line}")
    explanation = explain_code(plan.code)
    if explanation:
        click.secho("What the code does (from the skills it calls):", bold=True)
        for number, line in enumerate(explanation, start=1):
            click.echo(f"  {number}) {line}")


def show_result(result: AdaptationResult) -> None:
    """Print the outcome: status, size, notes for the reviewer and timings."""
    timings = result.timings
    if result.ok and result.trajectory is not None:
        click.secho(f"Result: ok, {len(result.trajectory)} waypoints", fg="green", bold=True)
    else:
        click.secho(f"Result: failed after {result.attempts} attempt(s): {result.error}", fg="red", err=True)
    if result.effect is not None:
        click.echo("What changed:")
        for line in result.effect.describe():
            click.echo(f"  {line}")
    for flag in result.contradictions:
        click.secho(f"  check this: {flag}", fg="red")
    for note in result.notes:
        click.secho(f"  note: {note.message}", fg="yellow")
    if result.stdout.strip():
        click.echo("Printed by the code:\n" + result.stdout.rstrip()[:2000])
    click.echo(
        f"Time: llm {timings.llm_s:.1f} s, execution {timings.exec_s * 1000:.0f} ms, "
        f"total {timings.total_s:.1f} s ({result.backend}, {result.model})"
    )


class CaseProgress:
    """Progress over many cases: click's bar with ETA on a terminal, one line per case otherwise."""

    def __init__(self, total: int, stream: TextIO | None = None) -> None:
        self.total = total
        self.stream = stream or sys.stderr
        self.done = 0
        self.started = time.monotonic()
        self._bar = (
            click.progressbar(length=total, label="adapting", show_eta=True, show_pos=True, file=self.stream)
            if self.stream.isatty()
            else None
        )

    def __enter__(self) -> CaseProgress:
        if self._bar is not None:
            self._bar.__enter__()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        if self._bar is not None:
            self._bar.__exit__(exc_type, exc, tb)

    def advance(self, name: str, outcome: str) -> None:
        """One case finished with ``outcome`` ('pass', 'fail', 'error', 'not judged')."""
        self.done += 1
        if self._bar is not None:
            self._bar.update(1)
            return
        elapsed = time.monotonic() - self.started
        remaining = elapsed / self.done * (self.total - self.done)
        click.echo(
            f"[{self.done}/{self.total}] {name}: {outcome} (elapsed {elapsed:.0f} s, ETA {remaining:.0f} s)",
            file=self.stream,
        )


class PrepareBar:
    """A progress bar for a backend's one-time preparation (e.g. assembling a 1.1 GB model)."""

    def __init__(self, stream: TextIO | None = None) -> None:
        self.stream = stream or sys.stderr
        self._what = ""
        self._shown = -1

    def __call__(self, what: str, done: int, total: int) -> None:
        """Show progress of ``what``: a bar on a terminal, a line per 10% otherwise."""
        percent = int(100 * done / total) if total else 100
        if what != self._what:
            self._what, self._shown = what, -1
        if self.stream.isatty():
            filled = percent // 4
            self.stream.write(f"\r{what}: [{'#' * filled}{'.' * (25 - filled)}] {percent:3d}%")
            if done >= total:
                self.stream.write("\n")
            self.stream.flush()
        elif percent // 10 != self._shown // 10 or done >= total:
            click.echo(f"{what}: {percent}%", file=self.stream)
        self._shown = percent

"""Host side of the sandbox: start the worker, send it jobs, turn its answers into SandboxResult."""

from __future__ import annotations

import concurrent.futures
import contextlib
import functools
import json
import logging
import shutil
import subprocess
import sys
import threading
from dataclasses import dataclass, field
from pathlib import Path
from types import TracebackType
from typing import IO, Any, Literal

from trajadapt.errors import SandboxError
from trajadapt.model.scene import Scene
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox import seccomp
from trajadapt.sandbox.bubblewrap import bwrap_command
from trajadapt.sandbox.protocol import MAX_ANSWER_CHARS, ProtocolError, WorkerAnswer, read_worker_answer

logger = logging.getLogger(__name__)

Isolation = Literal["auto", "bwrap", "process"]
WORKER_START_TIMEOUT_S = 30.0
WORKER_GRACE_S = 10.0
PROCESS_ONLY_WARNING = (
    "the sandbox runs without bubblewrap: generated code is kept from files, sockets and processes by "
    "the seccomp allow-list and the unprivileged user alone, and would see the host's file system if "
    "those failed; install bubblewrap (apt install bubblewrap) for the outer layer"
)


@dataclass(frozen=True)
class SandboxLimits:
    """Resource limits for one execution of generated code."""

    cpu_s: float = 5.0
    wall_s: float = 10.0
    memory_mb: int = 512
    max_output_chars: int = 20_000


@dataclass(frozen=True)
class ExecutionOptions:
    """What the generated code is given beyond the trajectory and scene.

    Attributes:
        skills: bind the skill library's functions into the code's namespace.
        positive_x: what +X means to the user ('left' or 'right'); skills read directions with it.
        near_rule: what "near an object" means to a speed change (``skills.speed.NEAR_RULES``).
        accept_last: when the code forgets ``modified_trajectory``, take the last (N, 4) array it built.
    """

    skills: bool = False
    positive_x: str = "left"
    near_rule: str = "zone"
    accept_last: bool = False


@dataclass(frozen=True)
class CodeError:
    """How generated code failed: exception type, message, and the line in the code if known."""

    type: str
    message: str
    line: int | None = None

    def describe(self) -> str:
        """One line for people and for the repair prompt."""
        where = f" (line {self.line})" if self.line else ""
        return f"{self.type}{where}: {self.message}"


@dataclass(frozen=True)
class SandboxResult:
    """What one execution produced: raw rows (unvalidated), printed text, or the error."""

    rows: list[list[float]] | None
    stdout: str
    error: CodeError | None
    duration_s: float
    layers: tuple[str, ...] = field(default=())
    notes: tuple[str, ...] = field(default=())

    @property
    def ok(self) -> bool:
        """True when the code ran to the end and set its result variable."""
        return self.error is None and self.rows is not None


class Sandbox:
    """Runs generated code in an isolated worker process; reuse one instance for many runs.

    The worker is started on first use and restarted if it dies. ``isolation`` picks the outer
    layer: ``"bwrap"`` (bubblewrap: no network, read-only file system, own PID namespace),
    ``"process"`` (child processes with limits and seccomp only), or ``"auto"`` (bwrap when it
    is installed and works, else process).
    """

    def __init__(
        self,
        limits: SandboxLimits | None = None,
        isolation: Isolation = "auto",
        *,
        python_layers: bool = True,
    ) -> None:
        """Prepare a sandbox; the worker starts on the first run.

        Args:
            limits: CPU, wall-clock, memory and output limits for each run.
            isolation: the outer layer (see the class docstring).
            python_layers: False skips the static check and the restricted namespace. Only tests use
                it, to show that the OS layers hold alone against code that got past them.
        """
        self.limits = limits or SandboxLimits()
        self.isolation = isolation
        self.python_layers = python_layers
        self._process: subprocess.Popen[str] | None = None
        self._lock = threading.Lock()
        self.outer_layer = ""

    def __enter__(self) -> Sandbox:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    def run(
        self, code: str, trajectory: Trajectory, scene: Scene, options: ExecutionOptions | None = None
    ) -> SandboxResult:
        """Execute ``code`` against ``trajectory`` and ``scene``; failures come back in the result.

        Raises:
            SandboxError: only when the sandbox itself cannot be started.
        """
        chosen = options or ExecutionOptions()
        job = {
            "skills": chosen.skills,
            "positive_x": chosen.positive_x,
            "near_rule": chosen.near_rule,
            "accept_last": chosen.accept_last,
            "code": code,
            "trajectory": trajectory.to_rows(),
            "objects": {obj.name: list(obj.position) for obj in scene.objects},
            "cpu_s": self.limits.cpu_s,
            "wall_s": self.limits.wall_s,
            "memory_mb": self.limits.memory_mb,
            "max_output_chars": self.limits.max_output_chars,
            "python_layers": self.python_layers,
        }
        with self._lock:
            try:
                answer = self._exchange(job)
            except ProtocolError as exc:
                logger.warning("sandbox worker sent a malformed answer (%s); replacing it", exc)
                self.close()
                return _protocol_failure(exc)
        return _to_result(answer, self._host_layers())

    def _host_layers(self) -> tuple[str, ...]:
        python = ("static-check", "restricted-namespace") if self.python_layers else ()
        return (*python, self.outer_layer)

    def close(self) -> None:
        """Stop the worker process."""
        process, self._process = self._process, None
        if process is None:
            return
        _close_quietly(process.stdin)
        try:
            process.wait(timeout=2)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
        _close_quietly(process.stdout)
        _close_quietly(process.stderr)

    def _exchange(self, job: dict[str, Any]) -> WorkerAnswer:
        for attempt in range(2):
            process = self._ensure_worker()
            # a worker that does not answer well after the child's own limit is stopped
            watchdog = threading.Timer(float(job["wall_s"]) + WORKER_GRACE_S, process.kill)
            watchdog.start()
            try:
                assert process.stdin is not None and process.stdout is not None
                process.stdin.write(json.dumps(job) + "\n")
                process.stdin.flush()
                line = process.stdout.readline(MAX_ANSWER_CHARS + 1)
            except (BrokenPipeError, OSError, UnicodeDecodeError):
                line = ""
            finally:
                watchdog.cancel()
            if line:
                return read_worker_answer(line)
            logger.warning("sandbox worker died (attempt %d); restarting it", attempt + 1)
            self.close()
        raise SandboxError(
            "the sandbox worker keeps dying or stopped answering; check that 'bwrap --unshare-all true' "
            "works, or run without bubblewrap: TRAJADAPT_ISOLATION=process"
        )

    def _ensure_worker(self) -> subprocess.Popen[str]:
        if self._process is not None and self._process.poll() is None:
            return self._process
        self.close()  # a dead worker's pipes
        for command, layer in self._candidate_commands():
            process = _start(command)
            if _wait_ready(process):
                self._process, self.outer_layer = process, layer
                _warn_once(layer)
                return process
            stderr = _drain(process)
            logger.warning("sandbox worker (%s) did not start: %s", layer, stderr.strip()[-500:])
        raise SandboxError(
            "the sandbox worker could not be started; check that numpy imports in this Python "
            f"({sys.executable}) and, for isolation='bwrap', that 'bwrap --unshare-all true' works"
        )

    def _candidate_commands(self) -> list[tuple[list[str], str]]:
        worker = [sys.executable, "-s", "-B", "-m", "trajadapt.sandbox.child"]
        bwrap = shutil.which("bwrap")
        if self.isolation == "bwrap" and bwrap is None:
            raise SandboxError("isolation='bwrap' but bubblewrap is not installed (apt install bubblewrap)")
        candidates = []
        if bwrap is not None and self.isolation in ("auto", "bwrap"):
            candidates.append((bwrap_command(bwrap, worker, PACKAGE_ROOT), "bwrap"))
        if self.isolation in ("auto", "process"):
            candidates.append((worker, "process"))
        return candidates


PACKAGE_ROOT = Path(__file__).resolve().parents[2]


@functools.cache
def _warn_once(outer_layer: str) -> None:
    """Say once per process what is weaker than the full sandbox on this machine."""
    if outer_layer == "process":
        logger.warning(PROCESS_ONLY_WARNING)
    if not seccomp.supported():
        logger.warning("no seccomp filter on this platform: the sandbox's OS layers are weaker")


def _worker_environment() -> dict[str, str]:
    return {
        "PATH": "/usr/bin:/bin",
        "PYTHONPATH": str(PACKAGE_ROOT),
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "MKL_NUM_THREADS": "1",
        "LANG": "C.UTF-8",
    }


_STARTER = concurrent.futures.ThreadPoolExecutor(max_workers=1, thread_name_prefix="sandbox-starter")
"""The one thread that starts workers. bubblewrap's --die-with-parent is PR_SET_PDEATHSIG, which fires
when the *thread* that started the worker ends: started from a request's thread (the review page), a
worker died with that request. This thread lives until the process ends, and so do the workers."""


def _start(command: list[str]) -> subprocess.Popen[str]:
    try:
        return _STARTER.submit(_popen, command).result()
    except RuntimeError as exc:  # the interpreter is shutting down: no new worker can be started
        raise SandboxError(f"no sandbox worker can be started while the program ends ({exc})") from exc


def _popen(command: list[str]) -> subprocess.Popen[str]:
    return subprocess.Popen(
        command,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=_worker_environment(),
        cwd="/",
        start_new_session=True,
    )


def _wait_ready(process: subprocess.Popen[str]) -> bool:
    holder: list[str] = []
    reader = threading.Thread(target=_read_line_into, args=(process, holder), daemon=True)
    reader.start()
    reader.join(WORKER_START_TIMEOUT_S)
    if holder and '"ready": true' in holder[0]:
        return True
    process.kill()
    process.wait()
    return False


def _read_line_into(process: subprocess.Popen[str], holder: list[str]) -> None:
    assert process.stdout is not None
    holder.append(process.stdout.readline())


def _drain(process: subprocess.Popen[str]) -> str:
    text = process.stderr.read() if process.stderr else ""
    for stream in (process.stdin, process.stdout, process.stderr):
        _close_quietly(stream)
    return text


def _close_quietly(stream: IO[str] | None) -> None:
    """Close a pipe whose other end may be gone (flushing it would raise BrokenPipeError)."""
    if stream is None:
        return
    try:
        stream.close()
    except OSError:
        with contextlib.suppress(OSError):
            stream.close()


def _to_result(answer: WorkerAnswer, host_layers: tuple[str, ...]) -> SandboxResult:
    result = answer.result
    error = result.error
    return SandboxResult(
        rows=result.rows if result.ok else None,
        stdout=result.stdout,
        error=CodeError(error["type"], error["message"], error["line"]) if error else None,
        duration_s=answer.duration_s,
        layers=(*host_layers, *answer.layers),
        notes=tuple(result.notes),
    )


def _protocol_failure(exc: ProtocolError) -> SandboxResult:
    message = f"the sandbox worker sent a malformed answer ({exc}); it was replaced and the result discarded"
    return SandboxResult(None, "", CodeError("SandboxProtocol", message), 0.0)

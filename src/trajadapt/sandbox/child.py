"""The sandbox worker: a long-lived process that forks one locked-down child per job.

This is the only module where generated code is executed. The host (``runner``) starts it as
``python -m trajadapt.sandbox.child``, inside bubblewrap where available, and talks JSON lines over
stdin/stdout: one job in, one answer out. For each job the worker forks; the child applies the OS
layers (``lockdown``: unprivileged user, resource limits, seccomp allow-list), runs the static check,
then executes the code in the restricted namespace and writes its result to a pipe. The worker
enforces the wall-clock limit, reads the child's result as untrusted (``protocol``), asks the kernel
which layers the child really ran under, and reports how a child died.
"""

from __future__ import annotations

import ast
import builtins
import contextlib
import json
import os
import select
import signal
import sys
import threading
import time
import traceback
from collections.abc import Callable
from typing import Any, NoReturn

import numpy as np

from trajadapt.model.trajectory import MAX_WAYPOINTS
from trajadapt.safe_text import safe_text
from trajadapt.sandbox.api import RESULT_VARIABLE, build_api
from trajadapt.sandbox.guard import check_code
from trajadapt.sandbox.lockdown import RESULT_FD, ChildLimits, lock_down, verified_layers
from trajadapt.sandbox.protocol import (
    MAX_CHILD_BYTES,
    MAX_NOTES,
    ChildResult,
    ProtocolError,
    decode_json,
    error_result,
    read_child_result,
    worker_answer_json,
)
from trajadapt.sandbox.restricted import BoundedOutput, make_builtins, preload_modules
from trajadapt.sandbox.rewrite import (
    assign_discarded_results,
    limits_last,
    measure_from_original,
    passes_last,
    smoothing_last,
)
from trajadapt.sandbox.template import Template, TemplateGone, ended, send_job
from trajadapt.skills import SKILL_NAMES, Axes, bind_skills

GENERATED_FILENAME = "<generated>"
# Names a small model invents for detect_objects (seen in the benchmark); in skills mode they work too.
DETECT_ALIASES = ("find_object", "find_objects", "detect_object", "get_object", "get_object_position")


def main() -> None:
    """Serve jobs from stdin until it closes; each answer is one JSON line on stdout."""
    modules = preload_modules()
    protocol_out = os.fdopen(os.dup(1), "w", buffering=1)
    os.dup2(os.open(os.devnull, os.O_RDWR), 1)  # stray writes never corrupt the protocol
    template = Template(lambda job, result_fd: _child(job, modules, result_fd))  # before any job is read
    protocol_out.write(json.dumps({"ready": True, "pid": os.getpid()}) + "\n")
    for line in sys.stdin:
        if not line.strip():
            continue
        job = json.loads(line)
        try:
            result, duration_s, layers = run_job_in_child(job, line.encode(), template)
        except TemplateGone:
            sys.exit(3)  # the host replaces the worker: a new template can only come from a fresh one
        protocol_out.write(worker_answer_json(result, duration_s, layers) + "\n")


def run_job_in_child(
    job: dict[str, Any], raw: bytes, template: Template
) -> tuple[ChildResult, float, list[str]]:
    """Have the template fork a child for ``job`` (sent as ``raw``); collect its result in time.

    Returns:
        The checked result, the seconds it took, and the layers the kernel shows for the child.
    """
    job_read, job_write = os.pipe()
    read_fd, write_fd = os.pipe()
    started = time.perf_counter()
    pid = template.fork_child(job_read, write_fd)
    os.close(job_read)
    os.close(write_fd)
    threading.Thread(target=send_job, args=(job_write, raw), daemon=True).start()
    deadline = started + float(job["wall_s"])
    payload, timed_out = _read_with_deadline(read_fd, deadline)  # None: too large
    if not timed_out:
        timed_out = not ended(pid, deadline - time.perf_counter())  # it closed the pipe and went on
    if timed_out:
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGKILL)
    layers = verified_layers(pid)  # before reaping: a zombie's status still shows its layers
    status, cpu_s = template.reap(pid)
    if payload is None:
        result = error_result(
            "Crash", f"the code's process sent more than {MAX_CHILD_BYTES} bytes; discarded"
        )
    elif payload:
        result = _decode(payload)
    else:
        result = _death_report(status, timed_out, cpu_s, job)
    return result, time.perf_counter() - started, layers


def _read_with_deadline(fd: int, deadline: float) -> tuple[bytes | None, bool]:
    chunks: list[bytes] = []
    size = 0
    try:
        while True:
            remaining = deadline - time.perf_counter()
            if remaining <= 0:
                return b"", True
            ready, _, _ = select.select([fd], [], [], remaining)
            if not ready:
                return b"", True
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                return b"".join(chunks), False
            size += len(chunk)
            if size > MAX_CHILD_BYTES:
                return None, False
            chunks.append(chunk)
    finally:
        os.close(fd)


def _decode(payload: bytes) -> ChildResult:
    try:
        return read_child_result(decode_json(payload, MAX_CHILD_BYTES))
    except ProtocolError as exc:
        return error_result("Crash", f"the code's process sent a malformed result ({exc}); it was discarded")


def _death_report(status: int, timed_out: bool, cpu_s: float, job: dict[str, Any]) -> ChildResult:
    if timed_out:
        return error_result(
            "Timeout", f"the code did not finish within {job['wall_s']:g} s (wall clock) and was stopped"
        )
    if os.WIFSIGNALED(status):
        number = os.WTERMSIG(status)
        used_it_all = number == signal.SIGKILL and cpu_s >= 0.95 * float(job["cpu_s"])  # SIGXCPU ignored
        if number == signal.SIGXCPU or used_it_all:
            return error_result(
                "Timeout", f"the code used more than {job['cpu_s']:g} s of CPU time and was stopped"
            )
        name = signal.Signals(number).name
        return error_result(
            "Crash", f"the code's process was killed by {name} (a resource limit or a refused system call)"
        )
    return error_result("Crash", "the code's process ended without a result")


def _child(job: dict[str, Any], modules: dict[str, Any], write_fd: int) -> NoReturn:
    try:
        lock_down(ChildLimits(float(job["cpu_s"]), int(job["memory_mb"])), write_fd)
        result = execute(job, modules)
    except BaseException as exc:  # noqa: BLE001 - anything escaping must still end the child
        result = error_result("Crash", f"sandbox child failed: {exc!r}")
    try:
        data = json.dumps(result.to_json()).encode()
        view = memoryview(data)
        while view:
            view = view[os.write(RESULT_FD, view) :]
    finally:
        os._exit(0)


def execute(job: dict[str, Any], modules: dict[str, Any]) -> ChildResult:
    """Check and run the job's code in the restricted namespace.

    With ``job["python_layers"]`` false the static check is skipped and the code gets the real
    builtins and modules: only tests ask for that, to show that the OS layers hold on their own.
    """
    python_layers = job.get("python_layers", True)
    violation = check_code(job["code"]) if python_layers else None
    if violation is not None:
        return error_result("Rejected", violation.message, violation.line)
    output = BoundedOutput(int(job["max_output_chars"]))
    api, calls = build_api(job["trajectory"], job["objects"])
    tree = ast.parse(job["code"], GENERATED_FILENAME)
    notes: list[str] = []
    if job.get("skills"):
        axes = Axes.from_positive_x(job.get("positive_x", "left"))
        api.update(bind_skills(axes, job.get("near_rule", "zone")))
        api.update(dict.fromkeys(DETECT_ALIASES, api["detect_objects"]))
        notes += assign_discarded_results(tree, SKILL_NAMES)
        notes += measure_from_original(tree)
        notes += passes_last(tree)
        notes += limits_last(tree)
        notes += smoothing_last(tree)
    namespace = _namespace(api, modules, output) if python_layers else _unrestricted_namespace(api, output)
    try:
        exec(compile(tree, GENERATED_FILENAME, "exec"), namespace)  # noqa: S102
        rows = _result_rows(namespace, set(api), notes if job.get("accept_last") else None)
    except MemoryError:
        failed = error_result("MemoryError", f"the code used more than {job['memory_mb']} MB of memory")
    except BaseException as exc:  # noqa: BLE001 - every failure is reported to the host
        message = "; ".join(part for part in (_describe(exc), calls.hint()) if part)
        failed = error_result(_kind(exc), safe_text(message), _generated_line(exc))
    else:
        return ChildResult(True, rows, output.text(), None, _capped(notes))
    return ChildResult(False, None, output.text(), failed.error, _capped(notes))


def _capped(notes: list[str]) -> list[str]:
    """At most ``MAX_NOTES`` notes: the first ones, and how many more there were."""
    if len(notes) <= MAX_NOTES:
        return notes
    return [*notes[: MAX_NOTES - 1], f"... and {len(notes) - MAX_NOTES + 1} more notes like these"]


def _namespace(
    api: dict[str, Callable[..., Any]], modules: dict[str, Any], output: BoundedOutput
) -> dict[str, Any]:
    return {
        "__builtins__": make_builtins(modules, output),
        "__name__": "generated",
        "np": modules["numpy"],
        "numpy": modules["numpy"],
        "math": modules["math"],
        **api,
    }


def _unrestricted_namespace(api: dict[str, Callable[..., Any]], output: BoundedOutput) -> dict[str, Any]:
    """What code that got past every Python layer would hold: the real builtins and modules.

    Only ``print`` still goes to the bounded output, so a test can read what an attack saw.
    """
    real = {**vars(builtins), "print": output.print}
    return {"__builtins__": real, "__name__": "generated", "np": np, "numpy": np, **api}


def _result_rows(namespace: dict[str, Any], provided: set[str], notes: list[str] | None) -> list[list[float]]:
    """The rows of ``modified_trajectory``; with ``notes``, the last trajectory the code built instead."""
    value = namespace.get(RESULT_VARIABLE)
    if value is None and notes is not None:
        value = _last_built_trajectory(namespace, provided, notes)
    if value is None:
        raise NameError(
            f"the code did not set the variable '{RESULT_VARIABLE}'; "
            f"store the new trajectory in it as an (N, 4) array of x, y, z, velocity"
        )
    try:
        array = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"'{RESULT_VARIABLE}' must be an (N, 4) array of numbers: {exc}") from None
    if array.ndim != 2 or array.shape[1] != 4 or array.shape[0] > MAX_WAYPOINTS:
        raise ValueError(
            f"'{RESULT_VARIABLE}' must be an (N, 4) array with at most {MAX_WAYPOINTS} rows, "
            f"got shape {array.shape}"
        )
    return [[float(value) for value in row] for row in array]


def _last_built_trajectory(namespace: dict[str, Any], provided: set[str], notes: list[str]) -> Any:
    """The most recently created variable holding an (N, 4) array, if the code forgot the result name."""
    for name, value in reversed(list(namespace.items())):
        if name.startswith("__") or name in provided:
            continue
        if isinstance(value, np.ndarray) and value.ndim == 2 and value.shape[1] == 4 and len(value) >= 2:
            notes.append(f"the code did not set '{RESULT_VARIABLE}'; used its variable '{name}' instead")
            return value
    return None


def _kind(exc: BaseException) -> str:
    name = type(exc).__name__
    return name if name.isidentifier() and len(name) <= 100 else "Exception"


def _describe(exc: BaseException) -> str:
    try:
        return safe_text(str(exc) or repr(exc))
    except Exception:  # noqa: BLE001 - an exception whose text cannot be made is still reported
        return f"{type(exc).__name__} (its message could not be read)"


def _generated_line(exc: BaseException) -> int | None:
    frames = traceback.extract_tb(exc.__traceback__)
    lines = [frame.lineno for frame in frames if frame.filename == GENERATED_FILENAME]
    if lines:
        return lines[-1]
    if isinstance(exc, SyntaxError) and exc.filename == GENERATED_FILENAME:
        return exc.lineno
    return None


if __name__ == "__main__":
    main()

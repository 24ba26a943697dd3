"""The sandbox worker: a long-lived process that forks one locked-down child per job.

This is the only module where generated code is executed. The host (``runner``) starts it as
``python -m trajadapt.sandbox.child``, inside bubblewrap where available, and talks JSON lines over
stdin/stdout: one job in, one result out. For each job the worker forks; the child
drops privileges, sets resource limits (CPU seconds, address space, file size, open files), installs
the seccomp filter, runs the static check, then executes the code in the restricted namespace and
writes its result to a pipe. The worker enforces the wall-clock limit and reports how a child died.
"""

from __future__ import annotations

import ast
import json
import os
import resource
import select
import signal
import sys
import time
import traceback
from collections.abc import Callable
from typing import Any

import numpy as np

from trajadapt.sandbox import seccomp
from trajadapt.sandbox.api import RESULT_VARIABLE, build_api
from trajadapt.sandbox.guard import check_code
from trajadapt.sandbox.restricted import BoundedOutput, make_builtins, preload_modules
from trajadapt.sandbox.rewrite import assign_discarded_results
from trajadapt.skills import SKILL_NAMES, Axes, bind_skills

GENERATED_FILENAME = "<generated>"
RESULT_FD = 3
NOBODY_ID = 65534
MAX_RESULT_BYTES = 32 * 1024 * 1024
MAX_WAYPOINTS = 100_000
# Names a small model invents for detect_objects (seen in the benchmark); in skills mode they work too.
DETECT_ALIASES = ("find_object", "find_objects", "detect_object", "get_object", "get_object_position")


def main() -> None:
    """Serve jobs from stdin until it closes; each answer is one JSON line on stdout."""
    modules = preload_modules()
    protocol_out = os.fdopen(os.dup(1), "w", buffering=1)
    os.dup2(os.open(os.devnull, os.O_RDWR), 1)  # stray writes never corrupt the protocol
    protocol_out.write(json.dumps({"ready": True, "pid": os.getpid()}) + "\n")
    for line in sys.stdin:
        if not line.strip():
            continue
        job = json.loads(line)
        protocol_out.write(json.dumps(run_job_in_child(job, modules)) + "\n")


def run_job_in_child(job: dict[str, Any], modules: dict[str, Any]) -> dict[str, Any]:
    """Fork, run ``job`` in the child, and collect its result within the wall-clock limit."""
    read_fd, write_fd = os.pipe()
    started = time.perf_counter()
    pid = os.fork()
    if pid == 0:  # child: never returns
        os.close(read_fd)
        _child(job, modules, write_fd)
    os.close(write_fd)
    payload, timed_out = _read_with_deadline(read_fd, started + float(job["wall_s"]))
    if timed_out:
        os.kill(pid, signal.SIGKILL)
    _, status = os.waitpid(pid, 0)
    result = _decode(payload) or _death_report(status, timed_out, job)
    result["duration_s"] = time.perf_counter() - started
    return result


def _read_with_deadline(fd: int, deadline: float) -> tuple[bytes, bool]:
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
            if size > MAX_RESULT_BYTES:
                return b"", False
            chunks.append(chunk)
    finally:
        os.close(fd)


def _decode(payload: bytes) -> dict[str, Any] | None:
    try:
        result = json.loads(payload) if payload else None
    except ValueError:
        return None
    return result if isinstance(result, dict) else None


def _death_report(status: int, timed_out: bool, job: dict[str, Any]) -> dict[str, Any]:
    if timed_out:
        message = f"the code did not finish within {job['wall_s']:g} s (wall clock) and was stopped"
        return _error("Timeout", message)
    if os.WIFSIGNALED(status):
        number = os.WTERMSIG(status)
        if number == signal.SIGXCPU:
            message = f"the code used more than {job['cpu_s']:g} s of CPU time and was stopped"
            return _error("Timeout", message)
        name = signal.Signals(number).name
        return _error("Crash", f"the code's process was killed by {name} (a resource limit?)")
    return _error("Crash", "the code's process ended without a result (output too large?)")


def _error(kind: str, message: str, line: int | None = None) -> dict[str, Any]:
    return {"ok": False, "error": {"type": kind, "message": message, "line": line}}


def _child(job: dict[str, Any], modules: dict[str, Any], write_fd: int) -> None:
    try:
        layers = _lock_down(job, write_fd)
        result = execute(job, modules)
        result["layers"] = layers
        data = json.dumps(result).encode()
    except BaseException as exc:  # noqa: BLE001 - anything escaping must still end the child
        data = json.dumps(_error("Crash", f"sandbox child failed: {exc!r}")).encode()
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(RESULT_FD, view) :]
    finally:
        os._exit(0)


def _lock_down(job: dict[str, Any], write_fd: int) -> list[str]:
    """Apply the OS layers in the child; return the names of the ones that took effect."""
    layers = []
    os.setsid()
    null = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(null, fd)
    os.dup2(write_fd, RESULT_FD)
    os.closerange(RESULT_FD + 1, 1 << 16)
    if _drop_privileges():
        layers.append("unprivileged-user")
    _set_limits(job)
    layers.append("rlimits")
    if seccomp.install_filter():
        layers.append("seccomp")
    return layers


def _drop_privileges() -> bool:
    if os.geteuid() != 0:
        return True
    try:
        os.setgroups([])
        os.setgid(NOBODY_ID)
        os.setuid(NOBODY_ID)
    except OSError:
        return False
    return True


def _set_limits(job: dict[str, Any]) -> None:
    cpu_s = max(1, int(np.ceil(float(job["cpu_s"]))))
    resource.setrlimit(resource.RLIMIT_CPU, (cpu_s, cpu_s + 1))
    address_space = _current_address_space() + int(job["memory_mb"]) * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
    resource.setrlimit(resource.RLIMIT_FSIZE, (0, 0))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_NOFILE, (RESULT_FD + 1, RESULT_FD + 1))
    resource.setrlimit(resource.RLIMIT_NPROC, (0, 0))


def _current_address_space() -> int:
    with open("/proc/self/statm") as statm:
        pages = int(statm.read().split()[0])
    return pages * resource.getpagesize()


def execute(job: dict[str, Any], modules: dict[str, Any]) -> dict[str, Any]:
    """Check and run the job's code in the restricted namespace; return a JSON-ready result."""
    violation = check_code(job["code"])
    if violation is not None:
        return {**_error("Rejected", violation.message, violation.line), "stdout": ""}
    output = BoundedOutput(int(job["max_output_chars"]))
    api, calls = build_api(job["trajectory"], job["objects"])
    tree = ast.parse(job["code"], GENERATED_FILENAME)
    notes: list[str] = []
    if job.get("skills"):
        api.update(bind_skills(Axes.from_positive_x(job.get("positive_x", "left"))))
        api.update(dict.fromkeys(DETECT_ALIASES, api["detect_objects"]))
        notes += assign_discarded_results(tree, SKILL_NAMES)
    namespace = _namespace(api, modules, output)
    try:
        exec(compile(tree, GENERATED_FILENAME, "exec"), namespace)  # noqa: S102
        rows = _result_rows(namespace, set(api), notes if job.get("accept_last") else None)
    except MemoryError:
        result = _error("MemoryError", f"the code used more than {job['memory_mb']} MB of memory")
    except BaseException as exc:  # noqa: BLE001 - every failure is reported to the host
        message = "; ".join(part for part in (str(exc) or repr(exc), calls.hint()) if part)
        result = _error(type(exc).__name__, message, _generated_line(exc))
    else:
        result = {"ok": True, "trajectory": rows}
    result["stdout"] = output.text()
    result["notes"] = notes
    return result


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
    if array.ndim != 2 or array.shape[0] > MAX_WAYPOINTS:
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

"""Fresh memory for every job: children are forked from a template that never held a job's bytes.

The worker reads each job (code, trajectory, scene) from the host, so its heap keeps freed remnants
of every earlier job; a child forked from the worker would inherit them, and a child that escapes
the Python layers could read them. So the worker forks a *template* once, right after the modules
are loaded and before it reads any job. For each job the worker hands the template two pipe ends
(``SCM_RIGHTS``: the job's way in, the result's way out); the template forks the child, which reads
its job from the pipe into memory no job has touched. The template only ever sees descriptors and
process ids, never a job's bytes. It reaps its children when the worker asks and reports how each
ended, and it dies with the worker (and each child with it).
"""

from __future__ import annotations

import json
import os
import select
import socket
import struct
from collections.abc import Callable
from typing import Any, NoReturn

from trajadapt.sandbox.lockdown import die_with

MAX_JOB_BYTES = 256 * 1024 * 1024


class TemplateGone(RuntimeError):
    """The template process no longer answers (it died): the worker must be replaced."""


class Template:
    """The worker's handle on its template process."""

    def __init__(self, run_child: Callable[[dict[str, Any], int], NoReturn]) -> None:
        """Fork the template now; ``run_child(job, result_fd)`` is what each job's child runs."""
        worker_end, template_end = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        pid = os.fork()
        if pid == 0:
            worker_end.close()
            _serve(template_end, run_child)
        template_end.close()
        self.pid, self._channel = pid, worker_end

    def fork_child(self, job_fd: int, result_fd: int) -> int:
        """A new child that reads its job from ``job_fd`` and writes its result to ``result_fd``."""
        return int(self._ask(b"fork", [job_fd, result_fd]))

    def reap(self, pid: int) -> tuple[int, float]:
        """Wait for the ended (or killed) child ``pid``: its wait status and the CPU seconds it used."""
        status, cpu_s = self._ask(b"reap %d" % pid).split()
        return int(status), float(cpu_s)

    def _ask(self, request: bytes, fds: list[int] | None = None) -> bytes:
        try:
            if fds:
                socket.send_fds(self._channel, [request], fds)
            else:
                self._channel.send(request)
            reply = self._channel.recv(128)
        except OSError as exc:
            raise TemplateGone(f"the sandbox template process is gone ({exc})") from exc
        if not reply or reply.startswith(b"error"):
            raise TemplateGone(
                f"the sandbox template process could not {request.split()[0].decode()}: {reply!r}"
            )
        return reply


def ended(pid: int, deadline_s: float) -> bool:
    """Whether process ``pid`` (not necessarily a child) ends within ``deadline_s`` seconds."""
    try:
        handle = os.pidfd_open(pid)
    except ProcessLookupError:
        return True
    try:
        ready, _, _ = select.select([handle], [], [], max(deadline_s, 0.0))
        return bool(ready)
    finally:
        os.close(handle)


def _serve(channel: socket.socket, run_child: Callable[[dict[str, Any], int], NoReturn]) -> NoReturn:
    """The template's loop: fork a child per request, reap it when asked. Never returns."""
    die_with(os.getppid())  # the template dies with the worker
    null = os.open(os.devnull, os.O_RDWR)
    os.dup2(null, 0)  # the worker's stdin carries jobs: the template never reads it
    os.closerange(3, channel.fileno())
    os.closerange(channel.fileno() + 1, 1 << 16)
    while True:
        try:
            message, fds, _, _ = socket.recv_fds(channel, 128, 2)
        except OSError:
            os._exit(0)
        if not message:
            os._exit(0)  # the worker is gone
        try:
            channel.send(_handle(message, fds, channel, run_child))
        except Exception as exc:  # noqa: BLE001 - the template reports and serves on
            channel.send(b"error " + type(exc).__name__.encode())


def _handle(message: bytes, fds: list[int], channel: socket.socket, run_child: Any) -> bytes:
    if message == b"fork" and len(fds) == 2:
        pid = os.fork()
        if pid == 0:
            channel.close()
            _child(fds[0], fds[1], run_child)
        for fd in fds:
            os.close(fd)
        return b"%d" % pid
    for fd in fds:
        os.close(fd)
    if message.startswith(b"reap "):
        _, status, usage = os.wait4(int(message[5:]), 0)
        return b"%d %.6f" % (status, usage.ru_utime + usage.ru_stime)
    return b"error unknown request"


def _child(job_fd: int, result_fd: int, run_child: Callable[[dict[str, Any], int], NoReturn]) -> NoReturn:
    try:
        job = json.loads(_read_all(job_fd))  # the child's own parent-death signal: lockdown
        os.close(job_fd)
    except BaseException:  # noqa: BLE001 - no job, no result: the worker reports a crash
        os._exit(1)
    run_child(job, result_fd)


def _read_all(fd: int) -> bytes:
    (size,) = struct.unpack("<Q", _read_exactly(fd, 8))
    if size > MAX_JOB_BYTES:
        raise ValueError("job too large")
    return _read_exactly(fd, size)


def _read_exactly(fd: int, size: int) -> bytes:
    chunks, left = [], size
    while left:
        chunk = os.read(fd, min(left, 1 << 20))
        if not chunk:
            raise EOFError("the job ended early")
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def send_job(fd: int, job: bytes) -> None:
    """Write ``job`` (with its length first) to the child's job pipe; a child that died is no error."""
    view = memoryview(struct.pack("<Q", len(job)) + job)
    try:
        while view:
            view = view[os.write(fd, view) :]
    except BrokenPipeError:
        pass
    finally:
        os.close(fd)

"""The operating-system layers of the sandbox child: applied in the child, checked from outside.

``lock_down`` runs in the freshly forked child before any generated code: a new session, standard
streams on /dev/null, every descriptor closed but the result pipe, an unprivileged user (nobody) when
running as root, resource limits, and the seccomp allow-list. ``verified_layers`` is the worker's
view of the same child, read from the kernel (``/proc/PID/status`` and ``/proc/PID/limits``), so
the layers a result reports are what the kernel enforced, not what the child claims.
"""

from __future__ import annotations

import ctypes
import math
import os
import resource
import signal
from dataclasses import dataclass
from pathlib import Path

from trajadapt.sandbox import seccomp

RESULT_FD = 3
NOBODY_ID = 65534


PR_SET_PDEATHSIG = 1


@dataclass(frozen=True)
class ChildLimits:
    """Resource limits of one child."""

    cpu_s: float
    memory_mb: int


class LockdownFailed(RuntimeError):
    """A layer that this platform supports could not be applied; the code must not run."""


def lock_down(limits: ChildLimits, write_fd: int) -> None:
    """Apply every OS layer to the calling (child) process.

    Raises:
        LockdownFailed: the seccomp filter could not be installed where it is supported, or root
            privileges could not be dropped.
    """
    os.setsid()
    null = os.open(os.devnull, os.O_RDWR)
    for fd in (0, 1, 2):
        os.dup2(null, fd)
    os.dup2(write_fd, RESULT_FD)
    os.closerange(RESULT_FD + 1, 1 << 16)
    address_space = _current_address_space() + limits.memory_mb * 1024 * 1024
    parent = os.getppid()
    _drop_privileges()
    die_with(parent)  # after the drop: changing user clears the parent-death signal
    _set_limits(limits, address_space)
    if not seccomp.install_filter() and seccomp.supported():
        raise LockdownFailed("the seccomp allow-list could not be installed; the code was not run")


def die_with(parent: int) -> None:
    """SIGKILL this process when its parent ends, so no child outlives its worker (set before seccomp)."""
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0) != 0 or os.getppid() != parent:
        os._exit(1)  # the parent is already gone


def _drop_privileges() -> None:
    if os.geteuid() != 0:
        return
    try:
        os.setgroups([])
        os.setgid(NOBODY_ID)
        os.setuid(NOBODY_ID)
    except OSError as exc:
        raise LockdownFailed(f"could not drop root privileges to user {NOBODY_ID} ({exc})") from None
    if os.geteuid() == 0 or os.getegid() == 0:
        raise LockdownFailed("still root after dropping privileges")


def _set_limits(limits: ChildLimits, address_space: int) -> None:
    cpu_s = max(1, math.ceil(limits.cpu_s))
    resource.setrlimit(resource.RLIMIT_CPU, (cpu_s, cpu_s + 1))
    resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
    resource.setrlimit(resource.RLIMIT_FSIZE, (0, 0))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    resource.setrlimit(resource.RLIMIT_NOFILE, (RESULT_FD + 1, RESULT_FD + 1))
    resource.setrlimit(resource.RLIMIT_NPROC, (0, 0))


def _current_address_space() -> int:
    with open("/proc/self/statm") as statm:
        pages = int(statm.read().split()[0])
    return pages * resource.getpagesize()


def verified_layers(pid: int, proc: Path = Path("/proc")) -> list[str]:
    """The layers the kernel shows for process ``pid`` (alive or a zombie not yet reaped).

    ``unprivileged-user``: no effective capability and a non-root user; ``seccomp-allowlist``: a
    seccomp filter with no-new-privileges; ``rlimits``: a finite CPU-time and address-space limit.
    """
    status = _fields(proc / str(pid) / "status")
    layers = []
    effective_uid = status.get("Uid", "0 0").split()[1]
    if effective_uid != "0" and int(status.get("CapEff", "1"), 16) == 0:
        layers.append("unprivileged-user")
    limits = _read(proc / str(pid) / "limits")
    if _limited(limits, "Max cpu time") and _limited(limits, "Max address space"):
        layers.append("rlimits")
    if status.get("Seccomp") == "2" and status.get("NoNewPrivs") == "1":
        layers.append("seccomp-allowlist")
    return layers


def _fields(path: Path) -> dict[str, str]:
    pairs = (line.split(":", 1) for line in _read(path).splitlines() if ":" in line)
    return {key.strip(): value.strip() for key, value in pairs}


def _limited(limits: str, name: str) -> bool:
    line = next((line for line in limits.splitlines() if line.startswith(name)), "")
    parts = line[len(name) :].split()
    return bool(parts) and parts[0] != "unlimited"


def _read(path: Path) -> str:
    try:
        return path.read_text()
    except OSError:
        return ""

"""The sandbox's outer layer: the worker runs inside bubblewrap with almost nothing of the host.

The worker (and so every child it forks) sees an empty root with only these bound read-only: the
Python installation and its site-packages, trajadapt's own package folder, and the system libraries
the interpreter links against (``/usr/lib``, ``/usr/lib64`` and the loader cache). No ``/etc``,
``/home``, ``/root``, ``/tmp`` or ``/var``; a private ``/proc`` and a minimal ``/dev``. Every
namespace is unshared (network, PID, IPC, UTS, cgroup, mount; the user namespace too when not root),
all capabilities are dropped, and the worker starts a new session so it cannot reach the terminal.

When trajadapt runs as root, the user namespace is *not* unshared: inside one, only root is mapped and
the child could not become anybody else. Instead the worker keeps just CAP_SETUID and CAP_SETGID (to
switch each child to the real unprivileged user ``nobody``, which clears every capability of the
child) and CAP_KILL (to stop a child past its wall-clock limit); its PID namespace holds only its own
children. Either way the code runs without any capability and as a user that owns nothing it can see.
"""

from __future__ import annotations

import os
import site
import sys
from collections.abc import Iterable
from pathlib import Path

SYSTEM_LIBRARIES = ("/usr/lib", "/usr/lib64", "/usr/lib32")
LOADER_CACHE = "/etc/ld.so.cache"
ROOT_LINKS = ("/lib", "/lib64", "/lib32")


def bwrap_command(bwrap: str, worker: list[str], package_root: Path) -> list[str]:
    """The full command that starts ``worker`` inside bubblewrap."""
    return [bwrap, *namespace_args(os.geteuid() == 0), *file_system_args(package_root), "--", *worker]


def namespace_args(as_root: bool) -> list[str]:
    """Unshare every namespace, drop capabilities (as root, keep those to switch to and stop nobody)."""
    common = ["--die-with-parent", "--new-session", "--chdir", "/", "--cap-drop", "ALL"]
    if as_root:
        unshare = ["--unshare-ipc", "--unshare-pid", "--unshare-net", "--unshare-uts", "--unshare-cgroup-try"]
        kept = ["--cap-add", "CAP_SETUID", "--cap-add", "CAP_SETGID", "--cap-add", "CAP_KILL"]
        return [*unshare, *common, *kept]
    return ["--unshare-all", *common]


def file_system_args(package_root: Path) -> list[str]:
    """Read-only binds of the interpreter, its packages, trajadapt and the system libraries; nothing else."""
    args = ["--proc", "/proc", "--dev", "/dev"]
    for path in _python_paths(package_root):
        args += ["--ro-bind", path, path]
    for library in SYSTEM_LIBRARIES:
        args += ["--ro-bind-try", library, library]
    args += ["--ro-bind-try", LOADER_CACHE, LOADER_CACHE]
    for link in ROOT_LINKS:  # merged-/usr systems: /lib -> usr/lib
        if os.path.islink(link):
            args += ["--symlink", os.readlink(link), link]
        elif os.path.isdir(link):
            args += ["--ro-bind", link, link]
    return args


def _python_paths(package_root: Path) -> list[str]:
    """The interpreter's installation, the environment's site-packages and trajadapt's package folder."""
    candidates = [
        sys.base_prefix,
        sys.prefix,
        str(Path(sys.executable).resolve().parent),
        str(package_root),
        *site.getsitepackages(),
    ]
    return _outermost(os.path.realpath(path) for path in candidates if os.path.isdir(path))


def _outermost(paths: Iterable[str]) -> list[str]:
    """Drop every path that lies inside another one of the list (one bind covers it)."""
    unique = sorted(set(paths))
    kept: list[str] = []
    for path in unique:
        if not any(path == parent or path.startswith(parent.rstrip("/") + "/") for parent in kept):
            kept.append(path)
    return kept

"""Result files: written whole or not at all."""

from __future__ import annotations

import ctypes
import errno
import json
import os
import tempfile
from pathlib import Path
from typing import Any

from trajadapt.errors import InputError

AT_FDCWD, AT_EMPTY_PATH = -100, 0x1000  # linux/fcntl.h


def sibling_file(result_file: Path, suffix: str) -> Path:
    """A file next to a result, named after it: ``case.result.json`` + ``.arm.png`` -> ``case.arm.png``."""
    stem = result_file.name.removesuffix(".json").removesuffix(".result")
    return result_file.with_name(stem + suffix)


def write_json_atomic(path: Path, data: Any) -> None:
    """Write ``data`` as JSON to ``path`` through a temporary file, so no half-written file remains.

    Raises:
        InputError: the folder does not exist or cannot be written.
    """
    write_bytes_atomic(path, (json.dumps(data, indent=2) + "\n").encode("utf-8"))


def write_bytes_atomic(path: Path, payload: bytes) -> None:
    """Write ``payload`` to ``path`` through a temporary file in the same folder, then rename."""
    folder = path.parent if str(path.parent) else Path(".")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=folder)
        try:
            with os.fdopen(handle, "wb") as stream:
                stream.write(payload)
            os.replace(temporary, path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
    except OSError as exc:
        raise InputError(f"{path}: cannot be written ({exc})") from exc


def publish_bytes(path: Path, payload: bytes, replace: bool = False) -> None:
    """Create ``path`` with ``payload``, whole or not at all; an existing file only with ``replace``.

    Without ``replace`` the file is created exclusively: of several writers of one new name, one
    succeeds and the others are told it exists. The bytes go to an anonymous file in the target
    folder first (``O_TMPFILE``, where the system has it), linked in under its name only when
    complete, so a writer killed half-way leaves nothing behind.

    Raises:
        InputError: the file exists (without ``replace``), or the folder is missing or not writable.
    """
    if replace:
        if not path.parent.is_dir():
            raise InputError(f"{path}: the folder {path.parent} does not exist")
        write_bytes_atomic(path, payload)
        return
    try:
        _link_new(path, payload)
    except FileExistsError as exc:
        raise InputError(f"{path} exists already; choose another name, or --force to replace it") from exc
    except OSError as exc:
        raise InputError(f"{path}: cannot be written ({exc.strerror or exc})") from exc


def _link_new(path: Path, payload: bytes) -> None:
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise FileNotFoundError(2, f"the folder {folder} does not exist")
    try:
        handle = os.open(folder, os.O_TMPFILE | os.O_WRONLY, 0o644)
    except (AttributeError, OSError):
        _link_named(folder, path, payload)
        return
    try:
        _write_all(handle, payload)
        if not _link_anonymous(handle, path):
            _link_named(folder, path, payload)
    finally:
        os.close(handle)


def _link_anonymous(handle: int, path: Path) -> bool:
    """Give the anonymous file ``handle`` the name ``path``; False where this system allows neither way.

    Through its /proc link (any user), else ``linkat(AT_EMPTY_PATH)`` (needs CAP_DAC_READ_SEARCH;
    some sandboxes' /proc links cross a mount and fail with EXDEV).

    Raises:
        FileExistsError: ``path`` exists.
    """
    try:
        os.link(f"/proc/self/fd/{handle}", path, follow_symlinks=True)
        return True
    except FileExistsError:
        raise
    except OSError:
        pass
    libc = ctypes.CDLL(None, use_errno=True)
    if libc.linkat(handle, b"", AT_FDCWD, os.fsencode(path), AT_EMPTY_PATH) == 0:
        return True
    error = ctypes.get_errno()
    if error == errno.EEXIST:
        raise FileExistsError(error, os.strerror(error), str(path))
    return False


def _link_named(folder: Path, path: Path, payload: bytes) -> None:
    """The fallback: a named temporary file in the folder, then a hard link (a kill can leave it)."""
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=folder)
    try:
        try:
            _write_all(handle, payload)
        finally:
            os.close(handle)
        os.link(temporary, path)
    finally:
        Path(temporary).unlink(missing_ok=True)


def _write_all(handle: int, payload: bytes) -> None:
    view = memoryview(payload)
    while view:
        view = view[os.write(handle, view) :]
    os.fsync(handle)

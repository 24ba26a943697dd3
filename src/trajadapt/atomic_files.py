"""Result files: written whole or not at all."""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any

from trajadapt.errors import InputError


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

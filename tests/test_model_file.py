"""Model assembly and verification, on small synthetic GGUF-like files (the real model is not needed)."""

from __future__ import annotations

import hashlib
import struct
from pathlib import Path

import pytest

from trajadapt.errors import ModelFileError
from trajadapt.llm.model_file import (
    ModelSpec,
    assemble_model,
    check_gguf_header,
    ensure_model,
    read_gguf_metadata,
)


def gguf_bytes(architecture: str = "qwen2", name: str = "Tiny Test Model", padding: int = 5000) -> bytes:
    def string(text: str) -> bytes:
        data = text.encode()
        return struct.pack("<Q", len(data)) + data

    entries = [
        string("general.architecture") + struct.pack("<I", 8) + string(architecture),
        string("general.alignment") + struct.pack("<I", 4) + struct.pack("<I", 32),
        string("general.tags") + struct.pack("<I", 9) + struct.pack("<IQ", 8, 2) + string("a") + string("b"),
        string("general.name") + struct.pack("<I", 8) + string(name),
    ]
    header = b"GGUF" + struct.pack("<IQQ", 3, 0, len(entries)) + b"".join(entries)
    return header + bytes(range(256)) * (padding // 256)


def split_into_parts(data: bytes, folder: Path, count: int = 3) -> list[Path]:
    size = -(-len(data) // count)
    parts = []
    for index in range(count):
        path = folder / f"part{index + 1:02d}.bin"
        path.write_bytes(data[index * size : (index + 1) * size])
        parts.append(path)
    return parts


@pytest.fixture
def model_data() -> bytes:
    return gguf_bytes()


@pytest.fixture
def spec(model_data: bytes) -> ModelSpec:
    return ModelSpec(
        sha256=hashlib.sha256(model_data).hexdigest(), architecture="qwen2", name="Tiny Test Model"
    )


def test_assembles_verifies_and_reports_progress(tmp_path: Path, model_data: bytes, spec: ModelSpec) -> None:
    parts = split_into_parts(model_data, tmp_path)
    destination = tmp_path / "cache" / "model.gguf"
    seen: list[tuple[int, int]] = []
    assemble_model(parts, destination, spec, lambda done, total: seen.append((done, total)))
    assert destination.read_bytes() == model_data
    assert seen[-1] == (len(model_data), len(model_data))
    assert not destination.with_name("model.gguf.partial").exists()


def test_corrupted_part_is_refused_and_nothing_is_left(
    tmp_path: Path, model_data: bytes, spec: ModelSpec
) -> None:
    parts = split_into_parts(model_data, tmp_path)
    damaged = bytearray(parts[1].read_bytes())
    damaged[10] ^= 0xFF
    parts[1].write_bytes(bytes(damaged))
    destination = tmp_path / "cache" / "model.gguf"
    with pytest.raises(ModelFileError, match="SHA-256 .* not the pinned .*Reinstall the parts"):
        assemble_model(parts, destination, spec)
    assert list(destination.parent.iterdir()) == []


def test_missing_part_file(tmp_path: Path, model_data: bytes, spec: ModelSpec) -> None:
    parts = split_into_parts(model_data, tmp_path)
    parts[2].unlink()
    with pytest.raises(ModelFileError, match="cannot be read"):
        assemble_model(parts, tmp_path / "cache" / "model.gguf", spec)


def test_wrong_header_with_matching_hash_is_refused(tmp_path: Path) -> None:
    data = gguf_bytes(name="Some Other Model")
    spec = ModelSpec(sha256=hashlib.sha256(data).hexdigest(), architecture="qwen2", name="Tiny Test Model")
    with pytest.raises(ModelFileError, match="general.name is 'Some Other Model'"):
        assemble_model(split_into_parts(data, tmp_path), tmp_path / "cache" / "m.gguf", spec)


def test_header_reader(tmp_path: Path) -> None:
    path = tmp_path / "m.gguf"
    path.write_bytes(gguf_bytes())
    metadata = read_gguf_metadata(path, ("general.architecture", "general.name", "general.tags"))
    assert metadata == {
        "general.architecture": "qwen2",
        "general.name": "Tiny Test Model",
        "general.tags": ["a", "b"],
    }
    (tmp_path / "not.gguf").write_bytes(b"PK\x03\x04rest")
    with pytest.raises(ModelFileError, match="not a GGUF file"):
        check_gguf_header(tmp_path / "not.gguf", ModelSpec())
    (tmp_path / "cut.gguf").write_bytes(gguf_bytes()[:30])
    with pytest.raises(ModelFileError, match="header cannot be read"):
        check_gguf_header(tmp_path / "cut.gguf", ModelSpec())


def test_missing_part_package_names_the_extra(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import trajadapt.llm.model_file as model_file

    monkeypatch.setattr(model_file, "PART_COUNT", 1)
    monkeypatch.setattr(
        model_file.resources, "files", lambda name: (_ for _ in ()).throw(ModuleNotFoundError(name))
    )
    with pytest.raises(ModelFileError, match=r'model part 1 is missing .*pip install "trajadapt\[local\]"'):
        ensure_model(tmp_path)


def test_verified_model_is_not_rebuilt(
    tmp_path: Path, model_data: bytes, spec: ModelSpec, monkeypatch: pytest.MonkeyPatch
) -> None:
    import trajadapt.llm.model_file as model_file

    parts = split_into_parts(model_data, tmp_path)
    monkeypatch.setattr(model_file, "installed_part_paths", lambda: parts)
    path = ensure_model(tmp_path / "cache", spec=spec)
    stamp = path.stat().st_mtime_ns
    assert ensure_model(tmp_path / "cache", spec=spec) == path and path.stat().st_mtime_ns == stamp
    path.write_bytes(model_data[:-1] + b"\x00")  # changed on disk: verified again, and rebuilt
    assert ensure_model(tmp_path / "cache", spec=spec).read_bytes() == model_data

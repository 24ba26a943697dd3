"""Recordings as an attacker leaves them: mutated, truncated, lying. Each is read or refused in words."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from trajadapt.errors import InputError
from trajadapt.files.recording_limits import MAX_DECOMPRESSED_BYTES, MCAP_MAGIC, check_declared_sizes
from trajadapt.files.rosbag_io import read_bag_trajectory, write_paths
from trajadapt.model.trajectory import Trajectory

pytest.importorskip("rosbags")

ROWS = np.column_stack([np.linspace(0, 1, 30), np.zeros(30), np.zeros(30), np.ones(30)])


def recording(folder: Path, fmt: str) -> bytes:
    path = folder / f"good.{fmt}"
    if not path.exists():
        write_paths(path, fmt, {"/plan": Trajectory(ROWS), "/other": Trajectory(ROWS)})
    return path.read_bytes()


def read_or_refuse(path: Path) -> None:
    try:
        read_bag_trajectory(path, "/plan")
    except InputError:
        pass  # refused in words: fine; any other exception fails the test


@pytest.mark.parametrize("fmt", ["mcap", "bag"])
@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_mutated_recordings_are_read_or_refused_in_words(tmp_path_factory, fmt, data):
    folder = tmp_path_factory.mktemp("fuzz")
    good = bytearray(recording(folder, fmt))
    for _ in range(data.draw(st.integers(1, 8))):
        at = data.draw(st.integers(0, len(good) - 1))
        good[at] = data.draw(st.integers(0, 255))
    cut = data.draw(st.integers(0, len(good)))
    mutated = folder / f"mutated.{fmt}"
    mutated.write_bytes(bytes(good[: cut if data.draw(st.booleans()) else len(good)]))
    read_or_refuse(mutated)


@pytest.mark.parametrize("fmt", ["mcap", "bag"])
def test_truncated_at_every_tenth_byte_is_read_or_refused(tmp_path, fmt):
    good = recording(tmp_path, fmt)
    for cut in range(0, len(good), max(1, len(good) // 60)):
        path = tmp_path / f"cut{cut}.{fmt}"
        path.write_bytes(good[:cut])
        read_or_refuse(path)


def test_a_file_that_is_only_the_mcap_magic_is_refused(tmp_path):
    path = tmp_path / "magic.mcap"
    path.write_bytes(MCAP_MAGIC)
    with pytest.raises(InputError):
        read_bag_trajectory(path, "/plan")


def test_a_chunk_declaring_a_gigabyte_is_refused_before_it_is_decompressed(tmp_path):
    body = struct.pack("<QQQI", 0, 0, 1 << 30, 0) + struct.pack("<I", 4) + b"zstd" + struct.pack("<Q", 0)
    path = tmp_path / "bomb.mcap"
    path.write_bytes(MCAP_MAGIC + struct.pack("<BQ", 0x06, len(body)) + body + MCAP_MAGIC)
    with pytest.raises(InputError, match="decompress"):
        check_declared_sizes(path)
    assert (1 << 30) > MAX_DECOMPRESSED_BYTES


def test_a_good_recording_still_reads(tmp_path):
    path = tmp_path / "good.mcap"
    recording(tmp_path, "mcap")
    read = read_bag_trajectory(path, "/plan")
    assert len(read.trajectory) == 30


@pytest.mark.parametrize("fmt", ["mcap", "bag"])
def test_a_message_too_large_to_hold_is_refused_before_it_is_deserialized(tmp_path, fmt, monkeypatch):
    """A small compressed file can hold one huge plan: its size is checked on the raw bytes."""
    import rosbags.highlevel

    path = tmp_path / f"big.{fmt}"
    s = np.linspace(0.0, 1.0, 2000)
    write_paths(
        path, fmt, {"/plan": Trajectory.from_rows(np.column_stack([s, s, s, s + 1]).tolist(), "rows")}
    )
    monkeypatch.setattr("trajadapt.files.rosbag_io.MAX_MESSAGE_BYTES", 20_000)
    deserialized: list[str] = []
    original = rosbags.highlevel.AnyReader.deserialize
    monkeypatch.setattr(
        rosbags.highlevel.AnyReader,
        "deserialize",
        lambda self, raw, msgtype: deserialized.append(msgtype) or original(self, raw, msgtype),
    )
    with pytest.raises(InputError, match=r"nav_msgs/msg/Path message of 0\.[12] MB is more than the 0\.0 MB"):
        read_bag_trajectory(path, "/plan")
    assert deserialized == []

"""Bounds on a recording, read from its own headers before anything is decompressed.

A 13.7 KB MCAP file can hold a chunk that decompresses to a gigabyte: ``rosbags`` would decompress it
whole before the first message. MCAP chunks and ROS 1 bag chunks both state their uncompressed size
in their header, so the file's records are walked once (headers only, nothing decompressed) and a
recording whose chunks declare more than ``MAX_DECOMPRESSED_BYTES`` together is refused. What the
walk cannot read (a truncated or odd file) is left to the reader, whose errors are mapped at its edge.
"""

from __future__ import annotations

import struct
from pathlib import Path
from typing import BinaryIO

from trajadapt.errors import InputError

MAX_DECOMPRESSED_BYTES = 64 * 1024 * 1024
MAX_RECORDING_BYTES = 512 * 1024 * 1024
MCAP_MAGIC = b"\x89MCAP0\r\n"
BAG_MAGIC = b"#ROSBAG V2.0\n"
MCAP_CHUNK, MCAP_FOOTER = 0x06, 0x02
BAG_CHUNK = 0x05


def check_declared_sizes(path: Path) -> None:
    """Refuse a recording over ``MAX_RECORDING_BYTES``, or whose chunks declare too much data.

    Raises:
        InputError: the file is too large, or what its chunks would decompress to is.
    """
    if path.is_dir():  # a ROS 2 bag folder: each of its MCAP files
        for member in sorted(path.glob("*.mcap")):
            check_declared_sizes(member)
        return
    if not path.is_file():
        return
    size = path.stat().st_size
    if size > MAX_RECORDING_BYTES:
        raise InputError(
            f"{path}: {size / 1e6:.0f} MB is more than the {MAX_RECORDING_BYTES / 1e6:.0f} MB read"
        )
    try:
        with path.open("rb") as stream:
            head = stream.read(len(BAG_MAGIC))
            stream.seek(0)
            if head.startswith(MCAP_MAGIC):
                declared = _mcap_declared(stream)
            elif head == BAG_MAGIC:
                declared = _bag_declared(stream)
            else:
                return
    except (OSError, ValueError, struct.error, OverflowError) as exc:
        raise InputError(f"{path}: cannot be read as a ROS recording ({type(exc).__name__}: {exc})") from exc
    if declared > MAX_DECOMPRESSED_BYTES:
        raise InputError(
            f"{path}: its chunks would decompress to {declared / 1e6:.0f} MB; at most "
            f"{MAX_DECOMPRESSED_BYTES / 1e6:.0f} MB are read (cut the recording to the topic you need)"
        )


def _mcap_declared(stream: BinaryIO) -> int:
    """The uncompressed sizes the chunks of an MCAP file declare, summed."""
    stream.seek(len(MCAP_MAGIC))
    total = 0
    while (header := stream.read(9)) and len(header) == 9:
        opcode, length = struct.unpack("<BQ", header)
        if opcode == MCAP_FOOTER:
            break
        if opcode == MCAP_CHUNK and length >= 24:
            fixed = stream.read(24)
            if len(fixed) < 24:
                break  # truncated: the reader will say so
            total += struct.unpack("<Q", fixed[16:24])[0]
            length -= 24
        stream.seek(length, 1)
    return total


def _bag_declared(stream: BinaryIO) -> int:
    """The uncompressed sizes the chunks of a ROS 1 bag declare, summed."""
    stream.seek(len(BAG_MAGIC))
    total = 0
    while (prefix := stream.read(4)) and len(prefix) == 4:
        header = stream.read(struct.unpack("<I", prefix)[0])
        fields = _bag_fields(header)
        if fields.get("op") == bytes([BAG_CHUNK]) and len(fields.get("size", b"")) == 4:
            total += struct.unpack("<I", fields["size"])[0]
        data_length = stream.read(4)
        if len(data_length) < 4:
            break
        stream.seek(struct.unpack("<I", data_length)[0], 1)
    return total


def _bag_fields(header: bytes) -> dict[str, bytes]:
    fields, position = {}, 0
    while position + 4 <= len(header):
        (length,) = struct.unpack("<I", header[position : position + 4])
        name, _, value = header[position + 4 : position + 4 + length].partition(b"=")
        fields[name.decode("latin-1")] = value
        position += 4 + length
    return fields

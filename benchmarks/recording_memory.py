"""Peak memory and time to read a 1 MB ROS recording, each kind in a fresh process.

Writes recordings of about ``--megabytes`` MB with rosbags (a nav_msgs/Path with that many poses, a
PoseStamped stream, a MultiDOFJointTrajectory; each as MCAP and as a ROS 1 bag), then reads each one
with ``read_bag_trajectory`` in a new interpreter and reports its peak resident memory (VmHWM)
beside that of an interpreter that only imports the reader.

Run: .venv/bin/python benchmarks/recording_memory.py [--megabytes 1]
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from trajadapt.files.rosbag_io import MULTIDOF_TYPE, PATH_TYPE, POSE_TYPE, WRITERS, write_paths
from trajadapt.model.trajectory import Trajectory

READ = """
import json, sys, time
from trajadapt.errors import InputError
from pathlib import Path
from trajadapt.files.rosbag_io import read_bag_trajectory
start = time.perf_counter()
count = 0
if sys.argv[1] != "-":
    try:
        count = len(read_bag_trajectory(Path(sys.argv[1]), sys.argv[2]).trajectory)
    except InputError as exc:
        count = "refused: " + str(exc).split(": ", 1)[-1][:70]
# VmHWM, not ru_maxrss: the latter keeps the forking parent's peak across exec
peak_kb = next(int(line.split()[1]) for line in open("/proc/self/status") if line.startswith("VmHWM:"))
print(json.dumps({"waypoints": count, "seconds": time.perf_counter() - start, "peak_mb": peak_kb / 1024}))
"""

BYTES_PER_POSE = {PATH_TYPE: 64, MULTIDOF_TYPE: 120}


def rows(count: int) -> np.ndarray:
    """A smooth test path of ``count`` waypoints."""
    s = np.linspace(0.0, 10.0, count)
    return np.column_stack([s, np.sin(s), 0.1 * s, 0.5 + 0.1 * np.cos(s)])


def write_stream(folder: Path, count: int, fmt: str) -> Path:
    """``count`` PoseStamped messages on /pose (the one kind ``write_paths`` does not write)."""
    from rosbags.rosbag1 import Writer as Writer1
    from rosbags.rosbag2 import StoragePlugin
    from rosbags.rosbag2 import Writer as Writer2
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC if fmt == "bag" else Stores.ROS2_HUMBLE)
    types = store.types
    serialize = store.serialize_ros1 if fmt == "bag" else store.serialize_cdr
    target = folder / f"stream.{fmt}" if fmt == "bag" else folder / "stream"
    writer = (
        Writer1(target) if fmt == "bag" else Writer2(target, version=9, storage_plugin=StoragePlugin.MCAP)
    )
    with writer:
        kwargs = {"typestore": store}
        connection = writer.add_connection("/pose", POSE_TYPE, **kwargs)
        for k, row in enumerate(rows(count)):
            ns = (k + 1) * 10_000_000
            header = types["std_msgs/msg/Header"](
                **({"seq": 0} if fmt == "bag" else {}),
                stamp=types["builtin_interfaces/msg/Time"](sec=ns // 10**9, nanosec=ns % 10**9),
                frame_id="map",
            )
            point = types["geometry_msgs/msg/Point"](x=row[0], y=row[1], z=row[2])
            quaternion = types["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
            pose = types["geometry_msgs/msg/Pose"](position=point, orientation=quaternion)
            message = types[POSE_TYPE](header=header, pose=pose)
            writer.write(connection, ns, serialize(message, POSE_TYPE))
    return target if fmt == "bag" else next(target.glob("*.mcap"))


def write_compressed_plan(folder: Path, poses: int) -> Path:
    """One Path of ``poses`` poses in one zstd chunk: a small file that decompresses to a large message."""
    from mcap.writer import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    message = WRITERS[PATH_TYPE](store.types, rows(poses), "map", 0, False)
    data = store.serialize_cdr(message, PATH_TYPE)
    target = folder / f"compressed-{poses}.mcap"
    with target.open("wb") as stream:
        writer = Writer(stream, chunk_size=len(data) + 1024)
        writer.start("ros2", "bench")
        schema = writer.register_schema(
            PATH_TYPE, "ros2msg", store.generate_msgdef(PATH_TYPE, ros_version=2)[0].encode()
        )
        channel = writer.register_channel("/plan", "cdr", schema)
        writer.add_message(channel, 0, bytes(data), 0)
        writer.finish()
    return target


def measure(path: str, topic: str) -> dict[str, Any]:
    """Read one recording in a fresh interpreter: waypoints (or the error), seconds, peak MB."""
    done = subprocess.run([sys.executable, "-c", READ, path, topic], capture_output=True, text=True)
    if done.returncode:
        return {
            "waypoints": done.stderr.strip().splitlines()[-1][-90:],
            "seconds": float("nan"),
            "peak_mb": float("nan"),
        }
    return json.loads(done.stdout)


def main() -> None:
    """Write the recordings and print one table row per reading."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--megabytes", type=float, default=1.0)
    args = parser.parse_args()
    base = measure("-", "-")
    print(f"interpreter with the reader imported: {base['peak_mb']:.0f} MB")
    print("| recording | size | waypoints | read (s) | peak RSS (MB) |\n|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        recordings: list[tuple[str, Path, str]] = []
        for fmt in ("mcap", "bag"):
            for msgtype, per_pose in BYTES_PER_POSE.items():
                count = int(args.megabytes * 1e6 / per_pose)
                target = folder / f"{msgtype.split('/')[-1]}.{fmt}"
                write_paths(target, fmt, {"/plan": Trajectory.from_rows(rows(count).tolist(), "rows")},
                            msgtype=msgtype)  # fmt: skip
                recordings.append((f"{msgtype} ({fmt})", target, "/plan"))
            recordings.append(
                (
                    f"{POSE_TYPE} stream ({fmt})",
                    write_stream(folder, int(args.megabytes * 1e6 / 110), fmt),
                    "/pose",
                )
            )
        for poses in (90_000, 200_000, 800_000):
            path = write_compressed_plan(folder, poses)
            recordings.append((f"{PATH_TYPE}, {poses} poses in one zstd chunk", path, "/plan"))
        for label, path, topic in recordings:
            got = measure(str(path), topic)
            size = path.stat().st_size / 1e6
            print(
                f"| {label} | {size:.2f} MB | {got['waypoints']} | {got['seconds']:.2f} | {got['peak_mb']:.0f} |"
            )


if __name__ == "__main__":
    main()

"""Trajectories in ROS recordings: read them from bags and MCAP files, write results back as nav_msgs/Path.

Reading (pure Python, ``rosbags``; no ROS install) takes one topic of a ROS 1 ``.bag``, a ROS 2
bag folder, a ``.db3`` or an ``.mcap`` file:

- ``nav_msgs/Path``: the last message on the topic (the latest plan), one waypoint per pose;
- ``geometry_msgs/PoseStamped``: the stream of poses, resampled to ``waypoints`` along the path;
- ``trajectory_msgs/MultiDOFJointTrajectory``: the last message, the first transform of each point.

Speeds come from the timestamps (header stamps, ``time_from_start``, else the recording's own
times): the speed at a waypoint is the length of the step that leaves it over that step's duration
(the last waypoint keeps the speed of the step before it). A Path whose poses carry no times gets
speed 1.0 everywhere, and the loader says so. Positions are taken as they are, in the message's
frame; ``--axes`` states how that frame's x reads (left or right).

Writing puts the adapted and the original trajectory on two topics, each as one message whose times
are those to reach each waypoint at its speed, so they play next to a recording in Foxglove or RViz:

- ``nav_msgs/Path`` (the default): the times are the poses' stamps;
- ``trajectory_msgs/MultiDOFJointTrajectory``, for a controller that follows timed points: one
  transform per point, ``time_from_start`` from the speeds and the velocity along the path (the
  speed in the direction of the step that leaves the waypoint).
"""

from __future__ import annotations

import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from trajadapt.errors import DependencyNotInstalled, InputError, TrajadaptError
from trajadapt.files.atomic_files import publish_bytes
from trajadapt.files.recording_limits import check_declared_sizes
from trajadapt.model.trajectory import MAX_WAYPOINTS, Trajectory

Array = npt.NDArray[np.float64]
BAG_SUFFIXES = (".bag", ".mcap", ".db3")
PATH_TYPE = "nav_msgs/msg/Path"
POSE_TYPE = "geometry_msgs/msg/PoseStamped"
MULTIDOF_TYPE = "trajectory_msgs/msg/MultiDOFJointTrajectory"
MULTIDOF_JOINT = "base"  # the one joint of a MultiDOF export: the robot's base or tool frame
NOMINAL_SPEED = 1.0
DEFAULT_WAYPOINTS = 50


@dataclass(frozen=True)
class BagTrajectory:
    """A trajectory read from a recording, with where it came from and what the reader assumed."""

    trajectory: Trajectory
    topic: str
    msgtype: str
    frame: str
    notes: tuple[str, ...] = ()


def is_bag(path: Path) -> bool:
    """Whether ``path`` is a ROS recording: a .bag/.mcap/.db3 file or a ROS 2 bag folder."""
    return path.suffix.lower() in BAG_SUFFIXES or (path.is_dir() and (path / "metadata.yaml").is_file())


def _rosbags() -> Any:
    try:
        import rosbags.highlevel
    except ImportError as exc:
        raise DependencyNotInstalled(
            "reading and writing ROS bags needs rosbags: pip install 'trajadapt[ros]'"
        ) from exc
    return rosbags.highlevel


def read_bag_trajectory(path: Path, topic: str | None, waypoints: int | None = None) -> BagTrajectory:
    """The trajectory on ``topic`` of the recording at ``path``.

    Raises:
        InputError: no topic given, the topic is missing, of a type that holds no trajectory, or
            empty; the message lists the recording's topics and types.
        DependencyNotInstalled: rosbags is not installed.
    """
    highlevel = _rosbags()
    check_declared_sizes(path)
    try:
        with highlevel.AnyReader([path]) as reader:
            topics = {name: info.msgtype for name, info in reader.topics.items()}
            _check_topic(path, topic, topics)
            msgtype = topics[str(topic)]
            messages, count = _messages(reader, [c for c in reader.connections if c.topic == topic], msgtype)
            if not messages:
                raise InputError(f"{path}: topic {topic} has no messages")
            rows, frame, notes = READERS[msgtype](messages, waypoints)
    except TrajadaptError:
        raise
    except Exception as exc:  # noqa: BLE001 - a recording is untrusted input: any failure reading it is one
        problem = f"{type(exc).__name__}: {str(exc)[:300]}"
        raise InputError(f"{path}: cannot be read as a ROS recording ({problem})") from exc
    if count > 1 and msgtype != POSE_TYPE:
        notes = [f"{count} messages on the topic: the last one was read", *notes]
    return BagTrajectory(
        Trajectory.from_rows(rows, f"{path} {topic}"), str(topic), msgtype, frame, tuple(notes)
    )


MAX_MESSAGES = 50_000
"""Messages read from one topic (a PoseStamped stream is resampled to ``DEFAULT_WAYPOINTS`` anyway)."""

MAX_MESSAGE_BYTES = MAX_WAYPOINTS * 128
"""Bytes of the one Path or MultiDOF message that is deserialized: ``MAX_WAYPOINTS`` points of 128
bytes (a stamped pose takes about 72, a MultiDOF point about 124). Checked before deserializing,
which takes some 600 bytes of Python objects for each serialized pose."""


def _messages(reader: Any, connections: list[Any], msgtype: str) -> tuple[list[tuple[int, Any]], int]:
    """The topic's messages as (time, message), and how many there were.

    For a Path or a MultiDOFJointTrajectory only the last one is read, so many large plans cost no
    memory; a PoseStamped stream is read whole, up to ``MAX_MESSAGES``.
    """
    kept: list[tuple[int, Any, bytes]] = []
    count = 0
    for connection, stamp, raw in reader.messages(connections):
        count += 1
        if count > MAX_MESSAGES:
            raise InputError(f"more than {MAX_MESSAGES} messages on the topic; cut the recording first")
        if msgtype == POSE_TYPE or not kept:
            kept.append((stamp, connection, raw))
        else:
            kept[-1] = (stamp, connection, raw)
    largest = max((len(raw) for _, _, raw in kept), default=0)
    if largest > MAX_MESSAGE_BYTES:
        raise InputError(
            f"a {msgtype} message of {largest / 1e6:.1f} MB is more than the "
            f"{MAX_MESSAGE_BYTES / 1e6:.1f} MB read (about {MAX_WAYPOINTS} waypoints); resample the "
            "trajectory first"
        )
    return [(stamp, reader.deserialize(raw, c.msgtype)) for stamp, c, raw in kept], count


def _check_topic(path: Path, topic: str | None, topics: dict[str, str]) -> None:
    listing = ", ".join(f"{name} ({kind})" for name, kind in sorted(topics.items())) or "none"
    if not topic:
        raise InputError(f"{path} is a ROS recording: name the topic with --topic; its topics: {listing}")
    if topic not in topics:
        raise InputError(f"{path}: no topic {topic}; its topics: {listing}")
    if topics[topic] not in READERS:
        supported = ", ".join(READERS)
        raise InputError(
            f"{path}: topic {topic} is {topics[topic]}, which holds no trajectory; use a topic of type "
            f"{supported}; its topics: {listing}"
        )


def _seconds(stamp: Any) -> float:
    return float(stamp.sec) + float(stamp.nanosec) * 1e-9


def _position(pose: Any) -> list[float]:
    return [float(pose.position.x), float(pose.position.y), float(pose.position.z)]


def _from_path(messages: list[tuple[int, Any]], _waypoints: int | None) -> tuple[Array, str, list[str]]:
    message = messages[-1][1]
    if not message.poses:
        raise InputError("the last Path message on the topic has no poses")
    positions = np.array([_position(p.pose) for p in message.poses])
    times = np.array([_seconds(p.header.stamp) for p in message.poses])
    notes: list[str] = []
    rows, timed = rows_from_times(positions, times)
    if not timed:
        notes.append(f"the poses carry no increasing times: speed {NOMINAL_SPEED} everywhere")
    return rows, str(message.header.frame_id), notes


def _from_poses(messages: list[tuple[int, Any]], waypoints: int | None) -> tuple[Array, str, list[str]]:
    positions = np.array([_position(m.pose) for _, m in messages])
    stamps = np.array([_seconds(m.header.stamp) for _, m in messages])
    recorded = np.array([stamp * 1e-9 for stamp, _ in messages])
    times = stamps if np.all(np.diff(stamps) > 0) else recorded
    rows, _ = rows_from_times(positions, times)
    count = waypoints or min(DEFAULT_WAYPOINTS, len(rows))
    notes = [f"{len(rows)} poses resampled to {count} waypoints"] if count != len(rows) else []
    return resample_along_path(rows, count), str(messages[-1][1].header.frame_id), notes


def _from_multidof(messages: list[tuple[int, Any]], _waypoints: int | None) -> tuple[Array, str, list[str]]:
    message = messages[-1][1]
    points = [p for p in message.points if p.transforms]
    if not points:
        raise InputError(
            "the last MultiDOFJointTrajectory message on the topic has no points with a transform"
        )
    positions = np.array([[p.transforms[0].translation.x, p.transforms[0].translation.y,
                           p.transforms[0].translation.z] for p in points], dtype=np.float64)  # fmt: skip
    times = np.array([_seconds(p.time_from_start) for p in points])
    rows, timed = rows_from_times(positions, times)
    if all(p.velocities for p in points):
        linear = [p.velocities[0].linear for p in points]
        rows[:, 3] = [float(np.linalg.norm([v.x, v.y, v.z])) for v in linear]
    elif not timed:
        rows[:, 3] = NOMINAL_SPEED
    return rows, str(message.header.frame_id), []


READERS: dict[str, Callable[[list[tuple[int, Any]], int | None], tuple[Array, str, list[str]]]] = {
    PATH_TYPE: _from_path,
    POSE_TYPE: _from_poses,
    MULTIDOF_TYPE: _from_multidof,
}


def rows_from_times(positions: Array, times: Array) -> tuple[Array, bool]:
    """(x, y, z, v) rows, v = leaving step's length / its duration; False if the times do not increase."""
    rows = np.column_stack([positions, np.full(len(positions), NOMINAL_SPEED)])
    if len(positions) < 2 or not np.all(np.diff(times) > 0):
        return rows, False
    steps = np.linalg.norm(np.diff(positions, axis=0), axis=1)
    rows[:-1, 3] = steps / np.diff(times)
    rows[-1, 3] = rows[-2, 3]
    return rows, True


def times_from_speeds(rows: Array) -> Array:
    """Seconds to reach each waypoint, leaving each at its speed (the inverse of ``rows_from_times``).

    A step that leaves a waypoint with speed 0 is taken at the next positive speed (or the mean one);
    a step that does not move (a wait) lasts one typical step.
    """
    steps = np.linalg.norm(np.diff(rows[:, :3], axis=0), axis=1)
    positive = rows[:, 3][rows[:, 3] > 0]
    fallback = float(positive.mean()) if positive.size else NOMINAL_SPEED
    speeds = rows[:-1, 3].copy()
    for k in range(len(speeds) - 1, -1, -1):
        if speeds[k] <= 0:
            speeds[k] = speeds[k + 1] if k + 1 < len(speeds) and speeds[k + 1] > 0 else fallback
    durations = np.where(steps > 0, steps / speeds, 0.0)
    typical = float(np.median(durations[durations > 0])) if np.any(durations > 0) else 1.0
    durations[durations == 0] = typical
    return np.concatenate([[0.0], np.cumsum(durations)])


def resample_along_path(rows: Array, count: int) -> Array:
    """``count`` rows evenly spaced along the path (positions and speeds interpolated)."""
    steps = np.linalg.norm(np.diff(rows[:, :3], axis=0), axis=1)
    s = np.concatenate([[0.0], np.cumsum(steps)])
    if s[-1] <= 0 or count == len(rows):
        return rows if count == len(rows) else rows[np.linspace(0, len(rows) - 1, count).round().astype(int)]
    target = np.linspace(0.0, s[-1], count)
    return np.column_stack([np.interp(target, s, rows[:, k]) for k in range(4)])


def write_paths(
    out: Path,
    fmt: str,
    paths: dict[str, Trajectory],
    frame: str = "map",
    start_ns: int = 0,
    replace: bool = False,
    msgtype: str = PATH_TYPE,
) -> None:
    """Write each trajectory as one message on its topic to ``out`` (``mcap`` or ``bag``).

    ``msgtype`` is ``PATH_TYPE`` or ``MULTIDOF_TYPE`` (see the module's docstring).

    Staged in the system's temporary folder, then published whole (``atomic_files.publish_bytes``):
    on any error, or a kill, nothing is left at ``out`` or beside it.

    Raises:
        InputError: ``out`` exists (without ``replace``), its folder is missing, or an unknown format
            or message type.
        DependencyNotInstalled: rosbags is not installed.
    """
    _rosbags()
    if fmt not in ("mcap", "bag"):
        raise InputError(f"unknown bag format {fmt!r}; use mcap or bag")
    if msgtype not in WRITERS:
        raise InputError(f"cannot write {msgtype!r}; use one of {', '.join(WRITERS)}")
    with tempfile.TemporaryDirectory(prefix="trajadapt-export-") as scratch:
        staged = Path(scratch) / "bag"
        if fmt == "mcap":
            _write_ros2(staged, paths, frame, start_ns, msgtype)
            written = next(staged.glob("*.mcap"))
        else:
            written = staged.with_suffix(".bag")
            _write_ros1(written, paths, frame, start_ns, msgtype)
        publish_bytes(out, written.read_bytes(), replace)


def _split_time(types: Any, kind: str, nanoseconds: int) -> Any:
    """A ``builtin_interfaces`` Time or Duration of ``nanoseconds``."""
    return types[f"builtin_interfaces/msg/{kind}"](sec=nanoseconds // 10**9, nanosec=nanoseconds % 10**9)


def _header(types: Any, frame: str, start_ns: int, seconds: float, ros1: bool) -> Any:
    stamp = _split_time(types, "Time", start_ns + round(seconds * 1e9))
    return types["std_msgs/msg/Header"](**({"seq": 0} if ros1 else {}), stamp=stamp, frame_id=frame)


def _path_message(types: Any, rows: Array, frame: str, start_ns: int, ros1: bool) -> Any:
    times = times_from_speeds(rows)

    def pose(row: Array) -> Any:
        point = types["geometry_msgs/msg/Point"](x=float(row[0]), y=float(row[1]), z=float(row[2]))
        orientation = types["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
        return types["geometry_msgs/msg/Pose"](position=point, orientation=orientation)

    poses = [
        types[POSE_TYPE](header=_header(types, frame, start_ns, t, ros1), pose=pose(row))
        for t, row in zip(times, rows, strict=True)
    ]
    return types[PATH_TYPE](header=_header(types, frame, start_ns, 0.0, ros1), poses=poses)


def _multidof_message(types: Any, rows: Array, frame: str, start_ns: int, ros1: bool) -> Any:
    times = times_from_speeds(rows)
    velocities = rows[:, 3:4] * path_directions(rows[:, :3])

    def vector(xyz: Array) -> Any:
        return types["geometry_msgs/msg/Vector3"](x=float(xyz[0]), y=float(xyz[1]), z=float(xyz[2]))

    def point(row: Array, velocity: Array, seconds: float) -> Any:
        rotation = types["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
        transform = types["geometry_msgs/msg/Transform"](translation=vector(row[:3]), rotation=rotation)
        twist = types["geometry_msgs/msg/Twist"](linear=vector(velocity), angular=vector(np.zeros(3)))
        duration = _split_time(types, "Duration", round(seconds * 1e9))
        return types["trajectory_msgs/msg/MultiDOFJointTrajectoryPoint"](
            transforms=[transform], velocities=[twist], accelerations=[], time_from_start=duration
        )

    points = [point(*item) for item in zip(rows, velocities, times, strict=True)]
    header = _header(types, frame, start_ns, 0.0, ros1)
    return types[MULTIDOF_TYPE](header=header, joint_names=[MULTIDOF_JOINT], points=points)


def path_directions(positions: Array) -> Array:
    """Unit direction of travel at each waypoint: the step that leaves it (the last: the step before).

    A waypoint whose step does not move takes the direction of the nearest step that does; a path
    that never moves has no direction (zeros).
    """
    steps = np.diff(positions, axis=0)
    lengths = np.linalg.norm(steps, axis=1)
    moving = np.flatnonzero(lengths > 0)
    directions = np.zeros_like(positions)
    if moving.size == 0:
        return directions
    leaving = np.arange(len(positions)).clip(max=len(steps) - 1)
    nearest = moving[np.abs(leaving[:, None] - moving[None, :]).argmin(axis=1)]
    unit: Array = steps[nearest] / lengths[nearest][:, None]
    return unit


WRITERS: dict[str, Callable[[Any, Array, str, int, bool], Any]] = {
    PATH_TYPE: _path_message,
    MULTIDOF_TYPE: _multidof_message,
}


def _write_ros2(folder: Path, paths: dict[str, Trajectory], frame: str, start_ns: int, msgtype: str) -> None:
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    with Writer(folder, version=9, storage_plugin=StoragePlugin.MCAP) as writer:
        for topic, trajectory in paths.items():
            connection = writer.add_connection(topic, msgtype, typestore=store)
            message = WRITERS[msgtype](store.types, trajectory.array, frame, start_ns, False)
            writer.write(connection, start_ns, store.serialize_cdr(message, msgtype))


def _write_ros1(file: Path, paths: dict[str, Trajectory], frame: str, start_ns: int, msgtype: str) -> None:
    from rosbags.rosbag1 import Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS1_NOETIC)
    with Writer(file) as writer:
        for topic, trajectory in paths.items():
            connection = writer.add_connection(topic, msgtype, typestore=store)
            message = WRITERS[msgtype](store.types, trajectory.array, frame, start_ns, True)
            writer.write(connection, start_ns, store.serialize_ros1(message, msgtype))

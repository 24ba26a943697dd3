"""ROS recordings in and out: bags and MCAP written with rosbags itself, read through `adapt`, exported back."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from click.testing import CliRunner

from trajadapt.cli import cli
from trajadapt.errors import InputError
from trajadapt.files.rosbag_io import read_bag_trajectory, rows_from_times, times_from_speeds

rosbags = pytest.importorskip("rosbags")
from rosbags.rosbag1 import Writer as Writer1  # noqa: E402
from rosbags.rosbag2 import StoragePlugin  # noqa: E402
from rosbags.rosbag2 import Writer as Writer2  # noqa: E402
from rosbags.typesys import Stores, get_typestore  # noqa: E402

ROWS = np.column_stack(
    [
        np.linspace(0.0, 1.0, 12),
        np.sin(np.linspace(0.0, 2.0, 12)),
        np.linspace(0.2, 0.5, 12),
        np.linspace(0.5, 1.0, 12),
    ]
)
KEEP = json.dumps({"high_level_plan": "1) Keep it.", "python_code": "modified_trajectory = get_trajectory()"})
LEFT = json.dumps({"high_level_plan": "1) Left.", "python_code": "t = get_trajectory()\nt = shift(t, 'left', 0.2)\nmodified_trajectory = t"})  # fmt: skip


class Recording:
    """Writes one-topic recordings in ROS 2 (.mcap, .db3) and ROS 1 (.bag) with rosbags."""

    def __init__(self, kind: str) -> None:
        self.kind = kind
        self.store = get_typestore(Stores.ROS1_NOETIC if kind == "bag" else Stores.ROS2_HUMBLE)
        self.types = self.store.types

    def stamp(self, seconds: float) -> Any:
        ns = round(seconds * 1e9)
        return self.types["builtin_interfaces/msg/Time"](sec=ns // 10**9, nanosec=ns % 10**9)

    def header(self, seconds: float) -> Any:
        extra = {"seq": 0} if self.kind == "bag" else {}
        return self.types["std_msgs/msg/Header"](**extra, stamp=self.stamp(seconds), frame_id="odom")

    def pose(self, row: np.ndarray, seconds: float) -> Any:
        t = self.types
        point = t["geometry_msgs/msg/Point"](x=float(row[0]), y=float(row[1]), z=float(row[2]))
        quaternion = t["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
        return t["geometry_msgs/msg/PoseStamped"](
            header=self.header(seconds),
            pose=t["geometry_msgs/msg/Pose"](position=point, orientation=quaternion),
        )

    def path_message(self, rows: np.ndarray) -> Any:
        times = times_from_speeds(rows)
        poses = [self.pose(row, time) for row, time in zip(rows, times, strict=True)]
        return self.types["nav_msgs/msg/Path"](header=self.header(0.0), poses=poses)

    def multidof_message(self, rows: np.ndarray) -> Any:
        t = self.types
        times = times_from_speeds(rows)
        points = []
        for row, time in zip(rows, times, strict=True):
            translation = t["geometry_msgs/msg/Vector3"](x=float(row[0]), y=float(row[1]), z=float(row[2]))
            rotation = t["geometry_msgs/msg/Quaternion"](x=0.0, y=0.0, z=0.0, w=1.0)
            ns = round(time * 1e9)
            points.append(t["trajectory_msgs/msg/MultiDOFJointTrajectoryPoint"](
                transforms=[t["geometry_msgs/msg/Transform"](translation=translation, rotation=rotation)],
                velocities=[], accelerations=[],
                time_from_start=t["builtin_interfaces/msg/Duration"](sec=ns // 10**9, nanosec=ns % 10**9),
            ))  # fmt: skip
        return t["trajectory_msgs/msg/MultiDOFJointTrajectory"](
            header=self.header(0.0), joint_names=["base"], points=points
        )

    def write(self, path: Path, topic: str, msgtype: str, messages: list[tuple[float, Any]]) -> Path:
        serialize = self.store.serialize_ros1 if self.kind == "bag" else self.store.serialize_cdr
        if self.kind == "bag":
            path = path.with_suffix(".bag")
            with Writer1(path) as writer:
                connection = writer.add_connection(topic, msgtype, typestore=self.store)
                for seconds, message in messages:
                    writer.write(connection, round(seconds * 1e9) + 1, serialize(message, msgtype))
            return path
        plugin = StoragePlugin.MCAP if self.kind == "mcap" else StoragePlugin.SQLITE3
        with Writer2(path, version=9, storage_plugin=plugin) as writer:
            connection = writer.add_connection(topic, msgtype, typestore=self.store)
            for seconds, message in messages:
                writer.write(connection, round(seconds * 1e9) + 1, serialize(message, msgtype))
        return next(path.glob(f"*.{self.kind}"))


@pytest.fixture(params=["mcap", "bag", "db3"])
def recording(request: pytest.FixtureRequest) -> Recording:
    return Recording(request.param)


def test_a_path_message_round_trips(tmp_path: Path, recording: Recording) -> None:
    bag = recording.write(
        tmp_path / "run", "/plan", "nav_msgs/msg/Path", [(0.0, recording.path_message(ROWS))]
    )
    read = read_bag_trajectory(bag, "/plan")
    assert read.frame == "odom" and read.msgtype == "nav_msgs/msg/Path"
    assert np.allclose(read.trajectory.positions, ROWS[:, :3], atol=1e-6)
    assert np.allclose(times_from_speeds(read.trajectory.array), times_from_speeds(ROWS), atol=1e-6)


def test_a_pose_stream_is_resampled_with_speeds_from_its_stamps(tmp_path: Path, recording: Recording) -> None:
    fine = np.column_stack([np.linspace(0, 2, 200), np.zeros(200), np.zeros(200)])
    times = np.linspace(0, 4, 200)  # 2 units in 4 s: speed 0.5
    messages = [
        (time, recording.pose(np.append(row, 0.0), time)) for row, time in zip(fine, times, strict=True)
    ]
    bag = recording.write(tmp_path / "run", "/pose", "geometry_msgs/msg/PoseStamped", messages)
    read = read_bag_trajectory(bag, "/pose", waypoints=20)
    assert len(read.trajectory) == 20 and np.allclose(read.trajectory.speeds, 0.5)
    assert np.allclose(read.trajectory.positions[[0, -1], 0], [0, 2]) and "200 poses" in read.notes[0]


def test_a_multidof_trajectory_reads_its_first_transforms(tmp_path: Path, recording: Recording) -> None:
    msgtype = "trajectory_msgs/msg/MultiDOFJointTrajectory"
    bag = recording.write(tmp_path / "run", "/drone", msgtype, [(0.0, recording.multidof_message(ROWS))])
    read = read_bag_trajectory(bag, "/drone")
    assert np.allclose(read.trajectory.positions, ROWS[:, :3], atol=1e-6)
    assert np.allclose(read.trajectory.speeds[:-1], ROWS[:-1, 3], rtol=1e-6)


def test_adapt_reads_a_bag_and_export_writes_every_format(tmp_path: Path) -> None:
    recording = Recording("mcap")
    bag = recording.write(
        tmp_path / "run", "/plan", "nav_msgs/msg/Path", [(0.0, recording.path_message(ROWS))]
    )
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([LEFT]))
    out = tmp_path / "run.result.json"
    runner = CliRunner()
    result = runner.invoke(cli, ["adapt", "--trajectory", str(bag), "--topic", "/plan", "-i", "go left", "-b", "scripted",
                                 "-o", "answers", str(answers), "--yes", "--no-log", "--out", str(out)])  # fmt: skip
    assert result.exit_code == 0, result.output
    assert "Read 12 waypoints from /plan (nav_msgs/msg/Path), frame 'odom'" in result.output
    adapted = np.asarray(json.loads(out.read_text())["modified_trajectory"])
    for fmt in ("mcap", "bag", "csv", "json"):
        target = tmp_path / f"exported.{fmt}"
        done = runner.invoke(
            cli, ["export", str(out), "--format", fmt, "--out", str(target), "--frame", "map"]
        )
        assert done.exit_code == 0, done.output
        if fmt in ("mcap", "bag"):
            back = read_bag_trajectory(target, "/adapted_plan")
            assert back.frame == "map" and np.allclose(back.trajectory.positions, adapted[:, :3], atol=1e-6)
            assert np.allclose(
                times_from_speeds(back.trajectory.array), times_from_speeds(adapted), atol=1e-6
            )
            original = read_bag_trajectory(target, "/original_plan").trajectory.positions
            assert np.allclose(original, ROWS[:, :3], atol=1e-6)
        elif fmt == "csv":
            table = np.loadtxt(target, delimiter=",", skiprows=1)
            assert np.allclose(table[:, :4], adapted) and np.allclose(table[:, 4], times_from_speeds(adapted))
        else:
            record = json.loads(target.read_text())
            assert np.allclose(record["trajectory"], adapted) and len(record["time_s"]) == len(adapted)


@pytest.mark.parametrize(
    ("topic", "message"),
    [
        (
            "/absent",
            "no topic /absent; its topics: /chatter (std_msgs/msg/String), /empty (nav_msgs/msg/Path)",
        ),
        ("/chatter", "topic /chatter is std_msgs/msg/String, which holds no trajectory"),
        ("/empty", "topic /empty has no messages"),
        (None, "name the topic with --topic"),
    ],
)
def test_wrong_topic_wrong_type_and_empty_topic_say_so_and_write_nothing(
    tmp_path: Path, topic: str | None, message: str
) -> None:
    recording = Recording("mcap")
    store = recording.store
    with Writer2(tmp_path / "run", version=9, storage_plugin=StoragePlugin.MCAP) as writer:
        chatter = writer.add_connection("/chatter", "std_msgs/msg/String", typestore=store)
        writer.add_connection("/empty", "nav_msgs/msg/Path", typestore=store)
        writer.write(
            chatter,
            1,
            store.serialize_cdr(store.types["std_msgs/msg/String"](data="hi"), "std_msgs/msg/String"),
        )
    bag = next((tmp_path / "run").glob("*.mcap"))
    with pytest.raises(InputError, match=message.replace("(", r"\(").replace(")", r"\)")):
        read_bag_trajectory(bag, topic)
    out = tmp_path / "never.result.json"
    arguments = [
        "adapt",
        "--trajectory",
        str(bag),
        "-i",
        "go left",
        "-b",
        "scripted",
        "--yes",
        "--out",
        str(out),
    ]
    result = CliRunner().invoke(cli, arguments + (["--topic", topic] if topic else []))
    assert result.exit_code != 0 and message.split(";")[0] in result.output and not out.exists()


def test_export_refuses_a_failed_result_and_an_existing_bag(tmp_path: Path) -> None:
    failed = tmp_path / "failed.result.json"
    failed.write_text(
        json.dumps({"original_trajectory": ROWS.tolist(), "modified_trajectory": None, "status": "error"})
    )
    result = CliRunner().invoke(cli, ["export", str(failed), "--out", str(tmp_path / "x.mcap")])
    assert (
        result.exit_code != 0
        and "no adapted trajectory" in result.output
        and not (tmp_path / "x.mcap").exists()
    )
    good = tmp_path / "good.result.json"
    good.write_text(json.dumps({"original_trajectory": ROWS.tolist(), "modified_trajectory": ROWS.tolist()}))
    (tmp_path / "taken.mcap").write_text("mine")
    result = CliRunner().invoke(cli, ["export", str(good), "--out", str(tmp_path / "taken.mcap")])
    assert result.exit_code != 0 and "exists already" in result.output
    assert (tmp_path / "taken.mcap").read_text() == "mine" and sorted(p.name for p in tmp_path.iterdir()) == [
        "failed.result.json", "good.result.json", "taken.mcap"]  # fmt: skip


def test_speeds_and_times_invert_each_other_and_stops_take_time() -> None:
    rows, timed = rows_from_times(ROWS[:, :3], times_from_speeds(ROWS))
    assert timed and np.allclose(rows[:-1, 3], ROWS[:-1, 3])
    stopped = ROWS.copy()
    stopped[4, 3] = 0.0
    times = times_from_speeds(stopped)
    assert np.all(np.diff(times) > 0)

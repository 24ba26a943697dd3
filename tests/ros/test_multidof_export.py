"""Timed trajectories back to the robot: MultiDOFJointTrajectory in MCAP and ROS 1 bags.

Read back three ways: with our own reader (the round trip), with ``rosbags`` (the message's fields)
and with ``mcap`` (the schema a player such as Foxglove decodes it with).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from trajadapt.cli import cli
from trajadapt.files.rosbag_io import MULTIDOF_TYPE, path_directions, read_bag_trajectory, times_from_speeds

pytest.importorskip("rosbags")

ROWS = np.column_stack(
    [
        np.linspace(0.0, 1.0, 15),
        np.cos(np.linspace(0.0, 3.0, 15)),
        np.linspace(0.3, 0.1, 15),
        np.concatenate([np.linspace(0.2, 1.2, 8), np.linspace(1.0, 0.3, 7)]),
    ]
)
ORIGINAL = ROWS * [1.0, 0.5, 1.0, 1.0]


@pytest.fixture
def result_file(tmp_path: Path) -> Path:
    path = tmp_path / "run.result.json"
    path.write_text(
        json.dumps({"original_trajectory": ORIGINAL.tolist(), "modified_trajectory": ROWS.tolist()})
    )
    return path


def export(result_file: Path, fmt: str) -> Path:
    target = result_file.with_name(f"timed.{fmt}")
    arguments = ["export", str(result_file), "--format", fmt, "--message", "multidof", "--out", str(target)]
    done = CliRunner().invoke(cli, arguments)
    assert done.exit_code == 0, done.output
    assert MULTIDOF_TYPE in done.output
    return target


def raw_points(target: Path, fmt: str) -> list:
    """The exported message's points, deserialized by rosbags alone."""
    from rosbags.highlevel import AnyReader

    with AnyReader([target]) as reader:
        connection = next(c for c in reader.connections if c.topic == "/adapted_plan")
        assert connection.msgtype == MULTIDOF_TYPE
        (_, _, raw), *_ = reader.messages(connections=[connection])
        message = reader.deserialize(raw, connection.msgtype)
    assert list(message.joint_names) == ["base"] and message.header.frame_id == "map"
    return list(message.points)


@pytest.mark.parametrize("fmt", ["mcap", "bag"])
def test_times_and_velocities_match_the_speeds(result_file: Path, fmt: str) -> None:
    points = raw_points(export(result_file, fmt), fmt)
    times = np.array([p.time_from_start.sec + p.time_from_start.nanosec * 1e-9 for p in points])
    assert np.allclose(times, times_from_speeds(ROWS), atol=1e-3)  # to 1 ms
    steps = np.linalg.norm(np.diff(ROWS[:, :3], axis=0), axis=1)
    assert np.allclose(np.diff(times), steps / ROWS[:-1, 3], atol=1e-3)
    velocities = np.array([[p.velocities[0].linear.x, p.velocities[0].linear.y, p.velocities[0].linear.z]
                           for p in points])  # fmt: skip
    assert np.allclose(np.linalg.norm(velocities, axis=1), ROWS[:, 3], atol=1e-9)
    leaving = np.diff(ROWS[:, :3], axis=0)
    assert np.all(np.einsum("ij,ij->i", velocities[:-1], leaving) > 0)  # along the path, forwards


@pytest.mark.parametrize("fmt", ["mcap", "bag"])
def test_our_reader_reads_the_export_back(result_file: Path, fmt: str) -> None:
    target = export(result_file, fmt)
    adapted = read_bag_trajectory(target, "/adapted_plan")
    assert adapted.msgtype == MULTIDOF_TYPE and adapted.frame == "map"
    assert np.allclose(adapted.trajectory.array, ROWS, atol=1e-6)
    original = read_bag_trajectory(target, "/original_plan").trajectory.array
    assert np.allclose(original, ORIGINAL, atol=1e-6)


def test_the_mcap_carries_the_schema_a_player_decodes(result_file: Path) -> None:
    from mcap.reader import make_reader

    with export(result_file, "mcap").open("rb") as stream:
        reader = make_reader(stream)
        summary = reader.get_summary()
        assert summary is not None
        schemas = {schema.name: schema for schema in summary.schemas.values()}
        channels = {channel.topic: channel for channel in summary.channels.values()}
        messages = list(reader.iter_messages(topics=["/adapted_plan"]))
    schema = schemas[MULTIDOF_TYPE]
    text = schema.data.decode()
    assert schema.encoding == "ros2msg"
    assert channels["/adapted_plan"].message_encoding == "cdr"
    for field in ("MultiDOFJointTrajectoryPoint[] points", "Duration time_from_start", "Twist[] velocities"):
        assert field in text
    assert len(messages) == 1 and messages[0][0].name == MULTIDOF_TYPE


def test_a_message_type_outside_a_recording_is_refused_in_words(result_file: Path) -> None:
    target = result_file.with_name("timed.csv")
    done = CliRunner().invoke(
        cli, ["export", str(result_file), "--format", "csv", "--message", "multidof", "--out", str(target)]
    )
    assert done.exit_code != 0 and "written in mcap or bag" in done.output and not target.exists()


@settings(max_examples=60, deadline=None)
@given(
    arrays(
        np.float64, st.tuples(st.integers(2, 12), st.just(3)), elements=st.sampled_from([0.0, 0.5, 1.0, -2.0])
    )
)
def test_directions_are_unit_wherever_the_path_moves(positions: np.ndarray) -> None:
    directions = path_directions(positions)
    norms = np.linalg.norm(directions, axis=1)
    moves = np.any(np.linalg.norm(np.diff(positions, axis=0), axis=1) > 0)
    assert np.allclose(norms, 1.0 if moves else 0.0)

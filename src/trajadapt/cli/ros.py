"""``trajadapt export``: a result file's trajectories where they are used (ROS bags, MCAP, CSV, JSON)."""

from __future__ import annotations

import csv
import io
import json
from pathlib import Path

import click

from trajadapt.errors import InputError
from trajadapt.files.atomic_files import publish_bytes
from trajadapt.files.rosbag_io import MULTIDOF_TYPE, PATH_TYPE, times_from_speeds, write_paths
from trajadapt.model.trajectory import Trajectory, read_json_file

FORMATS = ("mcap", "bag", "csv", "json")
MESSAGES = {"path": PATH_TYPE, "multidof": MULTIDOF_TYPE}


@click.command()
@click.argument("result_file", type=click.Path(path_type=Path, dir_okay=False))
@click.option("--format", "fmt", type=click.Choice(FORMATS), default="mcap", show_default=True,
              help="mcap (ROS 2, plays in Foxglove), bag (ROS 1), csv or json (x, y, z, v and the time "
              "of each waypoint).")  # fmt: skip
@click.option("--message", type=click.Choice(list(MESSAGES)), default="path", show_default=True,
              help="In mcap and bag: path (nav_msgs/Path, poses stamped with their times) or multidof "
              "(trajectory_msgs/MultiDOFJointTrajectory: time_from_start and the velocity along the "
              "path at each point, for a controller).")  # fmt: skip
@click.option("--topic", default="/adapted_plan", show_default=True, help="Topic of the adapted path.")
@click.option(
    "--original-topic", default="/original_plan", show_default=True, help="Topic of the original path."
)
@click.option("--frame", default="map", show_default=True, help="frame_id of the paths.")
@click.option("--out", "-o", type=click.Path(path_type=Path), default=None,
              help="Output file (default: RESULT_FILE with the format's suffix). An existing file is "
              "refused unless --force.")  # fmt: skip
@click.option(
    "--force", is_flag=True, help="Replace the output file if it exists (never RESULT_FILE itself)."
)
def export(
    result_file: Path,
    fmt: str,
    message: str,
    topic: str,
    original_topic: str,
    frame: str,
    out: Path | None,
    force: bool,
) -> None:
    """Write the adapted trajectory of RESULT_FILE (and the original) as a ROS message, CSV or JSON.

    In mcap or bag, the message is nav_msgs/Path or trajectory_msgs/MultiDOFJointTrajectory (see
    --message). Each waypoint's time is when the robot reaches it leaving each one at its speed, so the two
    trajectories play next to a recording. The output is created whole or not at all, and an
    existing file is only replaced with --force.
    """
    adapted, original = _trajectories(result_file)
    out = out or result_file.with_name(result_file.name.removesuffix(".result.json") + f".adapted.{fmt}")
    _check_target(out, result_file)
    if not frame.isprintable() or not _encodes(frame):
        raise InputError(f"--frame {frame!r} is not a printable UTF-8 name")
    if message != "path" and fmt not in ("mcap", "bag"):
        raise InputError(f"--message {message} is written in mcap or bag; {fmt} has no message types")
    if fmt in ("mcap", "bag"):
        if topic == original_topic:
            raise InputError("--topic and --original-topic must differ")
        paths = {topic: adapted, original_topic: original}
        write_paths(out, fmt, paths, frame, replace=force, msgtype=MESSAGES[message])
    elif fmt == "csv":
        publish_bytes(out, _csv(adapted).encode("utf-8"), replace=force)
    else:
        times = times_from_speeds(adapted.array)
        record = {"trajectory": adapted.to_rows(), "time_s": [round(float(t), 9) for t in times],
                  "original_trajectory": original.to_rows(), "frame": frame}  # fmt: skip
        publish_bytes(out, (json.dumps(record, indent=2) + "\n").encode("utf-8"), replace=force)
    kind = f"{fmt}, {MESSAGES[message]}" if fmt in ("mcap", "bag") else fmt
    click.echo(f"Wrote {out} ({kind}: {len(adapted)} adapted and {len(original)} original waypoints)")


def _check_target(out: Path, result_file: Path) -> None:
    """Refuse a target that is the result file itself, or that names something other than a file."""
    try:
        clash = out.exists() and (out.is_dir() or (result_file.exists() and out.samefile(result_file)))
    except OSError as exc:  # a name too long, a path through a file
        raise InputError(f"{out}: cannot be written ({exc.strerror or exc})") from exc
    if clash:
        what = "a folder" if out.is_dir() else "RESULT_FILE itself"
        raise InputError(f"{out} is {what}; give another output file with --out")


def _encodes(text: str) -> bool:
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _trajectories(result_file: Path) -> tuple[Trajectory, Trajectory]:
    data = read_json_file(result_file)
    if not isinstance(data, dict) or "original_trajectory" not in data:
        raise InputError(f"{result_file}: not a trajadapt result file (no original_trajectory)")
    if not data.get("modified_trajectory"):
        raise InputError(
            f"{result_file}: the result has no adapted trajectory (status {data.get('status')!r})"
        )
    return (
        Trajectory.from_rows(data["modified_trajectory"], f"{result_file}: modified_trajectory"),
        Trajectory.from_rows(data["original_trajectory"], f"{result_file}: original_trajectory"),
    )


def _csv(trajectory: Trajectory) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["x", "y", "z", "v", "t"])
    for row, time in zip(trajectory.array, times_from_speeds(trajectory.array), strict=True):
        writer.writerow([repr(float(value)) for value in row] + [repr(float(time))])
    return buffer.getvalue()

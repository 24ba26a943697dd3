"""Each simulated robot follows a known trajectory within its stated error and reports what it cannot do."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from trajadapt.errors import SimulationError
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sim import SimulationOptions, simulate

pytestmark = pytest.mark.sim
# The test paths are already in metres and in the simulator's own (right-handed, +X right) frame.
METRES = SimulationOptions(scale=1.0, offset=(0.0, 0.0, 0.0), positive_x="right")
S = np.linspace(0.0, 1.0, 100)


def arm_arc() -> Trajectory:
    """An arc over the table in front of the KUKA, 0.2 m/s."""
    xyz = np.c_[0.45 + 0.1 * np.sin(np.pi * S), -0.25 + 0.5 * S, 0.4 + 0.1 * np.sin(np.pi * S)]
    return Trajectory(np.c_[xyz, np.full(100, 0.2)])


def drone_path() -> Trajectory:
    """A climbing S across 1.6 m of room at 0.5 m/s."""
    xyz = np.c_[-0.8 + 1.6 * S, 0.5 * np.sin(2 * np.pi * S), 0.8 + 0.3 * S]
    return Trajectory(np.c_[xyz, np.full(100, 0.5)])


def gentle_curve() -> Trajectory:
    """A 4 m arc with 1 m of bow on the floor at 0.5 m/s."""
    xyz = np.c_[4.0 * S - 2.0, np.sin(np.pi * S), np.zeros(100)]
    return Trajectory(np.c_[xyz, np.full(100, 0.5)])


def test_arm_follows_within_one_centimetre() -> None:
    report = simulate(arm_arc(), Scene(), "arm", METRES)
    assert report.tracking.mean < 0.01, report.summary_lines()
    assert not [p for p in report.problems if p.kind == "unreachable"]


def test_drone_follows_within_five_centimetres() -> None:
    report = simulate(drone_path(), Scene(), "drone", METRES)
    assert report.tracking.mean < 0.05, report.summary_lines()
    assert report.tracking.final < 0.05


def test_ground_robot_follows_a_gentle_curve_within_ten_centimetres() -> None:
    report = simulate(gentle_curve(), Scene(), "ground", METRES)
    assert report.tracking.mean < 0.10, report.summary_lines()
    assert report.simulated_s > 8.0  # 4.5 m at 0.5 m/s: the speed profile was kept


def test_arm_reports_the_unreachable_waypoint() -> None:
    rows = arm_arc().to_rows()
    rows[60][:3] = [1.6, 0.0, 0.4]  # 1.6 m from the base: beyond the iiwa's reach
    report = simulate(Trajectory(np.asarray(rows)), Scene(), "arm", METRES)
    unreachable = [p for p in report.problems if p.kind == "unreachable"]
    assert [p.index for p in unreachable] == [60]
    assert "gets only within" in unreachable[0].detail
    assert any("waypoint 60: unreachable" in line for line in report.summary_lines())


def test_drone_reports_waypoints_below_the_floor_and_ground_robot_ignored_heights() -> None:
    rows = drone_path().to_rows()
    rows[10][2] = -0.2
    drone = simulate(Trajectory(np.asarray(rows)), Scene(), "drone", METRES)
    assert [p.index for p in drone.problems] == [10]
    ground = simulate(drone_path(), Scene(), "ground", METRES)
    assert [p.kind for p in ground.problems] == ["height_ignored"]


def test_case_units_are_fitted_into_the_workspace_and_the_map_is_reported() -> None:
    big = Trajectory(np.c_[100 * S, 50 * np.sin(np.pi * S), np.zeros(100), np.full(100, 4.0)])
    report = simulate(big, Scene((SceneObject("box", 50.0, 20.0, 0.0),)), "ground")
    assert report.mapping.startswith("robot = 0.1 x case (x mirrored: +X is left)")
    assert report.tracking.mean < 0.10


def test_too_fast_paths_are_slowed_down_and_said_so() -> None:
    fast = Trajectory(np.c_[gentle_curve().positions, np.full(100, 5.0)])
    report = simulate(fast, Scene(), "ground", METRES)
    assert any(note.startswith("slowed down") for note in report.notes)
    assert report.tracking.mean < 0.10


def test_pictures_and_report(tmp_path: Path) -> None:
    options = replace(METRES, image=tmp_path / "a.png", animation=tmp_path / "a.gif")
    report = simulate(arm_arc(), Scene((SceneObject("red mug", 0.5, 0.0, 0.3),)), "arm", options)
    assert (tmp_path / "a.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "a.gif").read_bytes()[:6] == b"GIF89a"
    data = report.to_dict()
    assert data["tracking_m"]["mean"] < 0.01 and data["image"] == str(tmp_path / "a.png")
    assert 0 < len(data["executed"]) <= 500


def test_bad_requests_are_clear() -> None:
    with pytest.raises(SimulationError, match="choose one of: arm, drone, ground"):
        simulate(arm_arc(), Scene(), "boat")
    still = Trajectory(np.c_[arm_arc().positions, np.zeros(100)])
    with pytest.raises(SimulationError, match="speed 0"):
        simulate(still, Scene(), "arm")

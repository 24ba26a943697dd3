"""Per-robot limits: the arm's reach, the drone's and ground robot's boxes, speed, clearance, fixed ends."""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.checks.constraints import (
    Constraints,
    approached_objects,
    constraints_for,
    distance_to,
    find_violations,
    index_ranges,
)
from trajadapt.checks.projection import project
from trajadapt.checks.robot_limits import ROBOT_LIMITS, robot_constraints, user_constraints
from trajadapt.cli import cli
from trajadapt.errors import InputError
from trajadapt.model.case import Case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings


def line(count: int = 40, x: float = 0.0, z: float = 0.6, speed: float = 0.5) -> np.ndarray:
    """A straight path along y at height z."""
    return np.c_[np.full(count, x), np.linspace(-0.6, 0.6, count), np.full(count, z), np.full(count, speed)]


def test_every_robot_has_limits_that_its_own_description_names() -> None:
    arm, drone, ground = (robot_constraints(name) for name in ("arm", "drone", "ground"))
    assert arm.reach is not None and (arm.reach.minimum, arm.reach.maximum) == (0.15, 1.2)
    assert arm.max_speed == 0.8 and "0.8" in ROBOT_LIMITS["arm"].description
    assert drone.lower == (-10, -10, 0) and drone.upper == (10, 10, 5) and drone.max_speed == 3
    assert ground.lower[2] == ground.upper[2] == 0 and ground.upper[:2] == (4, 3)
    assert robot_constraints("none").empty
    with pytest.raises(InputError, match="no robot limits called 'tank'; known: none, arm, drone, ground"):
        robot_constraints("tank")


def test_the_arms_reach_is_measured_on_both_sides() -> None:
    arm = robot_constraints("arm")
    far = line(x=1.0)  # 1.5 and more from the base at (-0.5, 0, 0.6)
    near = line(count=5, x=-0.5, z=0.6) * np.array([1, 0.1, 1, 1])  # right over the base
    (outer,) = find_violations(far, far, Scene(), replace(arm, max_speed=None))
    assert outer.key == "reach:far" and outer.waypoints == tuple(range(40))
    assert "farther than 1.2 from the base" in outer.message
    (inner,) = find_violations(near, near, Scene(), replace(arm, max_speed=None))
    assert inner.key == "reach:near" and "nearer than 0.15" in inner.message


def test_projection_brings_a_path_into_the_reach_shell_and_says_which_waypoints_moved() -> None:
    original = line(x=0.3)
    adapted = original.copy()
    adapted[15:25, 0] += 0.8  # a bulge out of reach
    limits = replace(robot_constraints("arm"), max_speed=None)
    projection = project(adapted, original, Scene(), limits)
    distance = np.linalg.norm(projection.trajectory[:, :3] - np.array([-0.5, 0, 0.6]), axis=1)
    assert distance.max() <= 1.2 + 1e-6 and not projection.remaining
    reach_move = next(m for m in projection.moves if m.constraint == "arm reach (outer)")
    assert set(reach_move.waypoints) <= set(range(15, 25)) and reach_move.largest_change > 0.1
    assert "arm reach (outer): waypoints" in reach_move.describe()


def test_the_ground_robot_stays_on_the_floor_and_under_its_speed() -> None:
    original = line(x=0.0, z=0.0, speed=1.0)
    adapted = original.copy()
    adapted[:, 2] += np.sin(np.linspace(0, np.pi, 40)) * 0.4  # lifted off the floor
    adapted[10:20, 3] = 5.0
    projection = project(adapted, original, Scene(), robot_constraints("ground"))
    assert np.abs(projection.trajectory[:, 2]).max() <= 1e-6
    assert projection.trajectory[:, 3].max() == 3.0
    names = {m.constraint: m for m in projection.moves}
    assert (
        names["speed limit"].waypoints == tuple(range(10, 20)) and names["speed limit"].largest_change == 2.0
    )
    assert "z upper bound" in names


def test_clearance_spares_the_objects_the_instruction_asks_to_approach() -> None:
    assert approached_objects("approach the cup, then avoid the box", ["cup", "box"]) == ("cup",)
    assert approached_objects(
        "slow down near the Red Box and keep away from the lamp", ["red box", "lamp"]
    ) == ("red box",)
    assert approached_objects("stay far from the cup", ["cup"]) == ()
    scene = Scene((SceneObject("cup", 0.0, 0.0, 0.6), SceneObject("box", 0.0, 0.4, 0.6)))
    limits = constraints_for(scene, Constraints(min_clearance=0.2), instruction="go closer to the cup")
    keys = {v.key for v in find_violations(line(), line(), scene, limits)}
    assert keys == {"clearance:box"}


def test_fixed_ends_hold_when_the_clearance_pushes_the_path() -> None:
    original = line()
    scene = Scene((SceneObject("post", 0.02, -0.55, 0.6),))  # right beside the start
    limits = Constraints(min_clearance=0.15, keep_start=True, keep_goal=True)
    projection = project(original, original, scene, limits)
    assert np.allclose(projection.trajectory[[0, -1], :3], original[[0, -1], :3])
    closest = np.linalg.norm(projection.trajectory[1:, :3] - np.array([0.02, -0.55, 0.6]), axis=1).min()
    assert closest >= 0.15 - 1e-3
    assert any(v.key == "clearance:post" for v in find_violations(original, original, scene, limits))


def test_the_users_limits_are_checked_in_words() -> None:
    assert user_constraints(workspace=(-1, 1, -2, 2, 0, 3)).upper == (1, 2, 3)
    assert user_constraints(fixed_ends="both").keep_goal
    for kwargs, message in (
        ({"workspace": (1, -1, 0, 1, 0, 1)}, "each minimum must be at most its maximum"),
        ({"reach": (0.1, 1.0)}, "give --reach-base X Y Z and --reach MIN MAX together"),
        ({"reach_base": (0, 0, 0), "reach": (1.0, 0.5)}, "need 0 <= MIN < MAX"),
        ({"clearance": -1.0}, "--clearance must be at least 0"),
        ({"max_speed": float("nan")}, "finite"),
        ({"fixed_ends": "middle"}, "not one of none, start, goal, both"),
    ):
        with pytest.raises(InputError, match=message):
            user_constraints(**kwargs)  # type: ignore[arg-type]
    assert index_ranges([4, 1, 2, 3, 9]) == "1-4, 9"


def answer(code: str) -> str:
    return json.dumps({"high_level_plan": "1) Raise the path.", "python_code": code})


def test_the_effect_report_says_which_robot_limit_moved_which_waypoints(
    simple_case: Case, sandbox: Sandbox
) -> None:
    flat = Trajectory(simple_case.trajectory.array * np.array([1, 1, 0, 1]))
    floor = Case("floor", flat, Scene(), "go up by 0.5")
    backend = ScriptedBackend(answers=[answer("modified_trajectory = shift(get_trajectory(), 'up', 0.5)")])
    settings = SessionSettings(robot="ground", read_against_words=False)
    session = AdaptationSession(floor, backend, sandbox, settings)
    session.draft()
    result = session.approve()
    assert result.ok and result.trajectory is not None and result.effect is not None
    assert np.abs(result.trajectory.positions[:, 2]).max() <= 1e-6
    (move,) = [m for m in result.effect.constraint_moves if m.constraint == "z upper bound"]
    assert move.largest_change == pytest.approx(0.5, abs=1e-3)
    assert any(line.startswith("projected: z upper bound: waypoints") for line in result.effect.describe())
    assert result.to_dict()["settings"]["robot"] == "ground"


def test_adapt_takes_the_robot_and_limit_flags(tmp_path: Path, simple_case: Case) -> None:
    simple_case_file = tmp_path / "simple.json"
    simple_case_file.write_text(json.dumps(simple_case.to_dict()))
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([answer("modified_trajectory = shift(get_trajectory(), 'left', 0.5)")]))
    out = tmp_path / "out.json"
    args = ["adapt", str(simple_case_file), "-b", "scripted", "-o", "answers", str(answers), "--yes",
            "--no-log", "--instruction", "go left by 0.5", "--out", str(out), "--workspace", "-1", "0.2", "-5", "5", "-5", "5"]  # fmt: skip
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.output
    record = json.loads(out.read_text())
    assert max(row[0] for row in record["modified_trajectory"]) <= 0.2 + 1e-6
    assert any(m["constraint"] == "x upper bound" for m in record["effect"]["constraint_moves"])
    assert "your workspace -1 0.2 -5 5 -5 5" in record["settings"]["constraints"]
    bad = CliRunner().invoke(cli, [*args[:-7], "--reach", "1", "0.5", "--reach-base", "0", "0", "0"])
    assert bad.exit_code == 1 and "need 0 <= MIN < MAX" in bad.output and "Traceback" not in bad.output


def test_a_pause_stays_a_pause_and_a_longer_result_keeps_the_originals_goal() -> None:
    original = line(count=20, z=0.0)
    paused = np.vstack([original[:10], np.repeat(original[9:10], 5, axis=0) * [1, 1, 1, 0], original[10:]])
    paused[:, 0] -= 0.3  # out of the room on the right side, everywhere
    limits = Constraints(lower=(-0.1, -5, -5), upper=(5, 5, 5), keep_goal=True)
    projection = project(paused, original, Scene(), limits)
    positions = projection.trajectory[:, :3]
    assert np.allclose(positions[9:15], positions[9])  # still standing at one place for the pause
    assert np.allclose(positions[-1], original[-1, :3]) and positions[:, 0].min() >= -0.1 - 1e-6


def test_clearance_is_measured_from_an_objects_box_when_its_size_is_known() -> None:
    path = line()  # along y at x = 0, z = 0.6
    table = SceneObject("table", 0.5, 0.0, 0.6, dimensions=(0.6, 0.6, 0.2))  # box edge at x = 0.2
    limits = Constraints(min_clearance=0.25)
    (violation,) = find_violations(path, path, Scene((table,)), limits)
    assert "within 0.2 of table; keep 0.25" in violation.message  # 0.2 to the box, 0.5 to its centre
    assert find_violations(path, path, Scene((replace(table, dimensions=None),)), limits) == []
    projection = project(path, path, Scene((table,)), limits)
    assert not projection.remaining
    assert distance_to(projection.trajectory, table).min() >= 0.25 - 1e-6


def test_the_projection_holds_the_ends_the_code_kept_unless_they_break_a_limit() -> None:
    original = line(z=0.2)
    rounder = original.copy()
    rounder[:, 2] -= 0.5 * np.sin(np.linspace(0, np.pi, 40))  # dips below the floor in the middle
    floor = Constraints(lower=(-5.0, -5.0, 0.0))
    held = project(rounder, original, Scene(), floor).trajectory
    assert np.array_equal(held[[0, -1], :3], original[[0, -1], :3]) and held[:, 2].min() >= -1e-6
    below = original.copy()
    below[:, 2] = -0.1  # the start itself breaks the floor: it may move
    moved = project(below, original, Scene(), floor).trajectory
    assert moved[:, 2].min() >= -1e-6

"""Planned input trajectories: they start and end where asked and keep clear of the scene's objects."""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.errors import PlanningError
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.planning import plan_case

ROOM = Scene(
    (SceneObject("person", 62, 45, 0), SceneObject("sofa", 25, 65, 0), SceneObject("box", 45, 25, 0),
     SceneObject("blocker", 50, 50, 0))
)  # fmt: skip


def clearance(points: np.ndarray, scene: Scene, dims: int = 2) -> float:
    centres = np.array([o.position for o in scene.objects])[:, :dims]
    return float(np.linalg.norm(points[:, None, :dims] - centres[None], axis=2).min())


@pytest.mark.parametrize("planner", ["astar", "rrt"])
def test_ground_paths_avoid_objects_and_keep_the_ends(planner: str) -> None:
    case = plan_case(
        ROOM, np.array([10, 10, 0.0]), np.array([90, 92, 0.0]), planner, count=60, speed=4, clearance=9
    )
    t = np.c_[case.trajectory.positions, case.trajectory.speeds]
    assert t.shape == (60, 4)
    assert np.allclose(t[0, :3], [10, 10, 0]) and np.allclose(t[-1, :3], [90, 92, 0])
    assert clearance(t[:, :3], ROOM) > 9 * 0.8  # corner rounding may cut in a little
    assert t[:, 3].max() == pytest.approx(4) and t[-1, 3] == 0 and t[0, 3] > 0


def test_rrt_plans_in_three_dimensions() -> None:
    scene = Scene((SceneObject("lamp", 5, 5, 1.5),))
    case = plan_case(scene, np.array([1, 1, 1.0]), np.array([9, 9, 2.0]), "rrt", clearance=1.0)
    t = case.trajectory.positions
    assert np.allclose(t[-1], [9, 9, 2]) and clearance(t, scene, dims=3) > 0.8


def test_blocked_start_and_unknown_planner_are_explained() -> None:
    with pytest.raises(PlanningError, match="the start .* is inside an obstacle"):
        plan_case(ROOM, np.array([62, 45, 0.0]), np.array([90, 92, 0.0]), "astar", clearance=5)
    with pytest.raises(PlanningError, match="choose one of: rrt, astar"):
        plan_case(ROOM, np.array([10, 10, 0.0]), np.array([90, 92, 0.0]), "prm")


def test_no_path_is_explained() -> None:
    angles = np.radians(np.arange(0, 360, 15))
    walled = Scene(
        tuple(
            SceneObject(f"post{k}", 90 + 10 * np.cos(a), 50 + 10 * np.sin(a), 0) for k, a in enumerate(angles)
        )
    )
    with pytest.raises(PlanningError, match="no free path"):
        plan_case(walled, np.array([10, 50, 0.0]), np.array([90, 50, 0.0]), "astar", clearance=6)

"""Write our own benchmark cases (benchmarks/cases/) from the paper's appendix instructions.

Scenes in the paper's units: a 100 x 100 ground-robot map (person, sofa, box, fan) with an RRT path,
a table-top arm scene (red mug, yellow bowl, box) with a smooth demonstration-like curve, and a
10 x 10 x 3 room for a drone with a 3-D RRT path. RRT paths come from ompl (pip install ompl==2.0.1;
needed only to regenerate the files, which are committed). Expectations are written by hand in
benchmarks/cases/expectations.toml.

Run: python benchmarks/make_cases.py
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

OUT = Path(__file__).resolve().parent / "cases"
SEED = 7

GROUND_OBJECTS = [
    {"name": "person", "x": 62.0, "y": 45.0, "z": 0.0},
    {"name": "sofa", "x": 25.0, "y": 65.0, "z": 0.0},
    {"name": "box", "x": 45.0, "y": 25.0, "z": 0.0},
    {"name": "fan", "x": 80.0, "y": 75.0, "z": 0.0},
]
ARM_OBJECTS = [
    {"name": "red mug", "x": 0.55, "y": -0.15, "z": 0.80},
    {"name": "yellow bowl", "x": 0.45, "y": 0.25, "z": 0.80},
    {"name": "box", "x": 0.30, "y": 0.05, "z": 0.80},
]
DRONE_OBJECTS = [
    {"name": "person", "x": 5.0, "y": 4.5, "z": 1.0},
    {"name": "table", "x": 3.0, "y": 7.0, "z": 0.8},
    {"name": "lamp", "x": 7.5, "y": 3.0, "z": 2.2},
]

GROUND = [
    ("go_left", "Go left"),
    ("go_right", "Go right"),
    ("go_left_by_20", "Go left by 20"),
    ("go_further_after_goal", "Go further by a distance of 20 after reaching the goal"),
    ("reach_sofa_and_stop", "Reach near the sofa and stop"),
    ("larger_distance_person", "Walk at a larger distance from the person"),
    ("slower_near_box", "Go slower when near to the box"),
    ("faster_near_person", "Go faster in the vicinity of the person"),
    ("at_least_20_from_person", "Walk at a distance of at least 20 from the person"),
    ("speed_5_near_box", "Traverse at a speed of 5 in the vicinity of the box"),
    (
        "further_person_slower_box",
        "Walk at a larger distance from the person, and go slower when near the box",
    ),
    ("left_10_speed_2", "Go to the left by 10 at a speed of 2"),
    ("keep_20_from_box", "Keep at least 20 distance from the box"),
    ("left_20_keep_10_box", "Go left by 20 keeping a distance of at least 10 from the box"),
    ("spiral_after_goal", "Execute a spiral of max radius 2 after reaching the goal"),
    ("faster_in_middle", "Go faster in the middle of the trajectory"),
    ("stop_near_box", "Stop when you reach near the box"),
    ("greater_distance_person", "Drive at a greater distance from person"),
]
ARM = [
    ("go_left", "Go left"),
    ("move_to_top", "Move to the top"),
    ("go_to_bottom", "Go to the bottom"),
    ("reach_red_mug", "Shift the trajectory gradually to reach the red mug"),
    ("reach_yellow_bowl", "Shift the trajectory to reach yellow bowl"),
    ("slower_near_mug", "Go slower when near the red mug"),
    ("closer_to_bowl", "Walk closer to the yellow bowl"),
    ("stop_near_box", "Stop when you reach near the box"),
    ("wait_near_bowl", "Wait for 5 timesteps near the yellow bowl"),
    ("higher_by_01", "Go higher by 0.1"),
    ("further_after_goal", "Go further by 0.1 after reaching the goal"),
    ("spiral_after_goal", "Execute a spiral of max radius 0.05 after reaching the goal"),
    ("faster", "Move faster"),
]
DRONE = [
    ("up_by_half", "Go up by 0.5"),
    ("left_closer_table", "Go towards left passing closer to the table"),
    ("keep_distance_person", "Keep a distance of at least 1.5 from the person"),
    ("slower_near_table", "Fly slower near the table"),
    ("stay_below_height", "Stay below a height of 1.2"),
    ("spiral_near_lamp", "Execute a spiral of max radius 0.5 when near the lamp"),
    ("right_by_1", "Go right by 1"),
    ("faster_in_middle", "Go faster in the middle of the trajectory"),
    ("reach_table_stop", "Reach near the table and stop"),
    ("further_after_goal", "Go further by 1 after reaching the goal"),
    ("decelerate_to_goal", "Slow down uniformly to a stop at the goal"),
    ("further_from_lamp", "Fly further away from the lamp"),
]


def rrt_path(
    start: list[float],
    goal: list[float],
    bounds: list[tuple[float, float]],
    obstacles: list[tuple[list[float], float]],
    count: int,
) -> np.ndarray:
    """An RRT path (ompl) between start and goal avoiding spheres, resampled to ``count`` points."""
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou

    ou.RNG.setSeed(SEED)
    space = ob.RealVectorStateSpace(len(start))
    limits = ob.RealVectorBounds(len(start))
    for axis, (low, high) in enumerate(bounds):
        limits.setLow(axis, low)
        limits.setHigh(axis, high)
    space.setBounds(limits)
    setup = og.SimpleSetup(space)

    def valid(state: object) -> bool:
        point = np.array([state[i] for i in range(len(start))])  # type: ignore[index]
        return all(np.linalg.norm(point - np.array(c)) > r for c, r in obstacles)

    setup.setStateValidityChecker(valid)
    start_state, goal_state = space.allocState(), space.allocState()
    for axis in range(len(start)):
        start_state[axis], goal_state[axis] = start[axis], goal[axis]
    setup.setStartAndGoalStates(start_state, goal_state)
    setup.setPlanner(og.RRT(setup.getSpaceInformation()))
    if not setup.solve(5.0):
        raise RuntimeError("RRT found no path")
    path = setup.getSolutionPath()
    setup.simplifySolution()
    path = setup.getSolutionPath()
    points = np.array([[path.getState(i)[a] for a in range(len(start))] for i in range(path.getStateCount())])
    return _smooth_resample(points, count)


def _smooth_resample(points: np.ndarray, count: int) -> np.ndarray:
    """Resample a polyline evenly by arc length, then round its corners a little."""
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    s = np.concatenate([[0], np.cumsum(steps)]) / steps.sum()
    target = np.linspace(0, 1, count)
    dense = np.stack([np.interp(target, s, points[:, k]) for k in range(points.shape[1])], axis=1)
    kernel = np.ones(5) / 5
    padded = np.pad(dense, ((2, 2), (0, 0)), mode="edge")
    rounded = np.stack(
        [np.convolve(padded[:, k], kernel, mode="valid") for k in range(points.shape[1])], axis=1
    )
    rounded[[0, -1]] = dense[[0, -1]]
    return rounded


def speed_profile(count: int, top: float) -> np.ndarray:
    """Trapezoidal speed: accelerate over the first 15%, cruise, decelerate to 0 at the goal."""
    s = np.linspace(0, 1, count)
    return top * np.clip(np.minimum(s, 1 - s) / 0.15, 0, 1) + 1e-3 * (s < 1)


def ground_trajectory() -> np.ndarray:
    """RRT path across the map, speed up to 4."""
    obstacles = [([o["x"], o["y"]], 9.0) for o in GROUND_OBJECTS]
    xy = rrt_path([10, 10], [90, 92], [(0, 100), (0, 100)], obstacles, 50)
    return np.c_[xy, np.zeros(len(xy)), speed_profile(len(xy), 4.0)]


def arm_trajectory() -> np.ndarray:
    """A smooth curve over the table, as a demonstration would give."""
    s = np.linspace(0, 1, 60)
    x = 0.25 + 0.3 * s + 0.05 * np.sin(2 * np.pi * s)
    y = -0.40 + 0.80 * s
    z = 1.00 + 0.15 * np.sin(np.pi * s)
    return np.c_[x, y, z, speed_profile(60, 0.3)]


def drone_trajectory() -> np.ndarray:
    """3-D RRT path across the room."""
    obstacles = [([o["x"], o["y"], o["z"]], 1.0) for o in DRONE_OBJECTS]
    xyz = rrt_path([1, 1, 1], [9, 9, 1.5], [(0, 10), (0, 10), (0.2, 3)], obstacles, 50)
    return np.c_[xyz, speed_profile(len(xyz), 1.0)]


def write_scene(  # noqa: D103 - writes one file per instruction
    folder: str,
    trajectory: np.ndarray,
    objects: list[dict[str, float]],
    cases: list[tuple[str, str]],
    description: str,
    constraints: str,
) -> None:
    (OUT / folder).mkdir(parents=True, exist_ok=True)
    rows = np.round(trajectory, 4).tolist()
    for name, instruction in cases:
        case = {
            "trajectory": rows,
            "objects": objects,
            "instruction": instruction,
            "Env_descp": description,
            "constraints": constraints,
        }
        text = json.dumps(case)
        (OUT / folder / f"{name}.json").write_text(text + "\n")


def main() -> None:
    """Write every scene's cases."""
    write_scene("ground", ground_trajectory(), GROUND_OBJECTS, GROUND,
                "A 100 x 100 room seen from above; a ground robot drives from the door to the kitchen.",
                "The robot moves in 2-D (z = 0) inside 0 <= x <= 100, 0 <= y <= 100.")  # fmt: skip
    write_scene("arm", arm_trajectory(), ARM_OBJECTS, ARM,
                "A KUKA arm over a table (top at z = 0.8); the gripper carries an object across the table.",
                "Reachable space: within 0.9 of the base at (0, 0, 0.8).")  # fmt: skip
    write_scene("drone", drone_trajectory(), DRONE_OBJECTS, DRONE,
                "A drone flies across a 10 x 10 x 3 room.",
                "The drone stays inside 0 <= x <= 10, 0 <= y <= 10, 0.2 <= z <= 3.")  # fmt: skip
    print(f"wrote {len(GROUND) + len(ARM) + len(DRONE)} cases to {OUT}")


if __name__ == "__main__":
    main()

"""Waypoints placed evenly again round a step far longer than the original's longest (checks.even_steps)."""

import numpy as np

from trajadapt.checks.even_steps import evened_steps
from trajadapt.checks.review import JUMP_FACTOR
from trajadapt.model.case import Case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.session import SessionSettings
from trajadapt.session.execution import execute
from trajadapt.skills import bind_skills

SKILLS = bind_skills()


def straight(n: int = 40) -> np.ndarray:
    s = np.linspace(0.0, 1.0, n)
    return np.column_stack([4.0 * s, np.zeros(n), np.zeros(n), 0.5 + 0.5 * s])


def longest(t: np.ndarray) -> float:
    return float(np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max())


def test_a_sharp_detour_is_evened_out_along_its_own_shape() -> None:
    original = straight()
    pushed = original.copy()
    pushed[:, 1] = 1.5 * np.exp(-(((np.arange(40) - 20) / 1.2) ** 2))  # a bump over 5 waypoints
    assert longest(pushed) > JUMP_FACTOR * longest(original)  # the bump's steps are jumps
    evened = evened_steps(pushed, original)
    assert evened is not None and longest(evened) <= JUMP_FACTOR * longest(original)
    np.testing.assert_array_equal(evened[:, 3], pushed[:, 3])  # speeds stay with their waypoints
    moved = np.flatnonzero(np.linalg.norm(evened[:, :3] - pushed[:, :3], axis=1) > 1e-12)
    assert 0 < moved.min() and moved.max() < len(pushed) - 1  # the ends stay
    assert evened[:, 1].max() >= 1.2 and np.all(evened[:, 1] >= -0.1)  # the detour's shape


def test_a_path_with_no_jump_is_left_alone() -> None:
    original = straight()
    assert evened_steps(SKILLS["shift"](original, "left", 0.3), original) is None


def test_a_pause_is_never_taken_into_a_stretch() -> None:
    original = straight()
    jumped = original.copy()
    jumped[20:, 0] += 2.0  # one step of 2.1 between waypoints 19 and 20
    paused = np.vstack([jumped[:18], np.repeat(jumped[18:19], 3, axis=0), jumped[18:]])
    evened = evened_steps(paused, original)
    assert evened is not None and longest(evened) < longest(paused)
    np.testing.assert_array_equal(evened[:21], paused[:21])  # the pause and what comes before it


def test_a_session_evens_out_the_jumps_of_a_run_and_says_so(sandbox) -> None:
    n = 20
    line = np.c_[np.zeros(n), np.linspace(0.0, 1.0, n), np.zeros(n), np.ones(n)]
    case = Case(
        "line", Trajectory(line), Scene((SceneObject("cup", 0.02, 0.5, 0.0),)), "keep well away from the cup"
    )
    code = "t = get_trajectory()\nmodified_trajectory = move_away(t, detect_objects('cup'), 'a lot')\n"
    ran = execute(code, case, sandbox, SessionSettings(), [case.instruction], True)
    assert ran.trajectory is not None and longest(ran.trajectory.array) <= JUMP_FACTOR * longest(line)
    assert any("placed evenly" in note for note in ran.notes)

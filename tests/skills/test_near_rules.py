"""What "near an object" means to a speed change: the zone (the default) and LaTTe's field."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.model.case import Case
from trajadapt.model.geometry import extent
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.runner import ExecutionOptions
from trajadapt.session import SessionSettings
from trajadapt.session.execution import execute
from trajadapt.skills import bind_skills, speed


def line(n: int = 60) -> np.ndarray:
    """A straight path one unit long along +y at constant speed 1."""
    return np.c_[np.zeros(n), np.linspace(0.0, 1.0, n), np.zeros(n), np.ones(n)]


def mean_over_reaches(t: np.ndarray, point: np.ndarray) -> np.ndarray:
    """The field max(0, 1 - d / r) averaged numerically over r uniform in LaTTe's reach."""
    low, high = (share * extent(t) for share in speed.LATTE_REACH)
    reaches = np.linspace(low, high, 20001)
    distance = np.linalg.norm(t[:, :3] - point, axis=1)
    return np.clip(1.0 - distance[:, None] / reaches[None, :], 0.0, None).mean(axis=1)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.0, 2.5), st.floats(-0.5, 1.5))
def test_the_latte_field_is_its_mean_over_the_generators_reaches(off: float, along: float) -> None:
    t = line()
    point = np.array([off, along, 0.0])
    field = speed.latte_field(t, point)
    assert np.allclose(field, mean_over_reaches(t, point), atol=1e-3)
    assert ((field >= 0.0) & (field <= 1.0)).all()


def test_the_latte_field_is_whole_at_the_object_and_nothing_beyond_its_reach() -> None:
    t = line()
    field = speed.latte_field(t, t[0, :3])
    assert field[0] == pytest.approx(1.0)
    assert (np.diff(field) <= 1e-12).all()  # the farther along the line, the less
    reach = speed.LATTE_REACH[1] * extent(t)
    assert speed.latte_field(t, np.array([reach, 0.5, 0.0])).max() == 0.0


def test_a_path_that_stays_far_keeps_its_speed_under_latte_but_not_in_the_zone() -> None:
    t = line()
    far = [2.0, 0.5, 0.0]  # two path sizes off the middle
    zone = speed.scale_speed(t, 0.5, near=far)
    latte = speed.scale_speed(t, 0.5, near=far, near_rule="latte")
    assert zone[:, 3].min() == pytest.approx(0.5)  # the zone slows the closest pass all the same
    assert np.array_equal(latte[:, 3], t[:, 3])


def test_near_the_object_latte_changes_most_there_and_a_little_further_on() -> None:
    t = line()
    box = [0.1, 0.5, 0.0]
    out = speed.set_speed(t, 0.0, near=box, near_rule="latte")
    middle = len(t) // 2
    assert out[middle, 3] == out[:, 3].min() < 0.9
    assert (out[:, 3] < 1.0).all()  # the whole path lies within the generator's reach
    assert np.array_equal(out[:, :3], t[:, :3])


def test_a_radius_is_kept_whatever_the_rule() -> None:
    t = line()
    zone = speed.scale_speed(t, 0.5, near=[0.0, 0.5, 0.0], radius=0.1)
    latte = speed.scale_speed(t, 0.5, near=[0.0, 0.5, 0.0], radius=0.1, near_rule="latte")
    assert np.array_equal(zone, latte)


def test_an_unknown_rule_is_named_in_the_error() -> None:
    with pytest.raises(ValueError, match="near_rule must be one of zone, latte, got 'field'"):
        speed.scale_speed(line(), 0.5, near=[0.0, 0.5, 0.0], near_rule="field")
    with pytest.raises(ValueError, match="near_rule must be one of"):
        bind_skills(near_rule="field")


def test_the_bound_skills_read_near_as_the_settings_say() -> None:
    t, far = line(), [2.0, 0.5, 0.0]
    latte = bind_skills(near_rule="latte")
    assert np.array_equal(latte["scale_speed"](t, 0.5, near=far)[:, 3], t[:, 3])
    assert bind_skills()["scale_speed"](t, 0.5, near=far)[:, 3].min() == pytest.approx(0.5)


def test_the_sandbox_binds_the_rule_it_is_given(sandbox) -> None:
    scene = Scene((SceneObject("lamp", 2.0, 0.5, 0.0),))
    code = "t = get_trajectory()\nmodified_trajectory = scale_speed(t, 0.5, near=detect_objects('lamp'))\n"
    speeds = {}
    for rule in speed.NEAR_RULES:
        result = sandbox.run(code, Trajectory(line()), scene, ExecutionOptions(skills=True, near_rule=rule))
        assert result.ok, result.error
        speeds[rule] = np.asarray(result.rows)[:, 3]
    assert np.allclose(speeds["latte"], 1.0) and speeds["zone"].min() == pytest.approx(0.5)


def test_a_session_runs_its_code_with_the_settings_rule(sandbox) -> None:
    scene = Scene((SceneObject("lamp", 2.0, 0.5, 0.0),))
    case = Case("far lamp", Trajectory(line()), scene, "slower near the lamp")
    code = "t = get_trajectory()\nmodified_trajectory = scale_speed(t, 0.5, near=detect_objects('lamp'))\n"
    latte = execute(code, case, sandbox, SessionSettings(near_rule="latte"), [case.instruction], True)
    zone = execute(code, case, sandbox, SessionSettings(), [case.instruction], True)
    assert latte.trajectory is not None and zone.trajectory is not None
    assert np.allclose(latte.trajectory.array[:, 3], 1.0)
    assert zone.trajectory.array[:, 3].min() == pytest.approx(0.5)

"""The measured effect gets the numbers and signs right on hand-made pairs; contradictions fire only when wrong."""

from __future__ import annotations

import numpy as np

from trajadapt.checks.contradictions import contradictions
from trajadapt.checks.effect import measure_effect
from trajadapt.model.geometry import Axes
from trajadapt.model.scene import SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.skills import bind_skills

SKILLS = bind_skills()
BOX = SceneObject("box", 0.3, 0.5, 0.5)


def line() -> Trajectory:
    """A straight line along +y at x = 0, z = 0.5, speed 1, 21 waypoints."""
    y = np.linspace(0.0, 1.0, 21)
    return Trajectory.from_rows(np.column_stack([np.zeros(21), y, np.full(21, 0.5), np.ones(21)]))


def adapted(original: Trajectory, array: np.ndarray) -> Trajectory:
    return Trajectory.from_rows(array)


def test_a_shift_left_by_0_2() -> None:
    t = line()
    moved = t.array.copy()
    moved[1:, 0] += 0.2  # paper axes: +x is left
    effect = measure_effect(t, adapted(t, moved), [BOX])
    assert effect.start_moved == 0 and np.isclose(effect.goal_moved, 0.2) and effect.goal_direction == "left"
    assert np.isclose(effect.largest_displacement, 0.2) and effect.mean_shift_direction == "left"
    assert np.isclose(effect.mean_shift[0], 0.2 * 20 / 21)
    assert effect.waypoints_before == effect.waypoints_after == 21
    assert any("goal moved 0.2 left" in line for line in effect.describe())
    assert contradictions("go left by 0.2", effect) == []
    assert contradictions("go right by 0.2", effect) == [
        "the instruction says right, but the path moved left on average"
    ]
    ovita = measure_effect(t, adapted(t, moved), [BOX], Axes.from_positive_x("right"))
    assert (
        ovita.goal_direction == "right"
        and contradictions("go right", ovita, Axes.from_positive_x("right")) == []
    )


def test_closer_to_an_object() -> None:
    t = line()
    closer = SKILLS["move_closer"](t.array, [BOX.x, BOX.y, BOX.z], 0.5)
    effect = measure_effect(t, adapted(t, closer), [BOX])
    (box,) = effect.objects
    assert np.isclose(box.closest_before, 0.3) and box.closest_after < 0.2
    assert contradictions("walk closer to the box", effect) == []
    assert "closest distance grew" not in " ".join(contradictions("walk closer to the box", effect))
    away = measure_effect(t, adapted(t, SKILLS["move_away"](t.array, [0.3, 0.5, 0.5], 0.1)), [BOX])
    assert contradictions("walk closer to the box", away)[0].startswith("the instruction asks to get closer")
    assert contradictions("stay away from the box", effect)[0].startswith("the instruction asks to keep away")


def test_slower_near_an_object() -> None:
    t = line()
    slower = SKILLS["scale_speed"](t.array, 0.5, near=[BOX.x, BOX.y, BOX.z])
    effect = measure_effect(t, adapted(t, slower), [BOX])
    (box,) = effect.objects
    assert box.speed_near_before == 1.0 and box.speed_near_after < 0.8
    assert effect.speed_after < effect.speed_before and effect.duration_after > effect.duration_before
    assert contradictions("go slower near the box", effect) == []
    assert contradictions("go faster near the box", effect)[0].startswith("the instruction asks for faster")


def test_start_moved_and_waypoints_added() -> None:
    t = line()
    moved = SKILLS["shift_start"](t.array, "down", 0.1)
    effect = measure_effect(t, adapted(t, moved))
    assert np.isclose(effect.start_moved, 0.1) and effect.start_direction == "down" and effect.goal_moved == 0
    longer = SKILLS["extend"](t.array, 0.5)
    grown = measure_effect(t, adapted(t, longer))
    assert grown.waypoints_after == 31 and np.isclose(grown.length_after, grown.length_before + 0.5)


def test_an_object_named_but_untouched_is_flagged() -> None:
    t = line()
    far_box = SceneObject("box", 5.0, 0.5, 0.5)
    effect = measure_effect(t, adapted(t, SKILLS["shift"](t.array, "up", 0.2)), [far_box])
    assert contradictions("pass closer to the box", effect)[0].startswith("the instruction names the box")
    assert contradictions("go up", effect) == []


def test_a_stop_on_a_moving_step_has_no_finite_time() -> None:
    t = line()
    stopped = t.array.copy()
    stopped[5:7, 3] = 0.0
    assert measure_effect(t, adapted(t, stopped)).duration_after is None

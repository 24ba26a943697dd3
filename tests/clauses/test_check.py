import numpy as np

from tests.conftest import line_trajectory
from trajadapt.checks.effect import measure_effect
from trajadapt.clauses.check import clause_findings
from trajadapt.model.geometry import Axes
from trajadapt.model.scene import SceneObject
from trajadapt.model.trajectory import Trajectory

LAMP = SceneObject("lamp", 0.2, 0.5, 0.5)


def effect_of(adapted: Trajectory):
    return measure_effect(line_trajectory(), adapted, (LAMP,), Axes())


def moved_left() -> Trajectory:
    array = line_trajectory().array.copy()
    array[5:, 0] += 0.1
    return Trajectory(array)


def slowed() -> Trajectory:
    array = line_trajectory().array.copy()
    array[:, 3] *= 0.6
    return Trajectory(array)


def test_a_pace_clause_whose_step_moved_the_path_is_a_finding():
    assert any(
        "only for a change of speed" in f
        for f in clause_findings("take it slower by the lamp", effect_of(moved_left()), Axes())
    )
    assert not any(
        "only for a change of speed" in f
        for f in clause_findings("take it slower by the lamp", effect_of(slowed()), Axes())
    )


def test_a_place_clause_whose_step_changed_only_the_speed_is_a_finding():
    found = clause_findings("keep a distance of at least 0.2 from the lamp", effect_of(slowed()), Axes())
    assert any("changed only the speed" in f for f in found)
    assert clause_findings("shift left and slow down", effect_of(slowed()), Axes()) == [] or all(
        "changed only the speed" not in f
        for f in clause_findings("shift left and slow down", effect_of(slowed()), Axes())
    )


def test_the_effect_reports_own_flags_apply_to_one_clause():
    right = Trajectory(np.c_[moved_left().array[:, 0] * -1, moved_left().array[:, 1:]])
    assert any("says left" in f for f in clause_findings("head over to the left", effect_of(right), Axes()))
    assert clause_findings("head over to the left", effect_of(moved_left()), Axes()) == []


def test_a_direction_said_and_nothing_moved_that_way_is_a_finding():
    found = clause_findings("go to the bottom part", effect_of(moved_left()), Axes())
    assert any("say down" in f for f in found)
    assert not any(
        "say left" in f for f in clause_findings("go to the left part", effect_of(moved_left()), Axes())
    )

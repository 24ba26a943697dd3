"""Trajectory: the one rule every trajectory keeps, and how each edge names a break of it."""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.checks.review import validate_result
from trajadapt.errors import InputError, InvalidTrajectory, InvalidWaypoints
from trajadapt.model.trajectory import Trajectory, waypoint_problem

GOOD = np.array([[0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0]])


@pytest.mark.parametrize(
    ("array", "words"),
    [
        (np.zeros((3, 3)), "has shape (3, 3); it must be (N, 4)"),
        (np.zeros((1, 4)), "needs at least 2 waypoints, got 1"),
        (
            np.array([[0, 0, 0, 1], [0, np.nan, 0, 1]]),
            "1 non-finite value(s) (NaN or inf), first at row 1, y = nan",
        ),
        (
            np.array([[0, 0, 0, 1], [2e9, 0, 0, 1]]),
            "beyond ±1e+09 (check the units), first at row 1, x = 2e+09",
        ),
        (np.array([[0, 0, 0, 1], [0, 0, 0, -1.5]]), "1 negative velocity value(s), first at row 1 (-1.5)"),
    ],
)
def test_the_rule_is_the_trajectorys_own_and_each_edge_names_its_source(
    array: np.ndarray, words: str
) -> None:
    assert words in (waypoint_problem(array) or "")
    with pytest.raises(InvalidWaypoints, match="the trajectory"):
        Trajectory(array)
    with pytest.raises(InvalidTrajectory, match=r"^modified_trajectory (has|needs)"):
        validate_result(array.tolist())
    if array.ndim == 2 and array.shape[1] == 4:
        with pytest.raises(InputError, match=r"^case.json: trajectory"):
            Trajectory.from_rows(array.tolist(), "case.json: trajectory")


def test_a_valid_trajectory_is_a_read_only_copy() -> None:
    source = GOOD.copy()
    trajectory = Trajectory(source)
    source[0, 0] = 5.0
    assert trajectory.array[0, 0] == 0.0 and not trajectory.array.flags.writeable
    assert waypoint_problem(GOOD) is None and len(trajectory) == 2


def test_ragged_code_output_is_explained() -> None:
    with pytest.raises(InvalidTrajectory, match="not a table of numbers"):
        validate_result([[0, 0, 0, 1], [0, 0]])

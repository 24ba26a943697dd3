"""pass_over: the path passes right above each point, in turn, with its start and goal kept."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.skills.objects import pass_over


def _line(count: int = 40) -> np.ndarray:
    x = np.linspace(0.0, 1.0, count)
    return np.stack([x, 0.1 * np.sin(3 * x), np.zeros(count), np.ones(count)], axis=1)


def _over(path: np.ndarray, point: np.ndarray) -> tuple[float, float]:
    """Height above the point and horizontal distance, at the waypoint horizontally nearest it."""
    horizontal = np.linalg.norm(path[:, :2] - point[:2], axis=1)
    k = int(np.argmin(horizontal))
    return float(path[k, 2] - point[2]), float(horizontal[k])


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.tuples(st.floats(0.2, 0.8), st.floats(-0.15, 0.15), st.floats(-0.2, 0.2)), min_size=1, max_size=2
    ).filter(lambda ps: len(ps) < 2 or abs(ps[0][0] - ps[1][0]) > 0.25)
)
def test_the_path_passes_above_each_point_and_keeps_its_ends(
    points: list[tuple[float, float, float]],
) -> None:
    path = _line()
    centres = [np.array(p) for p in points]
    adapted = pass_over(path, centres if len(centres) > 1 else centres[0])
    assert np.allclose(adapted[[0, -1]], path[[0, -1]])
    for centre in centres:
        above, off = _over(adapted, centre)
        assert above > 0.05
        assert off < 0.05


@settings(max_examples=30, deadline=None)
@given(st.floats(0.1, 0.6), st.floats(0.2, 0.8))
def test_without_a_stated_clearance_a_path_already_higher_keeps_its_height(
    raised: float, along: float
) -> None:
    """A raise before the pass ("raise the whole flight by 30 cm, fly over the keyboard") stays."""
    path = _line()
    path[:, 2] += raised
    centre = np.array([along, 0.1 * np.sin(3 * along), 0.0])
    above, off = _over(pass_over(path, centre), centre)
    assert above >= raised - 1e-6
    assert off < 0.05


def test_a_stated_clearance_is_the_height_above_the_point() -> None:
    above, off = _over(pass_over(_line(), [0.5, 0.0, 0.0], clearance=0.3), np.array([0.5, 0.0, 0.0]))
    assert above == pytest.approx(0.3, abs=0.03)
    assert off < 0.03


@settings(max_examples=40, deadline=None)
@given(st.floats(0.3, 0.7), st.floats(-0.1, 0.1), st.floats(-0.15, 0.05), st.floats(0.05, 0.2))
def test_a_stated_clearance_is_kept_all_the_way_over(x: float, y: float, z: float, gap: float) -> None:
    """The shoulders of the bend, lower and horizontally near the point, keep the stated gap too."""
    path, centre = _line(), np.array([x, y, z])
    adapted = pass_over(path, centre, clearance=gap)
    assert np.linalg.norm(adapted[:, :3] - centre, axis=1).min() >= gap - 1e-9
    assert np.allclose(adapted[[0, -1]], path[[0, -1]])


def test_a_stated_gap_near_an_end_leaves_no_cliff_beside_it() -> None:
    path = np.stack([np.linspace(0.0, 1.0, 40), np.zeros(40), np.zeros(40), np.ones(40)], axis=1)
    adapted = pass_over(path, np.array([0.97, 0.02, 0.0]), clearance=0.1)
    spacing = np.linalg.norm(np.diff(path[:, :3], axis=0), axis=1).max()
    assert np.allclose(adapted[[0, -1]], path[[0, -1]])
    assert np.linalg.norm(np.diff(adapted[:, :3], axis=0), axis=1).max() < 2.5 * spacing

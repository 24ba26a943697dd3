"""Property tests: a speed profile changes the speed in the direction its name says, wherever it applies."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.skills.speed import speed_profile

speeds = st.lists(st.floats(0.05, 5.0), min_size=4, max_size=60)


def path(values: list[float]) -> np.ndarray:
    n = len(values)
    return np.c_[np.linspace(0, 1, n), np.zeros(n), np.zeros(n), values]


@settings(max_examples=200, deadline=None)
@given(speeds, st.floats(0.0, 0.95))
def test_decelerating_never_speeds_a_waypoint_up(values, start):
    before = path(values)
    after = speed_profile(before, "decelerate", start=start)
    assert np.all(after[:, 3] <= before[:, 3] + 1e-12)
    assert after[-1, 3] == 0.0


@settings(max_examples=200, deadline=None)
@given(speeds, st.floats(0.0, 0.9))
def test_accelerating_never_slows_a_waypoint_down_and_always_speeds_up_the_end(values, start):
    before = path(values)
    after = speed_profile(before, "accelerate", start=start)
    assert np.all(after[:, 3] >= before[:, 3] - 1e-12)
    assert after[-1, 3] > before[-1, 3] or after[-1, 3] >= before[:, 3].max()


def test_accelerating_a_path_already_at_its_top_speed_speeds_it_up():
    flat = path([1.0] * 20)
    assert speed_profile(flat, "accelerate")[-1, 3] > 1.3

"""Property tests: a speed profile changes the speed in the direction its name says, wherever it applies."""

import numpy as np
from hypothesis import example, given, settings
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
@given(speeds, st.floats(0.0, 0.95))
def test_decelerating_slows_every_waypoint_of_its_part_by_the_ramp_and_never_rises(values, start):
    before = path(values)
    after = speed_profile(before, "decelerate", start=start)
    begin = min(start, 0.99)
    part = before[:, 0] >= begin  # progress is the x coordinate of these straight paths
    ramp = 1.0 - (before[part, 0] - begin) / (1.0 - begin)
    assert np.all(after[part, 3] <= before[part, 3] * ramp + 1e-9)
    assert np.all(np.diff(after[part, 3]) <= 1e-12)


@settings(max_examples=100, deadline=None)
@given(speeds, st.integers(0, 50), st.floats(0.0, 0.6))
@example([1.0, 0.0625, 1.0, 1.0], 0, 5e-324)  # a ramp from a hair past a rest at the start
def test_decelerating_past_a_rest_still_moves_and_stops_at_the_goal(values, rest, start):
    values = list(values) + [1.0, 1.0]
    values[rest % (len(values) - 2)] = 0.0  # at rest somewhere before the goal
    before = path(values)
    after = speed_profile(before, "decelerate", start=start)
    assert np.all(after[:, 3] <= before[:, 3] + 1e-12) and after[-1, 3] == 0.0
    assert after[:-1, 3].max() > 0.0  # not held at 0 from the rest on


@settings(max_examples=100, deadline=None)
@given(st.integers(8, 60), st.integers(1, 5), st.floats(0.2, 3.0))
def test_decelerating_a_path_that_speeds_up_from_rest_slows_it_over_its_last_part_gradually(n, resting, top):
    values = [0.0] * resting + list(np.linspace(0.0, top, n - resting + 1)[1:])
    before = path(values)
    after = speed_profile(before, "decelerate")
    tail = before[:, 0] >= 0.7
    assert np.all(np.diff(after[tail, 3]) <= 1e-12) and after[-1, 3] == 0.0
    assert after[-2, 3] > 0.0 and after[tail, 3].mean() < 0.6 * before[tail, 3].mean()


def test_decelerating_a_path_that_already_slows_to_the_goal_slows_it_further():
    slowing = path(list(np.linspace(1.0, 0.0, 40)))  # already the old uniform ramp
    tail = slowing[:, 0] >= 0.7
    after = speed_profile(slowing, "decelerate", start=0.7)
    assert after[tail, 3].mean() < 0.8 * slowing[tail, 3].mean()


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

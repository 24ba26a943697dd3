"""Each skill keeps its promise: what it moves, what it keeps, and how smoothly it changes the path."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.model.case import load_case
from trajadapt.model.geometry import Axes, progress
from trajadapt.skills import SKILLS, bind_skills, describe_skills, events, objects, shape, speed
from trajadapt.skills.core import AMOUNT_WORDS, as_point, resolve_amount
from trajadapt.skills.objects import CLOSER_FRACTIONS
from trajadapt.skills.shape import stay_above, stay_below

N = 100


def curve(n: int = N) -> np.ndarray:
    """A gentle S-curve along +y at height 1, speed rising then falling."""
    s = np.linspace(0.0, 1.0, n)
    return np.c_[0.3 * np.sin(np.pi * s), 2.0 * s, np.ones(n), 0.5 + 0.5 * np.sin(np.pi * s)]


def displacement_is_smooth(before: np.ndarray, after: np.ndarray, bound: float = 0.05) -> bool:
    """The change field has no kinks: its largest second difference is small against its size."""
    field = after[:, :3] - before[:, :3]
    size = np.abs(field).max()
    return size == 0 or np.abs(np.diff(field, n=2, axis=0)).max() <= bound * size


def test_original_is_never_modified() -> None:
    t = curve()
    frozen = t.copy()
    shape.shift(t, "left", 0.2)
    objects.move_closer(t, [0, 1, 1])
    speed.scale_speed(t, 0.5)
    events.wait(t, "middle", 3)
    assert np.array_equal(t, frozen)


@pytest.mark.parametrize(
    ("direction", "axis", "sign"),
    [
        ("left", 0, 1),
        ("right", 0, -1),
        ("front", 1, 1),
        ("backwards", 1, -1),
        ("up", 2, 1),
        ("bottom", 2, -1),
    ],
)
def test_shift_moves_the_path_and_keeps_the_start(direction: str, axis: int, sign: int) -> None:
    t = curve()
    out = shape.shift(t, direction, 0.2)
    assert np.allclose(out[0], t[0])
    assert np.isclose(out[-1, axis] - t[-1, axis], sign * 0.2)
    moved = (out[:, axis] - t[:, axis]) * sign
    assert (moved >= -1e-12).all() and np.mean(moved > 0.19) > 0.6
    assert np.allclose(np.delete(out[:, :3] - t[:, :3], axis, axis=1), 0)
    assert np.array_equal(out[:, 3], t[:, 3])
    assert displacement_is_smooth(t, out)


def test_an_alternating_shift_flips_every_block_and_eases_each_flip() -> None:
    t = curve(12)
    out = shape.shift(t, "up", 0.2, alternate=4)
    moved = out[:, 2] - t[:, 2]
    assert np.allclose(moved / 0.2, [1, 1, 1, 0.5, -0.5, -1, -1, -0.5, 0.5, 1, 1, 1])
    assert np.allclose(out[:, :2], t[:, :2]) and np.array_equal(out[:, 3], t[:, 3])
    assert np.abs(np.diff(moved)).max() <= 0.2 + 1e-12  # no step jumps the whole double offset


def test_axis_convention_flips_left_and_right() -> None:
    ovita = Axes.from_positive_x("right")
    out = shape.shift(curve(), "left", 0.2, axes=ovita)
    assert np.isclose(out[-1, 0] - curve()[-1, 0], -0.2)
    assert bind_skills(ovita)["shift"](curve(), "left", 0.2)[-1, 0] < curve()[-1, 0]


def test_vague_amounts_scale_with_the_path() -> None:
    t = curve()
    assert resolve_amount("slightly", t) < resolve_amount(None, t) < resolve_amount("a lot", t)
    assert np.isclose(resolve_amount("a lot", t), AMOUNT_WORDS["a lot"] * 2.0)
    with pytest.raises(ValueError, match="unknown amount 'loads'"):
        shape.shift(t, "left", "loads")
    assert resolve_amount("at least 0.5", t) == 0.5 and resolve_amount("0.2 m", t) == 0.2
    with pytest.raises(ValueError, match="unknown amount 'between 0.1 and 0.3'"):
        resolve_amount("between 0.1 and 0.3", t)  # two numbers: no guessing
    with pytest.raises(ValueError, match="unknown direction 'sideways'"):
        shape.shift(t, "sideways", 0.1)


def test_shift_goal_and_start() -> None:
    t = curve()
    goal = shape.shift_goal(t, "left", 0.3)
    assert np.allclose(goal[0], t[0]) and np.isclose(goal[-1, 0] - t[-1, 0], 0.3)
    assert displacement_is_smooth(t, goal)
    start = shape.shift_start(t, "down", 0.3)
    assert np.allclose(start[-1], t[-1]) and np.isclose(start[0, 2] - t[0, 2], -0.3)
    assert displacement_is_smooth(t, start)


def test_shift_part_by_words_and_indices() -> None:
    t = curve()
    middle = shape.shift_part(t, "up", 0.1, "middle")
    assert np.allclose(middle[[0, -1]], t[[0, -1]]) and np.isclose(middle[N // 2, 2] - 1, 0.1)
    assert displacement_is_smooth(t, middle, bound=0.12)
    first = shape.shift_part(t, "left", 0.1, (0, 10))
    assert np.allclose(first[:10, 0] - t[:10, 0], 0.1) and np.allclose(first[10:], t[10:])


def test_lift_middle() -> None:
    t = curve()
    out = shape.lift_middle(t, "up", 0.2)
    assert np.allclose(out[[0, -1]], t[[0, -1]]) and np.isclose((out[:, 2] - t[:, 2]).max(), 0.2, atol=1e-3)
    assert displacement_is_smooth(t, out)


def distances(t: np.ndarray, point: list[float]) -> np.ndarray:
    return np.linalg.norm(t[:, :3] - np.asarray(point), axis=1)


def test_move_closer_and_away() -> None:
    t, box = curve(), [0.8, 1.0, 1.0]
    closer = objects.move_closer(t, box)
    assert distances(closer, box).min() < (1 - 0.9 * CLOSER_FRACTIONS[""]) * distances(t, box).min()
    assert np.allclose(closer[[0, -1]], t[[0, -1]]) and displacement_is_smooth(t, closer)
    assert (
        distances(objects.move_closer(t, box, "a lot"), box).min()
        < distances(objects.move_closer(t, box, "a bit"), box).min()
    )
    away = objects.move_away(t, box, 0.3)
    assert distances(away, box).min() > distances(t, box).min() + 0.25
    assert np.allclose(away[[0, -1]], t[[0, -1]]) and displacement_is_smooth(t, away)


def test_an_object_move_given_a_part_moves_all_of_that_part_and_nothing_else() -> None:
    t, box = curve(), [0.8, 1.0, 1.0]
    closer = objects.move_closer(t, box, "a bit", part=(0, 6))
    away = objects.move_away(t, box, 0.2, part=(0, 6))
    assert np.allclose(closer[6:], t[6:]) and np.allclose(away[6:], t[6:])
    assert np.allclose(distances(closer, box)[:6], (1 - CLOSER_FRACTIONS["a bit"]) * distances(t, box)[:6])
    assert np.allclose(distances(away, box)[:6], distances(t, box)[:6] + 0.2)


def test_a_vague_move_away_from_something_far_asks_for_little_and_a_number_is_kept() -> None:
    t = curve()
    size = float(np.ptp(t[:, :3], axis=0).max())
    nearest = t[N // 2, :3]
    near, far = nearest + [0.0, 0.0, 0.1 * size], nearest + [0.0, 0.0, 0.9 * size]
    moved = lambda after: float(np.abs(after[:, :3] - t[:, :3]).max())  # noqa: E731
    assert moved(objects.move_away(t, near, "a lot")) > 0.15 * size
    assert moved(objects.move_away(t, far, "a lot")) < 1e-9
    assert moved(objects.move_away(t, far, 0.2)) > 0.19  # the user's own number


def test_avoid_from_one_and_several_points() -> None:
    t = curve()
    near = [[0.3, 1.0, 1.0], [0.0, 0.4, 1.0]]
    out = objects.avoid(t, near, 0.25)
    for point in near:
        assert distances(out, point).min() >= 0.25 - 1e-9
    assert np.allclose(out[-1], t[-1])
    steps = np.linalg.norm(np.diff(out[:, :3], axis=0), axis=1)
    assert steps.max() < 4 * np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max()
    single = objects.avoid(t, [0.3, 1.0, 1.0], 0.25)
    assert distances(single, [0.3, 1.0, 1.0]).min() >= 0.25 - 1e-9
    assert np.array_equal(objects.avoid(t, [3.0, 1.0, 1.0], 0.25), t)  # already clear: nothing moves


def test_pass_through_and_reach() -> None:
    t, target = curve(), np.array([0.6, 1.2, 1.4])
    out = objects.pass_through(t, target)
    assert distances(out, target).min() < 1e-9
    assert np.allclose(out[[0, -1]], t[[0, -1]]) and displacement_is_smooth(t, out, bound=0.1)
    reached = objects.reach(t, target)
    assert np.allclose(reached[-1, :3], target) and np.allclose(reached[0], t[0])
    assert np.allclose(objects.midpoint([0, 0, 0], [2, 4, 6]), [1, 2, 3])


def test_pass_through_a_point_off_the_path_near_the_goal_keeps_steps_short_and_the_goal() -> None:
    t = curve(60)
    longest = float(np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max())
    target = t[-4, :3] + [0.0, 0.0, 15 * longest]  # near the goal, far off the path
    out = objects.pass_through(t, target)
    assert distances(out, target).min() < 1e-9 and np.allclose(out[-1], t[-1])
    assert np.linalg.norm(np.diff(out[:, :3], axis=0), axis=1).max() < 3 * longest
    goal_moves = objects.pass_through(t, t[-1, :3] + [0.0, 0.0, 15 * longest])  # the goal is nearest
    assert np.allclose(goal_moves[-1, :3], t[-1, :3] + [0.0, 0.0, 15 * longest])


def test_pass_over_a_point_nearest_an_end_keeps_the_start_and_the_goal() -> None:
    t = curve(60)
    longest = float(np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max())
    for end in (0, -1):  # the box lies just beyond an end of the path
        box = t[end, :3] + (t[end, :3] - t[end + (1 if end == 0 else -1), :3]) * 2
        out = objects.pass_over(t, box)
        assert np.allclose(out[[0, -1]], t[[0, -1]])
        over = out[np.argmin(np.linalg.norm(out[:, :2] - box[:2], axis=1))]
        assert over[2] > box[2] and np.linalg.norm(over[:2] - box[:2]) < 2 * longest


def test_missing_object_and_words_are_explained() -> None:
    with pytest.raises(ValueError, match="detect_objects\\(\\) did not find"):
        objects.move_closer(curve(), None)
    with pytest.raises(ValueError, match="use detect_objects\\('top'\\)"):
        as_point("top")
    with pytest.raises(ValueError, match="shape \\(40, 3\\)"):
        shape.shift(np.zeros((40, 3)), "left")
    with pytest.raises(ValueError, match="pass it whole"):
        objects.pass_through(curve(), np.array([0.3, 1.0, 1.0])[0])
    with pytest.raises(ValueError, match="midpoint"):
        objects.pass_through(curve(), [0.3, 1.0, 1.0], [0.6, 1.5, 1.0])
    with pytest.raises(ValueError, match="detect_objects\\('mug'\\)"):
        events.wait(curve(), "mug", 5)


def test_wait_takes_the_count_first_too() -> None:
    t = curve()
    assert np.array_equal(events.wait(t, 5, "middle"), events.wait(t, "middle", 5))
    assert np.array_equal(events.wait(t, 5, [0.3, 1.0, 1.0]), events.wait(t, [0.3, 1.0, 1.0], 5))
    assert len(events.wait(t, 10, 3)) == N + 3  # two numbers: index first, as documented


def test_speed_near_an_object_only() -> None:
    t, box = curve(), [0.3, 1.0, 1.0]
    out = speed.scale_speed(t, 0.5, near=box)
    k = int(np.argmin(distances(t, box)))
    assert np.isclose(out[k, 3], 0.5 * t[k, 3])
    assert np.allclose(out[[0, -1], 3], t[[0, -1], 3], rtol=0.02)
    assert np.array_equal(out[:, :3], t[:, :3])
    radius = speed.set_speed(t, 0.1, near=box, radius=0.2)
    inside = distances(t, box) <= 0.2
    assert np.allclose(radius[inside, 3], 0.1) and np.allclose(
        radius[distances(t, box) > 0.3, 3], t[distances(t, box) > 0.3, 3]
    )


def test_speed_globally_in_parts_and_profiles() -> None:
    t = curve()
    assert np.allclose(speed.scale_speed(t, 2.0)[:, 3], 2 * t[:, 3])
    middle = speed.scale_speed(t, 2.0, part="middle")
    assert np.isclose(middle[N // 2, 3], 2 * t[N // 2, 3]) and np.isclose(middle[0, 3], t[0, 3])
    assert np.allclose(speed.speed_profile(t, "constant", 0.2)[:, 3], 0.2)
    slow = speed.speed_profile(t, "decelerate", start=0.7)
    assert slow[-1, 3] == 0 and (np.diff(slow[75:, 3]) < 0).all() and np.allclose(slow[:60, 3], t[:60, 3])
    trapezoid = speed.speed_profile(t, "trapezoidal", 1.0)[:, 3]
    assert trapezoid[0] == 0 and trapezoid[-1] == 0 and np.isclose(trapezoid.max(), 1.0)
    rising = speed.speed_profile(t, "accelerate", 2.0)[:, 3]
    assert (np.diff(rising) >= 0).all()
    with pytest.raises(ValueError):
        speed.scale_speed(t, -1)


def test_stop_wait_extend_segment() -> None:
    t = curve()
    stopped = events.stop_at(t, t[30, :3])
    assert len(stopped) == 31 and stopped[-1, 3] == 0
    waited = events.wait(t, "middle", 5)
    assert (
        len(waited) == N + 5 and (waited[51:56, 3] == 0).all() and np.allclose(waited[51:56, :3], t[50, :3])
    )
    longer = events.extend(t, 0.4)
    assert len(longer) == N + 10 and np.allclose(longer[: N - 1], t[: N - 1])
    heading = (t[-1, :3] - t[-2, :3]) / np.linalg.norm(t[-1, :3] - t[-2, :3])
    assert np.allclose(longer[-1, :3], t[-1, :3] + 0.4 * heading)
    left = events.extend(t, 0.2, "left")
    assert np.isclose(left[-1, 0] - t[-1, 0], 0.2)
    assert np.allclose(events.extend(t, 0.4, "goal"), longer)  # "towards the goal": the final heading
    segment = events.append_segment(t, [1, 1, 1], count=5)
    assert np.allclose(segment[-1, :3], [1, 1, 1]) and segment[-1, 3] == 0 and segment[N - 1, 3] > 0


def test_going_on_keeps_the_pace_the_path_arrives_with() -> None:
    t = curve()
    t[:, 3] = np.linspace(1.0, 0.0, N)  # fastest at the start, slowing to rest at the goal
    longer = events.extend(t, 0.2)
    pace = longer[N, 3]
    assert np.allclose(longer[N - 1 : -1, 3], pace) and longer[-1, 3] == 0
    assert 0.1 < pace < 0.5  # the pace of its final approach: no spell at the top speed, no crawl
    cruise = np.r_[np.full(N - 8, 0.8), np.linspace(0.8, 0.0, 8)]  # slows over its last waypoints
    t[:, 3] = cruise
    assert np.isclose(events.going_on_pace(t), 0.8)
    t[:, 3] = 0.5
    assert np.allclose(events.extend(t, 0.2)[N - 1 : -1, 3], 0.5)  # not at rest: its own speed


def test_spiral_and_circle() -> None:
    t = curve()
    at_goal = events.spiral(t, 0.1, turns=3)
    extra = at_goal[N:, :3]
    assert len(at_goal) > N and np.linalg.norm(extra - t[-1, :3], axis=1).max() <= 0.1 + 1e-9
    angles = np.unwrap(np.arctan2(extra[:, 1] - t[-1, 1], extra[:, 0] - t[-1, 0]))
    assert abs(angles[-1] - angles[0]) > 2 * np.pi * 2.5
    box = [0.5, 1.0, 1.0]
    around = events.circle_around(t, box, turns=1)
    assert np.allclose(around[-1], t[-1]) and len(around) > N
    loop_angles = np.unwrap(np.arctan2(around[:, 1] - 1.0, around[:, 0] - 0.5))
    assert np.ptp(loop_angles) > 1.8 * np.pi
    inserted = events.spiral(t, 0.1, at=box)
    assert np.allclose(inserted[-1], t[-1])


def test_heights_sides_rotation_scaling() -> None:
    t = curve()
    level = shape.set_height(t, 0.5, keep_start=False, keep_goal=False)
    assert np.allclose(level[:, 2], 0.5)
    kept = shape.set_height(t, 0.5)
    assert np.allclose(kept[[0, -1]], t[[0, -1]]) and np.isclose(kept[N // 2, 2], 0.5)
    assert shape.stay_above(t, 1.2)[:, 2].min() == 1.2 and shape.stay_below(t, 0.8)[:, 2].max() == 0.8
    right_of = shape.keep_side(t, "right", [0.1, 0, 0])
    assert right_of[:, 0].max() <= 0.1 + 1e-12
    turned = shape.rotate(t, 90)
    assert np.allclose(turned[0], t[0])
    assert np.isclose(turned[-1, 0], t[0, 0] - 2.0) and np.isclose(
        turned[-1, 1], t[0, 1]
    )  # front -> right (-x)
    doubled = shape.scale_about(t, [0, 1, 1], 2.0, keep_ends=False)
    assert np.allclose(distances(doubled, [0, 1, 1]), 2 * distances(t, [0, 1, 1]))
    bent = shape.exaggerate_curve(t, 2.0)
    assert np.isclose(bent[N // 2, 0], 2 * t[N // 2, 0], atol=0.01) and np.allclose(bent[[0, -1]], t[[0, -1]])


def test_zigzag_smooth_resample_noise() -> None:
    t = curve()
    zig = shape.zigzag(t, 0.05, cycles=4)
    sideways = zig[:, 0] - t[:, 0]
    assert np.allclose(zig[[0, -1]], t[[0, -1]]) and np.sum(np.diff(np.sign(sideways[5:-5])) != 0) >= 6
    noisy = shape.add_noise(t, 0.01)
    assert np.allclose(noisy[[0, -1]], t[[0, -1]]) and 0 < np.abs(noisy - t).max() < 0.06
    smoothed = shape.smooth(noisy, 0.5)
    assert (
        np.abs(np.diff(smoothed[:, :3], n=2, axis=0)).max() < np.abs(np.diff(noisy[:, :3], n=2, axis=0)).max()
    )
    assert np.allclose(smoothed[[0, -1]], noisy[[0, -1]])
    more = shape.resample(t, 2 * N)
    assert len(more) == 2 * N and np.allclose(more[[0, -1]], t[[0, -1]])
    fewer = shape.resample(t, 10)
    assert len(fewer) == 10 and (fewer[:, 3] >= 0).all()


def test_smoothing_at_its_default_strength_takes_out_most_of_a_wiggle() -> None:
    s = np.linspace(0.0, 1.0, 40)
    wiggle = 0.02 * np.sin(2 * np.pi * np.arange(40) / 8)  # 8 waypoints long
    t = np.stack([s, 0.3 * np.sin(np.pi * s) + wiggle, np.zeros(40), np.ones(40)], axis=1)

    def roughness(path: np.ndarray) -> float:
        bends = np.linalg.norm(np.diff(path[:, :3], n=2, axis=0), axis=1).sum()
        return float(bends / np.linalg.norm(np.diff(path[:, :3], axis=0), axis=1).sum())

    smoothed = shape.smooth(t)
    assert roughness(smoothed) < 0.5 * roughness(t) and np.allclose(smoothed[[0, -1]], t[[0, -1]])
    paused = events.wait(t, "middle", 10)
    still = shape.smooth(paused)
    pause = paused[:, 3] == 0
    assert np.array_equal(still[pause], paused[pause])  # a pause stays a pause


def test_every_skill_is_documented_and_listed() -> None:
    text = describe_skills()
    for function in SKILLS:
        assert function.__doc__ and function.__name__ + "(" in text
    assert "axes" not in text
    assert "resample(trajectory, count)" in text  # a required parameter is never hidden
    assert "move_closer(trajectory, point, amount=None)" in text  # keyword-only knobs are the pipeline's
    assert "scale_speed(trajectory, factor, near=None, radius=None, part=None)" in text


def test_a_zero_amount_means_the_default_amount() -> None:
    t = curve()
    assert np.allclose(shape.shift(t, "back", 0), shape.shift(t, "back"))
    assert not np.allclose(shape.shift(t, "back", 0), t)


@pytest.mark.parametrize(
    ("word", "advice"),
    [
        ("away", "use move_away"),
        ("closer", "move_closer"),
        ("goal", "use shift_goal"),
        ("middle", "part='middle'"),
        ("x", "use one of"),
    ],
)
def test_wrong_direction_words_say_what_to_use(word: str, advice: str) -> None:
    with pytest.raises(ValueError, match=advice.replace("(", "\\(")):
        shape.shift(curve(), word, 0.1)


def test_a_bend_near_the_goal_passes_through_without_blowing_up(ovita_dir: Path) -> None:
    case = load_case(
        ovita_dir / "manipulator" / "trajectory_16.json"
    )  # a path whose steps shrink near the goal
    t = case.trajectory.array.copy()
    found = {o.name: np.array(o.position) for o in case.scene.objects}
    target = objects.midpoint(found["banana"], found["glue"])
    out = objects.pass_through(t, target)
    before = np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max()
    after = np.linalg.norm(np.diff(out[:, :3], axis=0), axis=1).max()
    assert np.linalg.norm(out[:, :3] - target, axis=1).min() < 1e-9  # through it exactly
    assert np.allclose(out[[0, -1], :3], t[[0, -1], :3])  # the ends stay
    assert after <= 3 * before  # no gap (the old end correction made it 3.6x)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.floats(-1.0, 1.0), min_size=8, max_size=40), st.floats(-0.5, 0.5))
def test_a_height_limit_that_keeps_the_ends_holds_between_them(heights: list[float], limit: float) -> None:
    n = len(heights)
    path = np.column_stack([np.linspace(0, 2, n), np.zeros(n), heights, np.ones(n)])
    above = stay_above(path, limit, keep_ends=True)
    below = stay_below(path, limit, keep_ends=True)
    inner = (progress(path) >= 0.1) & (progress(path) <= 0.9)  # the skill weighs the path it is given
    assert (above[inner, 2] >= limit - 1e-9).all() and (below[inner, 2] <= limit + 1e-9).all()
    assert np.allclose(above[[0, -1]], path[[0, -1]]) and np.allclose(below[[0, -1]], path[[0, -1]])

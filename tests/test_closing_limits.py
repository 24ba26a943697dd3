"""The limits a program sets at its close hold together (checks.closing_limits; issue #24 item 4)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.checks.closing_limits import closing_limits, hold_closing_limits, kept_clearances
from trajadapt.checks.constraints import constraints_for, new_violations
from trajadapt.checks.projection import project
from trajadapt.model.case import load_case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.skills import bind_skills

SKILLS = bind_skills()
SCENE = Scene(objects=(SceneObject("person", 0.0, 0.0, 0.3), SceneObject("box", 0.5, 0.5, 0.0)))


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def dipping_path(depth: float = -0.3, n: int = 40) -> np.ndarray:
    """A path that dips below the person on its way across."""
    s = np.linspace(0.0, 1.0, n)
    return np.column_stack(
        [-1.0 + 2.0 * s, 0.05 * np.sin(3 * s), 0.8 + (depth - 0.8) * np.sin(np.pi * s), np.ones(n)]
    )


def run(code: str, path: np.ndarray) -> np.ndarray:
    """The program's steps applied in order, as the sandbox would (skills only)."""
    t = path.copy()
    for line in code.splitlines()[1:-1]:
        t = eval(line.split("=", 1)[1], {**SKILLS, "t": t, "detect_objects": _detect})  # noqa: S307 - test programs
    return t


def _detect(name: str) -> list[float]:
    found = SCENE.find(name)
    assert found is not None
    return list(found.position)


def clearance(t: np.ndarray, name: str) -> float:
    return float(np.linalg.norm(t[:, :3] - np.asarray(_detect(name)), axis=1).min())


CLEAR_THEN_ABOVE = program("t = avoid(t, detect_objects('person'), 0.6)", "t = stay_above(t, 0.2)")


def test_a_height_limit_that_breaks_the_clearance_before_it_is_held_with_it():
    ran = run(CLEAR_THEN_ABOVE, dipping_path())
    assert clearance(ran, "person") < 0.6  # the later limit broke the earlier one, as written
    held, note = hold_closing_limits(CLEAR_THEN_ABOVE, ran, SCENE)
    assert clearance(held, "person") >= 0.6 - 1e-6 and held[:, 2].min() >= 0.2 - 1e-9
    assert note is not None and "clearance 0.6 from person" in note


@settings(max_examples=30, deadline=None)
@given(
    depth=st.floats(-0.6, 0.6),
    clear=st.floats(0.1, 0.7),
    floor=st.floats(0.0, 0.4),
    order=st.booleans(),
)
def test_closing_limits_hold_together_or_the_result_stays(depth, clear, floor, order):
    clear, floor = round(clear, 3), round(floor, 3)  # as the program says them
    steps = [f"t = avoid(t, detect_objects('person'), {clear})", f"t = stay_above(t, {floor})"]
    code = program(*(steps if order else steps[::-1]))
    ran = run(code, dipping_path(depth))
    held, note = hold_closing_limits(code, ran, SCENE)
    if note is None:
        np.testing.assert_array_equal(held, ran)
    else:
        assert clearance(held, "person") >= clear - 1e-6 and held[:, 2].min() >= floor - 1e-6
        np.testing.assert_array_equal(held[:, 3], ran[:, 3])  # speeds are not the limits' business


@pytest.mark.parametrize(
    "code",
    [
        # a step after the limits is the program's own business ("end at the box")
        program(
            "t = avoid(t, detect_objects('person'), 0.6)",
            "t = stay_above(t, 0.2)",
            "t = reach(t, detect_objects('person'))",
        ),
        # one closing limit keeps itself
        program("t = shift(t, 'down', 0.5)", "t = avoid(t, detect_objects('person'), 0.6)"),
        # a clearance that is no literal, or from a point that is no scene object, is not read
        program("t = avoid(t, detect_objects('person'), 2 * 0.3)", "t = stay_above(t, 0.2)"),
        program("t = avoid(t, [0, 0, 0.3], 0.6)", "t = stay_above(t, 0.2)"),
        program("t = avoid(t, detect_objects('ghost'), 0.6)", "t = stay_above(t, 0.2)"),
    ],
)
def test_only_a_closing_run_of_readable_limits_is_held(code):
    path = run(
        program("t = avoid(t, detect_objects('person'), 0.6)", "t = stay_above(t, 0.2)"), dipping_path()
    )
    held, note = hold_closing_limits(code, path, SCENE)
    assert note is None
    np.testing.assert_array_equal(held, path)


def test_the_closing_run_is_read_in_order_with_lists_of_objects():
    code = program(
        "t = shift(t, 'up')",
        "t = stay_below(t, 1.5)",
        "t = avoid(t, [detect_objects('person'), detect_objects('box')], 0.25)",
    )
    limits = closing_limits(code, SCENE)
    assert [(x.skill, x.value, x.names) for x in limits] == [
        ("stay_below", 1.5, ()),
        ("avoid", 0.25, ("person", "box")),
    ]


def test_a_limit_that_keeps_the_ends_is_held_between_them():
    code = program("t = avoid(t, detect_objects('person'), 0.6)", "t = stay_above(t, 0.2, keep_ends=True)")
    path = dipping_path()
    path[[0, -1], 2] = 0.0  # the path starts and ends on the floor
    ran = run(code, path)
    held, note = hold_closing_limits(code, ran, SCENE)
    (_, limit) = closing_limits(code, SCENE)
    assert limit.keep_ends and limit.holds(held) and note is not None
    assert clearance(held, "person") >= 0.6 - 1e-6
    np.testing.assert_allclose(held[[0, -1], 2], 0.0, atol=1e-9)  # its ends stay on the floor


def test_a_pace_between_the_limits_does_not_end_the_closing_run() -> None:
    code = program(
        "t = avoid(t, detect_objects('person'), 0.6)",
        "t = scale_speed(t, 0.65, near=detect_objects('box'))",
        "t = stay_above(t, 0.2)",
    )
    assert [limit.skill for limit in closing_limits(code, SCENE)] == ["avoid", "stay_above"]
    assert kept_clearances(code, SCENE) == (((0.0, 0.0, 0.3), 0.6),)


def test_a_limit_before_a_step_on_its_object_is_no_kept_clearance() -> None:
    code = program(
        "t = avoid(t, detect_objects('person'), 0.6)", "t = pass_through(t, detect_objects('person'))"
    )
    assert kept_clearances(code, SCENE) == ()


def test_a_limit_before_a_step_on_other_things_is_a_kept_clearance() -> None:
    code = program("t = avoid(t, detect_objects('person'), 0.6)", "t = reach(t, detect_objects('box'))")
    assert kept_clearances(code, SCENE) == (((0.0, 0.0, 0.3), 0.6),)


def test_a_clearance_a_later_move_broke_is_held_with_the_ends_where_the_program_put_them() -> None:
    code = program("t = avoid(t, detect_objects('person'), 0.6)", "t = shift_part(t, 'down', 0.4, 'middle')")
    ran = run(code, dipping_path(depth=0.9))
    assert clearance(ran, "person") < 0.6  # the later move broke the clearance, as written
    held, note = hold_closing_limits(code, ran, SCENE)
    assert clearance(held, "person") >= 0.6 - 1e-6
    np.testing.assert_array_equal(held[[0, -1]], ran[[0, -1]])
    assert note is not None and "clearance 0.6 from person" in note


def test_a_clearance_that_would_move_an_end_is_not_held() -> None:
    code = program("t = avoid(t, detect_objects('person'), 0.6)", "t = reach(t, [0.0, 0.0, 0.0])")
    ran = run(code, dipping_path())
    held, note = hold_closing_limits(code, ran, SCENE)
    assert note is None
    np.testing.assert_array_equal(held, ran)


@pytest.mark.parametrize(("name", "clearance"), [("fan", 1.0), ("bed", 0.8)])
def test_pulling_a_path_back_inside_its_bounds_keeps_the_programs_clearance(
    ovita_dir, name, clearance
) -> None:
    """ground_robot/trajectory_22: ``avoid`` pushed the path past y = -3; the projection undid the clearance."""
    case = load_case(ovita_dir / "ground_robot" / "trajectory_22.json")
    original, found = case.trajectory.array, case.scene.find(name)
    assert found is not None
    ran = SKILLS["avoid"](original, [list(found.position)], clearance)
    limits = constraints_for(case.scene)
    assert new_violations(ran, original, case.scene, limits)  # the avoid leaves the bounds
    projected = project(ran, original, case.scene, limits, [(found.position, clearance)])
    nearest = np.linalg.norm(projected.trajectory[:, :3] - np.asarray(found.position), axis=1).min()
    assert nearest >= clearance - 1e-6 and not projected.remaining
    assert not projected.far_sides  # there is room on the side the path passes


@pytest.mark.parametrize("clearance", [0.6, 0.8, 1.0])
def test_a_clearance_the_bounds_leave_no_room_for_goes_round_the_objects_other_side(
    ovita_dir, clearance
) -> None:
    """ground_robot/trajectory_12: the bottle is 0.5 from the wall y = -3, which the path runs along."""
    case = load_case(ovita_dir / "ground_robot" / "trajectory_12.json")
    original, bottle = case.trajectory.array, case.scene.find("bottle")
    assert bottle is not None
    ran = SKILLS["avoid"](original, [list(bottle.position)], clearance)
    limits = constraints_for(case.scene)
    projected = project(ran, original, case.scene, limits, [(bottle.position, clearance)])
    closest = int(
        np.argmin(np.linalg.norm(projected.trajectory[:, :3] - np.asarray(bottle.position), axis=1))
    )
    assert nearest(projected.trajectory, bottle.position) >= clearance - 1e-6 and not projected.remaining
    assert projected.trajectory[closest, 1] > bottle.position[1]  # the wall's side is y < -2.5
    assert projected.far_sides == ("the bottle",) and "other side of the bottle" in projected.describe()


def test_going_round_the_far_side_does_not_pull_the_path_across_the_scene(ovita_dir) -> None:
    """ground_robot/trajectory_12 with its goal moved: the detour round the bottle stays without a jump."""
    case = load_case(ovita_dir / "ground_robot" / "trajectory_12.json")
    original, bottle = case.trajectory.array, case.scene.find("bottle")
    assert bottle is not None
    ran = SKILLS["avoid"](SKILLS["shift_goal"](original, "left", 1.0), [list(bottle.position)], 0.8)
    limits = constraints_for(case.scene)
    projected = project(ran, original, case.scene, limits, [(bottle.position, 0.8)])
    steps = np.linalg.norm(np.diff(projected.trajectory[:, :3], axis=0), axis=1)
    assert not projected.remaining
    assert steps.max() <= 2 * np.linalg.norm(np.diff(original[:, :3], axis=0), axis=1).max()


OVERLAPPING = Scene(objects=(SceneObject("fan", 0.0, 0.3, 0.0), SceneObject("bottle", 0.5, -0.3, 0.0)))


def straight_between(n: int = 40) -> np.ndarray:
    """A floor path that runs between the fan and the bottle, closer to each than 0.5."""
    s = np.linspace(0.0, 1.0, n)
    return np.column_stack([-1.5 + 3.0 * s, np.zeros(n), np.zeros(n), np.ones(n)])


def nearest(t: np.ndarray, point: tuple[float, float, float]) -> float:
    return float(np.linalg.norm(t[:, :3] - np.asarray(point), axis=1).min())


@pytest.mark.parametrize("clear", [0.45, 0.5, 0.6])
def test_one_avoid_of_two_points_whose_clearances_overlap_keeps_both(clear: float) -> None:
    fan, bottle = (0.0, 0.3, 0.0), (0.5, -0.3, 0.0)
    held = SKILLS["avoid"](straight_between(), [list(fan), list(bottle)], clear)
    assert nearest(held, fan) >= clear * (1 - 1e-9) and nearest(held, bottle) >= clear * (1 - 1e-9)


@pytest.mark.parametrize("clear", [0.45, 0.5, 0.6])
def test_two_closing_avoids_whose_clearances_overlap_are_held_together(clear: float) -> None:
    code = program(
        f"t = avoid(t, detect_objects('fan'), {clear})",
        f"t = avoid(t, detect_objects('bottle'), {clear})",
        "t = speed_profile(t, 'decelerate', start=0.6)",
    )
    fan, bottle = (0.0, 0.3, 0.0), (0.5, -0.3, 0.0)
    ran = SKILLS["avoid"](SKILLS["avoid"](straight_between(), list(fan), clear), list(bottle), clear)
    held, note = hold_closing_limits(code, ran, OVERLAPPING)
    assert nearest(held, fan) >= clear - 1e-6 and nearest(held, bottle) >= clear - 1e-6
    if nearest(ran, fan) < clear - 1e-6:
        assert note is not None and f"the clearance {clear:g} from fan" in note


def test_no_earlier_clearance_is_kept_where_a_later_step_goes_by_a_point_given_otherwise() -> None:
    code = program("t = avoid(t, detect_objects('person'), 0.6)", "t = move_closer(t, [0.0, 0.0, 0.3], 0.5)")
    assert kept_clearances(code, SCENE) == ()


def test_avoid_on_the_far_side_takes_the_path_round_the_points_other_side() -> None:
    path = straight_between()  # passes the bottle at (0.5, -0.3) on its +y side
    near, far = (SKILLS["avoid"](path, [0.5, -0.3, 0.0], 0.5, far_side=side) for side in (False, True))
    for held in (near, far):
        assert nearest(held, (0.5, -0.3, 0.0)) >= 0.5 - 1e-9
        np.testing.assert_allclose(held[[0, -1]], path[[0, -1]])
    beside = int(np.argmin(np.abs(path[:, 0] - 0.5)))
    assert near[beside, 1] > -0.3 + 0.45 and far[beside, 1] < -0.3 - 0.45

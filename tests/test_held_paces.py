"""A pace the words state near an object holds over the stretch nearest it; a vague one fades."""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.bench.judges import CheckContext, run_check
from trajadapt.model.geometry import PAPER_AXES
from trajadapt.readers import read_against_words
from trajadapt.readers.held_paces import hold_stated_paces
from trajadapt.skills.speed import held_zone, scale_speed

NAMES = ["kettle", "lamp", "red mug"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def near(factor: float, name: str = "kettle") -> str:
    return f"t = scale_speed(t, {factor}, near=detect_objects('{name}'))"


def held(factor: float, name: str = "kettle") -> str:
    return f"t = scale_speed(t, {factor}, near=detect_objects('{name}'), held=True)"


@pytest.mark.parametrize(
    ("words", "factor"),
    [
        ("go past the kettle at half your speed", 0.5),
        ("cut the pace by 40% when you are beside the kettle", 0.6),
        ("creep by the kettle at a third of the current speed, and keep 10 cm from the lamp", 1 / 3),
        ("by the kettle, run twice as fast", 2.0),
        ("ease right off as you near the kettle, to half speed or so", 0.5),
        ("keep 20 cm off the lamp; halve the speed around the kettle", 0.5),
    ],
)
def test_a_factor_the_words_state_near_the_object_is_held(words: str, factor: float) -> None:
    code, notes = hold_stated_paces(program(near(round(factor, 6))), [words], NAMES)
    assert code == program(held(round(factor, 6)))
    assert notes == [
        f"`{near(round(factor, 6))}` -> `{held(round(factor, 6))}`: the words state the pace near kettle, "
        "so it holds there"
    ]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("slow down near the kettle", near(0.65)),  # vague: the fading zone is what it means
        ("go a lot faster by the kettle", near(1.6)),
        ("halve the speed near the lamp and slow down by the kettle", near(0.5)),  # another object's number
        ("slow down near the kettle over the final 30 percent of the path", near(0.7)),  # a share of the path
        ("go at half speed near the kettle", near(0.65)),  # a factor the step does not write
        (
            "go at half speed near the kettle",
            "t = scale_speed(t, 0.5, near=detect_objects('kettle'), radius=0.2)",
        ),
        ("go at half speed everywhere", "t = scale_speed(t, 0.5)"),
    ],
)
def test_a_pace_the_words_do_not_state_there_is_left_as_written(words: str, step: str) -> None:
    assert hold_stated_paces(program(step), [words], NAMES) == (program(step), [])


def test_the_readers_hold_a_stated_pace() -> None:
    code, notes = read_against_words(
        program(near(0.5)), ["halve the speed in the vicinity of the kettle"], NAMES
    )
    assert code == program(held(0.5))
    assert [note.reader for note in notes] == ["held-paces"]


def path_by(point: np.ndarray) -> np.ndarray:
    """A straight path of 60 waypoints at speed 1 that passes 0.1 from ``point`` half-way."""
    x = np.linspace(-1.0, 1.0, 60)
    return np.stack([x, np.full(60, point[1] - 0.1), np.full(60, point[2]), np.ones(60)], axis=1)


def test_a_held_factor_is_met_over_the_stretch_nearest_the_object_and_the_rest_keeps_its_speed() -> None:
    point = np.array([0.0, 0.5, 0.0])
    original = path_by(point)
    adapted = scale_speed(original, 0.5, near=point, held=True)
    context = CheckContext(original, adapted, {"kettle": point}, PAPER_AXES)
    verdict = run_check(context, {"kind": "speed_near", "object": "kettle", "relation": "lower", "by": 0.45})
    assert verdict.passed, verdict.detail
    faded = scale_speed(original, 0.5, near=point)
    nearest = np.argsort(np.linalg.norm(original[:, :3] - point, axis=1))[:15]
    assert adapted[nearest, 3].mean() < faded[nearest, 3].mean()
    assert adapted[:5, 3].min() > 0.98 and adapted[-5:, 3].min() > 0.98


def test_the_held_zone_is_whole_by_the_object_and_nothing_far_from_it() -> None:
    point = np.array([0.0, 0.5, 0.0])
    weight = held_zone(path_by(point), point)
    assert weight[29] == weight[30] == 1.0
    assert weight[0] < 0.01 and weight[-1] < 0.01
    assert np.all(np.diff(weight[:30]) >= 0) and np.all(np.diff(weight[30:]) <= 0)


def test_the_step_keeps_the_programs_own_variable() -> None:
    code = "\n".join(
        [
            "traj = get_trajectory()",
            "traj = scale_speed(traj, 0.5, near=detect_objects('kettle'))",
            "modified_trajectory = traj",
        ]
    )
    held_code, _ = hold_stated_paces(code, ["halve the speed near the kettle"], NAMES)
    assert (
        held_code.splitlines()[1] == "traj = scale_speed(traj, 0.5, near=detect_objects('kettle'), held=True)"
    )

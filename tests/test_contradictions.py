"""The effect's flags read each clause as the readers do: no false alarm where the result does what is asked.

Wordings here are written for these tests (no benchmark set has them): objects crossed between
clauses, negated comparisons, a side, a height, a midpoint, a part of the path, a statement of how
the path is now. The true contradictions still fire.
"""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.checks.contradictions import contradictions
from trajadapt.checks.effect import Effect, measure_effect
from trajadapt.model.scene import SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.skills import bind_skills

SKILLS = bind_skills()
KETTLE = SceneObject("kettle", 0.3, 0.3, 0.5)
VASE = SceneObject("vase", -0.1, 0.8, 0.5)
SCENE = [KETTLE, VASE]


def line() -> np.ndarray:
    """A straight line along +y at x = 0, z = 0.5, speed 1, 41 waypoints."""
    y = np.linspace(0.0, 1.0, 41)
    return np.column_stack([np.zeros(41), y, np.full(41, 0.5), np.ones(41)])


def effect_of(*steps: tuple[str, tuple, dict]) -> Effect:
    """The measured effect of the skill steps run in order on ``line()``."""
    t = line()
    for name, args, kwargs in steps:
        t = SKILLS[name](t, *args, **kwargs)
    return measure_effect(Trajectory.from_rows(line()), Trajectory.from_rows(t), SCENE)


def at(obj: SceneObject) -> list[float]:
    return [obj.x, obj.y, obj.z]


CLOSER_TO_KETTLE_SLOWER_AT_VASE = effect_of(
    ("move_closer", (at(KETTLE),), {}), ("scale_speed", (0.6,), {"near": at(VASE), "radius": 0.2})
)


@pytest.mark.parametrize(
    "words",
    [
        "Head nearer the kettle, and ease off within 0.2 of the vase",
        "Within 0.2 of the vase take it slower; also hug the kettle",
        "It keeps too far from the kettle. Get nearer to the kettle and go slower within 0.2 of the vase.",
    ],
)
def test_two_clauses_two_objects_each_read_against_its_own_clause(words: str) -> None:
    assert contradictions(words, CLOSER_TO_KETTLE_SLOWER_AT_VASE) == []


def test_each_clause_is_flagged_against_its_own_object() -> None:
    flags = contradictions(
        "Keep clear of the kettle and speed up near the vase", CLOSER_TO_KETTLE_SLOWER_AT_VASE
    )
    assert any(flag.startswith("the instruction asks to keep away from the kettle") for flag in flags)
    slower_at_vase = effect_of(("scale_speed", (0.6,), {"near": at(VASE), "radius": 0.2}))
    flags = contradictions("Move further from the kettle and speed up near the vase", slower_at_vase)
    assert any(flag.startswith("the instruction names the kettle, but neither") for flag in flags)
    assert any(flag.startswith("the instruction asks for faster near the vase") for flag in flags)


@pytest.mark.parametrize(
    ("words", "factor", "flagged"),
    [
        ("don't zoom about near the kettle", 0.6, False),
        ("don't go nearly as fast around the kettle", 0.6, False),
        ("don't crawl by the kettle", 1.5, False),
        ("don't zoom about near the kettle", 1.5, True),
    ],
)
def test_a_negated_pace_near_an_object_is_read_as_what_it_asks(
    words: str, factor: float, flagged: bool
) -> None:
    effect = effect_of(("scale_speed", (factor,), {"near": at(KETTLE)}))
    assert bool(contradictions(words, effect)) is flagged


def test_a_negated_pace_of_the_whole_path() -> None:
    faster = effect_of(("scale_speed", (1.4,), {}))
    assert contradictions("stop plodding along", faster) == []
    assert contradictions("don't hurry", faster)[0].startswith(
        "the instruction asks for slower, but the mean speed rose"
    )


def test_a_side_and_a_height_are_places_not_moves() -> None:
    right = effect_of(("keep_side", ("right", at(KETTLE)), {}))
    assert contradictions("never pass left of the kettle", right) == []
    lowered = effect_of(("set_height", (0.2,), {}))
    assert contradictions("cruise at an altitude of 0.2 above the floor", lowered) == []


def test_an_object_only_named_or_a_part_moved_is_no_untouched_object() -> None:
    through = effect_of(("pass_through", ([0.1, 0.55, 0.5],), {}))
    assert contradictions("go via the point halfway between the kettle and the vase", through) == []
    start_only = effect_of(("move_closer", (at(VASE),), {"part": (0, 5)}))
    assert contradictions("pull the first five waypoints towards the vase", start_only) == []


def test_true_contradictions_still_fire() -> None:
    away = effect_of(("move_away", (at(KETTLE), 0.2), {}))
    assert contradictions("come in closer to the kettle", away)[0].startswith(
        "the instruction asks to get closer to the kettle, but the distance near it grew"
    )
    assert contradictions("steer clear of the kettle", away) == []
    closer = effect_of(("move_closer", (at(KETTLE),), {}))
    assert contradictions("steer clear of the kettle", closer)[0].startswith(
        "the instruction asks to keep away"
    )
    untouched = effect_of(("scale_speed", (1.0,), {}))
    assert contradictions("come in nearer to the vase", untouched)[0].startswith(
        "the instruction names the vase, but neither"
    )
    assert contradictions("drift to the right a little", effect_of(("shift", ("left", 0.1), {}))) == [
        "the instruction says right, but the path moved left on average"
    ]


def test_feedback_is_read_beside_the_instruction() -> None:
    closer = effect_of(("move_closer", (at(KETTLE),), {}))
    assert contradictions(["go up a bit", "and keep further from the kettle"], closer)[0].startswith(
        "the instruction asks to keep away from the kettle"
    )


def test_a_distance_asked_that_did_not_change_is_flagged() -> None:
    paced = effect_of(("scale_speed", (0.6,), {"near": at(KETTLE)}))  # the speed changed, the path did not
    assert contradictions("come nearer to the kettle", paced) == [
        "the instruction asks to get closer to the kettle, but the distance near it did not change (0.309 -> 0.309)"
    ]
    assert contradictions("come nearer to the kettle", effect_of(("move_closer", (at(KETTLE),), {}))) == []


@pytest.mark.parametrize(
    "words",
    [
        "Keep the start and end points fixed and pull the middle to the left",
        "pull the middle to the left without moving the endpoints",
        "pull the middle leftwards; the start and goal positions should stay where they are",
    ],
)
def test_an_end_the_words_keep_where_it_is(words: str) -> None:
    moved = effect_of(("shift", ("left", 0.1), {}))
    assert any(flag.startswith("the words keep the goal where it is, but it moved 0.1 left") for flag in
               contradictions(words, moved))  # fmt: skip
    middle_only = effect_of(("shift_part", ("left", 0.1), {"part": "middle"}))
    assert not any("keep the" in flag for flag in contradictions(words, middle_only))


def test_keeping_on_is_no_end_kept() -> None:
    longer = effect_of(("extend", (0.3,), {}))
    assert contradictions("keep going past the goal for 0.3", longer) == []
    assert contradictions("leave the end smooth and carry on 0.3 further", longer) == []


def test_a_negated_pace_or_a_limit_asks_no_change() -> None:
    shifted_faster = effect_of(("scale_speed", (1.3,), {}))
    assert contradictions("go left, but don't slow down", shifted_faster) == []
    assert contradictions("never go slower than 0.5", shifted_faster) == []
    assert contradictions("ease off around corners", shifted_faster) == []  # a place, not the whole path


def test_a_clearance_that_already_holds_asks_no_change() -> None:
    untouched = effect_of(("scale_speed", (1.0,), {}))
    assert contradictions("keep at least 0.1 from the kettle", untouched) == []
    assert contradictions("avoid the vase", untouched) == []


def test_feedback_that_moves_a_kept_end_takes_the_keeping_back() -> None:
    moved = effect_of(("shift", ("left", 0.1), {}))
    assert contradictions(["keep the endpoints fixed", "now move the goal left"], moved) == []
    assert contradictions("don't change the end speed", moved) == []

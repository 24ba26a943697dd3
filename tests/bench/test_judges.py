"""Each expectation check passes a correct result and fails a wrong one; identity results fail."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from trajadapt.bench.judges import CHECKS, CheckContext, run_check
from trajadapt.bench.metrics import discrete_frechet, dynamic_time_warping, roughness
from trajadapt.bench.runner import discover_cases, evaluate
from trajadapt.model.case import load_case
from trajadapt.model.geometry import Axes
from trajadapt.skills import events, objects, shape, speed

N = 60
S = np.linspace(0.0, 1.0, N)
ORIGINAL = np.c_[0.3 * np.sin(np.pi * S), 2.0 * S, np.ones(N), 0.5 + 0.5 * np.sin(np.pi * S)]
OBJECTS = {
    "box": np.array([0.6, 1.0, 1.0]),
    "ball": np.array([-0.2, 1.5, 1.0]),
    "cup": np.array([0.35, 1.0, 0.5]),
}

Make = Callable[[np.ndarray], np.ndarray]


def shifted_whole(t: np.ndarray, vector: list[float]) -> np.ndarray:
    out = t.copy()
    out[:, :3] += vector
    return out


def zigzag_wrong(t: np.ndarray) -> np.ndarray:
    out = t.copy()
    out[:, 0] += 0.1
    return out


def with_speed(t: np.ndarray, value: float) -> np.ndarray:
    out = t.copy()
    out[:, 3] = value
    return out


def jump(t: np.ndarray) -> np.ndarray:
    out = t.copy()
    out[30:, 0] += 1.0
    return out


# (spec, correct result, wrong result)
CASES: list[tuple[dict[str, Any], Make, Make]] = [
    (
        {"kind": "shift", "direction": "left"},
        lambda t: shape.shift(t, "left", 0.2),
        lambda t: shape.shift(t, "right", 0.2),
    ),
    (
        {"kind": "shift", "direction": "right", "amount": 0.3},
        lambda t: shape.shift(t, "right", 0.3),
        lambda t: shape.shift(t, "right", 0.1),
    ),
    (
        {"kind": "shift", "direction": "up", "part": "goal", "amount": 0.2},
        lambda t: shape.shift_goal(t, "up", 0.2),
        lambda t: shape.shift_start(t, "up", 0.2),
    ),
    (
        {"kind": "start_kept"},
        lambda t: shape.shift_goal(t, "left", 0.3),
        lambda t: shape.shift_start(t, "left", 0.3),
    ),
    (
        {"kind": "goal_kept"},
        lambda t: shape.shift_start(t, "left", 0.3),
        lambda t: shape.shift_goal(t, "left", 0.3),
    ),
    (
        {"kind": "distance", "object": "box", "relation": "decreased"},
        lambda t: objects.move_closer(t, OBJECTS["box"]),
        lambda t: objects.move_away(t, OBJECTS["box"]),
    ),
    (
        {"kind": "distance", "object": "box", "relation": "increased"},
        lambda t: objects.move_away(t, OBJECTS["box"]),
        lambda t: objects.move_closer(t, OBJECTS["box"]),
    ),
    (
        {"kind": "distance", "object": "cup", "relation": "at_least", "value": 0.6},
        lambda t: objects.avoid(t, OBJECTS["cup"], 0.6),
        lambda t: t,
    ),
    (
        {"kind": "distance", "object": "box", "relation": "increased", "factor": 2},
        lambda t: shape.scale_about(t, OBJECTS["box"], 2.2, keep_ends=False),
        lambda t: objects.move_away(t, OBJECTS["box"], 0.05),
    ),
    (
        {"kind": "distance", "object": "ball", "relation": "decreased", "first": 10},
        lambda t: shape.shift_part(t, "right", 0.1, (0, 10)),
        lambda t: shape.shift_part(t, "right", 0.1, (40, 60)),
    ),
    (
        {"kind": "passes_near", "object": "box"},
        lambda t: objects.pass_through(t, OBJECTS["box"]),
        lambda t: t,
    ),
    (
        {"kind": "passes_near", "objects": ["box", "ball"]},
        lambda t: objects.pass_through(t, objects.midpoint(OBJECTS["box"], OBJECTS["ball"])),
        lambda t: objects.move_closer(t, OBJECTS["box"], 0.3),
    ),
    (
        {"kind": "ends_near", "object": "box", "stopped": True},
        lambda t: events.stop_at(t, OBJECTS["box"]),
        lambda t: t,
    ),
    (
        {"kind": "ends_near", "object": "ball", "at_object": True},
        lambda t: objects.reach(t, OBJECTS["ball"]),
        lambda t: events.stop_at(t, OBJECTS["box"]),
    ),
    (
        {"kind": "speed_near", "object": "box", "relation": "lower"},
        lambda t: speed.scale_speed(t, 0.5, near=OBJECTS["box"]),
        lambda t: speed.scale_speed(t, 0.5),
    ),
    (
        {"kind": "speed_near", "object": "box", "relation": "higher", "by": 0.3},
        lambda t: speed.scale_speed(t, 2.0, near=OBJECTS["box"]),
        lambda t: speed.scale_speed(t, 1.1, near=OBJECTS["box"]),
    ),
    (
        {
            "kind": "speed_near",
            "object": "cup",
            "relation": "equal",
            "value": 0.2,
            "radius": 0.6,
            "elsewhere_kept": False,
        },
        lambda t: speed.set_speed(t, 0.2, near=OBJECTS["cup"], radius=0.6),
        lambda t: speed.set_speed(t, 0.4, near=OBJECTS["cup"], radius=0.6),
    ),
    (
        {"kind": "speed", "relation": "lower", "by": 0.4},
        lambda t: speed.scale_speed(t, 0.5),
        lambda t: speed.scale_speed(t, 0.9),
    ),
    (
        {"kind": "speed", "part": "middle", "relation": "higher"},
        lambda t: speed.scale_speed(t, 2.0, part="middle"),
        lambda t: speed.scale_speed(t, 2.0, part="start"),
    ),
    (
        {"kind": "constant_speed", "value": 0.2},
        lambda t: speed.speed_profile(t, "constant", 0.2),
        lambda t: speed.speed_profile(t, "constant", 0.5),
    ),
    (
        {"kind": "decelerates", "after": 0.7, "final": 0},
        lambda t: speed.speed_profile(t, "decelerate", start=0.7),
        lambda t: speed.speed_profile(t, "accelerate", 2.0),
    ),
    ({"kind": "extends", "distance": 0.4}, lambda t: events.extend(t, 0.4), lambda t: events.extend(t, 0.1)),
    (
        {"kind": "extends", "direction": "back", "distance": 0.3},
        lambda t: events.extend(t, 0.3, "back"),
        lambda t: events.extend(t, 0.3, "front"),
    ),
    (
        {"kind": "loop", "turns": 3},
        lambda t: events.spiral(t, 0.1, turns=3),
        lambda t: events.spiral(t, 0.1, turns=1),
    ),
    ({"kind": "loop", "turns": 1}, lambda t: events.circle_around(t, OBJECTS["box"]), lambda t: t),
    (
        {"kind": "waypoints", "relation": "more"},
        lambda t: shape.resample(t, 2 * N),
        lambda t: shape.resample(t, N // 2),
    ),
    ({"kind": "waypoints", "relation": "fewer"}, lambda t: shape.resample(t, N // 2), lambda t: t),
    (
        {"kind": "waypoints", "relation": "delta", "delta": 5},
        lambda t: events.wait(t, "middle", 5),
        lambda t: events.wait(t, "middle", 3),
    ),
    (
        {"kind": "pause", "steps": 5},
        lambda t: events.wait(t, "middle", 5),
        lambda t: events.wait(t, "middle", 2),
    ),
    (
        {"kind": "pause", "steps": 4, "object": "ball"},
        lambda t: events.wait(t, OBJECTS["ball"], 4),
        lambda t: events.wait(t, "start", 4),
    ),
    (
        {"kind": "height", "min": 0.45, "max": 0.55, "middle_only": True},
        lambda t: shape.set_height(t, 0.5),
        lambda t: t,
    ),
    (
        {"kind": "side", "side": "right", "object": "box"},
        lambda t: shape.keep_side(t, "right", [0.1, 0, 0]),
        lambda t: shape.shift(t, "left", 0.5),
    ),
    ({"kind": "smooth"}, lambda t: shape.shift(t, "left", 0.3), jump),
    ({"kind": "zigzag", "swings": 4}, lambda t: shape.zigzag(t, 0.05, cycles=4), zigzag_wrong),
    ({"kind": "changed"}, lambda t: speed.scale_speed(t, 0.5), lambda t: t),
    ({"kind": "rotated", "degrees": 90}, lambda t: shape.rotate(t, 90), lambda t: shape.rotate(t, -90)),
    (
        {"kind": "bend", "relation": "more"},
        lambda t: shape.exaggerate_curve(t, 2.0),
        lambda t: shape.exaggerate_curve(t, 0.5),
    ),
    (
        {"kind": "smoother"},
        lambda t: shape.smooth(shape.add_noise(t, 0.01), 0.8),
        lambda t: shape.add_noise(t, 0.05),
    ),
    (
        {"kind": "passes_above", "objects": ["cup"]},
        lambda t: shape.lift_middle(shifted_whole(t, [0, 0, -0.45]), "up", 0.3),
        lambda t: shifted_whole(t, [0, 0, -0.7]),
    ),
]


def context(adapted: np.ndarray, original: np.ndarray = ORIGINAL) -> CheckContext:
    return CheckContext(original, adapted, OBJECTS, Axes())


def test_every_check_kind_is_covered() -> None:
    assert {spec["kind"] for spec, _, _ in CASES} == set(CHECKS)


@pytest.mark.parametrize(
    ("spec", "correct", "wrong"), CASES, ids=[f"{i}-{c[0]['kind']}" for i, c in enumerate(CASES)]
)
def test_check_passes_correct_and_fails_wrong(spec: dict[str, Any], correct: Make, wrong: Make) -> None:
    original = shape.add_noise(ORIGINAL, 0.002) if spec["kind"] == "smoother" else ORIGINAL
    good = run_check(context(correct(original), original), spec)
    bad = run_check(context(wrong(original), original), spec)
    assert good.passed, good.detail
    assert not bad.passed, bad.detail


def test_metrics() -> None:
    shifted = shifted_whole(ORIGINAL, [0.1, 0, 0])
    assert discrete_frechet(ORIGINAL, ORIGINAL) == 0
    assert np.isclose(discrete_frechet(ORIGINAL, shifted), 0.1)
    assert 0.05 * N < dynamic_time_warping(ORIGINAL, shifted) <= 0.1 * N + 1e-9
    assert dynamic_time_warping(ORIGINAL, ORIGINAL) == 0
    line = np.c_[np.zeros(N), S, np.zeros(N), np.ones(N)]
    assert roughness(line) < 1e-12 < roughness(ORIGINAL)


OWN_CASES = Path(__file__).resolve().parents[2] / "benchmarks" / "cases"


@pytest.fixture(params=["ovita-dev", "own"])
def case_folder(request: pytest.FixtureRequest, ovita_dir: Path) -> Path:
    return ovita_dir if request.param == "ovita-dev" else OWN_CASES


def test_own_cases_are_enough() -> None:
    assert len(discover_cases([OWN_CASES])) >= 40


def test_the_original_trajectory_fails_nearly_every_case(case_folder: Path) -> None:
    cases = discover_cases([case_folder])
    outcomes = []
    for case in cases:
        loaded = load_case(case.path)
        record = {"status": "ok", "error": None, "modified_trajectory": loaded.trajectory.to_rows()}
        evaluation = evaluate(case, loaded, record, Axes())
        if evaluation["judged"]:
            outcomes.append(evaluation["passed"])
    assert len(outcomes) >= 40
    assert sum(outcomes) <= 0.02 * len(outcomes)


def test_expectations_name_existing_objects(case_folder: Path) -> None:
    for case in discover_cases([case_folder]):
        expectation = case.expectations.cases[case.key] if case.expectations else None
        assert expectation is not None, f"{case.key} has no expectation"
        names = {obj.name.casefold() for obj in load_case(case.path).scene.objects}
        for spec in expectation.checks:
            for name in spec.get("objects", [spec["object"]] if "object" in spec else []):
                assert name in names, f"{case.key}: {name!r} not in {names}"

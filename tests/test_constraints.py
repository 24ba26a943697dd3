"""Constraints: parsed from case texts, measured on results, repaired by the LLM or projected."""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.checks.constraints import (
    Constraints,
    constraints_for,
    find_violations,
    new_violations,
    parse_constraints_text,
)
from trajadapt.checks.projection import project
from trajadapt.model.case import Case, load_case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings


def test_parses_every_constraint_text_in_the_ovita_cases(ovita_dir: Path) -> None:
    texts = {load_case(path).scene.constraints for path in ovita_dir.rglob("*.json")}
    parsed = {text: parse_constraints_text(text) for text in texts}
    drone = next(c for t, c in parsed.items() if "drone's operational envelope" in t)
    assert drone.lower == (-2, -3, 0) and drone.upper == (2, 3, 2)
    room = next(c for t, c in parsed.items() if "minimum distance of 0.1" in t)
    assert room.lower == (-4, -3, 0) and room.upper == (4, 2, 0) and room.min_clearance == 0.1
    ground = next(c for t, c in parsed.items() if "maximum x of 3" in t)
    assert ground.upper[0] == 3 and ground.lower[0] == -4 and ground.upper[2] == 0
    assert parse_constraints_text("").empty


def test_original_cases_do_not_break_their_own_constraints_by_our_reading(ovita_dir: Path) -> None:
    for path in ovita_dir.rglob("*.json"):
        case = load_case(path)
        limits = constraints_for(case.scene)
        assert new_violations(case.trajectory.array, case.trajectory.array, case.scene, limits) == []


def test_violations_are_measured() -> None:
    t = np.c_[np.linspace(0, 1, 10), np.zeros(10), np.zeros(10), np.ones(10)]
    scene = Scene((SceneObject("box", 0.5, 0.05, 0),))
    limits = Constraints(upper=(0.8, math.inf, math.inf), min_clearance=0.2, max_speed=0.5)
    messages = [v.message for v in find_violations(t, t, scene, limits)]
    assert any("x above 0.8 (highest 1)" in m for m in messages)
    assert any("within 0.07474 of box; keep 0.2" in m for m in messages)
    assert any("top speed 1 is above the limit 0.5" in m for m in messages)


def test_projection_keeps_bounds_clearance_and_ends() -> None:
    s = np.linspace(0, 1, 60)
    t = np.c_[0.3 * np.sin(np.pi * s), 2 * s, np.ones(60), np.ones(60)]
    scene = Scene((SceneObject("box", 0.3, 1.0, 1.0),))
    limits = Constraints(upper=(0.25, math.inf, math.inf), min_clearance=0.2, keep_start=True, keep_goal=True)
    original = np.c_[0.2 * np.sin(np.pi * s), t[:, 1:]]  # inside the bound: the program broke it
    result = project(t, original, scene, limits)
    assert result.remaining == ()
    assert result.trajectory[:, 0].max() <= 0.25 + 1e-6
    assert np.linalg.norm(result.trajectory[:, :3] - [0.3, 1, 1], axis=1).min() >= 0.2 - 1e-6
    assert np.allclose(result.trajectory[[0, -1], :3], t[[0, -1], :3])
    steps = np.linalg.norm(np.diff(result.trajectory[:, :3], axis=0), axis=1)
    assert steps.max() < 3 * np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max()
    assert "moved by at most" in result.describe()


def test_a_stretch_the_original_runs_outside_the_room_is_left_as_far_out_as_it_was() -> None:
    """ground_robot/trajectory_24 starts 1.8 outside y >= -3: pulling only its second waypoint in made a jump."""
    s = np.linspace(0, 1, 40)
    original = np.c_[np.zeros(40), -4.8 + 6 * s, np.zeros(40), np.ones(40)]  # y < -3 for its first 12
    moved = original.copy()
    moved[:, 0] = 0.5 * np.sin(np.pi * s)  # the program bends it sideways, past x <= 0.3
    limits = Constraints(lower=(-math.inf, -3.0, -math.inf), upper=(0.3, math.inf, math.inf))
    result = project(moved, original, Scene(()), limits)
    steps = np.linalg.norm(np.diff(result.trajectory[:, :3], axis=0), axis=1)
    assert result.trajectory[:, 0].max() <= 0.3 + 1e-6 and result.remaining == ()
    assert steps.max() < 1.5 * np.linalg.norm(np.diff(original[:, :3], axis=0), axis=1).max()
    assert "y below -3" in " ".join(result.as_original) and "outside the room" in result.describe()


def answer(code: str) -> str:
    return json.dumps({"high_level_plan": "1) Shift left.", "python_code": code})


@pytest.fixture
def bounded_case(simple_case: Case) -> Case:
    scene = replace(
        simple_case.scene, constraints="The x-axis range is -1 to 0.2, the y-axis range is -1 to 2"
    )
    return replace(simple_case, scene=scene)


def test_violation_goes_back_with_numbers(bounded_case: Case, sandbox: Sandbox) -> None:
    backend = ScriptedBackend(answers=[answer("modified_trajectory = shift(get_trajectory(), 'left', 0.5)"),
                                       answer("modified_trajectory = shift(get_trajectory(), 'left', 0.15)")])  # fmt: skip
    session = AdaptationSession(
        bounded_case, backend, sandbox, SessionSettings(project=False, read_against_words=False)
    )
    session.draft()
    result = session.approve()
    assert result.ok and result.attempts == 2
    assert "ConstraintViolation" in backend.requests[-1].messages[-1].content
    assert "x above 0.2 (highest 0.5)" in backend.requests[-1].messages[-1].content


def test_projection_by_default_keeps_the_room_and_says_what_bound_it(
    bounded_case: Case, sandbox: Sandbox
) -> None:
    backend = ScriptedBackend(answers=[answer("modified_trajectory = shift(get_trajectory(), 'left', 0.5)")])
    session = AdaptationSession(bounded_case, backend, sandbox, SessionSettings(read_against_words=False))
    session.draft()
    result = session.approve()
    assert result.ok and result.attempts == 1 and result.trajectory is not None
    assert result.trajectory.positions[:, 0].max() <= 0.2 + 1e-6
    note = next(note.message for note in result.notes if "projected onto the constraints" in note.message)
    assert "moved by at most" in note and "x above 0.2 (highest 0.5)" in note

"""A smoothing runs after the moves and passes written after it, so the path it leaves is smooth."""

from __future__ import annotations

import ast

import numpy as np
import pytest

from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.rewrite import limits_last, passes_last, smoothing_last
from trajadapt.sandbox.runner import ExecutionOptions
from trajadapt.skills import bind_skills


def rewritten(code: str) -> tuple[list[str], list[str]]:
    """The program as the sandbox runs it (the three reorderings in the sandbox's order), and the notes."""
    tree = ast.parse(code)
    notes = passes_last(tree) + limits_last(tree) + smoothing_last(tree)
    return ast.unparse(tree).splitlines()[1:-1], notes


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def test_a_smoothing_runs_after_a_move_written_after_it() -> None:
    lines, notes = rewritten(program("t = smooth(t)", "t = move_closer(t, detect_objects('quill'))"))
    assert lines == ["t = move_closer(t, detect_objects('quill'))", "t = smooth(t)"]
    assert len(notes) == 1 and "smooth() runs after" in notes[0] and "smooth" in notes[0]


def test_a_smoothing_runs_after_the_moves_and_a_clearance_and_a_pass_still_close() -> None:
    lines, _ = rewritten(
        program(
            "t = smooth(t, 0.8)",
            "t = avoid(t, detect_objects('chair'), 1.0)",
            "t = pass_through(t, detect_objects('table'))",
            "t = shift(t, 'left', 0.2)",
        )
    )
    assert lines == [
        "t = shift(t, 'left', 0.2)",
        "t = smooth(t, 0.8)",
        "t = avoid(t, detect_objects('chair'), 1.0)",
        "t = pass_through(t, detect_objects('table'))",
    ]


@pytest.mark.parametrize(
    "steps",
    [
        ("t = shift(t, 'up')", "t = smooth(t)"),  # already last
        ("t = smooth(t)", "t = scale_speed(t, 0.5)"),  # a pace reshapes nothing
        ("t = smooth(t)", "t = avoid(t, detect_objects('box'), 0.3)"),  # the limit stays last
        ("t = smooth(t)", "t = wait(t, 'middle', 3)"),  # no move: a pause is left where it is
        # a pass, a weave: shapes asked on purpose, which a smoothing after them would blunt
        ("t = smooth(t)", "t = pass_through(t, detect_objects('table'))"),
        ("t = smooth(t)", "t = pass_over(t, detect_objects('box'), clearance=0.1)"),
        ("t = smooth(t)", "t = zigzag(t)"),
    ],
    ids=[
        "already-last",
        "a-pace-after",
        "a-limit-after",
        "a-pause-after",
        "a-pass",
        "a-pass-over",
        "a-weave",
    ],
)
def test_other_programs_are_left_as_written(steps) -> None:
    code = program(*steps)
    assert rewritten(code) == (list(steps), [])


def wavy(n: int = 40) -> np.ndarray:
    """A gentle arc going front with a wiggle 8 waypoints long, speed 1."""
    s = np.linspace(0.0, 1.0, n)
    wiggle = 0.02 * np.sin(2 * np.pi * np.arange(n) / 8)
    return np.c_[0.3 * np.sin(np.pi * s) + wiggle, 2 * s, np.full(n, 0.5), np.ones(n)]


def test_in_the_sandbox_the_move_is_smoothed_too(sandbox) -> None:
    scene = Scene((SceneObject("quill", 0.8, 1.0, 0.5),))
    code = program("t = smooth(t)", "t = move_closer(t, detect_objects('quill'))")
    result = sandbox.run(code, Trajectory(wavy()), scene, ExecutionOptions(skills=True))
    assert result.ok, result.error
    skills = bind_skills()
    quill = [0.8, 1.0, 0.5]
    expected = skills["smooth"](skills["move_closer"](wavy(), quill))
    assert np.allclose(np.asarray(result.rows), expected)
    assert any("smooth() runs after" in note for note in result.notes)

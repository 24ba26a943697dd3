"""Objects a clause asks the path to pass over get ``pass_over`` (readers.asked_pass_overs).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.readers.asked_pass_overs import add_asked_pass_overs, passed_over
from trajadapt.skills import bind_skills

NAMES = ["crate", "lamp", "red box", "box"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "objects"),
    [
        ("sail straight over the crate on the way", ["crate"]),
        ("take it across the top of the red box and the lamp", ["red box", "lamp"]),
        ("go above the lamp; then over the crate", ["lamp", "crate"]),
        ("clear the crate by going over it, rather than around the lamp", []),  # "it": no name after
        ("arc over the crate instead of around the lamp", ["crate"]),
        ("don't go over the crate", []),  # a negation
        ("finish just above the lamp", []),  # an end placed there
        ("hover above the crate for a moment", []),  # a pause placed there
        ("fly over to the lamp after the goal", []),  # a move over to a place
        ("speed up over the last stretch", []),  # no object
        ("shift the path over towards the crate a bit", []),  # over as a side, no object right after
        ("stay over 0.2 away from the lamp", []),  # over as more than
        ("lean over toward the lamp", []),
    ],
)
def test_the_objects_a_clause_asks_to_pass_over(words: str, objects: list[str]) -> None:
    assert passed_over(words, NAMES) == objects


@pytest.mark.parametrize(
    ("step", "why"),
    [
        ("t = avoid(t, detect_objects('crate'), 0.5)", "not avoid"),
        ("t = keep_side(t, 'up', detect_objects('crate'))", "not keep_side"),
        ("t = shift(t, 'up')", "not a move up"),
        ("t = lift_middle(t, 'up', 'a bit')", "not a move up"),
    ],
)
def test_the_models_guess_at_passing_over_becomes_pass_over(step: str, why: str) -> None:
    code, notes = add_asked_pass_overs(program(step), ["sail right over the crate"], NAMES)
    assert code == program("t = pass_over(t, detect_objects('crate'))") and why in notes[0]


def test_with_no_guess_the_pass_over_is_added_after_the_last_step() -> None:
    code, notes = add_asked_pass_overs(
        program("t = scale_speed(t, 0.5)"), ["slow down, and route it over the crate and the lamp"], NAMES
    )
    added = "t = pass_over(t, [detect_objects('crate'), detect_objects('lamp')])"
    assert code == program("t = scale_speed(t, 0.5)", added) and notes[0].startswith("added")


@pytest.mark.parametrize(
    "steps",
    [
        ("t = pass_over(t, detect_objects('lamp'))",),  # the model passes over something: its reading
        ("t = shift(t, 'up', 0.3)",),  # a stated amount is no guess: it stays, and a pass over is added
    ],
)
def test_the_models_own_pass_over_stands_and_a_stated_move_up_stays(steps: tuple[str, ...]) -> None:
    code, _ = add_asked_pass_overs(program(*steps), ["go over the crate"], NAMES)
    assert all(step in code.splitlines() for step in steps)


def test_code_that_is_not_skill_calls_alone_is_left_alone() -> None:
    code = program("t[:, 2] += 0.3")
    assert add_asked_pass_overs(code, ["go over the crate"], NAMES) == (code, [])


def test_the_path_made_passes_over_the_object() -> None:
    path = np.column_stack([np.linspace(-1, 1, 40), np.zeros(40), np.full(40, 0.2), np.full(40, 0.3)])
    crate = np.array([0.0, 0.3, 0.1])
    code, _ = add_asked_pass_overs(
        program("t = avoid(t, detect_objects('crate'), 0.5)"), ["go over the crate"], NAMES
    )
    scope: dict[str, object] = {
        **bind_skills(),
        "get_trajectory": path.copy,
        "detect_objects": lambda name: crate if name == "crate" else None,
    }
    exec(code, scope)  # the reader's program of skill calls, on the test's own path
    adapted = np.asarray(scope["modified_trajectory"])
    nearest = int(np.argmin(np.linalg.norm(adapted[:, :2] - crate[:2], axis=1)))
    assert np.linalg.norm(adapted[nearest, :2] - crate[:2]) < 0.05 and adapted[nearest, 2] > crate[2]


def test_a_height_said_before_the_word_is_the_clearance() -> None:
    code, _ = add_asked_pass_overs(
        program("t = avoid(t, detect_objects('crate'), 0.2)"), ["fly 0.2 over the crate"], NAMES
    )
    assert code == program("t = pass_over(t, detect_objects('crate'), 0.2)")


def test_a_move_up_by_a_keyword_amount_is_no_guess() -> None:
    code, notes = add_asked_pass_overs(
        program("t = shift(t, 'up', amount=0.2)"), ["go over the crate"], NAMES
    )
    assert "t = shift(t, 'up', amount=0.2)" in code and notes[0].startswith("added")

"""Back-to-back copies of a step are a decoding loop: one copy is kept (readers.repeated_steps)."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.repeated_steps import leave_out_repeats


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("steps", "kept"),
    [
        (["t = shift(t, 'left', 0.2)"] * 5, ["t = shift(t, 'left', 0.2)"]),
        (["t = shift(t, 'up', 'slightly')", "t = shift(t, 'right', 'slightly')"] * 4 + ["t = smooth(t)"],
         ["t = shift(t, 'up', 'slightly')", "t = shift(t, 'right', 'slightly')", "t = smooth(t)"]),
        (["t = move_away(t, detect_objects('vase'))", *["t = shift(t, 'right', 'a bit')"] * 4, "t = shift(t, 'up')"],
         ["t = move_away(t, detect_objects('vase'))", "t = shift(t, 'right', 'a bit')", "t = shift(t, 'up')"]),
    ],
)  # fmt: skip
def test_a_run_of_copies_keeps_its_first_with_a_note(steps: list[str], kept: list[str]) -> None:
    code, notes = leave_out_repeats(program(*steps), ["whatever the words"])
    assert code.splitlines()[1:-1] == kept
    assert len(notes) == 1 and "decoding loop" in notes[0]


@pytest.mark.parametrize(
    "steps",
    [
        ["t = shift(t, 'up')", "t = shift(t, 'left')", "t = shift(t, 'up')"],  # something between: no loop
        ["t = shift(t, 'up', 0.1)", "t = shift(t, 'up', 0.2)"],  # different amounts
        ["t = get_trajectory()"],  # reading the path again moves nothing
    ],
)
def test_copies_that_are_not_back_to_back_or_not_the_same_stay(steps: list[str]) -> None:
    code = program(*steps)
    assert leave_out_repeats(code, ["go up"]) == (code, [])


def test_code_the_parser_refuses_is_left_as_it_is() -> None:
    code = "t = get_trajectory(\nt = shift(t, 'up')\nt = shift(t, 'up')"
    assert leave_out_repeats(code, ["go up"]) == (code, [])


def test_after_the_loop_the_one_guess_becomes_the_asked_step() -> None:
    """The readers after it look for the one step of a kind: five copies hid it from them."""
    code, notes = read_against_words(
        program(*["t = shift(t, 'left', 0.2)"] * 5),
        ["pull the first 4 waypoints toward the cup"],
        ["cup", "vase"],
    )
    assert code.splitlines()[1:-1] == ["t = move_closer(t, detect_objects('cup'), part=(0, 4))"]
    assert notes[0].reader == "repeated-steps"


def test_a_readers_step_that_repeats_the_models_is_cut_after_the_last_reader() -> None:
    code = "t = get_trajectory()\nt = shift(t, 'up', 0.2)\nt = set_height(t, 0.2)\nmodified_trajectory = t"
    read, notes = read_against_words(code, ["fly the whole path about 0.2 higher"], [])
    assert read.splitlines()[1:-1] == ["t = shift(t, 'up', 0.2)"]
    assert any("back to back after the readers" in note.message for note in notes)

"""An object pointed back to with "it" after a word of place is called by its name."""

from __future__ import annotations

import pytest

from trajadapt.readers.pointed_objects import objects_for_it

NAMES = ["fan", "box", "lamp"]


@pytest.mark.parametrize(
    ("words", "plain"),
    [
        ("Don't come within 0.8 of the fan, and go slower as you pass by it",
         "Don't come within 0.8 of the fan, and go slower as you pass by the fan"),
        ("approach the lamp, then keep clear of it", "approach the lamp, then keep clear of the lamp"),
        ("the box is in the way: fly over it", "the box is in the way: fly over the box"),
        # of a distance from it (fresh-v)
        ("leave the lamp alone; never get within 0.3 m of it", "leave the lamp alone; never get within 0.3 m of the lamp"),
        ("the fan is loud, stay 1.5 away from it", "the fan is loud, stay 1.5 away from the fan"),
        ("pass the box but keep 0.2 between the arm and it", "pass the box but keep 0.2 between the arm and the box"),
    ],
)  # fmt: skip
def test_it_after_a_word_of_place_is_the_object_named_before(words: str, plain: str) -> None:
    assert objects_for_it(words, NAMES) == plain


@pytest.mark.parametrize(
    "words",
    [
        "move it left near the box",  # "it" the path: no word of place before it
        "slow it down near the lamp",
        "go near the box and the lamp, then slow down past it",  # two objects before: which one?
        "speed up near it",  # no object named before
        "pass by it is what it does now near the fan",  # "by it is": a statement
        "go 0.2 left of the box and keep the rest of it unchanged",  # "the rest of it": the path
        "go round the box and slow down over the last 2 m of it",
        "pass the box, and keep the speed even within the first half of it",
        "pass the lamp; the path is long, so cut 1 m off it",
    ],
)
def test_it_that_may_be_the_path_or_several_objects_stays(words: str) -> None:
    assert objects_for_it(words, NAMES) == words

"""A side of an object nobody named, where the words name no object (readers.scene_sides)."""

from __future__ import annotations

import pytest

from trajadapt.readers.scene_sides import sides_of_the_scene

NAMES = ["Lamp", "sofa"]


def program(step: str) -> str:
    return f"t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        ("t = keep_side(t, 'front', detect_objects('sofa'))", "stay on the front part a bit",
         "t = shift(t, 'front', 'a bit')"),
        ("t = keep_side(t, 'left', detect_objects('Lamp'))", "keep to the left", "t = shift(t, 'left')"),
    ],
)  # fmt: skip
def test_a_side_where_no_object_is_named_is_a_side_of_the_scene(step: str, words: str, expected: str) -> None:
    code, notes = sides_of_the_scene(program(step), [words], NAMES)
    assert code == program(expected)
    assert len(notes) == 1 and "names no object" in notes[0]


def test_a_side_of_a_named_object_stays() -> None:
    code = program("t = keep_side(t, 'right', detect_objects('sofa'))")
    assert sides_of_the_scene(code, ["never pass left of the sofa"], NAMES) == (code, [])

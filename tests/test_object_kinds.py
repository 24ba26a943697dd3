"""Other names of the same kind of object: the words' name for it written as the scene spells it."""

from __future__ import annotations

import pytest

from trajadapt.readers.object_kinds import GENERAL_WORDS, kinds, names_by_their_kind, other_names
from trajadapt.readers.plain_words import plain_words


def test_every_kind_has_several_names_and_the_scenes_names_are_among_them() -> None:
    assert all(len(kind) > 1 for kind in kinds())
    assert {"oboe", "hautboy"} <= other_names("hautbois")
    assert "red breasted merganser" in other_names("Mergus serrator")


@pytest.mark.parametrize(
    ("words", "names", "plain"),
    [
        ("Give the oboe a wider berth", ["milk can", "hautbois"], "Give the hautbois a wider berth"),
        ("slow down past that trash can", ["Dustbin", "person"], "slow down past that Dustbin"),
        ("keep 0.3 from the coyote", ["prairie wolf", "hen"], "keep 0.3 from the prairie wolf"),
        ("hover over the polar bear", ["Ursus Maritimus"], "hover over the Ursus Maritimus"),
    ],
)
def test_another_name_of_an_objects_kind_is_its_scene_name(words: str, names: list[str], plain: str) -> None:
    assert names_by_their_kind(words, names) == plain


@pytest.mark.parametrize(
    ("words", "names"),
    [
        ("land at the spot near the table", ["spotlight", "table"]),  # an everyday word
        ("go past the oboe and the hautbois", ["hautbois", "milk can"]),  # the scene's own name is said
        ("keep clear of the panda", ["lesser panda", "giant panda"]),  # a name two objects share
        ("pass an oboe", ["hautbois"]),  # no "the": any oboe, not the scene's
    ],
)
def test_a_name_that_may_mean_something_else_is_left_as_said(words: str, names: list[str]) -> None:
    assert names_by_their_kind(words, names) == words


def test_no_everyday_word_is_anyones_other_name() -> None:
    assert not any(GENERAL_WORDS & other_names(name) for kind in kinds() for name in kind)


def test_the_plain_words_call_the_object_by_its_scene_name() -> None:
    plain = plain_words("back off from the oboe", ["hautbois"], keep=lambda sentence: False)
    assert plain == "back off from the hautbois"

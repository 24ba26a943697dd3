"""An object called by a name no scene object has is read as the one object the answer chose."""

from __future__ import annotations

from trajadapt.readers import read_against_words
from trajadapt.readers.object_mentions import chosen_referents
from trajadapt.readers.object_words import object_asks

NAMES = ["hautbois", "drum", "Siberian husky"]


def _code(*lines: str) -> str:
    return "\n".join(["t = get_trajectory()", *lines, "modified_trajectory = t"])


def test_the_other_name_is_read_as_the_chosen_object():
    code = _code("t = move_closer(t, detect_objects('hautbois'))")
    read, notes = chosen_referents("swing in tighter to the oboe", code, NAMES)
    assert read == "swing in tighter to the hautbois"
    assert "the oboe" in notes[0]


def test_the_readers_keep_the_step_the_other_name_asks():
    names = ["scabbard", "drum"]  # "sheath" is no name of the scabbard's kind (readers.object_kinds)
    code = _code("t = move_away(t, detect_objects('scabbard'))")
    read, notes = read_against_words(code, ["give the sheath a wider berth"], names)
    assert "move_away(t, detect_objects('scabbard')" in read
    assert [n.reader for n in notes] == ["object-mentions"]


def test_another_name_of_the_objects_kind_is_read_before_the_answer_is():
    code = _code("t = move_away(t, detect_objects('hautbois'))")
    read, notes = read_against_words(code, ["give the oboe a wider berth"], NAMES)
    assert "move_away(t, detect_objects('hautbois')" in read
    assert [n.reader for n in notes] == ["request-words"]  # "the oboe" written as "the hautbois"


def test_nothing_is_read_where_the_choice_is_not_one():
    two = _code("t = move_closer(t, detect_objects('hautbois'))", "t = avoid(t, detect_objects('drum'))")
    assert chosen_referents("swing in tighter to the oboe", two, NAMES)[1] == []
    named = _code("t = move_closer(t, detect_objects('drum'))")
    assert chosen_referents("go nearer to the drum and the oboe", named, NAMES)[1] == []  # drum is named
    two_words = _code("t = move_closer(t, detect_objects('hautbois'))")
    assert chosen_referents("go from the oboe to the bell", two_words, NAMES)[1] == []


def test_a_hyphened_name_said_as_written_is_that_object() -> None:
    names = ["groenendael", "horse-cart", "hand-held microcomputer"]
    code = _code("t = wait(t, detect_objects('groenendael'), 3)")
    for words in (
        "hold still for a few waypoints close to the horse-cart",
        "pause beside the hand-held microcomputer",
    ):
        assert chosen_referents(words, code, names) == (words, [])


def test_parts_and_places_are_no_other_name():
    code = _code("t = scale_speed(t, 1.4, near=detect_objects('drum'))")
    for words in ("speed up through the middle section", "slow down towards the end", "go past the goal"):
        assert chosen_referents(words, code, NAMES) == (words, [])


def test_a_side_said_as_what_not_to_do_is_the_other_side():
    asks = object_asks("make sure it doesn't pass to the left of the drum", NAMES)
    assert asks["drum"].relation == "side"
    assert asks["drum"].side == "right"


def test_never_closer_than_is_a_least_distance():
    for words in (
        "make sure you're never closer than 0.3 to the drum",
        "don't get any nearer than 0.3 to the drum",
        "never allow the arm to get closer than 0.3 to the drum",  # words between the negation and "closer"
        "do not let the robot come any nearer than 0.3 to the drum",
    ):
        assert object_asks(words, NAMES)["drum"].relation == "away", words


def test_never_within_is_a_least_distance():
    for words in (
        "the robot should never come within 0.3 of the drum",
        "don't let it get within 0.3 of the drum",
        "do not pass within 0.3 of the drum",
    ):
        assert object_asks(words, NAMES)["drum"].relation == "away", words

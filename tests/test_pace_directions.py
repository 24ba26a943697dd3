"""A speed step near an object that goes against the pace its clause asks there (readers.pace_directions)."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.pace_directions import asked_paces_near, turn_paces_as_asked

NAMES = ["kettle", "lamp", "red box", "box"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def near(factor: float, name: str) -> str:
    return f"t = scale_speed(t, {factor}, near=detect_objects({name!r}))"


@pytest.mark.parametrize(
    ("words", "written", "read"),
    [
        # crossed: each object got the other's pace
        ("Speed up by the kettle, but take it slow past the lamp.", (0.65, 1.4), (1.4, 0.65)),
        ("hurry near the kettle; crawl near the lamp", (0.5, 1.6), (1.4, 0.65)),
        # a stated factor is taken in the asked way
        ("Go 20% quicker around the kettle and 30% slower beside the lamp.", (0.8, 1.3), (1.2, 0.7)),
        # the amount word of the clause sizes it
        ("a lot faster close to the kettle, and a bit slower by the lamp", (0.45, 1.25), (1.6, 0.75)),
    ],
)
def test_crossed_paces_are_turned_the_way_each_clause_asks(words, written, read):
    code = program(near(written[0], "kettle"), near(written[1], "lamp"))
    out, notes = turn_paces_as_asked(code, [words], NAMES)
    assert out == program(near(read[0], "kettle"), near(read[1], "lamp"))
    assert len(notes) == 2 and "the words ask faster near kettle" in notes[0]


def test_in_the_whole_stage_the_crossed_paces_come_out_the_asked_way():
    code = program(near(0.65, "kettle"), near(1.4, "lamp"))
    out, _ = read_against_words(code, ["Be quicker near the kettle and slower near the lamp."], NAMES)
    assert "scale_speed(t, 1.4, near=detect_objects('kettle'))" in out
    assert "scale_speed(t, 0.65, near=detect_objects('lamp'))" in out


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        # the steps agree with the words
        ("faster near the kettle and slower near the lamp", (near(1.4, "kettle"), near(0.65, "lamp"))),
        # a pace clause with no object: which step serves it is unknown
        ("slow down near the lamp, then speed up once past it", (near(0.65, "lamp"), near(1.4, "lamp"))),
        # two ways for one object
        ("faster near the kettle at first, and slower near the kettle later", (near(0.65, "kettle"),)),
        # negated, or only how the path is now
        ("don't go faster near the kettle", (near(0.8, "kettle"),)),
        # one clause, two ways
        ("faster near the kettle rather than slower", (near(0.65, "kettle"),)),
        # a pace compared, not asked one way; a factor the clause states
        ("go half as fast near the kettle", (near(0.5, "kettle"),)),
        ("twice as slow near the kettle, please", (near(0.5, "kettle"),)),
        # the pace placed elsewhere than by the object named
        ("slow down everywhere except near the kettle", (near(1.54, "kettle"),)),
        ("speed up once you're clear of the lamp", (near(0.7, "lamp"),)),
    ],
    ids=[
        "agreeing",
        "pointing-back",
        "torn",
        "negated",
        "both-ways",
        "compared",
        "stated",
        "except",
        "clear-of",
    ],
)
def test_other_programs_are_left_as_written(words, steps):
    code = program(*steps)
    assert turn_paces_as_asked(code, [words], NAMES) == (code, [])


def test_the_longest_name_is_the_object():
    assert asked_paces_near("slow down next to the red box", NAMES) == {
        "red box": (False, "slow down next to the red box")
    }


def test_code_beyond_skill_calls_is_left_alone():
    code = program("for i in range(2):", "    " + near(0.65, "kettle"))
    assert turn_paces_as_asked(code, ["go faster near the kettle"], NAMES) == (code, [])

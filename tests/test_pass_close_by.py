"""A clause that asks the path to pass close by an object (not closer than now: close to it) gets a pass.

Written from fresh-a (new instructions: "swing by the chetah", "fly close past the wall lamp"); the
wordings here are none of any set's. Comparatives stay closer/further; keeping near an object, a
refusal, and a lead-in that places another request ask no visit.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.object_words import object_asks

NAMES = ["kettle", "Floor lamp", "crate"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def steps_after(words: str, *steps: str) -> list[str]:
    code, _ = read_against_words(program(*steps), [words], NAMES)
    return code.splitlines()[1:-1]


@pytest.mark.parametrize(
    "words",
    [
        "stop by the kettle on your way",
        "route the drive via the crate",
        "cruise right past the floor lamp",
        "make sure you go by the crate",
        "head through the kettle",
        "get close to the crate before the end",
        "visit the kettle",
    ],
)
def test_a_visit_is_asked_of_the_object(words: str) -> None:
    asks = object_asks(words, NAMES)
    assert [ask.relation for ask in asks.values()] == ["by"]


@pytest.mark.parametrize(
    "words",
    [
        "stay close to the kettle",  # keeping near it
        "keep the crate close by",
        "don't go by the kettle",  # refused
        "avoid passing next to the crate",
        "you came too close to the kettle",  # a complaint: further
        "while going past the crate, hurry",  # a lead-in placing a pace
        "move a bit closer to the kettle",  # a comparative: closer, as before
    ],
)
def test_no_visit_is_asked(words: str) -> None:
    assert all(ask.relation != "by" for ask in object_asks(words, NAMES).values())


def test_a_dropped_visit_becomes_a_pass_through_the_object() -> None:
    assert steps_after("speed up overall and stop by the crate", "t = scale_speed(t, 1.4)") == [
        "t = scale_speed(t, 1.4)",
        "t = pass_through(t, detect_objects('crate'))",
    ]


def test_a_closer_step_for_a_visit_becomes_the_pass() -> None:
    assert steps_after(
        "cruise right past the floor lamp", "t = move_closer(t, detect_objects('Floor lamp'), 'a bit')"
    ) == ["t = pass_through(t, detect_objects('Floor lamp'))"]


def test_a_pass_already_written_stays() -> None:
    written = "t = pass_through(t, detect_objects('kettle'))"
    assert steps_after("stop by the kettle", written) == [written]

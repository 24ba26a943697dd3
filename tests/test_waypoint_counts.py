"""A count of waypoints the words give gets the resample that makes it (readers.waypoint_counts).

Written from fresh-b/fresh-c ("use 10 more waypoints", "resample with 10 more waypoints"); the
wordings here are none of any set's.
"""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.waypoint_counts import asked_count, count_as_asked
from trajadapt.skills import bind_skills


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "count"),
    [
        ("throw in 6 extra points", "len(t) + 6"),
        ("insert five additional waypoints", "len(t) + 5"),
        ("make do with 4 fewer way-points", "len(t) - 4"),
        ("drop 3 of the waypoints", None),  # "of the": which ones, not how many
        ("remove 3 waypoints", "len(t) - 3"),
        ("double the waypoints", "2 * len(t)"),
        ("halve the number of points", "len(t) // 2"),
        ("resample it into 64 evenly spaced points", "64"),
        ("a total of 30 waypoints", "30"),
        ("move the first 10 points up", None),  # a part of the path
        ("alternate in groups of 8 points", None),
        ("go 10 points to the right", None),  # no count of waypoints
        ("use 20 more waypoints, or maybe use 40 waypoints", None),  # two counts: unclear
    ],
)  # fmt: skip
def test_the_count_the_words_give(words: str, count: str | None) -> None:
    assert asked_count(words) == count


@pytest.mark.parametrize(
    "written", ["t = resample(t, 7)", "t = resample(t, 7 * len(t))", "t = resample(t, len(t) - 7)"]
)
def test_a_resample_of_another_count_takes_the_asked_one(written: str) -> None:
    code, notes = count_as_asked(program(written), ["please add 7 more waypoints"])
    assert code == program("t = resample(t, len(t) + 7)")
    assert "count of waypoints" in notes[0]


def test_a_missing_resample_is_added_last_and_makes_the_count() -> None:
    code, notes = read_against_words(
        program("t = shift(t, 'left', 0.1)"), ["Shift left by 0.1 and throw in 6 extra points."], []
    )
    assert code.splitlines()[-2] == "t = resample(t, len(t) + 6)"
    t = np.column_stack([np.linspace(0, 1, 20), np.zeros(20), np.zeros(20), np.ones(20)])
    namespace = {**bind_skills(), "get_trajectory": t.copy}
    exec(code, namespace)  # skill calls alone, checked by the reader
    assert len(namespace["modified_trajectory"]) == 26
    assert any(note.reader == "waypoint-counts" for note in notes)


def test_the_asked_resample_already_written_stays() -> None:
    code = program("t = resample(t, len(t)+6)")
    assert count_as_asked(code, ["6 more waypoints"]) == (code, [])


def test_code_beyond_the_skills_is_left_alone() -> None:
    code = program("t = t[::2]")
    assert count_as_asked(code, ["halve the waypoints"]) == (code, [])


@pytest.mark.parametrize(
    ("words", "added"),
    [
        ("go via fewer way points", "t = resample(t, len(t) // 2)"),
        ("cut down the number of points", "t = resample(t, len(t) // 2)"),
        ("thin it out a bit", "t = resample(t, len(t) // 2)"),
        ("give it more waypoints", "t = resample(t, 2 * len(t))"),
        ("make the path denser", "t = resample(t, 2 * len(t))"),
    ],
)
def test_a_way_without_a_count_halves_or_doubles_it(words: str, added: str) -> None:
    code, notes = count_as_asked(program("t = smooth(t)"), [words])
    assert code == program("t = smooth(t)", added)
    assert notes


@pytest.mark.parametrize(
    "words", ["I'm thinking of going left", "stay more than 5 points away", "fewer points and more points"]
)
def test_no_way_or_both_ways_add_nothing(words: str) -> None:
    code = program("t = smooth(t)")
    assert count_as_asked(code, [words]) == (code, [])


def test_a_made_up_count_for_a_way_takes_the_ways_count() -> None:
    """The reader cannot see the path's length: 30 may be more than it has, half is always fewer."""
    code, notes = count_as_asked(program("t = resample(t, 30)"), ["use fewer waypoints"])
    assert code == program("t = resample(t, len(t) // 2)") and notes


def test_a_count_for_a_way_the_words_say_stays() -> None:
    code = program("t = resample(t, 30)")
    assert count_as_asked(code, ["use fewer waypoints, say 30"]) == (code, [])

"""A distance from an object the words multiply by a factor (readers.scaled_distances).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.scaled_distances import scale_distances, scaled_distances

NAMES = ["vase", "blue cup", "cup", "shelf"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "name", "factor"),
    [
        ("make the route three times as far from the cup", "cup", 3.0),
        ("triple the gap between the path and the vase", "vase", 3.0),
        ("keep 2x the clearance you have now from the shelf", "shelf", 2.0),
        ("halve the distance to the blue cup", "blue cup", 0.5),
        ("stay away from the vase by a factor of 1.5", "vase", 1.5),
        ("the waypoints should sit four-fold further from the shelf", "shelf", 4.0),
    ],
)  # fmt: skip
def test_a_factor_of_the_distance_from_one_object(words: str, name: str, factor: float) -> None:
    assert [(s.name, s.factor) for s in scaled_distances(words, NAMES)] == [(name, factor)]


@pytest.mark.parametrize(
    "words",
    [
        "go twice as fast near the vase",  # a factor of speed
        "double the distance from the vase to the shelf",  # two objects
        "stay away from the vase for the first half",  # a part, not a factor
        "move away from the vase",  # no factor
    ],
)
def test_no_factor_no_distance_or_no_one_object_asks_no_scaling(words: str) -> None:
    assert scaled_distances(words, NAMES) == []


def test_a_move_by_the_object_gives_way_to_the_scaling() -> None:
    code, notes = scale_distances(
        program("t = move_away(t, detect_objects('vase'))", "t = shift(t, 'up')"),
        ["lift it and put the waypoints twice as far from the vase"],
        NAMES,
    )
    assert code == program("t = shift(t, 'up')", "t = scale_about(t, detect_objects('vase'), 2)")
    assert len(notes) == 2


def test_a_scaling_already_there_stays() -> None:
    code = program("t = scale_about(t, [0.0, 1.0, 0.0], 2.0)")
    assert scale_distances(code, ["twice as far from the vase"], NAMES) == (code, [])


def test_in_the_stage_an_answer_emptied_of_its_speed_guess_gets_the_scaling() -> None:
    code, notes = read_against_words(
        program("t = scale_speed(t, 3.0, near=detect_objects('shelf'))"),
        ["put every waypoint three times as far from the shelf"],
        NAMES,
    )
    assert code == program("t = scale_about(t, detect_objects('shelf'), 3)")
    assert [note.reader for note in notes] == ["unasked-steps", "scaled-distances"]

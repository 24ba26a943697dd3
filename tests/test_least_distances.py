"""A step that falls short of a least distance its clause states becomes that clearance (readers.least_distances).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import pytest

from trajadapt.readers.least_distances import come_within_stated_reaches, keep_stated_clearances

NAMES = ["table", "lamp"]


def kept(words: str, step: str) -> list[str]:
    lines, notes = [step], list[str]()
    keep_stated_clearances(lines, notes, words, NAMES)
    return lines


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("go round the table so you never get closer than 1.5 to the table", "t = pass_over(t, detect_objects('table'), clearance=1.5)"),
        ("keep no less than 0.4 from the lamp", "t = move_away(t, detect_objects('lamp'))"),
        ("don't pass within 0.4 of the lamp", "t = pass_through(t, detect_objects('lamp'))"),
        ("keep 0.4 from the lamp, no closer", "t = move_away(t, detect_objects('lamp'))"),  # a distance kept
        ("stay a full 0.4 away from the lamp", "t = move_away(t, detect_objects('lamp'))"),
        ("steer clear of the lamp by 0.4 or more", "t = pass_over(t, detect_objects('lamp'))"),  # fresh-r
        ("give the lamp a wider margin, 0.4 minimum", "t = move_away(t, detect_objects('lamp'))"),  # fresh-s
        ("always leave 0.4 clear of the lamp", "t = move_away(t, detect_objects('lamp'))"),  # fresh-v
        ("hold a good 0.4 clear of the lamp on the way", "t = move_closer(t, detect_objects('lamp'))"),
        ("keep 0.4 between the gripper and the lamp", "t = move_away(t, detect_objects('lamp'))"),
        ("maintain 0.4 of clearance from the lamp", "t = move_away(t, detect_objects('lamp'))"),
        ("give the lamp 0.4 of room on the way past", "t = move_away(t, detect_objects('lamp'))"),
        ("leave 0.4 of space around the lamp", "t = move_away(t, detect_objects('lamp'))"),
        ("keep the gripper 0.4 away from the lamp", "t = move_away(t, detect_objects('lamp'))"),
        ("it must clear the lamp by 0.4", "t = move_away(t, detect_objects('lamp'))"),
        ("min 0.4 separation from the lamp", "t = move_away(t, detect_objects('lamp'))"),
    ],
)  # fmt: skip
def test_a_step_short_of_the_stated_least_distance_becomes_the_clearance(words: str, step: str) -> None:
    name = "table" if "table" in words else "lamp"
    assert kept(words, step) == [
        f"t = avoid(t, detect_objects('{name}'), {'1.5' if name == 'table' else '0.4'})"
    ]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("fly over the table at least 0.5 above it", "t = pass_over(t, detect_objects('table'), clearance=0.5)"),
        ("come closer to the lamp, but no closer than 0.3", "t = move_closer(t, detect_objects('lamp'))"),
        ("stay at least 0.3 from the lamp", "t = move_away(t, detect_objects('lamp'), 0.4)"),  # a number given
        ("slow down at least 30% near the lamp", "t = move_away(t, detect_objects('lamp'))"),  # a pace
        ("hop over the table, and keep at least 0.3 from the table",
         "t = pass_over(t, detect_objects('table'))"),  # another clause asks the pass over
    ],
)  # fmt: skip
def test_a_step_the_words_may_ask_stays(words: str, step: str) -> None:
    assert kept(words, step) == [step]


def came_within(words: str, step: str) -> list[str]:
    lines, notes = [step], list[str]()
    come_within_stated_reaches(lines, notes, words, NAMES)
    return lines


@pytest.mark.parametrize(
    ("words", "expected"),
    [
        ("on the way, swing over to within roughly 0.1 of the lamp", "t = pass_through(t, detect_objects('lamp'))"),
        ("make a detour so the route passes within 0.25 of the table", "t = pass_through(t, detect_objects('table'))"),
        ("park the robot within 0.2 of the table", "t = reach(t, detect_objects('table'))"),
        ("come to a stop within about 0.1 of the lamp", "t = reach(t, detect_objects('lamp'))"),
        ("finish within 0.1 of the lamp", "t = reach(t, detect_objects('lamp'))"),
        ("route it past the table, no more than about 0.25 from it", "t = pass_through(t, detect_objects('table'))"),
        ("swing by the lamp at most 0.2 from it", "t = pass_through(t, detect_objects('lamp'))"),
        ("bring the path within about 0.04 of the lamp, keeping the start and the goal fixed",
         "t = pass_through(t, detect_objects('lamp'))"),  # keeping the ends is no band kept
    ],
)  # fmt: skip
def test_a_clearance_where_the_words_ask_to_come_within_a_distance_passes_by(
    words: str, expected: str
) -> None:
    name = "table" if "table" in words else "lamp"
    assert came_within(words, f"t = avoid(t, detect_objects('{name}'), 0.1)") == [expected]
    assert came_within(words, f"t = move_closer(t, detect_objects('{name}'), 'a bit')") == [expected]


@pytest.mark.parametrize(
    "words",
    [
        "never come within 0.1 of the lamp",  # a least distance
        "don't let it get within 0.1 of the lamp",
        "avoid getting within 0.1 of the lamp",
        "slow down within 0.1 of the lamp",  # a pace's place
        "stay at least 0.3 away from the lamp, and within 0.5 of it",  # a least distance said too
        "keep within 0.1 of the table",  # another object
        "go around the lamp, staying within 0.2 of it",  # a band kept all along, not a visit
    ],
)
def test_a_clearance_the_words_may_ask_stays(words: str) -> None:
    step = "t = avoid(t, detect_objects('lamp'), 0.1)"
    assert came_within(words, step) == [step]


def test_the_step_keeps_the_programs_own_variable() -> None:
    lines, notes = ["traj = avoid(traj, detect_objects('lamp'), 0.2)"], list[str]()
    come_within_stated_reaches(lines, notes, "detour to within about 0.1 of the lamp", NAMES)
    assert lines == ["traj = pass_through(traj, detect_objects('lamp'))"]

"""A clause that asks one end of the path to move ("end 0.2 higher", "finish further right") gets the move.

Written from fresh-a (new instructions); the wordings here are none of any set's. The end's step is
``shift_goal`` / ``shift_start``, added when no step moves that end that way; a shift in a direction no
word says is the model's guess at it and becomes it. A move past the goal, a place, another part and a
negation ask no end move. Phrasal verbs ("end up", "wrap up") and a "right" that stresses a place
("right at the vest") say no direction.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.asked_directions import asked_end_move
from trajadapt.readers.direction_words import said_directions

NAMES = ["vest", "lamp"]


def steps_after(words: str, *steps: str) -> list[str]:
    code = "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])
    return read_against_words(code, [words], NAMES)[0].splitlines()[1:-1]


@pytest.mark.parametrize(
    ("clause", "asked"),
    [
        ("finish 0.15 further back", ("shift_goal", "back")),
        ("finish a touch lower", ("shift_goal", "down")),
        ("have it end up a bit more to the right", ("shift_goal", "right")),
        ("the final position should sit higher", ("shift_goal", "up")),
        ("start 0.1 further to the left", ("shift_start", "left")),
        # the goal named with a word between (session 31; fresh-j's "the final hover point")
        ("lower the final resting position a bit", ("shift_goal", "down")),
        ("put the final parking point 0.2 further left", ("shift_goal", "left")),
        # the other end kept beside it (session 37: "move the end point 0.4 m backward, keeping the start unchanged")
        ("shift the goal a little to the left while the start stays put", ("shift_goal", "left")),
        ("raise the starting point, with the end left unchanged", ("shift_start", "up")),
    ],
)
def test_an_end_move_is_read(clause: str, asked: tuple[str, str]) -> None:
    assert asked_end_move(clause) == asked


@pytest.mark.parametrize(
    "clause",
    [
        "after reaching the goal, go 0.2 left",  # past the goal
        "once you get there, head up",
        "end the path above the lamp",  # a place
        "the middle should end higher",  # another part
        "don't finish lower",  # a negation
        "shift the end of the path left",  # the end part, not the goal
        "finish at the vest",  # no direction
        "shift the final few points left",  # the end part, not the goal
    ],
)
def test_no_end_move_is_read(clause: str) -> None:
    assert asked_end_move(clause) == ("", None)


def test_a_dropped_end_move_is_added_with_its_number() -> None:
    assert steps_after("slow down, and finish 0.15 further back", "t = scale_speed(t, 0.65)") == [
        "t = shift_goal(t, 'back', 0.15)",
        "t = scale_speed(t, 0.65)",
    ]


def test_a_dropped_end_move_in_a_metric_unit_is_added_in_metres() -> None:
    words = "keep at least half a metre from the lamp and lift the final landing point by 20 cm"
    assert steps_after(words, "t = move_away(t, detect_objects('lamp'))") == [
        "t = shift_goal(t, 'up', 0.2)",
        "t = avoid(t, detect_objects('lamp'), 0.5)",
    ]


def test_an_unsaid_shift_is_the_guess_at_the_end_move() -> None:
    assert steps_after("stop by the lamp and finish 0.25 further front", "t = shift(t, 'left', 0.25)") == [
        "t = shift_goal(t, 'front', 0.25)",
        "t = pass_through(t, detect_objects('lamp'))",
    ]


def test_an_end_already_moved_that_way_gets_nothing() -> None:
    written = ["t = shift(t, 'up', 0.1)", "t = move_closer(t, detect_objects('lamp'))"]
    assert steps_after("go up by 0.1, get closer to the lamp and finish higher", *written) == written


@pytest.mark.parametrize(
    ("words", "directions"),
    [
        ("wrap up with a gentle finish", set()),
        ("wrap it up beside the vest, stopping dead there", set()),  # the verb's object between
        ("finish things up near the lamp", set()),
        ("end up further to the left", {"left"}),
        ("come to rest right at the vest", set()),
        ("sweep right past the lamp", set()),
        ("turn right at the lamp", {"right"}),
        ("move the start right by 0.2", {"right"}),
        ("stay to the right of the vest", {"right"}),
    ],
)
def test_phrasal_and_stressing_words_say_no_direction(words: str, directions: set[str]) -> None:
    assert said_directions(words) == directions


def test_a_part_move_in_a_direction_no_word_says_takes_the_clause_direction() -> None:
    assert steps_after(
        "lower the first half by 0.05", "t = shift_part(t, 'left', 0.05, part='first half')"
    ) == ["t = shift_part(t, 'down', 0.05, part='first half')"]


def test_a_part_move_in_a_said_direction_stays() -> None:
    written = "t = shift_part(t, 'left', 0.05, part='first half')"
    assert steps_after("move the first half left by 0.05, and lower the goal", written)[-1] == written

"""The words in plain form: lists, decimals in words, short names of objects, what not to do.

Every example here is worded anew: none is an instruction of ovita-dev or of a reworded set.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.plain_words import plain_words
from trajadapt.readers.request_words import is_statement, request_words

NAMES = ["electric kettle", "red mug", "coffee table", "table lamp", "goal post"]


def _plain(words: str) -> str:
    return plain_words(words, NAMES, is_statement)


@pytest.mark.parametrize(
    ("words", "plain"),
    [
        ("1) rise by 0.1\n2) keep away from the lamp", "rise by 0.1. keep away from the table lamp."),
        ("- slow down near the red mug\n- then go left", "slow down near the red mug. then go left."),
        ("First:\n1. go up\n2. go left", "First: go up. go left."),
        ("3) go right 4) stop at the goal", "go right. stop at the goal."),
    ],
)
def test_a_list_becomes_sentences_and_its_numbers_no_amounts(words, plain):
    assert _plain(words) == plain


@pytest.mark.parametrize("words", ["- ", "\n- \n", "1)"])
def test_marks_with_no_item_are_kept_as_said(words):
    assert _plain(words) == words


@pytest.mark.parametrize(
    ("words", "plain"),
    [
        ("shift up by zero point two five", "shift up by 0.25"),
        ("lower the goal by point four", "lower the goal by 0.4"),
        ("one point five further along", "1.5 further along"),
        ("keep within three of the red mug", "keep within 3 of the red mug"),
        ("go back by two", "go back by 2"),
        ("rise four units", "rise 4 units"),
        ("back off two and a half from the table lamp", "back off 2.5 from the table lamp"),
        ("drop it by one-and-a-quarter", "drop it by 1.25"),
        ("3 and three quarters to the left", "3.75 to the left"),
    ],
)
def test_numbers_in_words_become_digits(words, plain):
    assert _plain(words) == plain


@pytest.mark.parametrize(
    "words",
    [
        "increase the clearance by two times",  # a factor, not a distance
        "go through one of the gaps",
        "stop at this point",
        "pass the waypoints two at a time",
        "a hand and a half away",  # no number before the fraction
    ],
)
def test_numbers_that_are_no_distance_stay_in_words(words):
    assert _plain(words) == words


@pytest.mark.parametrize(
    ("words", "plain"),
    [
        ("swing wide of the kettle", "swing wide of the electric kettle"),
        ("Pass the mug on its left", "Pass the red mug on its left"),
        ("approach the kettles", "approach the electric kettle"),
        (
            "pass left of the electric kettle, then keep 0.2 from the kettle",
            "pass left of the electric kettle, then keep 0.2 from the electric kettle",
        ),  # the full name said before: the short one is the same object
        ("slow near the Red Mug, then lift the mug", "slow near the Red Mug, then lift the red mug"),
    ],
)
def test_an_object_called_by_one_word_of_its_name_is_called_by_its_name(words, plain):
    assert _plain(words) == plain


@pytest.mark.parametrize(
    "words",
    [
        "go around the table",  # two objects have 'table'
        "stop at the goal",  # 'goal' names no object, even beside a goal post
        "keep away from the red mug and the electric kettle",  # already the full names
    ],
)
def test_a_word_two_objects_share_or_no_object_is_called_is_kept(words):
    assert _plain(words) == words


@pytest.mark.parametrize(
    ("words", "names", "plain"),
    [
        ("skim the bookcase", ["book case", "lamp"], "skim the book case"),
        ("skim the book case", ["bookcase", "lamp"], "skim the bookcase"),
        ("circle the tea-pot", ["teapot"], "circle the teapot"),
        ("steer clear of the fire hydrant", ["firehydrant"], "steer clear of the firehydrant"),
        ("stay left a bit", ["leftbit"], "stay left a bit"),  # split anywhere but whole words only
        ("near the water spaniel, hurry", ["Irish water spaniel"], "near the Irish water spaniel, hurry"),
        ("orbit the grand piano", ["black grand piano"], "orbit the black grand piano"),  # the rest said
    ],
)
def test_a_name_spaced_otherwise_or_in_part_is_written_as_the_scene_spells_it(words, names, plain):
    assert plain_words(words, names, keep=lambda sentence: False) == plain


@pytest.mark.parametrize(
    ("words", "plain"),
    [
        ("Please don't fly so near the red mug", "Please fly further from the red mug"),
        ("never brush that close by the table lamp", "brush further from the table lamp"),
        ("do not leave as much room around the red mug", "leave less room around the red mug"),
        ("don't give the red mug so wide a berth", "give the red mug less berth"),
        ("don't hover quite so far from the table lamp", "hover closer to the table lamp"),
        ("never go that fast around the red mug", "go slower around the red mug"),
        ("Don't hurry through the last stretch", "Slow down through the end"),
        ("don't crawl along nearly as slowly past the lamp", "crawl along a lot faster past the table lamp"),
        ("not anything like as close to the red mug, please", "a lot further from the red mug, please"),
        ("do not carry on after the goal", "stop after the goal"),
    ],
)
def test_what_not_to_do_is_said_as_what_to_do(words, plain):
    assert _plain(words) == plain


@pytest.mark.parametrize(
    "words",
    [
        "don't slow down near the red mug",  # a plain pace negated asks no change
        "don't go faster than 0.5 near the red mug",  # a limit
        "never get closer than 0.2 to the table lamp",
        "don't turn left when close to the red mug",  # the negation is of the turn
        "It doesn't go so close to the red mug. Raise it by 0.1.",  # a statement, no request
    ],
)
def test_negations_that_ask_no_opposite_are_kept(words):
    assert _plain(words) == words


def test_the_request_is_in_plain_words():
    assert request_words("1) don't go so fast near the mug 2) rise by point one", NAMES) == (
        "go slower near the red mug. rise by 0.1."
    )


def test_the_readers_read_the_plain_words():
    code = "t = get_trajectory()\nt = scale_speed(t, 1.4, near=detect_objects('red mug'))\nmodified_trajectory = t"
    read, notes = read_against_words(code, ["don't drive quite so fast near the mug"], NAMES)
    assert "scale_speed(t, 0.7" in read or "scale_speed(t, 0.6" in read, read
    assert notes[0].reader == "request-words"


@pytest.mark.parametrize(
    ("words", "plain"),
    [
        ("Stop dawdling around the red mug.", "Speed up around the red mug."),
        ("quit zooming past the table lamp", "slow down past the table lamp"),
        ("stop hovering so close to the red mug", "hovering further from the red mug"),
    ],
)
def test_what_to_stop_doing_is_said_as_what_to_do(words, plain):
    assert _plain(words) == plain


@pytest.mark.parametrize(
    "words", ["stop near the red mug", "stop moving near the red mug", "stop at the goal"]
)
def test_stopping_somewhere_is_no_negation(words):
    assert _plain(words) == words

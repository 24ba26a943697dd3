"""A speed change the words place near one object, written for the whole path, is placed there."""

from __future__ import annotations

import pytest

from trajadapt.readers.speed_scope import localize_speed, scoped_object

NAMES = ["box", "red box", "person"]
CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("instruction", "target"),
    [
        ("walk a lot faster in the proximity of the person", "person"),
        ("go slower while passing close to the red box", "red box"),  # the longest name that matches
        ("drive much faster while passing nearby the box", "box"),
        ("go faster near the box and slower near the person", None),  # two speed clauses
        ("go faster and pass closer to the box", None),  # the speed clause names no object
        ("go faster with the box", None),  # no place word
        ("go slower near the box or the person", None),  # two objects
    ],
)
def test_the_one_place_of_the_one_speed_clause(instruction: str, target: str | None) -> None:
    assert scoped_object(instruction, NAMES) == target


def test_an_unplaced_speed_step_gets_the_place_and_a_note() -> None:
    code, notes = localize_speed(
        CODE.format(step="t = scale_speed(t, 1.6)"), ["go a lot faster near the person"], NAMES
    )
    assert "t = scale_speed(t, 1.6, near=detect_objects('person'))" in code.splitlines()
    assert "changes the speed near person, not everywhere" in notes[0]


def test_a_scaling_placed_at_an_end_only_another_clause_names_goes_where_its_own_clause_says() -> None:
    """In "halve the speed through the middle, then ease down to a stop by the goal", 0.5 is the middle's."""
    step = "t = scale_speed(t, 0.5, near=detect_objects('goal'))"
    words = ["halve the speed through the middle, then ease down to a full stop by the goal"]
    code, notes = localize_speed(CODE.format(step=step), words, NAMES)
    assert code.splitlines()[1] == "t = scale_speed(t, 0.5, part='middle')" and "its clause" in notes[0]


def test_a_pace_said_of_an_end_as_a_stretch_is_that_part() -> None:
    step = "t = scale_speed(t, 1.4, near=detect_objects('start'))"
    code, _ = localize_speed(CODE.format(step=step), ["speed up the start"], NAMES)
    assert code.splitlines()[1] == "t = scale_speed(t, 1.4, part='start')"
    near = "t = scale_speed(t, 0.65, near=detect_objects('start'))"
    assert (
        localize_speed(CODE.format(step=near), ["slow down near the start"], NAMES)[0].splitlines()[1] == near
    )


def test_the_one_pace_at_an_object_no_pace_clause_names_goes_to_the_paced_part() -> None:
    step = "t = move_away(t, detect_objects('box'))\nt = scale_speed(t, 0.45, near=detect_objects('box'))"
    words = ["give the box a wider margin; the end should also run slower"]  # the plain words' part
    code, notes = localize_speed(CODE.format(step=step), words, NAMES)
    assert "t = scale_speed(t, 0.45, part='end')" in code.splitlines()


def test_a_speed_another_clause_states_stays_on_the_whole_path() -> None:
    """In "drive at 0.3 and go slower near the box", 0.3 is the first clause's, for the whole way."""
    step = "t = set_speed(t, 0.3)\nt = scale_speed(t, 0.65)"
    code, _ = localize_speed(CODE.format(step=step), ["drive at 0.3 and go slower near the box"], NAMES)
    assert code.splitlines()[1:3] == [
        "t = set_speed(t, 0.3)",
        "t = scale_speed(t, 0.65, near=detect_objects('box'))",
    ]


@pytest.mark.parametrize(
    "step",
    [
        "t = set_speed(t, 0.2, detect_objects('box'))",
        "t = scale_speed(t, 1.6)\nt = scale_speed(t, 0.5)",  # which one? left alone
        "t = shift(t, 'left')",
    ],
)
def test_steps_with_a_place_or_ambiguous_ones_stay(step: str) -> None:
    code = CODE.format(step=step)
    assert localize_speed(code, ["go faster near the person"], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("words", "placed"),
    [
        ("hurry when you pass the person", "near=detect_objects('person')"),
        ("within 0.3 of the person, hurry", "near=detect_objects('person'), radius=0.3"),
    ],
)
def test_a_part_the_words_never_name_gives_way_to_the_object(words: str, placed: str) -> None:
    code, notes = localize_speed(
        CODE.format(step="t = scale_speed(t, 1.4, part='second half')"), [words], NAMES
    )
    assert f"t = scale_speed(t, 1.4, {placed})" in code.splitlines()
    assert len(notes) == 1


def test_a_part_the_words_name_is_a_place_of_its_own() -> None:
    code = CODE.format(step="t = scale_speed(t, 1.6, part='end')")
    assert localize_speed(code, ["towards the end, go faster near the person"], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("words", "step", "placed"),
    [
        ("hurry through the middle section", "t = scale_speed(t, 1.4, near=detect_objects('goal'))",
         "t = scale_speed(t, 1.4, part='middle')"),
        ("crawl along for the second half", "t = set_speed(t, 0.2, near=detect_objects('start'), radius=0.3)",
         "t = set_speed(t, 0.2, part='second half')"),
        ("ease off the pace in stages", "t = scale_speed(t, 0.65, near=detect_objects('goal position'))",
         "t = scale_speed(t, 0.65)"),
    ],
)  # fmt: skip
def test_a_speed_placed_near_an_end_nobody_named_goes_where_the_words_say(
    words: str, step: str, placed: str
) -> None:
    code, notes = localize_speed(CODE.format(step=step), [words], ["lamp"])
    assert code == CODE.format(step=placed) and "the words never name the" in notes[0]


@pytest.mark.parametrize(
    ("words", "step"),
    [
        ("ease off as you arrive", "t = scale_speed(t, 0.65, near=detect_objects('goal'))"),
        ("brisker right at the beginning", "t = scale_speed(t, 1.4, near=detect_objects('start'))"),
        ("slower close to the end point", "t = scale_speed(t, 0.65, near=detect_objects('end point'))"),
    ],
)  # fmt: skip
def test_a_speed_placed_near_an_end_the_words_name_stays(words: str, step: str) -> None:
    assert localize_speed(CODE.format(step=step), [words], ["lamp"]) == (CODE.format(step=step), [])


def test_an_end_given_in_order_and_the_part_of_the_pace_clause_only() -> None:
    step = "t = scale_speed(t, 1.4, detect_objects('goal'), 0.2)"
    code, _ = localize_speed(CODE.format(step=step), ["shift the middle left and go faster"], ["lamp"])
    assert code == CODE.format(step="t = scale_speed(t, 1.4)")  # "middle" belongs to the shift's clause


@pytest.mark.parametrize(
    ("words", "step"),
    [
        # a profile for a pace the words place at an object (session 31; fresh-i's "on the approach to")
        (
            "slow down as the robot approaches the person",
            "t = scale_speed(t, 0.65, near=detect_objects('person'))",
        ),
        (
            "go a lot slower in the vicinity of the box",
            "t = scale_speed(t, 0.45, near=detect_objects('box'))",
        ),
        ("speed up when passing the person", "t = scale_speed(t, 1.4, near=detect_objects('person'))"),
    ],
)
def test_a_profile_for_a_pace_placed_at_an_object_is_placed_there(words: str, step: str) -> None:
    kind = "accelerate" if "up" in words else "decelerate"
    code, notes = localize_speed(
        CODE.format(step=f"t = speed_profile(t, {kind!r}, start=0.7)"), [words], NAMES
    )
    assert code.splitlines()[1] == step
    assert "not towards the goal" in notes[0]


@pytest.mark.parametrize(
    "words",
    [
        "slow down near the person and stop at the end",  # a stop: the profile makes it
        "slow down near the person in the second half",  # a part of the path
        "slow down towards the goal",  # no object
    ],
)
def test_a_profile_for_an_end_a_part_or_no_object_stays(words: str) -> None:
    code = CODE.format(step="t = speed_profile(t, 'decelerate', start=0.7)")
    assert localize_speed(code, [words], NAMES)[0] == code


@pytest.mark.parametrize(
    "words",
    [
        # a part the pace's words never name (session 31; fresh-f's "slow to roughly half speed")
        "around the box, bring the speed down to about half; the goal stays where it is",
        "keep at least 0.2 from the person, and near the box go at half speed",
    ],
)
def test_a_number_of_the_speed_or_a_kept_end_names_no_part_for_the_pace(words: str) -> None:
    code = CODE.format(step="t = scale_speed(t, 0.5, part='middle')")
    assert localize_speed(code, [words], NAMES)[0].splitlines()[1] == (
        "t = scale_speed(t, 0.5, near=detect_objects('box'))"
    )


@pytest.mark.parametrize(
    ("words", "near", "step"),
    [
        ("pick up the pace over the final stretch", "t[-1]", "t = scale_speed(t, 1.4, part='final')"),
        ("go a bit faster at the very beginning", "t[0, :3]", "t = scale_speed(t, 1.4, part='beginning')"),
        ("slow it down by roughly 30%", "t[0]", "t = scale_speed(t, 1.4)"),  # no end named: everywhere
    ],
)
def test_a_pace_placed_at_an_end_waypoint_is_the_part_the_words_name(
    words: str, near: str, step: str
) -> None:
    code = CODE.format(step=f"t = scale_speed(t, 1.4, near={near})")
    assert localize_speed(code, [words], NAMES)[0].splitlines()[1] == step


def test_a_pace_going_past_an_object_is_placed_there() -> None:
    code = CODE.format(step="t = scale_speed(t, 0.5)")
    placed = localize_speed(code, ["take it slower going past the box, roughly half speed there"], NAMES)[0]
    assert placed.splitlines()[1] == "t = scale_speed(t, 0.5, near=detect_objects('box'))"


def test_a_place_at_a_waypoint_of_another_list_is_no_end_of_the_path() -> None:
    code = CODE.format(step="t = scale_speed(t, 1.4, near=pts[-1])")
    assert localize_speed(code, ["speed up over the final stretch"], NAMES)[0] == code


@pytest.mark.parametrize(
    ("words", "part"),
    [
        ("cruise the first half at a gentler pace", "first half"),
        ("go quicker through the middle", "middle"),
        ("start off slower", "start"),
    ],
)
def test_a_whole_path_pace_goes_to_the_one_part_its_clause_names(words: str, part: str) -> None:
    code = "t = get_trajectory()\nt = scale_speed(t, 0.65)\nmodified_trajectory = t"
    placed, notes = localize_speed(code, [words], ["lamp"])
    assert placed.splitlines()[1] == f"t = scale_speed(t, 0.65, part={part!r})" and notes


@pytest.mark.parametrize(
    "words",
    [
        "hold a steady 0.3 from start to finish",  # the whole path, ends named
        "slow down near the lamp in the middle",  # an object's place: the other rule's
        "slow down in the middle, then speed up at the end",  # two pace clauses
        "ease off until you stop at the end",  # a stop: a profile
    ],
)
def test_no_part_or_another_reading_leaves_the_pace_unplaced_here(words: str) -> None:
    code = "t = get_trajectory()\nt = set_speed(t, 0.3)\nmodified_trajectory = t"
    placed, _ = localize_speed(code, [words], ["lamp"])
    assert "part=" not in placed


def test_a_pace_said_only_by_a_word_of_slower_is_placed_at_its_object_too() -> None:
    code = "t = get_trajectory()\nt = scale_speed(t, 0.65)\nmodified_trajectory = t"
    placed, _ = localize_speed(code, ["keep the start where it is and really crawl past the person"], NAMES)
    assert placed.splitlines()[1] == "t = scale_speed(t, 0.65, near=detect_objects('person'))"


@pytest.mark.parametrize(
    ("words", "kept"),
    [
        (
            "give the box a wider berth, and hold a steady 0.4 throughout",
            False,
        ),  # the box's clause asks no pace
        ("give the box a wider berth, and slow down near the box", True),  # a pace clause names it
    ],
)
def test_a_pace_at_an_object_no_pace_clause_names_leaves_beside_another(words: str, kept: bool) -> None:
    placed = "t = scale_speed(t, 0.65, near=detect_objects('box'))"
    code = "\n".join(["t = get_trajectory()", "t = set_speed(t, 0.4)", placed, "modified_trajectory = t"])
    assert (placed in localize_speed(code, [words], NAMES)[0].splitlines()) is kept


@pytest.mark.parametrize(
    "words",
    [
        "ease off right from the start",
        "go slower than at the start",
        "slow it all so the goal is reached gently",
    ],
)
def test_a_part_that_places_no_pace_leaves_the_pace_whole(words: str) -> None:
    code = "t = get_trajectory()\nt = scale_speed(t, 0.65)\nmodified_trajectory = t"
    assert "part=" not in localize_speed(code, [words], NAMES)[0]


def test_a_pace_near_an_object_whose_clause_asks_nothing_else_of_it_stays() -> None:
    code = "t = get_trajectory()\nt = scale_speed(t, 1.25)\nt = scale_speed(t, 0.65, near=detect_objects('box'))\nmodified_trajectory = t"
    words = ["be careful around the box, and go a bit faster overall"]
    assert "near=detect_objects('box')" in localize_speed(code, words, NAMES)[0]


def test_an_even_pace_said_with_a_move_closer_holds_the_whole_way() -> None:
    code = "t = get_trajectory()\nt = set_speed(t, 0.2)\nmodified_trajectory = t"
    words = ["hold a constant velocity of 0.2 as you move nearer to the box"]
    assert localize_speed(code, words, NAMES) == (code, [])


@pytest.mark.parametrize(
    "words",
    [  # an end kept where it is is no part of the pace (session 37: "keeping the same final pose")
        "cut the overall speed by about a third, keeping the same final pose",
        "slow everything down a little and leave the end position unchanged",
    ],
)
def test_words_that_keep_an_end_place_no_pace_there(words: str) -> None:
    code, notes = localize_speed(CODE.format(step="t = scale_speed(t, 0.65)"), [words], NAMES)
    assert "t = scale_speed(t, 0.65)" in code.splitlines() and notes == []

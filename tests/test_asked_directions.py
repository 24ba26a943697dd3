"""A direction a clause asks, with no step that moves that way, gets a shift (readers.asked_directions)."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.asked_directions import add_asked_directions

NAMES = ["lamp", "Sofa"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "steps", "added"),
    [
        ("head left while easing to a halt at the end", ("t = speed_profile(t, 'decelerate', start=0.6)",),
         "t = shift(t, 'left')"),
        ("hug the lamp and climb slightly", ("t = move_closer(t, detect_objects('lamp'))",),
         "t = shift(t, 'up', 'slightly')"),
        ("swing the route backwards a lot, then slow down", ("t = scale_speed(t, 0.65)",),
         "t = shift(t, 'back', 'a lot')"),
        # a move of the start or goal alone neither makes nor undoes a move of the whole path
        ("lower the whole route a bit; the end point, though, goes up a bit",
         ("t = shift_goal(t, 'up', 'a bit')",), "t = shift(t, 'down', 'a bit')"),
    ],
)  # fmt: skip
def test_a_dropped_direction_becomes_the_first_step(words: str, steps: tuple[str, ...], added: str) -> None:
    code, notes = add_asked_directions(program(*steps), [words])
    assert code.splitlines()[1] == added
    assert code.splitlines()[2:-1] == list(steps)
    assert "no step does" in notes[0]


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        (
            "go down a little and hurry",
            ("t = shift_part(t, 'downwards', 'a little', part='middle')",),
        ),  # done
        ("after the goal carry on 2 to the rear", ("t = extend(t, 2, 'back')",)),  # extend goes back
        ("fly above the lamp", ("t = stay_above(t, 0.5)",)),  # a place, and a height step
        ("pass to the left of the sofa", ("t = keep_side(t, 'left', detect_objects('Sofa'))",)),
        ("do not drift right", ("t = smooth(t)",)),  # a negation
        ("move the first 5 waypoints up", ("t = scale_speed(t, 1.4)",)),  # a part: not the whole path
        ("speed up and calm down near the end", ("t = scale_speed(t, 1.4)",)),  # paces, no direction
        ("go left of the lamp", ("t = move_closer(t, detect_objects('lamp'))",)),  # a place
        ("ease up when the sofa is near", ("t = scale_speed(t, 0.65, near=detect_objects('Sofa'))",)),
        ("fly up to the lamp", ("t = move_closer(t, detect_objects('lamp'))",)),  # "up to": a place
        # "it" is the named end: its move the same way makes the clause
        ("The end point sits too low. Lift it 0.05.", ("t = shift_goal(t, 'up', 0.05)",)),
    ],
)
def test_directions_already_moved_places_parts_and_paces_add_nothing(
    words: str, steps: tuple[str, ...]
) -> None:
    code = program(*steps)
    assert add_asked_directions(code, [words]) == (code, [])


def test_the_added_shift_takes_the_clause_number_from_the_readers_after_it() -> None:
    code, _ = read_against_words(
        program("t = move_closer(t, detect_objects('Sofa'))"), ["sink by 0.15, nearing the sofa"], NAMES
    )
    assert "t = shift(t, 'down', 0.15)" in code.splitlines()


def test_a_clause_that_also_names_an_object_still_asks_its_direction() -> None:
    code, _ = add_asked_directions(
        program("t = move_closer(t, detect_objects('lamp'), 'slightly')"),
        ["drift left a little, keeping a smaller gap to the lamp"],
    )
    assert code.splitlines()[1] == "t = shift(t, 'left', 'a little')"


def test_the_shift_goes_to_the_variable_the_trajectory_was_read_into() -> None:
    code, _ = add_asked_directions(
        "path = get_trajectory()\npath = smooth(path)\nmodified_trajectory = path", ["head forward"]
    )
    assert code.splitlines()[1] == "path = shift(path, 'front')"


def test_an_answer_with_no_step_gets_the_asked_direction() -> None:
    """A program that keeps the path, whether the model wrote it or a reader emptied it, drops the clause."""
    code, notes = add_asked_directions(program(), ["take it over to the right"])
    assert code.splitlines() == ["t = get_trajectory()", "t = shift(t, 'right')", "modified_trajectory = t"]
    assert "no step does" in notes[0]


def test_an_answer_the_readers_cannot_follow_is_left_alone() -> None:
    code = "t = get_trajectory()\nt[:, 0] += 1\nmodified_trajectory = t"
    assert add_asked_directions(code, ["head forward"]) == (code, [])


@pytest.mark.parametrize(
    ("words", "shift"),
    [
        ("slide 0.3 over to the right", "t = shift(t, 'right', 0.3)"),
        ("head over to the left", "t = shift(t, 'left')"),
    ],
)
def test_over_to_a_side_is_a_move_not_a_place(words: str, shift: str) -> None:
    code, _ = read_against_words(program("t = smooth(t)"), [words], NAMES)
    assert shift in code.splitlines()


def test_the_readers_do_not_read_a_statement_of_the_problem_as_a_request() -> None:
    """'too slow ... keeps well away' states the problem; read as asks they are the opposite of the fix."""
    words = (
        "It is too slow within 0.3 of the lamp and keeps well away from the sofa. "
        "Hurry up inside 0.3 of the lamp, and come in nearer to the sofa."
    )
    code = program("t = avoid(t, detect_objects('lamp'), 0.3)", "t = move_closer(t, detect_objects('Sofa'))")
    read, _ = read_against_words(code, [words], NAMES)
    assert read.splitlines()[1:3] == [
        "t = scale_speed(t, 1.4, near=detect_objects('lamp'), radius=0.3)",
        "t = move_closer(t, detect_objects('Sofa'))",
    ]


@pytest.mark.parametrize(
    "words",
    [
        "begin 0.5 further forward and keep the goal where it is",
        "have the path start 0.3 more to the left",
    ],
)
def test_a_whole_path_shift_for_a_start_move_becomes_the_start_move(words: str) -> None:
    """A shift keeps the start: for a start move it is the model's reading of it, not a move of its own."""
    direction = "front" if "forward" in words else "left"
    code, _ = add_asked_directions(program(f"t = shift(t, '{direction}', 0.3)"), [words])
    assert [called for called in code.splitlines()[1:-1] if "shift" in called] == [
        f"t = shift_start(t, '{direction}')"
    ]


def test_a_shift_another_clause_asks_stays_beside_the_start_move() -> None:
    words = "begin 0.2 more to the left, then move the whole path left by 0.2"
    code, _ = add_asked_directions(program("t = shift(t, 'left', 0.2)"), [words])
    assert code.splitlines()[1:3] == ["t = shift_start(t, 'left')", "t = shift(t, 'left', 0.2)"]


@pytest.mark.parametrize(
    "words",
    ["crawl by the lamp, and make the route finish a little higher", "end the path a touch further up"],
)
def test_a_part_move_of_a_part_nobody_names_becomes_the_asked_end_move(words: str) -> None:
    code, notes = add_asked_directions(program("t = shift_part(t, 'up', None, 'middle')"), [words])
    assert len(code.splitlines()) == 3 and code.splitlines()[1].startswith("t = shift_goal(t, 'up'")
    assert "no word names the part" in notes[0]


def test_a_part_move_of_a_named_part_stays_beside_the_added_end_move() -> None:
    code, _ = add_asked_directions(
        program("t = shift_part(t, 'up', None, 'middle')"), ["raise the middle, and end a bit higher"]
    )
    assert "t = shift_part(t, 'up', None, 'middle')" in code.splitlines()


def test_a_bow_of_the_middle_the_other_way_turns_the_way_its_clause_says() -> None:
    code, notes = add_asked_directions(
        program("t = lift_middle(t, 'up', 0.1)"), ["dip the middle of the motion by 0.1"]
    )
    assert code.splitlines()[1] == "t = lift_middle(t, 'down', 0.1)" and "no word asks" in notes[0]


def test_a_part_move_another_clause_asks_stays_beside_the_end_move() -> None:
    words = "bring the path up halfway along, and make it end a bit higher"
    code, _ = add_asked_directions(program("t = shift_part(t, 'up', None, 'middle')"), [words])
    assert "t = shift_part(t, 'up', None, 'middle')" in code.splitlines()

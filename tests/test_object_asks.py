"""What the words ask of each object, and a step on it that does something else, replaced."""

from __future__ import annotations

import pytest

from trajadapt.readers.object_asks import replace_object_steps
from trajadapt.readers.object_words import object_asks

NAMES = ["Lamp", "red box", "box", "sofa"]
CODE = "t = get_trajectory()\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("words", "name", "relation", "extra"),
    [
        ("hurry up whenever the lamp is within 0.4", "Lamp", "faster", 0.4),
        ("take it slowly near the red box", "red box", "slower", None),  # the longest name
        ("never pass to the left of the sofa", "sofa", "side", "right"),
        ("stay to the front of the box", "box", "side", "front"),
        ("remain on the left-hand side of the sofa throughout", "sofa", "side", "left"),
        ("drive on the right hand side of the red box", "red box", "side", "right"),
        ("keep every waypoint behind the sofa", "sofa", "side", "back"),
        ("don't ever go behind the lamp", "Lamp", "side", "front"),
        ("keep a smaller distance to the sofa", "sofa", "closer", None),
        ("give the lamp a wider berth", "Lamp", "away", None),
        ("ease off if the lamp is no more than 0.4 away", "Lamp", "slower", 0.4),
        ("speed up when less than 0.25 m from the sofa", "sofa", "faster", 0.25),
        ("hurry inside 0.6 of the lamp", "Lamp", "faster", 0.6),
        ("keep no closer than 0.3 to the sofa", "sofa", "away", None),
        ("hold a minimum gap of 0.1 from the red box", "red box", "away", None),
    ],
)
def test_each_clause_asks_one_thing_of_the_one_object_it_names(
    words: str, name: str, relation: str, extra: object
) -> None:
    ask = object_asks(words, NAMES)[name]
    assert ask.relation == relation
    assert (ask.radius if relation in ("faster", "slower") else ask.side or None) == extra


@pytest.mark.parametrize(
    ("words", "asks"),
    [
        ("approach the sofa giving the lamp a wider berth", {"sofa": "closer", "Lamp": "away"}),
        ("hug the red box while slowing near the Lamp", {"red box": "closer", "Lamp": "slower"}),
    ],
)
def test_each_object_of_a_joined_instruction_is_read_in_its_own_clause(
    words: str, asks: dict[str, str]
) -> None:
    """One splitter: a participle or 'while' that starts a request gives each object its own clause."""
    assert {name: ask.relation for name, ask in object_asks(words, NAMES).items()} == asks


@pytest.mark.parametrize(
    "words",
    [
        "move closer to the sofa and then further from the sofa",  # two different asks
        "go closer to the lamp or the sofa",  # two objects in one clause
        "go faster with the box",  # a speed word without a place
        "approach the lamp slowly",  # closer and slower: which one does a step on the lamp make?
    ],
)
def test_unclear_asks_are_left_out(words: str) -> None:
    assert object_asks(words, NAMES) == {}


def test_a_way_to_go_and_a_pace_there_ask_the_way() -> None:
    """A pace is where something happens, not a way to go: the clause asking closer is the ask."""
    asks = object_asks("go right next to the sofa and slow down as you get close to the sofa", NAMES)
    assert asks["sofa"].relation == "closer"
    assert "sofa" not in object_asks("speed up near the sofa, then slow down near the sofa", NAMES)


@pytest.mark.parametrize(
    ("step", "words", "expected"),
    [
        (
            "t = avoid(t, detect_objects('lamp'), 0.3)",
            "move slower when the lamp is within 0.3",
            ["t = scale_speed(t, 0.65, near=detect_objects('Lamp'), radius=0.3)"],
        ),
        (
            "t = avoid(t, [detect_objects('lamp'), detect_objects('sofa')], 0.3)",
            "speed up a lot near the lamp",
            [
                "t = avoid(t, detect_objects('sofa'), 0.3)",
                "t = scale_speed(t, 1.6, near=detect_objects('Lamp'))",
            ],
        ),
        (
            "t = avoid(t, detect_objects('sofa'), 0.5)",
            "do not drive right of the sofa",
            ["t = keep_side(t, 'left', detect_objects('sofa'))"],
        ),
        (
            "t = avoid(t, detect_objects('sofa'), 0.5)",
            "pass at a slightly smaller distance from the sofa",
            ["t = move_closer(t, detect_objects('sofa'), 'slightly')"],
        ),
        (
            "t = move_away(t, detect_objects('sofa'), 'a lot')",
            "pass a lot closer to the sofa",
            ["t = move_closer(t, detect_objects('sofa'), 'a lot')"],
        ),
        (
            "t = pass_through(t, midpoint(detect_objects('sofa'), detect_objects('lamp')))",
            "go right through the sofa",
            ["t = pass_through(t, detect_objects('sofa'))"],
        ),
        (
            "t = avoid(t, detect_objects('sofa'), 0.5)",
            "walk a lot further from the sofa",
            ["t = move_away(t, detect_objects('sofa'), 'a lot')"],
        ),
        (
            "t = avoid(t, detect_objects('sofa'), 0.4)",
            "pass the sofa with at least 1 to spare",
            ["t = avoid(t, detect_objects('sofa'), 1)"],
        ),  # a clearance the clause does not state, where it states a least distance: that one
        (
            "t = move_away(t, detect_objects('sofa'))",
            "keep a minimum separation of 0.4 from the sofa",
            ["t = avoid(t, detect_objects('sofa'), 0.4)"],
        ),  # a least distance stated: a vague move away may stay nearer
        (
            "t = circle_around(t, detect_objects('sofa'))",
            "ease off all around the sofa",
            ["t = scale_speed(t, 0.65, near=detect_objects('sofa'))"],
        ),  # "around" placed a pace; no word asks to go round
        (
            "t = keep_side(t, 'back', detect_objects('sofa'))",
            "the path ought to come a bit nearer the sofa than today",
            ["t = move_closer(t, detect_objects('sofa'), 'a bit')"],
        ),  # a side nobody asked, for a distance
        (
            "t = keep_side(t, 'left', detect_objects('sofa'))",
            "steer well clear of the sofa",
            ["t = move_away(t, detect_objects('sofa'))"],
        ),
        (
            "t = keep_side(t, 'front', detect_objects('lamp'))",
            "crawl by the lamp",
            ["t = scale_speed(t, 0.65, near=detect_objects('Lamp'))"],
        ),
    ],
)
def test_a_step_that_does_something_else_is_replaced_with_a_note(
    step: str, words: str, expected: list[str]
) -> None:
    code, notes = replace_object_steps(CODE.format(step=step), [words], NAMES)
    assert code.splitlines()[1:-1] == expected
    assert len(notes) == 1


@pytest.mark.parametrize(
    ("step", "words"),
    [
        (
            "t = avoid(t, detect_objects('sofa'), 0.5)",
            "stay further than 0.5 from the sofa",
        ),  # stated clearance
        ("t = move_away(t, detect_objects('sofa'))", "walk further from the sofa"),  # already right
        ("t = avoid(t, detect_objects('lamp'), 0.2)\nt = scale_speed(t, 0.5)", "go slower near the lamp"),
        ("t = shift(t, 'left')", "go slower near the lamp"),  # no step on the object to replace
        ("t = circle_around(t, detect_objects('sofa'))", "loop around the sofa, slowing as you go round it"),
        ("t = keep_side(t, 'left', detect_objects('sofa'))", "stay left of the sofa"),  # names it
        (
            "t = pass_through(t, midpoint(detect_objects('sofa'), detect_objects('lamp')))",
            "between the sofa and x",
        ),
    ],
)
def test_steps_the_words_agree_with_stay(step: str, words: str) -> None:
    code = CODE.format(step=step)
    assert replace_object_steps(code, [words], NAMES) == (code, [])


@pytest.mark.parametrize(
    ("words", "steps", "expected"),
    [
        (  # the pace went to the object of the distance clause, the distance to the other
            "ease off whenever the lamp is within 0.5, and give the sofa a wider berth",
            [
                "t = move_away(t, detect_objects('Lamp'))",
                "t = scale_speed(t, 0.6, near=detect_objects('sofa'))",
            ],
            [
                "t = move_away(t, detect_objects('sofa'))",
                "t = scale_speed(t, 0.6, near=detect_objects('Lamp'), radius=0.5)",
            ],
        ),
        (  # a clearance kept on the wrong object keeps its amount on the right one
            "go slower when the sofa is not more than 0.3 off; keep at least 0.4 from the lamp",
            [
                "t = avoid(t, detect_objects('sofa'), 0.4)",
                "t = scale_speed(t, 0.6, near=detect_objects('Lamp'))",
            ],
            [
                "t = avoid(t, detect_objects('Lamp'), 0.4)",
                "t = scale_speed(t, 0.6, near=detect_objects('sofa'), radius=0.3)",
            ],
        ),
        (  # the distance clause's object has its own step: the one on the paced object leaves
            "hug the red box. Hurry up close to the sofa",
            [
                "t = move_closer(t, detect_objects('sofa'))",
                "t = scale_speed(t, 0.7, near=detect_objects('red box'))",
                "t = move_closer(t, detect_objects('red box'))",
            ],
            [
                "t = scale_speed(t, 1.4, near=detect_objects('sofa'))",
                "t = move_closer(t, detect_objects('red box'))",
            ],
        ),
    ],
)
def test_a_pace_placed_near_the_object_of_a_distance_clause_is_swapped(
    words: str, steps: list[str], expected: list[str]
) -> None:
    assert_replaced(words, steps, expected)


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        # each object's step is where its clause asks it
        ("ease off near the lamp and give the sofa a wider berth",
         ["t = move_away(t, detect_objects('sofa'))", "t = scale_speed(t, 0.6, near=detect_objects('Lamp'))"]),
        # two paces asked: which speed step belongs where is not this reader's to say
        ("slow near the lamp, faster near the box and keep away from the sofa",
         ["t = scale_speed(t, 0.6, near=detect_objects('sofa'))"]),
    ],
)  # fmt: skip
def test_paces_placed_where_asked_or_unclear_stay(words: str, steps: list[str]) -> None:
    code = CODE.format(step="\n".join(steps))
    assert replace_object_steps(code, [words], NAMES)[0] == code


@pytest.mark.parametrize(
    ("words", "steps", "expected"),
    [
        (  # a clearance kept from the object of a pause goes to the object a distance is asked of
            "wait by the lamp for 5 steps, and give the sofa a wider berth",
            ["t = avoid(t, detect_objects('Lamp'), 0.4)", "t = wait(t, detect_objects('Lamp'), 5)"],
            ["t = move_away(t, detect_objects('sofa'))", "t = wait(t, detect_objects('Lamp'), 5)"],
        ),
        (  # a clearance from an object only a pace is asked near, with its speed step: out; its reach in
            "stay 0.3 clear of the sofa. When the lamp is within 0.5, creep slower",
            [
                "t = avoid(t, detect_objects('sofa'), 0.3)",
                "t = avoid(t, detect_objects('Lamp'), 0.5)",
                "t = scale_speed(t, 0.6, near=detect_objects('Lamp'))",
            ],
            [
                "t = avoid(t, detect_objects('sofa'), 0.3)",
                "t = scale_speed(t, 0.6, near=detect_objects('Lamp'), radius=0.5)",
            ],
        ),
        (  # a step against the asked way, beside one that goes it: out
            "bring the route in toward the red box, then descend 0.1",
            [
                "t = move_closer(t, detect_objects('red box'))",
                "t = move_away(t, detect_objects('red box'), 'a bit')",
                "t = shift(t, 'down', 0.1)",
            ],
            ["t = move_closer(t, detect_objects('red box'))", "t = shift(t, 'down', 0.1)"],
        ),
    ],
)
def test_distance_steps_go_where_a_distance_is_asked(
    words: str, steps: list[str], expected: list[str]
) -> None:
    assert_replaced(words, steps, expected)


def assert_replaced(words: str, steps: list[str], expected: list[str]) -> None:
    """The steps read against the words are the expected ones, with a note saying why."""
    code, notes = replace_object_steps(CODE.format(step="\n".join(steps)), [words], NAMES)
    assert code == CODE.format(step="\n".join(expected))
    assert notes


def test_a_distance_asked_of_no_named_object_keeps_every_distance_step() -> None:
    steps = "t = scale_speed(t, 0.6, near=detect_objects('Lamp'))\nt = move_away(t, detect_objects('Lamp'))"
    code = CODE.format(step=steps)
    assert replace_object_steps(code, ["slow down near the lamp and keep further from it"], NAMES)[0] == code


@pytest.mark.parametrize(
    "words", ["keep the sofa behind the robot at the end", "keep going with the lamp behind you"]
)
def test_something_else_behind_is_no_side_kept(words: str) -> None:
    assert all(ask.relation != "side" for ask in object_asks(words, NAMES).values())

"""A closer/further a clause asks of an object, with no step that moves by it, gets one (readers.asked_relations)."""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.asked_relations import add_asked_relations

NAMES = ["lamp", "Sofa", "red box"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "steps", "added"),
    [
        ("halve the speed and give the sofa a wider berth", ("t = scale_speed(t, 0.5)",),
         "t = move_away(t, detect_objects('Sofa'))"),
        ("raise the path by 0.1 while drifting a lot nearer to the red box", ("t = shift(t, 'up', 0.1)",),
         "t = move_closer(t, detect_objects('red box'), 'a lot')"),
        # the lamp only names where the speed changes: no step moves the path by it
        ("hurry, and keep more distance from the lamp", ("t = scale_speed(t, 1.4, near=detect_objects('lamp'))",),
         "t = move_away(t, detect_objects('lamp'))"),
        # a least distance stated: the clearance to keep
        ("hurry, and stay at least 0.35 away from the lamp", ("t = scale_speed(t, 1.4)",),
         "t = avoid(t, detect_objects('lamp'), 0.35)"),
        # an even pace and a move closer in one clause (session 33)
        ("hold a steady speed of 0.2 while you drift nearer to the lamp", ("t = set_speed(t, 0.2)",),
         "t = move_closer(t, detect_objects('lamp'))"),
        # a side to stay on (session 28)
        ("rise 0.1, and keep to the left side of the red box all the way", ("t = shift(t, 'up', 0.1)",),
         "t = keep_side(t, 'left', detect_objects('red box'))"),
    ],
)  # fmt: skip
def test_a_dropped_relation_becomes_the_last_step(words: str, steps: tuple[str, ...], added: str) -> None:
    code, notes = add_asked_relations(program(*steps), [words], NAMES)
    assert code.splitlines()[1:-1] == [*steps, added]
    assert "no step moves the path by it" in notes[0]


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        # a step already names the object: right or wrong, it answers the clause (object_asks reads it)
        ("come closer to the lamp", ("t = avoid(t, detect_objects('lamp'), 0.2)",)),
        ("come closer to the lamp", ("t = pass_through(t, detect_objects('lamp'))",)),
        ("come closer to the lamp", ("lamp = detect_objects('lamp')", "t = move_closer(t, lamp)")),
        # a part or an end of the path, a pace near the object, two asks of one object
        ("after the goal, head closer to the sofa", ("t = extend(t, 0.2)",)),
        ("slow down near the sofa", ("t = shift(t, 'left')",)),
        ("closer to the sofa, then further from the sofa", ("t = smooth(t)",)),
        # no step at all keeps the path; code a reader cannot follow is left alone
        ("keep further from the red box", ()),
        ("keep further from the red box", ("for i in range(3):", "    t = smooth(t)")),
    ],
)
def test_answered_placed_or_unclear_relations_add_nothing(words: str, steps: tuple[str, ...]) -> None:
    code = program(*steps)
    assert add_asked_relations(code, [words], NAMES) == (code, [])


def test_the_reader_runs_in_the_stage_and_names_itself() -> None:
    words = ["cut the speed in half and keep further from the lamp"]
    code, notes = read_against_words(program("t = scale_speed(t, 0.5)"), words, NAMES)
    assert code.splitlines()[1:-1] == ["t = scale_speed(t, 0.5)", "t = move_away(t, detect_objects('lamp'))"]
    assert [note.reader for note in notes] == ["asked-relations"]


def test_a_clearance_whose_step_a_later_reader_left_out_gets_its_step_at_the_end() -> None:
    written = "\n".join([
        "t = get_trajectory()",
        "t = stop_at(t, detect_objects('box'))",
        "t = scale_speed(t, 0.4, near=detect_objects('box'))",
        "modified_trajectory = t",
    ])  # fmt: skip
    words = "Arrive gently, decelerating to a stop at the end instead of at full speed, and keep at least 0.3 from the box throughout."
    code, notes = read_against_words(written, [words], ["box", "lamp"])
    assert code.splitlines()[1:-1] == [
        "t = speed_profile(t, 'decelerate', start=0.6)",
        "t = avoid(t, detect_objects('box'), 0.3)",
    ]
    assert notes[-1].reader == "relations-left"

"""A pace a clause asks and no step makes (readers.asked_paces)."""

from __future__ import annotations

import numpy as np
import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.asked_paces import add_asked_paces, asked_pace
from trajadapt.skills import bind_skills

NAMES = ["kettle", "floor lamp", "lamp", "crate"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("clause", "step"),
    [
        # a speed said as a value
        ("hold the velocity steady at 0.25", "t = set_speed(t, 0.25)"),
        ("cruise at 0.4 speed", "t = set_speed(t, 0.4)"),
        ("roll along at a steady 0.35", "t = set_speed(t, 0.35)"),
        ("maintain a uniform 0.25 all along", "t = set_speed(t, 0.25)"),
        ("from beginning to end keep the speed at 0.2", "t = set_speed(t, 0.2)"),  # no part: all of it
        ("with the pace set to .3 around the crate", "t = set_speed(t, 0.3, near=detect_objects('crate'))"),
        # a number with a unit of speed
        ("take the end at 0.3 m/s", "t = set_speed(t, 0.3, part='end')"),
        ("roll by the crate at 0.15 metres per second", "t = set_speed(t, 0.15, near=detect_objects('crate'))"),
        ("cruise at 0.5m/s", "t = set_speed(t, 0.5)"),
        # slower towards the goal or the end, decelerate, accelerate: profiles
        ("ease off as you come up to the destination", "t = speed_profile(t, 'decelerate', start=0.6)"),
        ("ease off towards the end", "t = speed_profile(t, 'decelerate', start=0.6)"),
        ("decelerate", "t = speed_profile(t, 'decelerate', start=0.6)"),
        ("accelerate as you go", "t = speed_profile(t, 'accelerate')"),
        # faster or slower: the stated factor, else the phrase table's for the amount word
        ("crawl past the floor lamp", "t = scale_speed(t, 0.65, near=detect_objects('floor lamp'))"),
        ("move three times as fast", "t = scale_speed(t, 3)"),
        ("go 20% slower", "t = scale_speed(t, 0.8)"),
        ("hurry a lot in the second half", "t = scale_speed(t, 1.6, part='second half')"),
        ("slow down a little at the beginning", "t = scale_speed(t, 0.75, part='start')"),
        ("pick up the pace in the first half", "t = scale_speed(t, 1.4, part='first half')"),
    ],
)  # fmt: skip
def test_the_step_a_clause_asks(clause: str, step: str) -> None:
    pace = asked_pace(clause, NAMES)
    assert pace is not None and pace.step == step


@pytest.mark.parametrize(
    "clause",
    [
        "never go faster than 0.5",  # a limit
        "stay under 0.4 m/s near the kettle",  # a limit with its unit
        "speed it up by 0.1 m/s",  # a change by an amount
        "cap the velocity at 2",  # a limit
        "raise the speed by 0.2",  # a change by an amount
        "don't slow down near the kettle",  # a negation
        "it is too slow near the kettle",  # a statement of how the path is now
        "keep the same pace",  # nothing to change
        "go left by 0.3",  # no pace
        "fly at a constant 0.3 height",  # a level, not a pace
        "speed up near the kettle and then slow down",  # both ways in one clause
    ],
)  # fmt: skip
def test_clauses_that_ask_no_pace(clause: str) -> None:
    assert asked_pace(clause, NAMES) is None


def test_a_dropped_speed_clause_gets_its_step_after_the_last_step() -> None:
    code, notes = add_asked_paces(
        program("t = shift(t, 'left', 0.2)"), ["slide left by 0.2 and take it easy near the crate"], NAMES
    )
    assert code == program(
        "t = shift(t, 'left', 0.2)", "t = scale_speed(t, 0.65, near=detect_objects('crate'))"
    )
    assert len(notes) == 1 and "take it easy near the crate" in notes[0]


def test_each_of_two_paces_gets_its_own_object() -> None:
    kept = "t = scale_speed(t, 1.4, near=detect_objects('kettle'))"
    code, _ = add_asked_paces(program(kept), ["zip past the kettle but go slowly by the crate"], NAMES)
    assert code == program(kept, "t = scale_speed(t, 0.65, near=detect_objects('crate'))")


@pytest.mark.parametrize(
    "steps",
    [
        ("t = scale_speed(t, 0.5)",),  # placed nowhere: the speed-scope reader places it
        ("t = scale_speed(t, 0.5, near=detect_objects('crate'))",),
        ("t = speed_profile(t, 'decelerate')",),
    ],
)
def test_a_pace_a_step_makes_is_left_alone(steps: tuple[str, ...]) -> None:
    code = program(*steps)
    assert add_asked_paces(code, ["dawdle near the crate"], NAMES) == (code, [])


def test_code_that_is_not_skill_calls_alone_is_left_alone() -> None:
    code = program("t[:, 3] = t[:, 3] * 2")
    assert add_asked_paces(code, ["twice as fast please"], NAMES) == (code, [])


def test_the_added_step_runs_and_makes_the_asked_speed() -> None:
    t = np.column_stack([np.linspace(0, 1, 30), np.zeros(30), np.full(30, 0.5), np.full(30, 0.4)])
    code, notes = read_against_words(
        program("t = shift(t, 'up', 0.1)"), ["lift it slightly, holding the speed steady at 0.15"], NAMES
    )
    assert any(note.reader == "asked-paces" for note in notes)
    namespace = {**bind_skills(), "get_trajectory": t.copy}
    exec(code, namespace)  # skill calls alone, checked by the reader
    assert np.allclose(namespace["modified_trajectory"][:, 3], 0.15)


@pytest.mark.parametrize(
    ("words", "written", "kept"),
    [
        ("crawl along at a speed of 0.15 near the kettle", "t = scale_speed(t, 0.15, near=detect_objects('kettle'))",
         "t = set_speed(t, 0.15, near=detect_objects('kettle'))"),
        ("hold the velocity at 0.4", "t = scale_speed(t, 0.4)", "t = set_speed(t, 0.4)"),
    ],
)  # fmt: skip
def test_a_stated_speed_written_as_a_factor_becomes_the_speed_to_keep(
    words: str, written: str, kept: str
) -> None:
    code, notes = add_asked_paces(program(written), [words], NAMES)
    assert code.splitlines()[1:-1] == [kept]
    assert "not a factor" in notes[0]


@pytest.mark.parametrize(
    ("words", "written"),
    [
        ("halve the speed", "t = scale_speed(t, 0.5)"),  # a factor the words give
        ("never faster than 0.4", "t = scale_speed(t, 0.4)"),  # a limit, not the speed to keep
        (
            "a speed of 0.4 near the crate",
            "t = scale_speed(t, 0.65, near=detect_objects('crate'))",
        ),  # another factor
    ],
)
def test_factors_and_limits_stay_factors(words: str, written: str) -> None:
    code, _ = add_asked_paces(program(written), [words], NAMES)
    assert written in code


@pytest.mark.parametrize(
    ("words", "written", "kept", "why"),
    [
        ("glide at an even 0.3 throughout", "t = set_height(t, 0.3)", "t = set_speed(t, 0.3)", "not a height"),
        ("maintain a uniform velocity of 0.6", "t = speed_profile(t, 'constant')", "t = set_speed(t, 0.6)",
         "with its value"),
        ("keep a fixed speed of 0.45", "t = set_speed(t, 0.2)", "t = set_speed(t, 0.45)", "with its value"),
    ],
)  # fmt: skip
def test_a_stated_speed_taken_for_a_level_or_left_out_becomes_the_speed_to_keep(
    words: str, written: str, kept: str, why: str
) -> None:
    code, notes = add_asked_paces(program(written), [words], NAMES)
    assert code.splitlines()[1:-1] == [kept]
    assert why in notes[0]


@pytest.mark.parametrize(
    ("words", "written"),
    [
        ("hover at a height of 0.3 at a steady 0.3", "t = set_height(t, 0.3)"),  # the words say a height
        ("keep a fixed speed of 0.45", "t = speed_profile(t, 'constant', 0.45)"),  # the value kept already
        ("hold a speed of 0.45 and crawl near the crate", "t = set_speed(t, 0.1, near=detect_objects('crate'))"),
    ],
)  # fmt: skip
def test_a_level_the_words_say_or_a_value_kept_stays(words: str, written: str) -> None:
    code, _ = add_asked_paces(program(written), [words], NAMES)
    assert written in code


def test_a_pace_placed_at_the_other_clause_s_object_moves_to_its_own() -> None:
    code, notes = add_asked_paces(
        program("t = scale_speed(t, 0.65, near=detect_objects('crate'))"),
        ["take it slower around the kettle, and stay left of the crate"],
        NAMES,
    )
    assert code.splitlines()[1:-1] == ["t = scale_speed(t, 0.65, near=detect_objects('kettle'))"]
    assert "no pace near the crate" in notes[0]


@pytest.mark.parametrize(
    "words",
    [
        "come up to the crate and slow down near it",  # the pace names no object: it may be the crate
        "slow down near the crate and stay left of the crate",  # a clause asks a pace near it
    ],
)
def test_a_pace_step_the_words_may_place_there_stays(words: str) -> None:
    step = "t = scale_speed(t, 0.65, near=detect_objects('crate'))"
    code, _ = add_asked_paces(program(step), [words], NAMES)
    assert step in code


@pytest.mark.parametrize(
    ("words", "steps", "added"),
    [
        ("zoom along through the middle part", ("t = speed_profile(t, 'accelerate', start=0.7)",),
         "t = scale_speed(t, 1.4, part='middle')"),  # a profile changes the end, not the middle
        ("take the first half at a crawl", ("t = scale_speed(t, 0.8, part='second half')",),
         "t = scale_speed(t, 0.65, part='first half')"),  # a step on another part
    ],
)  # fmt: skip
def test_a_pace_of_a_part_needs_a_step_on_that_part(words: str, steps: tuple[str, ...], added: str) -> None:
    code, _ = add_asked_paces(program(*steps), [words], NAMES)
    assert code == program(*steps, added)


@pytest.mark.parametrize(
    "steps",
    [
        ("t = scale_speed(t, 1.4)",),  # all of it: the speed-scope reader places it
        ("t = scale_speed(t, 1.4, near=detect_objects('goal'))",),  # at an end: placed by speed-scope too
        ("t = speed_profile(t, 'accelerate', start=0.5)",),  # a profile serves the second half
    ],
)
def test_a_pace_of_the_second_half_a_step_may_make_is_left_alone(steps: tuple[str, ...]) -> None:
    code = program(*steps)
    assert add_asked_paces(code, ["hurry in the second half"], NAMES) == (code, [])


@pytest.mark.parametrize("clause", ["then come to a dead stop there", "come to a standstill at the end"])
def test_a_stop_at_the_end_runs_the_speed_down_to_it(clause: str) -> None:
    pace = asked_pace(clause, NAMES)
    assert pace is not None and pace.step == "t = speed_profile(t, 'decelerate', start=0.6)"


@pytest.mark.parametrize("step", ["t = stop_at(t, detect_objects('crate'))", "t = wait(t, 'middle', 5)"])
def test_a_stop_a_step_makes_is_left_alone(step: str) -> None:
    code = program(step)
    assert add_asked_paces(code, ["head for the crate, then come to a complete stop"], NAMES) == (code, [])

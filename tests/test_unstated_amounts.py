"""Distances and heights nobody gave are replaced by the user's vague word or the default, with a note."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.bench.judges import CheckContext, run_check
from trajadapt.model.geometry import PAPER_AXES
from trajadapt.readers.paces import STOP_RAMP_START
from trajadapt.readers.unstated_amounts import replace_unstated_amounts
from trajadapt.readers.words import intensity_word
from trajadapt.skills.speed import speed_profile

START, END = "t = get_trajectory()\n", "\nmodified_trajectory = t"


def steps(code: str) -> list[str]:
    return code.splitlines()[1:-1]


@pytest.mark.parametrize(
    ("instruction", "step", "expected"),
    [
        ("go to the left", "t = shift(t, 'left', 0.2)", "t = shift(t, 'left')"),
        ("go a lot to the left", "t = shift(t, 'left', 0.2)", "t = shift(t, 'left', 'a lot')"),
        (
            "pass further away from the box",
            "t = move_away(t, detect_objects('box'), 10.0)",
            "t = move_away(t, detect_objects('box'))",
        ),  # fmt: skip
        ("go on past the goal upwards", "t = extend(t, 20, 'up')", "t = extend(t, None, 'up')"),
        ("zig-zag a little", "t = zigzag(t, amplitude=0.3)", "t = zigzag(t, amplitude='a little')"),
    ],
)
def test_a_made_up_distance_is_replaced(instruction: str, step: str, expected: str) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [expected] and len(notes) == 1 and "gives no such number" in notes[0]


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("go left by 0.2", "t = shift(t, 'left', 0.2)"),
        ("go left by 20 cm", "t = shift(t, 'left', 0.2)"),  # cm read as m
        ("go down by 0.1", "t = shift(t, 'down', -0.1)"),
        (
            "walk slower near the box",
            "t = scale_speed(t, 0.65, near=detect_objects('box'))",
        ),  # not a distance
        ("keep 0.3 from the box", "t = avoid(t, detect_objects('box'), 0.3)"),
        ("fly at a height of 0.5", "t = set_height(t, 0.5)"),
    ],
)
def test_stated_numbers_and_other_kinds_stay(instruction: str, step: str) -> None:
    assert replace_unstated_amounts(START + step + END, [instruction]) == (START + step + END, [])


def test_a_made_up_height_leaves_the_step_out_and_feedback_counts() -> None:
    code, notes = replace_unstated_amounts(
        START + "t = shift(t, 'up', 'slightly')\nt = set_height(t, 0.2923)" + END, ["upper part"]
    )
    assert steps(code) == ["t = shift(t, 'up')"] and any(
        "no such height" in note for note in notes
    )  # 'slightly': unsaid
    kept, _ = replace_unstated_amounts(
        START + "t = set_height(t, 0.8)" + END, ["fly higher", "at 0.8 please"]
    )
    assert steps(kept) == ["t = set_height(t, 0.8)"]


@pytest.mark.parametrize(
    ("words", "said"),
    [
        ("crawl way slower past the crate", "a lot"),
        ("keep loads further from the sofa", "a lot"),
        ("on the way to the goal go left", None),  # "way" before no comparative
        ("tons of room around the lamp", None),
    ],
)
def test_a_comparative_made_strong_is_a_lot(words: str, said: str | None) -> None:
    assert intensity_word(words) == said


@pytest.mark.parametrize(
    ("words", "said"),
    [
        ("nudge it a tad towards the window", "slightly"),
        ("lift the route a hair", "slightly"),
        ("marginally lower, please", "slightly"),
        ("pull it a good deal further back", "a lot"),
        ("drop it considerably", "a lot"),
        ("touch down at the goal", None),  # "touch" is no amount without "a"
    ],
)
def test_amount_idioms_are_the_skills_words(words: str, said: str | None) -> None:
    assert intensity_word(words) == said


@pytest.mark.parametrize(
    ("words", "step", "expected"),
    [
        ("reverse for some distance once the goal is reached", "t = extend(t, 'a bit', 'back')",
         "t = extend(t, None, 'back')"),
        ("drift over to the right", "t = shift(t, 'right', 'a lot')", "t = shift(t, 'right')"),
        ("drift a tad to the right", "t = shift(t, 'right', 'slightly')", "t = shift(t, 'right', 'slightly')"),
        ("drift right, and a lot higher", "t = shift(t, 'right', 'a bit')", "t = shift(t, 'right', 'a bit')"),
    ],
)  # fmt: skip
def test_an_amount_word_the_words_never_say_gives_way_to_the_default(
    words: str, step: str, expected: str
) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [words])
    assert steps(code) == [expected]
    assert ("no such amount word" in notes[0]) if step != expected else notes == []


def test_the_longest_intensity_word_wins() -> None:
    assert intensity_word("move very slightly left") == "very slightly" and intensity_word("go left") is None


def test_numbers_written_as_words_count() -> None:
    step = "t = move_away(t, detect_objects('table'), 2)"
    code = START + step + END
    assert replace_unstated_amounts(code, ["increase the distance by two times from the table"]) == (code, [])
    assert replace_unstated_amounts(code, ["twice as far from the table"]) == (code, [])


@pytest.mark.parametrize(
    ("instruction", "step", "expected"),
    [
        ("walk a lot slower near the box", "t = scale_speed(t, 0.65, near=detect_objects('box'))", 0.45),
        ("go very faster", "t = scale_speed(t, 1.4)", 1.6),
        ("go slightly upwards and a bit faster", "t = scale_speed(t, 1.6)", 1.25),
        ("go faster", "t = scale_speed(t, 2.5)", 1.4),
        ("go a lot to the left and slower", "t = scale_speed(t, 0.3)", 0.65),  # 'a lot' is the shift's
        # the statement of the problem says no amount of the fix
        ("It's too slow near the box; go a lot faster by it", "t = scale_speed(t, 1.3)", 1.6),
    ],
)
def test_a_made_up_speed_factor_becomes_the_phrase_tables(
    instruction: str, step: str, expected: float
) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert f"scale_speed(t, {expected}" in steps(code)[0] and "gives no such number" in notes[0]


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("go 20% faster", "t = scale_speed(t, 1.2)"),
        ("twice as fast", "t = scale_speed(t, 2.0)"),
        ("half as fast near the box", "t = scale_speed(t, 0.5, near=detect_objects('box'))"),
        ("four times slower", "t = scale_speed(t, 0.25)"),
        # a percentage with no way beside it keeps either reading
        ("go 30% less fast", "t = scale_speed(t, 0.7)"),
        ("run 50% as fast", "t = scale_speed(t, 0.5)"),
        ("it is too slow: add 30% to the speed", "t = scale_speed(t, 1.3)"),
    ],
)
def test_stated_speed_factors_stay(instruction: str, step: str) -> None:
    assert replace_unstated_amounts(START + step + END, [instruction]) == (START + step + END, [])


def test_the_phrase_table_in_the_prompt_is_the_calibrated_one() -> None:
    from importlib import resources

    from trajadapt.skills.speed import SPEED_FACTORS

    prompt = resources.files("trajadapt.prompts").joinpath("system_skills.md").read_text(encoding="utf-8")
    for direction, sizes in SPEED_FACTORS.items():
        for size, factor in sizes.items():
            phrase = f'"{size + " " if size else "walk "}{direction}" -> '
            assert phrase in prompt and f"{factor}" in prompt.split(phrase, 1)[1][:40], (direction, size)


def test_a_made_up_radius_of_a_speed_change_is_left_to_the_default_and_a_stated_one_kept() -> None:
    made_up = "t = set_speed(t, 5, near=detect_objects('box'), radius=1.0)"
    code, notes = replace_unstated_amounts(made_up, ["traverse at a speed of 5 in the vicinity of the box"])
    assert code == "t = set_speed(t, 5, near=detect_objects('box'))" and len(notes) == 1
    stated = "t = set_speed(t, 5, near=detect_objects('box'), radius=2)"
    assert replace_unstated_amounts(stated, ["a speed of 5 within 2 of the box"]) == (stated, [])


@pytest.mark.parametrize(
    ("instruction", "step", "expected"),
    [
        ("go a little quicker", "t = scale_speed(t, 0.8)", "t = scale_speed(t, 1.25)"),
        ("brake near the end", "t = scale_speed(t, 1.3)", "t = scale_speed(t, 0.65)"),
        ("faster by the lamp, slower by the sofa", "t = scale_speed(t, 0.8)", "t = scale_speed(t, 0.65)"),
    ],
)
def test_a_made_up_factor_takes_the_one_pace_the_words_ask(
    instruction: str, step: str, expected: str
) -> None:
    """Session 13: the direction comes from the words when they ask one pace, else from the model."""
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [expected] and notes


@pytest.mark.parametrize(
    ("words", "made_up", "stated"),
    [
        ("keep left and cut the pace by half", 0.45, 0.5),
        ("cruise twice as quickly along the whole route", 1.7, 2.0),
        ("go 30% slower after the lamp", 0.5, 0.7),
        # a percentage counts in the direction the words ask: 0.7 is no "30% quicker"
        ("can we take the opening bit about 30% quicker?", 0.7, 1.3),
        ("roll 40% faster while crossing the rug", 0.6, 1.4),
        ("be 25% slower as the bin comes close", 1.25, 0.75),
    ],
)
def test_a_made_up_factor_becomes_the_one_the_words_state(words, made_up, stated):
    code = f"t = get_trajectory()\nt = scale_speed(t, {made_up})\nmodified_trajectory = t"
    read, notes = replace_unstated_amounts(code, [words])
    assert f"scale_speed(t, {stated})" in read
    assert "the factor the words state" in notes[0]


def test_the_amount_is_the_one_a_clause_of_that_pace_says():
    code = "t = get_trajectory()\nt = scale_speed(t, 1.3)\nmodified_trajectory = t"
    read, _ = replace_unstated_amounts(code, ["Drive faster by the lamp; it must be much faster there."])
    assert "scale_speed(t, 1.6)" in read


@pytest.mark.parametrize(
    "words", ["it barely clears the box; move away", "dry it with a hair dryer", "a tadpole pond"]
)
def test_words_that_only_look_like_amount_idioms(words: str) -> None:
    assert intensity_word(words) is None


def test_a_double_quoted_amount_word_is_named_in_the_note() -> None:
    code, notes = replace_unstated_amounts(START + 't = shift(t, "right", "a lot")' + END, ["drift right"])
    assert steps(code) == ["t = shift(t, 'right')"] and "no such amount word" in notes[0]


SLOWING = "t = speed_profile(t, 'decelerate', start=0.7)"


@pytest.mark.parametrize(
    "instruction",
    [
        "brake gently so it is standing still when it arrives",
        "wind the speed down to nothing by the finish",
        "let it come to a halt at the end, nice and easy",
    ],
)
def test_a_slowing_starts_at_the_stop_ramp_where_the_words_give_no_share(instruction: str) -> None:
    code, notes = replace_unstated_amounts(START + SLOWING + END, [instruction])
    assert steps(code) == [f"t = speed_profile(t, 'decelerate', start={STOP_RAMP_START})"]
    assert len(notes) == 1 and "stop ramp" in notes[0]


@pytest.mark.parametrize(
    "instruction",
    [
        "slow to a stop over the final 30% of the route",
        "over the last third, ease down to zero",
        "begin braking at 0.7 of the way and stop at the goal",
        "decelerate to rest across the second half",
    ],
)
def test_a_slowing_keeps_a_share_the_words_give(instruction: str) -> None:
    code, notes = replace_unstated_amounts(START + SLOWING + END, [instruction])
    assert steps(code) == [SLOWING] and notes == []


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.05, 2.0), min_size=12, max_size=40))
def test_the_stop_ramp_falls_over_the_judges_last_part_and_ovitas(speeds: list[float]) -> None:
    n = len(speeds)
    path = np.column_stack([np.linspace(0, 1, n), np.zeros(n), np.zeros(n), speeds])
    slowed = speed_profile(path, "decelerate", start=STOP_RAMP_START)
    for after in (0.6, 0.7):  # the judges' default part, and OVITA's expectations'
        context = CheckContext(path, slowed, {}, PAPER_AXES)
        assert run_check(context, {"kind": "decelerates", "after": after}).passed


@pytest.mark.parametrize(
    ("instruction", "step", "expected"),
    [
        (
            "stay at least 0.12 away from the jack",  # the readers' words: "12 cm" read in metres
            "t = avoid(t, detect_objects('jack'), 12)",
            "t = avoid(t, detect_objects('jack'), 0.12)",
        ),
        ("nudge it left by 0.05", "t = shift(t, 'left', 5)", "t = shift(t, 'left', 0.05)"),
        ("drop down by 0.005", "t = shift(t, 'down', -5)", "t = shift(t, 'down', -0.005)"),
        ("never dip below 1.3", "t = stay_above(t, 130)", "t = stay_above(t, 1.3)"),
        (
            "keep 0.25 to the left of the cone",
            "t = keep_side(t, 'left', detect_objects('cone'), margin=25)",
            "t = keep_side(t, 'left', detect_objects('cone'), margin=0.25)",
        ),
    ],
)
def test_a_length_copied_without_its_unit_is_the_users_length(
    instruction: str, step: str, expected: str
) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [expected] and len(notes) == 1 and "another unit" in notes[0]


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("pause for 2 waypoints, 0.02 above the box", "t = wait(t, 'goal', 2)"),  # a count is no length
        ("go left 0.2 and then 20 more", "t = shift(t, 'left', 20)"),  # the words say 20 itself
        ("slow to 0.5 near the box", "t = set_speed(t, 50, near=detect_objects('box'))"),  # a speed
        ("left by 0.1 or 0.01", "t = shift(t, 'left', 10)"),  # 100 x one, 1000 x the other: which?
    ],
)
def test_only_a_length_that_is_no_number_of_the_words_is_read_in_metres(instruction: str, step: str) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert not any("another unit" in note for note in notes)


@pytest.mark.parametrize(
    ("instruction", "step", "expected"),
    [
        ("take the first half at half speed", "t = set_speed(t, 0.5)", "t = scale_speed(t, 0.5)"),
        ("cruise by the box at a third of the pace", "t = set_speed(t, 0.333333, near=detect_objects('box'))",
         "t = scale_speed(t, 0.333333, near=detect_objects('box'))"),
        ("go twice as fast", "t = set_speed(t, 2)", "t = scale_speed(t, 2)"),
    ],
)  # fmt: skip
def test_a_factor_set_as_a_speed_scales_the_speed(instruction: str, step: str, expected: str) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [expected] and "states a factor" in notes[0]


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("hold 0.5 at half the height", "t = set_speed(t, 0.5)"),  # the words say 0.5 itself
        ("slow down to 0.3", "t = set_speed(t, 0.3)"),  # a speed, no factor
        ("hold half a metre a second near the box", "t = set_speed(t, 0.5)"),  # a speed said in words
    ],
)
def test_a_speed_the_words_may_give_stays_set(instruction: str, step: str) -> None:
    code, _ = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [step]


@pytest.mark.parametrize(
    ("instruction", "step", "expected"),
    [
        ("come in slower over the final stretch", "t = set_speed(t, 0.319, part='end')",
         "t = scale_speed(t, 0.65, part='end')"),
        ("a lot quicker near the box", "t = set_speed(t, 1.0, near=detect_objects('box'))",
         "t = scale_speed(t, 1.6, near=detect_objects('box'))"),
    ],
)  # fmt: skip
def test_a_made_up_speed_where_the_words_ask_a_pace_scales_by_that_pace(
    instruction: str, step: str, expected: str
) -> None:
    code, notes = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [expected] and "the pace its words ask" in notes[0]


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("slow down to 0.3 at the end", "t = set_speed(t, 0.3, part='end')"),  # the words give it
        ("hold 0.4 and then speed up", "t = set_speed(t, 0.4)"),
        ("change the speed near the box", "t = set_speed(t, 0.2, near=detect_objects('box'))"),  # which way?
    ],
)
def test_a_speed_is_kept_where_the_words_give_it_or_ask_no_one_pace(instruction: str, step: str) -> None:
    code, _ = replace_unstated_amounts(START + step + END, [instruction])
    assert steps(code) == [step]


@pytest.mark.parametrize(
    ("words", "written"),
    [
        ("nudge the first half 0.05 to the left", "t = shift_part(t, 'left', 0.5, part='first half')"),
        (
            "take the final third at half the pace and drop it 0.02",
            "t = shift_part(t, 'down', 0.5, part='end')",
        ),
        ("lift it 0.1 and halve the speed", "t = shift(t, 'up', 0.5)"),
        ("hover for four waypoints, then move 0.2 back", "t = shift(t, 'back', 4)"),
        ("go up by 0.3 halfway along", "t = shift(t, 'up', 0.5)"),
    ],
)
def test_a_share_a_factor_or_a_count_is_no_length(words: str, written: str) -> None:
    code, notes = replace_unstated_amounts(written, [words])
    assert code != written and "no such number" in notes[0]


@pytest.mark.parametrize(
    ("words", "written"),
    [
        ("move the second half 0.5 up", "t = shift_part(t, 'up', 0.5, part='second half')"),
        ("move half a metre left", "t = shift(t, 'left', 0.5)"),  # plain words say 0.5 by now; "half" too
        ("pause 3 steps, then 3 cm up", "t = shift(t, 'up', 0.03)"),
    ],
)
def test_a_length_said_beside_a_share_or_a_count_stays(words: str, written: str) -> None:
    assert replace_unstated_amounts(written, [words]) == (written, [])

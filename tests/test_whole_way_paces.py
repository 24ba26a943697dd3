"""A pace the words hold the whole way, written for one part (readers.whole_way_paces).

Phrasings written for the reader; none of the benchmark sets has them.
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.whole_way_paces import whole_way_paces

NAMES = ["lamp", "box"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


@pytest.mark.parametrize(
    ("words", "step", "whole"),
    [
        ("hold 0.3 m/s throughout, never slowing at the end", "t = set_speed(t, 0.3, part='end')", "t = set_speed(t, 0.3)"),
        ("keep a constant speed from start to finish, don't rush the start", "t = scale_speed(t, 0.8, part='start')",
         "t = scale_speed(t, 0.8)"),
        ("a uniform pace all the way", "t = set_speed(t, 0.5, part='middle')", "t = set_speed(t, 0.5)"),
    ],
)  # fmt: skip
def test_a_pace_held_the_whole_way_takes_the_whole_path(words: str, step: str, whole: str) -> None:
    code, notes = whole_way_paces(program(step), [words], NAMES)
    assert code == program(whole) and "the whole way" in notes[0]


@pytest.mark.parametrize(
    ("words", "steps"),
    [
        ("hold 0.3 m/s throughout, and slow down at the end", ("t = set_speed(t, 0.3, part='end')",)),  # asked there
        ("drive slowly the whole way past the lamp", ("t = scale_speed(t, 0.6, part='middle')",)),  # an object
        ("keep 0.3 m/s the whole way", ("t = set_speed(t, 0.3, part='end')", "t = scale_speed(t, 0.5)")),  # two
        ("go at a steady 0.3 m/s in the middle", ("t = set_speed(t, 0.3, part='middle')",)),  # a part, not all of it
        ("go slowly throughout the middle section", ("t = scale_speed(t, 0.5, part='middle')",)),  # a part too
        ("keep a slow pace all the way through the final third", ("t = scale_speed(t, 0.5, part='end')",)),
    ],
)  # fmt: skip
def test_a_part_the_words_may_ask_stays(words: str, steps: tuple[str, ...]) -> None:
    code = program(*steps)
    assert whole_way_paces(code, [words], NAMES) == (code, [])


def test_the_stage_reads_it() -> None:
    code, notes = read_against_words(
        program("t = set_speed(t, 0.3, part='middle')"),
        ["0.3 m/s the entire way, no dawdling in the middle"],
        NAMES,
    )
    assert code == program("t = set_speed(t, 0.3)") and any(n.reader == "whole-way-paces" for n in notes)

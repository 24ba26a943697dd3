"""The readers that compare the user's words with the code never fail and always leave valid code.

Whatever the instruction and whatever skill lines the model wrote, leaving out unasked steps,
replacing amounts, scoping parts, reading object asks and unsaid directions return Python that
parses, keeps ``t = get_trajectory()`` and ``modified_trajectory = t``, and one note per change.
"""

from __future__ import annotations

import ast

from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.readers import READERS, read_against_words
from trajadapt.readers.repeated_steps import cut_copies

NAMES = ["box", "red box", "Lamp", "goal"]
FRAGMENTS = [
    "go", "move", "shift", "the start", "starting position", "the goal", "goal position", "after reaching",
    "the goal", "left", "right", "up", "upwards", "down", "front", "back", "by 0.2", "by 3", "a bit",
    "a lot", "slightly", "closer to", "further from", "away from", "the box", "the red box", "the lamp",
    "slower", "faster", "near", "within 0.3 of", "do not go", "stay", "of", "and", "then", "but", ",",
    ".", "at a height of 0.5", "below 2", "never higher than 1", "the new goal is", "midpoint of",
    "first 6 points", "in the middle", "continue further", "keep", "the same", "approach",
]  # fmt: skip
STEPS = [
    "t = shift(t, 'left')", "t = shift(t, 'up', 'slightly')", "t = shift(t, 'right', 0.2)",
    "t = shift_goal(t, 'back', 1.5)", "t = shift_part(t, 'right', part='middle')",
    "t = move_closer(t, detect_objects('box'))", "t = move_away(t, detect_objects('goal'), 'a bit')",
    "t = avoid(t, detect_objects('Lamp'), 0.3)",
    "t = avoid(t, [detect_objects('box'), detect_objects('Lamp')], 0.2)",
    "t = pass_through(t, midpoint(detect_objects('box'), detect_objects('red box')))",
    "t = keep_side(t, 'front', detect_objects('box'))", "t = scale_speed(t, 0.5)",
    "t = set_speed(t, 2, near=detect_objects('box'), radius=1.0)", "t = stay_below(t, 0.5)",
    "t = extend(t, 10.0)", "t = wait(t, detect_objects('Lamp'), 5)", "t = zigzag(t, 'left', 0.1, 4)",
    "x = detect_objects('box')", "t = t",
]  # fmt: skip

words = st.lists(st.sampled_from(FRAGMENTS), max_size=14).map(" ".join)
code = st.lists(st.sampled_from(STEPS), max_size=6).map(
    lambda steps: "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])
)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(words, code)
def test_the_readers_never_fail_and_leave_valid_code(instruction: str, written: str) -> None:
    asked = [instruction]
    result = written
    for reader in READERS:
        before = result
        result, more = reader.read(result, asked, NAMES)
        assert (result == before) == (not more), reader.name
    result, _ = cut_copies(result, "")  # the stage's last pass: copies a reader left back to back
    assert read_against_words(written, asked, NAMES)[0] == result
    ast.parse(result)
    lines = result.splitlines()
    assert lines[0] == "t = get_trajectory()" and lines[-1] == "modified_trajectory = t"

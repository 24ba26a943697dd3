"""Steps nobody asked for are left out of skills code, with a note; asked-for steps stay."""

from __future__ import annotations

import json

import pytest

from trajadapt.model.case import Case
from trajadapt.readers.unasked_steps import TOPICS, leave_out_unasked
from trajadapt.sandbox.runner import Sandbox
from trajadapt.skills import SKILL_NAMES

CODE = "t = get_trajectory()\nt = move_away(t, detect_objects('sandal'), 'a lot')\n{step}\nmodified_trajectory = t"


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("pass much further away from the sandal", "t = extend(t, 10.0)"),
        ("drive a lot closer to the stop watch", "t = set_speed(t, 0.6)"),
        ("keep a bigger distance from the sandal", "t = wait(t, 'goal', 5)"),
        ("go to the left", "t = spiral(t)"),
        ("stay on the top", "t = add_noise(t)"),
        ("away from the sandal, easing off once every 5 waypoints", "t = resample(t, 5)"),  # how often
        ("away from the sandal, then idle for three waypoints", "t = resample(t, 3)"),  # a pause's length
        ("away from the sandal and linger for a couple of points", "t = resample(t, 2)"),
    ],
)
def test_a_step_of_a_topic_never_mentioned_is_left_out(instruction: str, step: str) -> None:
    code, notes = leave_out_unasked(CODE.format(step=step), [instruction], ["sandal", "stop watch"])
    assert step not in code and "move_away" in code and code.endswith("modified_trajectory = t")
    assert len(notes) == 1 and step in notes[0] and "does not ask for" in notes[0]


@pytest.mark.parametrize(
    ("instruction", "step"),
    [
        ("walk slower near the sandal", "t = scale_speed(t, 0.5, near=detect_objects('sandal'))"),
        ("cruise at a steady 0.3 the whole way", "t = set_speed(t, 0.3)"),  # a speed said as a number
        ("go past the goal by 0.2", "t = extend(t, 0.2)"),
        ("the path ends too soon; keep moving a bit once you arrive", "t = extend(t)"),
        ("after reaching the goal go straight to the door", "t = append_segment(t, detect_objects('door'))"),
        ("pause 5 timesteps at the end", "t = wait(t, 'goal', 5)"),
        ("hover there for two waypoints", "t = wait(t, 'goal', 2)"),  # the pause readers' verbs too
        ("idle by the lamp a moment", "t = wait(t, detect_objects('lamp'))"),
        ("revolve once around the piano", "t = circle_around(t, detect_objects('piano'))"),
        ("double the number of waypoints", "t = resample(t, 2 * len(t))"),
        ("wait for 3 waypoints, then use 80 waypoints", "t = resample(t, 80)"),  # a count besides the pause
        ("add a little random noise", "t = add_noise(t)"),
        # a least distance said as a place not to come within, beside a pace (fresh-q)
        (
            "never come within 0.8 of the fan, and go slower near it",
            "t = avoid(t, detect_objects('fan'), 0.8)",
        ),
    ],
)
def test_a_step_the_words_ask_for_stays(instruction: str, step: str) -> None:
    code, notes = leave_out_unasked(CODE.format(step=step), [instruction])
    assert step in code and not [note for note in notes if step in note]


def test_feedback_words_count_and_other_forms_of_code_are_not_touched() -> None:
    step = "t = scale_speed(t, 0.5)"
    code, notes = leave_out_unasked(CODE.format(step=step), ["go left", "and a bit slower"])
    assert step in code and not [note for note in notes if step in note]
    numpy_style = "t = get_trajectory()\nu = scale_speed(t, 2)\nmodified_trajectory = u"
    assert leave_out_unasked(numpy_style, ["go left"]) == (numpy_style, [])


def test_every_guarded_skill_exists() -> None:
    for topic in TOPICS:
        assert set(topic.skills) <= set(SKILL_NAMES), topic.name


def test_the_session_leaves_the_step_out_and_says_so(simple_case: Case, sandbox: Sandbox) -> None:
    from trajadapt.backends.scripted import ScriptedBackend
    from trajadapt.session import AdaptationSession, SessionSettings

    code = "t = get_trajectory()\nt = shift(t, 'left', 0.2)\nt = extend(t, 10.0)\nmodified_trajectory = t"
    answer = json.dumps({"high_level_plan": "1) Shift left. 2) Extend.", "python_code": code})
    case = simple_case.with_instruction("go left by 0.2")
    for leave_out, expected_length in ((True, len(case.trajectory)), (False, len(case.trajectory) + 10)):
        backend = ScriptedBackend(answers=[answer])
        session = AdaptationSession(case, backend, sandbox, SessionSettings(read_against_words=leave_out))
        assert ("extend" in session.draft().code) is not leave_out
        result = session.approve()
        assert result.trajectory is not None and len(result.trajectory) == expected_length
        assert any(n.code == "unasked-steps" for n in result.notes) is leave_out
        assert (
            result.answer == answer and result.to_dict()["answer"] == answer
        )  # the model's own, for replays


@pytest.mark.parametrize(
    ("instruction", "kept"),
    [
        ("walk a lot faster in the proximity of the box", False),  # the place of a speed change
        ("go slower when passing close to the box", False),
        ("go slower near the box and further away from it", True),  # asks for distance too
        ("keep away from the box", True),  # no speed: distance steps are never guarded
        ("go near the box", True),
    ],
)
def test_a_distance_step_in_a_speed_instruction_is_left_out_unless_asked(
    instruction: str, kept: bool
) -> None:
    step = "t = move_away(t, detect_objects('box'), 'a bit')"
    code = f"t = get_trajectory()\n{step}\nt = scale_speed(t, 1.4, near=detect_objects('box'))\nmodified_trajectory = t"
    result, notes = leave_out_unasked(code, [instruction], ["box"])
    assert (step in result) == kept
    assert kept or "does not ask for a change of distance to an object" in notes[0]


def test_increase_or_decrease_of_speed_is_not_a_distance_word() -> None:
    code = (
        "t = get_trajectory()\nt = move_away(t, detect_objects('rocker'))\n"
        "t = scale_speed(t, 0.65, near=detect_objects('rocker'))\nmodified_trajectory = t"
    )
    kept, notes = leave_out_unasked(code, ["Decrease the speed near the rocker"], ["rocker"])
    assert "move_away" not in kept and "a change of distance" in notes[0]


@pytest.mark.parametrize(
    ("name", "words"),
    [("ear", "hurry, and pass nearer to the ear"), ("par", "hurry and move apart from the par")],
)
def test_a_name_inside_a_word_leaves_the_word_alone(name: str, words: str) -> None:
    """Only whole words are the object's name: the object 'ear' does not hide the 'near' of 'nearer'."""
    step = f"t = move_closer(t, detect_objects('{name}'))"
    code = f"t = get_trajectory()\n{step}\nt = scale_speed(t, 1.4)\nmodified_trajectory = t"
    assert leave_out_unasked(code, [words], [name]) == (code, [])


@pytest.mark.parametrize("words", ["ease up a little around the box", "take it easy when the box is close"])
def test_a_pace_in_the_shared_vocabulary_asks_for_a_speed_change(words: str) -> None:
    code = (
        "t = get_trajectory()\nt = scale_speed(t, 0.65, near=detect_objects('box'))\nmodified_trajectory = t"
    )
    assert leave_out_unasked(code, [words], ["box"]) == (code, [])


@pytest.mark.parametrize(
    "words", ["slow down by the box and give it a wider berth", "hurry past the box, hugging it"]
)
def test_a_distance_in_the_shared_vocabulary_keeps_its_step_in_a_speed_instruction(words: str) -> None:
    code = (
        "t = get_trajectory()\nt = move_away(t, detect_objects('box'))\n"
        "t = scale_speed(t, 0.65, near=detect_objects('box'))\nmodified_trajectory = t"
    )
    assert leave_out_unasked(code, [words], ["box"]) == (code, [])


@pytest.mark.parametrize(
    "words", ["double the distance from the box, two times as far", "keep 3 times further from the box"]
)
def test_a_count_of_times_asks_for_no_speed_change(words: str) -> None:
    code = "t = get_trajectory()\nt = move_away(t, detect_objects('box'))\nt = scale_speed(t, 2.0)\nmodified_trajectory = t"
    kept, notes = leave_out_unasked(code, [words], ["box"])
    assert "scale_speed" not in kept and "a speed change" in notes[0]

"""An answer that changes nothing, repeats a step or runs on is asked once more; the better one is kept."""

import json

import pytest

from tests.conftest import line_trajectory
from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.clauses.shape import asking_clauses, program_steps, shape_findings
from trajadapt.model.case import Case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.session import AdaptationSession, SessionSettings

LEFT, RIGHT = "t = shift(t, 'left', 0.1)", "t = shift(t, 'right', 0.1)"
SLOWER = "t = scale_speed(t, 0.65, near=detect_objects('lamp'))"
NAMES = ("box", "lamp")


def program(*lines: str) -> str:
    return "\n".join(["t = get_trajectory()", *lines, "modified_trajectory = t"])


def answer(*lines: str) -> str:
    return json.dumps({"high_level_plan": "1) as asked", "python_code": program(*lines)})


def case(instruction: str = "go left by 0.1 and slow down near the lamp") -> Case:
    scene = Scene((SceneObject("box", 0.2, 0.5, 0.5), SceneObject("lamp", -0.3, 0.8, 0.5)))
    return Case("shape", line_trajectory(), scene, instruction)


def test_the_steps_of_a_plain_program_and_none_for_other_code() -> None:
    assert program_steps(program(LEFT, SLOWER)) == (LEFT, SLOWER)
    assert program_steps(program()) == ()
    assert program_steps(program("for i in range(3):", "    " + LEFT)) is None
    assert program_steps(program("lamp = detect_objects('lamp')", LEFT)) is None


@pytest.mark.parametrize(
    ("lines", "found"),
    [
        ((LEFT, SLOWER), []),
        ((), ["it leaves the path unchanged"]),
        ((LEFT, LEFT), [f"it repeats `{LEFT}` 2 times"]),
        ((LEFT, RIGHT, SLOWER, RIGHT.replace("0.1", "0.2"), SLOWER.replace("0.65", "0.5")), []),
    ],
)
def test_findings_of_shape(lines: tuple[str, ...], found: list[str]) -> None:
    asking = asking_clauses(("go left by 0.1", "slow down near the lamp"), NAMES)
    assert shape_findings(program(*lines), asking) == found


def test_clauses_that_only_keep_something_ask_for_no_step() -> None:
    asking = asking_clauses(("go left by 0.1", "keep the start where it is"), NAMES)
    assert asking == ("go left by 0.1",)
    assert shape_findings(program(), ()) == []  # nothing asked, nothing to find
    assert shape_findings(program(), asking) == ["it leaves the path unchanged"]


def test_an_empty_answer_is_asked_afresh_with_the_requests_and_the_better_answer_kept(sandbox) -> None:
    backend = ScriptedBackend(answers=[answer(), answer(LEFT, SLOWER)])
    session = AdaptationSession(case(), backend, sandbox, SessionSettings(read_against_words=False))
    plan = session.draft()
    assert plan.code.strip() == program(LEFT, SLOWER) and len(backend.requests) == 2
    first, again = backend.requests
    assert len(again.messages) == len(first.messages) == 2  # the first answer is not in view
    asked = again.messages[-1].content
    assert asked.startswith(first.messages[-1].content) and "leaves the path unchanged" in asked
    assert "1. go left by 0.1" in asked and "2. slow down near the lamp" in asked
    assert again.grammar != first.grammar  # one to two steps per request
    assert any("kept the new answer" in note.message for note in session._left_out)
    assert session.messages[1] == first.messages[1] and len(session.messages) == 3
    assert session.approve().ok


def test_the_grammar_asked_afresh_admits_one_to_two_steps_per_request() -> None:
    from trajadapt.llm.answer_grammar import answer_grammar

    bounded = answer_grammar(NAMES, (1, 4))
    assert not bounded.matches(answer())
    assert bounded.matches(answer(LEFT, SLOWER))
    assert not bounded.matches(answer(LEFT, RIGHT, LEFT, RIGHT, SLOWER))
    assert answer_grammar(NAMES).matches(answer())


def test_a_second_answer_no_better_leaves_no_trace_but_the_note(sandbox) -> None:
    backend = ScriptedBackend(answers=[answer(LEFT, LEFT), answer(RIGHT, RIGHT)])
    session = AdaptationSession(case(), backend, sandbox, SessionSettings(read_against_words=False))
    plan = session.draft()
    assert plan.code.strip() == program(LEFT, LEFT) and len(session.turns) == 1 and len(session.messages) == 3
    assert [note.reader for note in session._left_out] == ["shape-check"]
    assert "no better" in session._left_out[0].message


def test_a_step_the_readers_leave_out_counts_as_missing(sandbox) -> None:
    unasked = "t = scale_speed(t, 2.0, near=detect_objects('box'))"  # no speed word in the words
    noise = "t = add_noise(t)"  # no reader adds this step: only a second answer can
    backend = ScriptedBackend(answers=[answer(unasked), answer(noise)])
    session = AdaptationSession(case("finish by adding some noise"), backend, sandbox, SessionSettings())
    assert session.draft().code.strip() == program(noise) and len(backend.requests) == 2


def test_a_direction_left_without_its_step_gets_it_back_without_asking_again(sandbox) -> None:
    """The readers give an emptied answer the asked direction ("go left"), so one request is enough."""
    unasked = "t = scale_speed(t, 2.0, near=detect_objects('box'))"
    backend = ScriptedBackend(answers=[answer(unasked), answer("t = shift(t, 'right')")])
    session = AdaptationSession(case("go left"), backend, sandbox, SessionSettings())
    assert session.draft().code.strip() == program("t = shift(t, 'left')") and len(backend.requests) == 1


@pytest.mark.parametrize(
    "settings",
    [SessionSettings(shape_check=False), SessionSettings(mode="paper")],
)
def test_no_second_answer_when_off_or_in_paper_mode(sandbox, settings) -> None:
    backend = ScriptedBackend(answers=[answer(LEFT, LEFT)])
    AdaptationSession(case(), backend, sandbox, settings).draft()
    assert len(backend.requests) == 1


def test_a_good_answer_is_asked_once(sandbox) -> None:
    backend = ScriptedBackend(answers=[answer(LEFT, SLOWER)])
    AdaptationSession(case(), backend, sandbox, SessionSettings()).draft()
    assert len(backend.requests) == 1

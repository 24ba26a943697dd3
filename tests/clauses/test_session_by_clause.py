"""The session's first answer keeps a step per clause, and a step that contradicts its words is asked again."""

import json

from tests.conftest import line_trajectory
from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.model.case import Case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.session import AdaptationSession, SessionSettings


class GrammarFollowing(ScriptedBackend):
    """A scripted backend that says it keeps to grammars, as llama.cpp does."""

    @property
    def follows_grammar(self) -> bool:
        return True


def answer(*lines: str) -> str:
    code = "\n".join(["t = get_trajectory()", *lines, "modified_trajectory = t"])
    return json.dumps({"high_level_plan": "1) as asked", "python_code": code})


LEFT, RIGHT = "t = shift(t, 'left', 0.1)", "t = shift(t, 'right', 0.1)"
SLOWER = "t = scale_speed(t, 0.65, near=detect_objects('lamp'))"


def case() -> Case:
    scene = Scene((SceneObject("box", 0.2, 0.5, 0.5), SceneObject("lamp", -0.3, 0.8, 0.5)))
    return Case("two", line_trajectory(), scene, "go left by 0.1 and slow down near the lamp")


def test_the_first_answer_is_asked_under_the_clause_grammar_and_feedback_under_the_scenes(sandbox):
    backend = GrammarFollowing(answers=[answer(LEFT, SLOWER), answer(LEFT)])
    session = AdaptationSession(case(), backend, sandbox, SessionSettings(clause_steps=True))
    session.draft()
    session.feedback("forget the lamp")
    first, feedback = backend.requests
    assert "steps-c0" in first.grammar and "steps-c1" in first.grammar
    assert "steps-c0" not in feedback.grammar


def test_a_step_contradicting_its_words_is_asked_again_and_the_better_answer_kept(sandbox):
    backend = GrammarFollowing(answers=[answer(RIGHT, SLOWER), answer(LEFT, SLOWER)])
    session = AdaptationSession(case(), backend, sandbox, SessionSettings(clause_steps=True))
    plan = session.draft()
    assert LEFT in plan.code and len(backend.requests) == 2
    asked = backend.requests[1].messages[-1].content
    assert "\u201cgo left by 0.1\u201d" in asked and "says left" in asked and "lamp\u201d" not in asked
    assert "steps-c1" in backend.requests[1].grammar
    assert any("asked once more" in note for note in (n.message for n in session._left_out))
    assert session.approve().ok


def test_a_second_answer_no_better_leaves_no_trace_but_the_note(sandbox):
    backend = GrammarFollowing(answers=[answer(RIGHT, SLOWER), answer(RIGHT, SLOWER)])
    session = AdaptationSession(case(), backend, sandbox, SessionSettings(clause_steps=True))
    plan = session.draft()
    assert RIGHT in plan.code and len(session.turns) == 1 and len(session.messages) == 3
    assert session.versions == [plan]
    assert any("no better" in note for note in (n.message for n in session._left_out))


def test_without_the_check_or_a_grammar_following_backend_one_answer_is_asked(sandbox):
    for backend, settings in [
        (
            GrammarFollowing(answers=[answer(RIGHT, SLOWER)]),
            SessionSettings(clause_steps=True, clause_check=False),
        ),
        (ScriptedBackend(answers=[answer(RIGHT, SLOWER)]), SessionSettings(clause_steps=True)),
    ]:
        AdaptationSession(case(), backend, sandbox, settings).draft()
        assert len(backend.requests) == 1
    assert "steps-c0" not in backend.requests[0].grammar  # the plain backend gets the scene's grammar


def test_clause_steps_are_off_by_default(sandbox):
    backend = GrammarFollowing(answers=[answer(LEFT, SLOWER)])
    AdaptationSession(case(), backend, sandbox, SessionSettings()).draft()
    assert "steps-c0" not in backend.requests[0].grammar


def test_code_that_is_not_a_skill_program_never_runs_where_the_grammar_held(sandbox):
    numpy_code = "t = get_trajectory()\nt[:, 0] += 0.1\nmodified_trajectory = t"
    backend = GrammarFollowing(
        answers=[json.dumps({"high_level_plan": "1) left", "python_code": numpy_code})]
    )
    session = AdaptationSession(
        case(), backend, sandbox, SessionSettings(clause_steps=True, repair_attempts=0, clause_check=False)
    )
    session.draft()
    result = session.approve()
    assert not result.ok and "skill calls" in str(result.error)

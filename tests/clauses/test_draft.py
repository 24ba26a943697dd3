import json

from tests.conftest import line_trajectory
from trajadapt.backends.base import ChatRequest
from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.case import Case
from trajadapt.clauses.draft import ClauseRequests, ClauseStep, compose_plan, draft_by_clause, step_lines
from trajadapt.clauses.examples import clause_pairs, render_clause_examples
from trajadapt.errors import EmptyCompletion
from trajadapt.example_bank import Example
from trajadapt.geometry import AXIS_CONVENTIONS
from trajadapt.scene import Scene, SceneObject
from trajadapt.session import AdaptationSession, SessionSettings


class GrammarFollowing(ScriptedBackend):
    """A scripted backend that says it keeps to grammars, as llama.cpp does."""

    @property
    def follows_grammar(self) -> bool:
        return True


def two_clause_case() -> Case:
    scene = Scene((SceneObject("box", 0.2, 0.5, 0.5), SceneObject("lamp", -0.3, 0.8, 0.5)))
    return Case("two", line_trajectory(), scene, "go left by 0.1 and slow down near the lamp")


def test_the_bank_is_cut_into_one_example_per_clause():
    pairs = clause_pairs(
        [
            Example(
                "go left and slow down near the box",
                "",
                "t = get_trajectory()\nt = shift(t, 'left')\nt = scale_speed(t, 0.65, near=detect_objects('box'))\nmodified_trajectory = t",
            ),
            Example(
                "ramp up, cruise, then ramp down",
                "",
                "t = get_trajectory()\nt = speed_profile(t, 'trapezoidal')\nmodified_trajectory = t",
            ),
        ]
    )
    assert [(p.instruction, p.code) for p in pairs] == [
        ("go left", "t = shift(t, 'left')"),
        ("slow down near the box", "t = scale_speed(t, 0.65, near=detect_objects('box'))"),
    ]  # three clauses for one step: left out


def test_clause_examples_match_the_clauses_words():
    shown = render_clause_examples("take it slower next to the lamp", 3, ["lamp"])
    assert shown.count("Words:") == 3 and "scale_speed" in shown.split("Words:")[-1]


def test_each_clause_gets_its_own_request_grammar_and_step():
    backend = GrammarFollowing(
        answers=["t = shift(t, 'left', 0.1)", "t = scale_speed(t, 0.65, near=detect_objects('lamp'))"]
    )
    drafted = draft_by_clause(two_clause_case(), backend.complete, ClauseRequests(AXIS_CONVENTIONS["paper"]))
    first, second = backend.requests
    assert first.messages[1].content.rstrip().endswith("Words: go left by 0.1")
    assert "detect_objects('lamp')" not in first.messages[1].content.split("INSTRUCTION")[0]
    assert "lamp" in second.grammar and "'box'" not in second.grammar and "0.1" not in second.grammar
    assert first.messages[1].content.split("STEPS FOR")[0] == second.messages[1].content.split("STEPS FOR")[0]
    assert drafted.plan.code.splitlines() == [
        "t = get_trajectory()",
        "t = shift(t, 'left', 0.1)",
        "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        "modified_trajectory = t",
    ]
    assert drafted.plan.steps[0].endswith("\u201cgo left by 0.1\u201d") and "lamp" in drafted.plan.steps[1]
    assert json.loads(drafted.plan.raw_text)["python_code"] == drafted.plan.code


def test_a_clause_without_a_step_is_said_in_the_plan():
    plan = compose_plan([ClauseStep("hum a tune", (), ChatRequest(messages=()), None, "no answer")])
    assert plan.steps == ("(no step for \u201chum a tune\u201d)",)


def test_only_step_lines_are_taken_from_an_answer():
    text = "Here you go:\n```\nt = get_trajectory()\nt = shift(t, 'up')\nimport os\nt = smooth(t\nt = smooth(t)\nt = smooth(t)\n```"
    assert step_lines(text) == ("t = shift(t, 'up')", "t = smooth(t)")


def test_the_session_drafts_by_clause_and_runs_the_composed_program(sandbox):
    backend = GrammarFollowing(
        answers=["t = shift(t, 'left', 0.1)", "t = scale_speed(t, 0.65, near=detect_objects('lamp'))"]
    )
    session = AdaptationSession(two_clause_case(), backend, sandbox, SessionSettings())
    plan = session.draft()
    assert "shift(t, 'left', 0.1)" in plan.code and len(backend.requests) == 2
    result = session.approve()
    assert result.ok
    assert result.trajectory.positions[-1][0] > 0.05  # +x is left in the paper's axes


def test_a_failing_clause_request_leaves_the_other_steps():
    backend = GrammarFollowing(answers=["t = shift(t, 'left', 0.1)"])  # the second request finds no answer
    drafted = draft_by_clause(two_clause_case(), backend.complete, ClauseRequests(AXIS_CONVENTIONS["paper"]))
    assert [s.lines for s in drafted.steps] == [("t = shift(t, 'left', 0.1)",), ()]
    assert drafted.steps[1].error and drafted.plan.steps[-1].startswith("(no step")
    assert isinstance(EmptyCompletion("x"), Exception)


def test_without_a_grammar_following_backend_the_whole_answer_is_asked(sandbox):
    answer = json.dumps(
        {
            "high_level_plan": "1) left",
            "python_code": "t = get_trajectory()\nt = shift(t, 'left', 0.1)\nmodified_trajectory = t",
        }
    )
    backend = ScriptedBackend(answers=[answer])
    session = AdaptationSession(two_clause_case(), backend, sandbox, SessionSettings())
    assert session.draft().steps == ("left",) and len(backend.requests) == 1


def test_clause_steps_off_asks_the_whole_answer(sandbox):
    answer = json.dumps(
        {
            "high_level_plan": "1) left",
            "python_code": "t = get_trajectory()\nt = shift(t, 'left', 0.1)\nmodified_trajectory = t",
        }
    )
    backend = GrammarFollowing(answers=[answer])
    session = AdaptationSession(two_clause_case(), backend, sandbox, SessionSettings(clause_steps=False))
    assert session.draft().steps == ("left",)


def test_a_step_a_reader_changed_is_explained_again():
    backend = GrammarFollowing(
        answers=["t = shift(t, 'left', 0.1)", "t = scale_speed(t, 0.75, near=detect_objects('lamp'))"]
    )
    drafted = draft_by_clause(two_clause_case(), backend.complete, ClauseRequests(AXIS_CONVENTIONS["paper"]))
    changed = drafted.replanned(drafted.plan.code.replace("0.75", "0.65"))
    assert "0.65" in changed.steps[1] and changed.steps[1].endswith("\u201cslow down near the lamp\u201d")
    fewer = drafted.replanned("t = get_trajectory()\nt = shift(t, 'left', 0.1)\nmodified_trajectory = t")
    assert len(fewer.steps) == 1 and "\u2014 for" not in fewer.steps[0]


def test_a_line_repeating_an_earlier_clauses_step_is_left_out():
    backend = GrammarFollowing(
        answers=[
            "t = shift(t, 'left', 0.1)",
            "t = shift(t, 'left', 0.1)\nt = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        ]
    )
    drafted = draft_by_clause(two_clause_case(), backend.complete, ClauseRequests(AXIS_CONVENTIONS["paper"]))
    assert [s.lines for s in drafted.steps] == [
        ("t = shift(t, 'left', 0.1)",),
        ("t = scale_speed(t, 0.65, near=detect_objects('lamp'))",),
    ]


def test_a_step_contradicting_its_words_is_asked_once_more_and_the_better_kept():
    backend = GrammarFollowing(
        answers=[
            "t = scale_speed(t, 1.4)",
            "t = shift(t, 'left', 0.1)",
            "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        ]
    )
    findings = {"t = scale_speed(t, 1.4)": ["the step changed only the speed"]}
    drafted = draft_by_clause(
        two_clause_case(),
        backend.complete,
        ClauseRequests(AXIS_CONVENTIONS["paper"]),
        check=lambda clause, lines: findings.get(lines[0], []),
    )
    first = drafted.steps[0]
    assert (
        first.lines == ("t = shift(t, 'left', 0.1)",)
        and first.asked_again
        and first.kept_second
        and not first.findings
    )
    retry = backend.requests[1].messages
    assert retry[-2].content == "t = scale_speed(t, 1.4)" and "changed only the speed" in retry[-1].content
    assert len(drafted.completion.text.split("Words:")) == 3 and len(first.completions) == 2


def test_a_second_answer_no_better_leaves_the_first():
    backend = GrammarFollowing(
        answers=[
            "t = shift(t, 'right', 0.1)",
            "t = smooth(t)",
            "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        ]
    )
    drafted = draft_by_clause(
        two_clause_case(),
        backend.complete,
        ClauseRequests(AXIS_CONVENTIONS["paper"]),
        check=lambda clause, lines: ["wrong way"] if "left" in clause else [],
    )
    assert drafted.steps[0].lines == ("t = shift(t, 'right', 0.1)",) and drafted.steps[0].findings == (
        "wrong way",
    )


def test_the_session_checks_each_clause_in_the_sandbox(sandbox):
    backend = GrammarFollowing(
        answers=[
            "t = shift(t, 'right', 0.1)",
            "t = shift(t, 'left', 0.1)",
            "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
        ]
    )
    session = AdaptationSession(two_clause_case(), backend, sandbox, SessionSettings())
    plan = session.draft()
    assert "shift(t, 'left', 0.1)" in plan.code and "'right'" not in plan.code
    assert "says left" in backend.requests[1].messages[-1].content
    assert any("asked once more" in note for note in session._left_out)


def test_a_clause_that_only_keeps_something_gets_no_request():
    scene = Scene((SceneObject("lamp", -0.3, 0.8, 0.5),))
    case = Case("keep", line_trajectory(), scene, "go left by 0.1 keeping the start fixed")
    backend = GrammarFollowing(answers=["t = shift(t, 'left', 0.1)"])
    drafted = draft_by_clause(case, backend.complete, ClauseRequests(AXIS_CONVENTIONS["paper"]))
    assert (
        len(backend.requests) == 1
        and drafted.plan.steps[-1] == "(keeps: \u201ckeeping the start fixed\u201d)"
    )

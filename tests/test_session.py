"""The review loop with the scripted backend: draft, feedback, approve, automatic repair, logging."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.errors import AnswerParseError, SessionStateError
from trajadapt.files.store import Store
from trajadapt.model.case import Case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings

SHIFT_LEFT = (
    "t = get_trajectory()\nw = np.linspace(0, 1, len(t))\nt[:, 0] += 0.2 * w\nmodified_trajectory = t\n"
)


def answer(plan: str, code: str) -> str:
    return json.dumps({"high_level_plan": plan, "python_code": code})


def make_session(
    case: Case, sandbox: Sandbox, *answers: str, store: Store | None = None, **settings: object
) -> tuple[AdaptationSession, ScriptedBackend]:
    backend = ScriptedBackend(answers=answers)
    return AdaptationSession(case, backend, sandbox, SessionSettings(**settings), store), backend  # type: ignore[arg-type]


def test_draft_then_approve(simple_case: Case, sandbox: Sandbox) -> None:
    session, _ = make_session(
        simple_case, sandbox, answer("1) Shift the goal left. 2) Keep the start.", SHIFT_LEFT)
    )
    plan = session.draft()
    assert plan.steps == ("Shift the goal left.", "Keep the start.")
    result = session.approve()
    assert result.ok and result.trajectory is not None
    assert result.attempts == 1
    assert np.isclose(result.trajectory.positions[-1, 0], 0.2)
    assert simple_case.trajectory.positions[-1, 0] == 0.0  # the original is untouched
    payload = result.to_dict()
    for key in (
        "case",
        "instruction",
        "high_level_plan",
        "code",
        "modified_trajectory",
        "status",
        "error",
        "attempts",
        "backend",
        "model",
        "timings_s",
    ):
        assert key in payload
    assert set(payload["timings_s"]) == {"llm", "exec", "total"}


def test_feedback_carries_instruction_and_previous_plan(simple_case: Case, sandbox: Sandbox) -> None:
    session, backend = make_session(
        simple_case,
        sandbox,
        answer("1) Shift everything right.", SHIFT_LEFT),
        answer("1) Shift left.", SHIFT_LEFT),
    )
    session.draft()
    plan = session.feedback("No: left means +x here, and keep the start.")
    assert plan.steps == ("Shift left.",)
    last = backend.requests[-1].messages[-1].content
    assert "No: left means +x here" in last
    assert "go left" in last and "Shift everything right." in last
    assert [turn.kind for turn in session.turns] == ["draft", "feedback"]


def test_failing_code_goes_back_to_the_llm(simple_case: Case, sandbox: Sandbox) -> None:
    broken = (
        "t = get_trajectory()\nbox = detect_objects('sofa')\nt[:, 0] += box[0]\nmodified_trajectory = t\n"
    )
    session, backend = make_session(simple_case, sandbox, answer("1) a", broken), answer("1) b", SHIFT_LEFT))
    session.draft()
    result = session.approve()
    assert result.ok and result.attempts == 2
    repair_message = backend.requests[-1].messages[-1].content
    assert "TypeError (line 3)" in repair_message
    assert "no object named 'sofa'" in repair_message


def test_repairs_are_bounded(simple_case: Case, sandbox: Sandbox) -> None:
    broken = answer("1) a", "x = 1\n")
    session, backend = make_session(simple_case, sandbox, broken, broken, broken, repair_attempts=1)
    session.draft()
    result = session.approve()
    assert not result.ok and result.attempts == 2
    assert result.error is not None and "modified_trajectory" in result.error
    assert len(backend.queue) == 1


def test_a_repair_the_backend_refuses_keeps_the_failure(simple_case: Case, sandbox: Sandbox) -> None:
    broken = answer("1) a", "x = 1\n")
    session, _ = make_session(simple_case, sandbox, broken)  # the repair request finds no answer left
    session.draft()
    result = session.approve()
    assert not result.ok and result.attempts == 1 and result.error is not None
    assert result.error.startswith("NameError") and "(no repair: EmptyCompletion:" in result.error


def test_invalid_result_is_repaired(simple_case: Case, sandbox: Sandbox) -> None:
    nan_code = "t = get_trajectory()\nt[3, 1] = np.nan\nmodified_trajectory = t\n"
    session, backend = make_session(
        simple_case, sandbox, answer("1) a", nan_code), answer("1) b", SHIFT_LEFT)
    )
    session.draft()
    assert session.approve().ok
    assert "non-finite" in backend.requests[-1].messages[-1].content


def test_unreadable_answer_is_retried_once_then_fails(simple_case: Case, sandbox: Sandbox) -> None:
    session, backend = make_session(simple_case, sandbox, "no idea", answer("1) a", SHIFT_LEFT))
    assert session.draft().steps == ("a",)
    assert "could not be read" in backend.requests[-1].messages[-1].content
    session, _ = make_session(simple_case, sandbox, "no idea", "still no idea")
    with pytest.raises(AnswerParseError):
        session.draft()


def test_methods_out_of_order(simple_case: Case, sandbox: Sandbox) -> None:
    session, _ = make_session(simple_case, sandbox, answer("1) a", SHIFT_LEFT))
    with pytest.raises(SessionStateError):
        session.approve()
    with pytest.raises(SessionStateError):
        session.feedback("x")
    session.draft()
    with pytest.raises(SessionStateError):
        session.draft()


def test_every_exchange_is_logged(simple_case: Case, sandbox: Sandbox, tmp_path: Path) -> None:
    store = Store(tmp_path / "log.db")
    session, _ = make_session(
        simple_case, sandbox, answer("1) a", "x = 1\n"), answer("1) b", SHIFT_LEFT), store=store
    )
    session.draft()
    session.approve()
    records = store.recent_exchanges(10)
    assert [r.kind for r in records] == ["draft", "execution", "repair", "execution"]
    assert records[1].error and not records[3].error
    assert records[0].instruction == "go left"
    full = store.request_of(records[0].id)
    assert full["request"][0]["role"] == "system" and "high_level_plan" in full["answer"]
    store.close()


def test_skills_mode_binds_the_library_and_takes_the_last_trajectory(
    simple_case: Case, sandbox: Sandbox
) -> None:
    code = "t = get_trajectory()\nt2 = shift(t, 'left', 0.3)\n"
    session, _ = make_session(
        simple_case, sandbox, answer("1) Shift left.", code), mode="skills", read_against_words=False
    )
    session.draft()
    result = session.approve()
    assert result.ok and result.trajectory is not None
    assert np.isclose(result.trajectory.positions[-1, 0], 0.3)
    assert any("used its variable 't2'" in note.message for note in result.notes)


def test_paper_mode_has_no_skills_and_needs_the_result_variable(simple_case: Case, sandbox: Sandbox) -> None:
    code = "t = get_trajectory()\nt2 = shift(t, 'left', 0.3)\n"
    session, backend = make_session(
        simple_case, sandbox, answer("1) a", code), mode="paper", repair_attempts=0
    )
    session.draft()
    result = session.approve()
    assert (
        not result.ok and result.error is not None and "NameError" in result.error and "shift" in result.error
    )
    assert "shift(trajectory" not in backend.requests[0].messages[0].content


def test_ovita_axes_flip_skills_in_the_sandbox(simple_case: Case, sandbox: Sandbox) -> None:
    from trajadapt.model.geometry import AXIS_CONVENTIONS

    code = "modified_trajectory = shift(get_trajectory(), 'left', 0.3)\n"
    session, backend = make_session(
        simple_case, sandbox, answer("1) a", code), axes=AXIS_CONVENTIONS["ovita"], read_against_words=False
    )
    session.draft()
    result = session.approve()
    assert result.trajectory is not None and np.isclose(result.trajectory.positions[-1, 0], -0.3)
    assert "The positive X axis is right" in backend.requests[0].messages[0].content


def test_discarded_skill_results_are_kept(simple_case: Case, sandbox: Sandbox) -> None:
    code = "t = get_trajectory()\nshift(t, 'left', 0.3)\nmodified_trajectory = t\n"
    session, _ = make_session(simple_case, sandbox, answer("1) Shift left.", code))
    session.draft()
    result = session.approve()
    assert result.trajectory is not None and np.isclose(result.trajectory.positions[-1, 0], 0.3)
    assert any("result of shift() was not kept" in note.message for note in result.notes)


def test_repair_quotes_the_signature_of_the_misused_skill(simple_case: Case, sandbox: Sandbox) -> None:
    bad = "t = get_trajectory()\nt = shift(t, 'away', 0.2)\nmodified_trajectory = t\n"
    session, backend = make_session(simple_case, sandbox, answer("1) a", bad), answer("1) b", SHIFT_LEFT))
    session.draft()
    assert session.approve().ok
    repair = backend.requests[-1].messages[-1].content
    assert "relative to an object: use move_away(t, detect_objects('name'), amount)" in repair
    assert "How to call it:\n- shift(trajectory, direction, amount=None):" in repair


def test_invented_detect_names_work_in_skills_mode(simple_case: Case, sandbox: Sandbox) -> None:
    code = "t = get_trajectory()\nbox = find_object('box')\nmodified_trajectory = move_closer(t, box)\n"
    session, _ = make_session(simple_case, sandbox, answer("1) a", code))
    session.draft()
    assert session.approve().ok


def test_skills_mode_sends_the_scenes_answer_grammar(simple_case: Case, sandbox: Sandbox) -> None:
    from trajadapt.llm.answer_grammar import answer_grammar

    code = "t = get_trajectory()\nt = shift(t, 'left', 0.3)\nmodified_trajectory = t"
    session, backend = make_session(simple_case, sandbox, answer("1) Shift left.", code))
    session.draft()
    grammar = backend.requests[0].grammar
    names = tuple(obj.name for obj in simple_case.scene.objects)
    assert grammar is not None and grammar == answer_grammar(names).to_gbnf()
    assert all(f'"{name}"' in grammar for name in names)


@pytest.mark.parametrize("settings", [{"mode": "paper"}, {"grammar": False}])
def test_no_grammar_in_paper_mode_or_when_off(
    simple_case: Case, sandbox: Sandbox, settings: dict[str, object]
) -> None:
    session, backend = make_session(simple_case, sandbox, answer("1) a", SHIFT_LEFT), **settings)
    session.draft()
    assert backend.requests[0].grammar is None


def test_the_result_carries_the_measured_effect_and_flags(simple_case: Case, sandbox: Sandbox) -> None:
    right = "t = get_trajectory()\nt = shift(t, 'right', 0.2)\nmodified_trajectory = t"
    session, _ = make_session(
        simple_case.with_instruction("go left by 0.2"), sandbox, answer("1) Shift.", right)
    )
    session.draft()
    payload = session.approve().to_dict()
    effect = payload["effect"]
    assert np.isclose(effect["goal_moved"], 0.2) and effect["goal_direction"] == "right"
    assert effect["contradictions"] == ["the instruction says left, but the path moved right on average"]
    assert any(line.startswith("start kept, goal moved 0.2 right") for line in effect["in_words"])


@pytest.mark.parametrize("second_code", ["t = get_trajectory()\nt = shift(t, 'left', 0.2)\nmodified_trajectory = t",
                                         "t = get_trajectory()\nt = shift(t, 'right', 0.4)\nmodified_trajectory = t"])  # fmt: skip
def test_a_contradiction_gets_one_more_answer_kept_only_if_better(
    simple_case: Case, sandbox: Sandbox, second_code: str
) -> None:
    right = "t = get_trajectory()\nt = shift(t, 'right', 0.2)\nmodified_trajectory = t"
    session, backend = make_session(
        simple_case,
        sandbox,
        answer("1) Shift.", right),
        answer("1) Shift left.", second_code),
        repair_contradictions=True,
    )
    session.draft()
    result = session.approve()
    assert "contradicts the instruction" in backend.requests[1].messages[-1].content
    assert result.trajectory is not None
    went_left = "'left'" in second_code
    assert (
        bool(result.trajectory.positions[-1, 0] > 0) is went_left
    )  # the better answer is kept, else the first
    assert (result.contradictions == ()) is went_left


def test_no_second_look_by_default(simple_case: Case, sandbox: Sandbox) -> None:
    right = "t = get_trajectory()\nt = shift(t, 'right', 0.2)\nmodified_trajectory = t"
    session, backend = make_session(simple_case, sandbox, answer("1) Shift.", right))
    session.draft()
    assert session.approve().contradictions and len(backend.requests) == 1


def test_a_failure_is_typed_and_the_report_reads_its_kind_not_its_words(
    simple_case: Case, sandbox: Sandbox
) -> None:
    from trajadapt.bench.report import failure_kind

    broken = json.dumps(
        {"high_level_plan": "1) Shift.", "python_code": "modified_trajectory = shift(1, 2, 3, 4, 5)"}
    )
    session = AdaptationSession(
        simple_case, ScriptedBackend(answers=[broken]), sandbox, SessionSettings(repair_attempts=0)
    )
    session.draft()
    result = session.approve()
    assert result.failure is not None and result.failure.kind == "TypeError"
    assert result.error == result.failure.message and result.error.startswith("TypeError")
    record = result.to_dict()
    assert record["error_kind"] == "TypeError"
    record["error"] = "something else entirely"  # the kind, not the words, names the failure
    assert failure_kind(record) == "error: TypeError"
    assert failure_kind({"status": "error", "error": "ValueError: old file"}) == "error: ValueError"


def test_a_rejected_second_answer_leaves_the_first_result_intact(simple_case: Case, sandbox: Sandbox) -> None:
    right = "t = get_trajectory()\nprint('{tag}')\nt = shift(t, 'right', 0.2)\nmodified_trajectory = t"
    session, backend = make_session(
        simple_case, sandbox,
        answer("1) First.", right.format(tag="first answer")),
        answer("1) Second.", right.format(tag="second answer")),
        repair_contradictions=True, read_against_words=False,
    )  # fmt: skip
    session.draft()
    result = session.approve()
    assert len(backend.requests) == 2  # "go left" moved right: asked once more, and no better
    assert result.plan is not None and result.plan.steps == ("First.",)
    assert session.plan is not None and session.plan.steps == ("First.",)
    assert "first answer" in result.stdout and "second answer" not in result.stdout
    assert len(session.versions) == 1 and len(session.turns) == 1


def test_undo_takes_back_the_words_of_the_feedback_it_drops(simple_case: Case, sandbox: Sandbox) -> None:
    left = "t = get_trajectory()\nt = shift(t, 'left', 0.2)\nmodified_trajectory = t"
    session, _ = make_session(
        simple_case, sandbox, answer("1) Left.", left), answer("1) Away.", left), read_against_words=False
    )
    session.draft()
    session.feedback("stay away from the box")
    session.rewind(0)
    result = session.approve()  # moves towards the box: only words still said may flag that
    assert result.ok and not any("box" in flag for flag in result.contradictions)
    assert session._asked == [simple_case.instruction]

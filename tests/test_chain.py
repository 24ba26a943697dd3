"""Corrections on the current result chain steps; on the original they re-plan; undo spans both."""

from __future__ import annotations

import json

import numpy as np
import pytest

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.chain import AdaptationChain
from trajadapt.errors import SessionStateError
from trajadapt.model.case import Case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import SessionSettings
from trajadapt.skills import bind_skills

LEFT = "t = get_trajectory()\nt = shift(t, 'left', 0.2)\nmodified_trajectory = t"
SLOW = "t = get_trajectory()\nt = scale_speed(t, 0.5, near=detect_objects('box'))\nmodified_trajectory = t"
VERBATIM = SessionSettings(read_against_words=False)  # the codes' numbers are not in these instructions
UP = "t = get_trajectory()\nt = shift(t, 'up', 0.1)\nmodified_trajectory = t"


def answer(code: str) -> str:
    return json.dumps({"high_level_plan": "1) Do it.", "python_code": code})


def test_a_two_step_current_chain_equals_the_two_codes_in_turn(simple_case: Case, sandbox: Sandbox) -> None:
    backend = ScriptedBackend(answers=[answer(LEFT), answer(SLOW)])
    chain = AdaptationChain(simple_case, backend, sandbox, VERBATIM)
    chain.draft()
    first = chain.approve()
    chain.feedback("now also slow down near the box", on="current")
    second = chain.approve()
    skills = bind_skills()
    box = [simple_case.scene.objects[0].x, simple_case.scene.objects[0].y, simple_case.scene.objects[0].z]
    expected = skills["scale_speed"](
        skills["shift"](simple_case.trajectory.array, "left", 0.2), 0.5, near=box
    )
    assert first.trajectory is not None and second.trajectory is not None
    assert np.allclose(second.trajectory.array, expected)
    assert "TRAJECTORY" in backend.requests[1].messages[1].content
    assert backend.requests[1].messages[1].content.rstrip().endswith("now also slow down near the box")
    record = chain.to_dict(second)
    assert [step["instruction"] for step in record["chain"]] == ["go left", "now also slow down near the box"]
    assert [step["code"].strip() for step in record["chain"]] == [LEFT, SLOW]
    assert np.allclose(record["original_trajectory"], simple_case.trajectory.array)
    assert np.allclose(record["chain"][0]["trajectory"], first.trajectory.array)


def test_original_replans_from_the_start_with_everything_said(simple_case: Case, sandbox: Sandbox) -> None:
    backend = ScriptedBackend(answers=[answer(LEFT), answer(SLOW), answer(UP)])
    chain = AdaptationChain(simple_case, backend, sandbox, VERBATIM)
    chain.draft()
    chain.approve()
    chain.feedback("slow down near the box", on="current")
    chain.approve()
    chain.feedback("and go up instead of left", on="original")
    result = chain.approve()
    assert result.trajectory is not None
    assert np.allclose(
        result.trajectory.array, bind_skills()["shift"](simple_case.trajectory.array, "up", 0.1)
    )
    sent = backend.requests[2].messages[-1].content
    assert "slow down near the box; and go up instead of left" in sent and "go left" in sent
    assert len(chain.steps) == 1 and [s["code"].strip() for s in chain.to_dict(result)["chain"]] == [UP]


def test_undo_works_across_both_kinds(simple_case: Case, sandbox: Sandbox) -> None:
    backend = ScriptedBackend(answers=[answer(LEFT), answer(SLOW)])
    chain = AdaptationChain(simple_case, backend, sandbox, VERBATIM)
    chain.draft()
    chain.approve()
    chain.feedback("slow down near the box", on="current")
    assert [plan.code.strip() for plan in chain.versions] == [LEFT, SLOW]
    assert chain.rewind(0).code.strip() == LEFT and len(chain.steps) == 1
    result = chain.approve()
    assert result.trajectory is not None
    assert np.allclose(
        result.trajectory.array, bind_skills()["shift"](simple_case.trajectory.array, "left", 0.2)
    )
    with pytest.raises(SessionStateError, match="versions are 0..0"):
        chain.rewind(3)


def test_current_needs_a_result_first(simple_case: Case, sandbox: Sandbox) -> None:
    chain = AdaptationChain(simple_case, ScriptedBackend(answers=[answer(LEFT)]), sandbox, VERBATIM)
    chain.draft()
    with pytest.raises(SessionStateError, match="approve a plan first"):
        chain.feedback("slower", on="current")
    with pytest.raises(SessionStateError, match="'current' or 'original'"):
        chain.feedback("slower", on="sideways")  # type: ignore[arg-type]


def test_the_cli_chains_a_correction_on_the_result(simple_case: Case, tmp_path) -> None:  # type: ignore[no-untyped-def]
    from click.testing import CliRunner

    from trajadapt.cli import cli

    case_file = tmp_path / "case.json"
    case_file.write_text(json.dumps(simple_case.to_dict()))
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps([answer(LEFT), answer(SLOW)]))
    case_file.write_text(json.dumps(simple_case.with_instruction("go left by 0.2").to_dict()))
    out = tmp_path / "case.result.json"
    result = CliRunner().invoke(
        cli,
        [
            "adapt",
            str(case_file),
            "-b",
            "scripted",
            "-o",
            "answers",
            str(answers),
            "--no-log",
            "--out",
            str(out),
        ],
        input="a\nx\nc: now slow down near the box\na\n\n",
    )
    assert result.exit_code == 0, result.output
    assert "Write 'c: what to change'" in result.output
    record = json.loads(out.read_text())
    assert [step["instruction"] for step in record["chain"]] == [
        "go left by 0.2",
        "now slow down near the box",
    ]
    assert record["instruction"] == "go left by 0.2; now slow down near the box"

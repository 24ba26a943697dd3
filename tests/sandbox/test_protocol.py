"""The host reads the worker's answers as untrusted: forged or broken messages become errors in words."""

from __future__ import annotations

import json
import sys
import textwrap

import pytest

from tests.conftest import line_trajectory
from trajadapt.errors import SandboxError
from trajadapt.model.scene import Scene
from trajadapt.sandbox.protocol import (
    ProtocolError,
    decode_json,
    read_child_result,
    read_worker_answer,
)
from trajadapt.sandbox.runner import Sandbox, SandboxLimits

GOOD_RESULT = {
    "ok": True,
    "trajectory": [[0, 0, 0, 1], [1, 1, 1, 1]],
    "stdout": "",
    "error": None,
    "notes": [],
}


def _answer(result: object, **extra: object) -> str:
    return json.dumps({"result": result, "duration_s": 0.1, "layers": ["rlimits"], **extra}) + "\n"


def test_a_well_formed_answer_is_read() -> None:
    answer = read_worker_answer(_answer(GOOD_RESULT))
    assert answer.result.ok and answer.result.rows == [[0, 0, 0, 1], [1, 1, 1, 1]]
    assert answer.layers == ("rlimits",)


@pytest.mark.parametrize(
    "result",
    [
        {"ok": False, "error": "forged"},
        {**GOOD_RESULT, "layers": ["everything"]},
        {**GOOD_RESULT, "ok": "yes"},
        {**GOOD_RESULT, "trajectory": [[0, 0, 0]]},
        {**GOOD_RESULT, "trajectory": [[0, 0, 0, "1"]]},
        {**GOOD_RESULT, "trajectory": [[0, 0, 0, True]]},
        {**GOOD_RESULT, "trajectory": [[0, 0, 0, 10**400]]},
        {**GOOD_RESULT, "trajectory": "rows"},
        {**GOOD_RESULT, "error": {"type": "X", "message": "m", "line": None}},
        {**GOOD_RESULT, "ok": False, "trajectory": None, "error": None},
        {"ok": False, "stdout": "", "notes": [], "error": {"type": "not a name", "message": "m", "line": 1}},
        {"ok": False, "stdout": "", "notes": [], "error": {"type": "E", "message": 5, "line": 1}},
        {"ok": False, "stdout": "", "notes": [], "error": {"type": "E", "message": "m", "line": -1}},
        {**GOOD_RESULT, "notes": ["n"] * 1000},
        {**GOOD_RESULT, "stdout": None},
        [1, 2, 3],
        None,
    ],
)
def test_a_forged_result_is_refused(result: object) -> None:
    with pytest.raises(ProtocolError):
        read_worker_answer(_answer(result))


@pytest.mark.parametrize(
    "line",
    [
        "not json\n",
        _answer(GOOD_RESULT).rstrip("\n"),
        json.dumps({"result": GOOD_RESULT, "duration_s": -1, "layers": []}) + "\n",
        json.dumps({"result": GOOD_RESULT, "duration_s": 0.1, "layers": ["bwrap", "root"]}) + "\n",
        "[" * 100_000 + "\n",
    ],
)
def test_a_broken_answer_line_is_refused(line: str) -> None:
    with pytest.raises(ProtocolError):
        read_worker_answer(line)


def test_text_is_made_safe_and_capped() -> None:
    result = read_child_result(
        {
            "ok": False,
            "stdout": "a\ud800b",
            "notes": [],
            "error": {"type": "E", "message": "x" * 10**6, "line": 2},
        }
    )
    assert result.stdout == "a\ufffdb"
    assert result.error is not None and len(result.error["message"]) < 5_000


def test_oversized_messages_are_refused_before_parsing() -> None:
    with pytest.raises(ProtocolError, match="over the limit"):
        decode_json(b"1" * 101, limit=100)


FORGING_WORKER = textwrap.dedent(
    """
    import sys
    print('{"ready": true, "pid": 1}', flush=True)
    for line in sys.stdin:
        print(%r, flush=True)
    """
)


@pytest.mark.parametrize(
    "forged",
    [
        '{"ok": false, "error": "forged"}',
        json.dumps({"result": {**GOOD_RESULT, "layers": ["all"]}, "duration_s": 0, "layers": []}),
        json.dumps({"result": GOOD_RESULT, "duration_s": 0, "layers": ["bwrap", "kernel-verified"]}),
        "x" * 1000,
    ],
)
def test_the_host_refuses_a_forged_worker_answer_and_replaces_the_worker(
    forged: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake = [sys.executable, "-c", FORGING_WORKER % forged]
    monkeypatch.setattr(Sandbox, "_candidate_commands", lambda self: [(fake, "process")])
    with Sandbox() as sandbox:
        result = sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
        assert not result.ok
        assert result.error is not None and result.error.type == "SandboxProtocol"
        assert "malformed" in result.error.message and "replaced" in result.error.message
        assert sandbox._process is None  # the worker was stopped; the next run starts a fresh one


def test_a_forged_success_cannot_claim_layers(monkeypatch: pytest.MonkeyPatch) -> None:
    honest = json.dumps({"result": GOOD_RESULT, "duration_s": 0, "layers": []})
    fake = [sys.executable, "-c", FORGING_WORKER % honest]
    monkeypatch.setattr(Sandbox, "_candidate_commands", lambda self: [(fake, "process")])
    with Sandbox() as sandbox:
        result = sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
    assert result.ok
    assert "seccomp-allowlist" not in result.layers


def test_a_worker_that_never_answers_is_stopped(monkeypatch: pytest.MonkeyPatch) -> None:
    silent = [
        sys.executable,
        "-c",
        "import sys, time\nprint('{\"ready\": true}', flush=True)\ntime.sleep(600)",
    ]
    monkeypatch.setattr(Sandbox, "_candidate_commands", lambda self: [(silent, "process")])
    monkeypatch.setattr("trajadapt.sandbox.runner.WORKER_GRACE_S", 0.2)
    with Sandbox(SandboxLimits(wall_s=0.3)) as sandbox, pytest.raises(SandboxError, match="keeps dying"):
        sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())

"""Every hostile snippet is stopped, leaves no trace, and the worker keeps serving."""

from __future__ import annotations

import os

import pytest

from tests.conftest import line_trajectory
from tests.sandbox.hostile_snippets import HOSTILE_SNIPPETS, MARKER
from trajadapt.sandbox.runner import Sandbox
from trajadapt.scene import Scene


def test_corpus_is_large_enough() -> None:
    assert len(HOSTILE_SNIPPETS) >= 25
    assert len({name for name, _ in HOSTILE_SNIPPETS}) == len(HOSTILE_SNIPPETS)


@pytest.mark.parametrize(("name", "code"), HOSTILE_SNIPPETS, ids=[n for n, _ in HOSTILE_SNIPPETS])
def test_hostile_snippet_is_blocked(sandbox: Sandbox, name: str, code: str) -> None:
    if os.path.exists(MARKER):
        os.unlink(MARKER)
    result = sandbox.run(code, line_trajectory(), Scene())
    assert not result.ok, f"{name} ran to a result: {result}"
    assert result.error is not None and result.error.message
    assert not os.path.exists(MARKER), f"{name} wrote a file"
    assert len(result.stdout) <= sandbox.limits.max_output_chars + 100


def test_worker_survives_the_corpus(sandbox: Sandbox) -> None:
    result = sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
    assert result.ok


def test_static_check_reports_the_line(sandbox: Sandbox) -> None:
    result = sandbox.run("x = 1\ny = 2\nimport os\n", line_trajectory(), Scene())
    assert result.error is not None
    assert result.error.type == "Rejected"
    assert result.error.line == 3


def test_huge_output_is_cut(sandbox: Sandbox) -> None:
    code = "for i in range(10 ** 6):\n    print('spam' * 100)\nmodified_trajectory = get_trajectory()"
    result = sandbox.run(code, line_trajectory(), Scene())
    assert result.ok
    assert "output cut" in result.stdout
    assert len(result.stdout) < sandbox.limits.max_output_chars + 100

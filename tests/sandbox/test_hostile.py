"""Every hostile snippet is stopped, leaves no trace, and the worker keeps serving."""

from __future__ import annotations

import os

import pytest

from tests.conftest import line_trajectory
from tests.sandbox.hostile_snippets import HOSTILE_SNIPPETS, MARKER
from tests.sandbox.os_attacks import OS_ATTACKS
from trajadapt.model.scene import Scene
from trajadapt.sandbox.runner import Sandbox


def test_corpus_is_large_enough() -> None:
    assert len(HOSTILE_SNIPPETS) >= 100
    assert len(OS_ATTACKS) >= 50
    assert len({name for name, _ in HOSTILE_SNIPPETS}) == len(HOSTILE_SNIPPETS)
    assert len({name for name, _ in OS_ATTACKS}) == len(OS_ATTACKS)


@pytest.mark.parametrize(("name", "code"), HOSTILE_SNIPPETS, ids=[n for n, _ in HOSTILE_SNIPPETS])
def test_hostile_snippet_is_blocked(sandbox: Sandbox, name: str, code: str) -> None:
    if os.path.exists(MARKER):
        os.unlink(MARKER)
    result = sandbox.run(code, line_trajectory(), Scene())
    assert not result.ok, f"{name} ran to a result: {result}"
    assert result.error is not None and result.error.message
    assert not os.path.exists(MARKER), f"{name} wrote a file"
    assert len(result.stdout) <= sandbox.limits.max_output_chars + 100


@pytest.mark.parametrize(("name", "template"), OS_ATTACKS, ids=[n for n, _ in OS_ATTACKS])
def test_os_attack_is_refused_by_the_python_layers_too(sandbox: Sandbox, name: str, template: str) -> None:
    paths = {"secret": "/etc/shadow", "secret_text": "", "victim": MARKER + ".victim", "marker": MARKER}
    result = sandbox.run(template.format(**paths), line_trajectory(), Scene())
    assert not result.ok, f"{name} ran to a result: {result}"
    assert not os.path.exists(MARKER), f"{name} wrote a file"


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

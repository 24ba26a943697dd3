"""The layers behind the static check hold on their own: module proxies, import, seccomp, limits."""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest

from tests.conftest import line_trajectory
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.sandbox import seccomp
from trajadapt.sandbox.guard import check_code
from trajadapt.sandbox.restricted import BoundedOutput, SafeModule, make_builtins, preload_modules
from trajadapt.sandbox.runner import Sandbox


def test_safe_module_never_hands_back_a_disallowed_module() -> None:
    numpy_view = SafeModule(np, "numpy")
    with pytest.raises(AttributeError):
        _ = numpy_view.random.mtrand
    with pytest.raises(AttributeError):
        _ = numpy_view.lib
    with pytest.raises(AttributeError):
        _ = numpy_view.save
    assert isinstance(numpy_view.linalg, SafeModule)
    assert numpy_view.linalg.norm([3.0, 4.0]) == 5.0


def test_restricted_import_refuses_other_modules() -> None:
    modules = preload_modules()
    builtins = make_builtins(modules, BoundedOutput(100))
    with pytest.raises(ImportError):
        builtins["__import__"]("os")
    assert isinstance(builtins["__import__"]("numpy.linalg", fromlist=("norm",)), SafeModule)
    assert "open" not in builtins and "eval" not in builtins and "getattr" not in builtins


def test_benign_code_passes_the_static_check() -> None:
    code = textwrap.dedent(
        """
        import numpy as np
        from numpy.linalg import norm
        import math
        traj = get_trajectory()
        label = "{} points, {:.2f}".format(len(traj), math.pi)
        print(f"{label} {norm(traj[0, :3])}")
        modified_trajectory = traj
        """
    )
    assert check_code(code) is None


SECCOMP_PROBE = textwrap.dedent(
    """
    import os, socket, sys
    sys.path.insert(0, {src!r})
    from trajadapt.sandbox import seccomp
    assert seccomp.install_filter()
    outcomes = []
    for name, attempt in [
        ("fork", os.fork),
        ("open-write", lambda: open("/tmp/trajadapt-seccomp-probe", "w")),
        ("open-read", lambda: open("/etc/hostname")),
        ("socket", lambda: socket.socket()),
        ("exec", lambda: os.execv("/bin/true", ["true"])),
        ("listdir", lambda: os.listdir("/")),
        ("kill", lambda: os.kill(os.getppid(), 0)),
    ]:
        try:
            attempt()
            outcomes.append(name + ":allowed")
        except OSError:
            outcomes.append(name + ":blocked")
    print(" ".join(outcomes))
    """
)


@pytest.mark.skipif(not seccomp.supported(), reason="no seccomp table for this machine")
def test_seccomp_filter_blocks_processes_files_and_sockets() -> None:
    from pathlib import Path

    src = str(Path(seccomp.__file__).resolve().parents[2])
    completed = subprocess.run(
        [sys.executable, "-c", SECCOMP_PROBE.format(src=src)], capture_output=True, text=True, timeout=60
    )
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.split() == [
        "fork:blocked",
        "open-write:blocked",
        "open-read:blocked",
        "socket:blocked",
        "exec:blocked",
        "listdir:blocked",
        "kill:blocked",
    ]


def test_children_report_their_layers(sandbox: Sandbox) -> None:
    result = sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
    assert "rlimits" in result.layers
    assert "seccomp-allowlist" in result.layers
    assert "unprivileged-user" in result.layers
    assert {"static-check", "restricted-namespace"} <= set(result.layers)


def test_result_carries_trajectory_and_output(sandbox: Sandbox) -> None:
    code = "t = get_trajectory()\nt[:, 0] += 0.25\nprint('shifted', len(t))\nmodified_trajectory = t"
    result = sandbox.run(code, line_trajectory(5), Scene())
    assert result.ok and result.rows is not None
    assert np.allclose(np.asarray(result.rows)[:, 0], 0.25)
    assert result.stdout == "shifted 5\n"


def test_detect_objects_is_case_insensitive_and_none_when_absent(sandbox: Sandbox) -> None:
    scene = Scene((SceneObject("Red Mug", 1.0, 2.0, 3.0),))
    code = "print(detect_objects('red mug'), detect_objects('sofa'))\nmodified_trajectory = get_trajectory()"
    result = sandbox.run(code, line_trajectory(), scene)
    assert result.stdout.strip() == "[1.0, 2.0, 3.0] None"


def test_detect_objects_knows_the_start_and_goal_unless_the_scene_names_them(sandbox: Sandbox) -> None:
    code = "print(detect_objects('goal position'), detect_objects('Start'))\nmodified_trajectory = get_trajectory()"
    rows = line_trajectory(5)
    result = sandbox.run(code, rows, Scene())
    goal, start = rows.positions[-1].tolist(), rows.positions[0].tolist()
    assert result.stdout.strip() == f"{goal} {start}"
    named = "print(detect_objects('goal'))\nmodified_trajectory = get_trajectory()"
    shadowed = sandbox.run(named, rows, Scene((SceneObject("goal", 9.0, 9.0, 9.0),)))
    assert shadowed.stdout.strip() == "[9.0, 9.0, 9.0]"


def test_error_names_the_line_and_the_missing_object(sandbox: Sandbox) -> None:
    code = (
        "t = get_trajectory()\nsofa = detect_objects('sofa')\nd = t[:, :3] - sofa[0]\nmodified_trajectory = t"
    )
    result = sandbox.run(code, line_trajectory(), Scene((SceneObject("box", 0, 0, 0),)))
    assert result.error is not None
    assert result.error.line == 3
    assert "no object named 'sofa'" in result.error.message and "'box'" in result.error.message


def test_missing_result_variable_is_explained(sandbox: Sandbox) -> None:
    result = sandbox.run("t = get_trajectory()", line_trajectory(), Scene())
    assert result.error is not None and "modified_trajectory" in result.error.message


def test_get_trajectory_returns_a_copy(sandbox: Sandbox) -> None:
    code = "get_trajectory()[:, 0] = 99\nmodified_trajectory = get_trajectory()"
    result = sandbox.run(code, line_trajectory(), Scene())
    assert result.ok and result.rows is not None and result.rows[0][0] == 0.0


def test_worker_restarts_after_it_is_killed(sandbox: Sandbox) -> None:
    sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
    assert sandbox._process is not None
    sandbox._process.kill()
    sandbox._process.wait()
    assert sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene()).ok

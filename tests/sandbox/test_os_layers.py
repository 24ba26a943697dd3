"""The OS layers hold alone: hostile code run with the static check and restricted namespace turned off.

Every attack in ``os_attacks`` runs straight in the sandbox child with the real builtins, ``os`` and
``ctypes``, under each isolation this machine has (process; bubblewrap when installed). None may run to
a result, leak the planted secret, write or remove a file, or harm the worker.
"""

from __future__ import annotations

import os
import platform
import shutil
import subprocess
import sys
import tempfile
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.conftest import line_trajectory
from tests.sandbox.os_attacks import OS_ATTACKS
from trajadapt.model.scene import Scene
from trajadapt.sandbox.bubblewrap import bwrap_command
from trajadapt.sandbox.runner import PACKAGE_ROOT, Sandbox, SandboxLimits

pytestmark = pytest.mark.skipif(
    platform.system() != "Linux" or platform.machine() != "x86_64",
    reason="the attacks use x86-64 system-call numbers",
)
ISOLATIONS = ["process"] + (["bwrap"] if shutil.which("bwrap") else [])


@pytest.fixture(scope="module")
def planted() -> Iterator[dict[str, str]]:
    """A secret file outside the bound paths, a victim file that must survive, a marker that must not appear.

    The folder is open to everyone (pytest's own temporary folders are not), so file permissions
    cannot be what stops a read: only the sandbox can.
    """
    folder = Path(tempfile.mkdtemp(prefix="trajadapt-outside-", dir="/tmp"))
    folder.chmod(0o777)
    secret = folder / "secret.txt"
    secret_text = f"TOPSECRET-{uuid.uuid4().hex}"
    secret.write_text(secret_text)
    secret.chmod(0o644)  # readable by anyone: only the sandbox may stop the read
    victim = folder / "victim.txt"
    victim.write_text("keep me")
    victim.chmod(0o666)
    yield {
        "secret": str(secret),
        "secret_text": secret_text,
        "victim": str(victim),
        "marker": str(folder / "marker"),
    }
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="module", params=ISOLATIONS)
def bare_sandbox(request: pytest.FixtureRequest) -> Iterator[Sandbox]:
    """A sandbox with the Python layers off: only the OS layers stand between the code and the host."""
    limits = SandboxLimits(cpu_s=1.0, wall_s=3.0, memory_mb=256)
    with Sandbox(limits, isolation=request.param, python_layers=False) as box:
        yield box


@pytest.mark.parametrize(("name", "template"), OS_ATTACKS, ids=[name for name, _ in OS_ATTACKS])
def test_attack_is_blocked_by_the_os_layers_alone(
    bare_sandbox: Sandbox, planted: dict[str, str], name: str, template: str
) -> None:
    before = _worker_pid(bare_sandbox)
    result = bare_sandbox.run(template.format(**planted), line_trajectory(), Scene())
    assert not result.ok, f"{name} ran to a result: {result}"
    assert result.error is not None and result.error.message
    seen = result.stdout + result.error.message
    assert planted["secret_text"] not in seen, f"{name} leaked the secret"
    assert not os.path.lexists(planted["marker"]), f"{name} wrote a file"
    assert Path(planted["victim"]).read_text() == "keep me", f"{name} changed a file"
    assert oct(Path(planted["victim"]).stat().st_mode)[-3:] == "666"
    assert before is None or _worker_pid(bare_sandbox) == before, f"{name} killed the worker"
    if result.error.type not in ("Timeout", "Crash"):  # the child reported: the kernel showed its layers
        assert {"unprivileged-user", "rlimits", "seccomp-allowlist"} <= set(result.layers)


def test_the_worker_still_serves_after_the_attacks(bare_sandbox: Sandbox) -> None:
    result = bare_sandbox.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
    assert result.ok
    assert "static-check" not in result.layers


def test_forged_layers_are_not_reported(bare_sandbox: Sandbox) -> None:
    forged = dict(OS_ATTACKS)["forged-layers"].format(secret="", secret_text="", victim="", marker="")
    result = bare_sandbox.run(forged, line_trajectory(), Scene())
    assert result.error is not None and "malformed" in result.error.message
    assert "everything" not in result.layers


@pytest.mark.skipif(shutil.which("bwrap") is None, reason="bubblewrap is not installed")
def test_bubblewrap_shows_only_the_interpreter_and_libraries(planted: dict[str, str]) -> None:
    probe = (
        "import os, json; print(json.dumps({'root': sorted(os.listdir('/')), "
        f"'secret': os.path.exists({planted['secret']!r}), 'etc': sorted(os.listdir('/etc')), "
        "'net': sorted(os.listdir('/sys/class/net')) if os.path.isdir('/sys/class/net') else []}))"
    )
    command = bwrap_command(shutil.which("bwrap") or "bwrap", [sys.executable, "-c", probe], PACKAGE_ROOT)
    completed = subprocess.run(
        command, capture_output=True, text=True, timeout=60, env={"PATH": "/usr/bin:/bin"}
    )
    assert completed.returncode == 0, completed.stderr
    seen = __import__("json").loads(completed.stdout)
    assert not seen["secret"]
    assert seen["etc"] == ["ld.so.cache"]
    assert set(seen["root"]) <= {
        "usr",
        "lib",
        "lib64",
        "lib32",
        "etc",
        "proc",
        "dev",
        *_top_level_of_python(),
    }
    assert seen["net"] in ([], ["lo"])


def _top_level_of_python() -> set[str]:
    return {Path(path).resolve().parts[1] for path in (sys.prefix, sys.base_prefix, str(PACKAGE_ROOT))}


def _worker_pid(sandbox: Sandbox) -> int | None:
    process = sandbox._process
    return process.pid if process is not None and process.poll() is None else None

"""No job's child holds bytes of an earlier job: each child starts from memory no job has touched.

Job A carries a secret (in its code and an object's name); job B, with the Python layers off, scans
every page of its own address space around its heap and its small-object arenas, probing each page
with madvise (allowed by the seccomp filter; an unmapped page answers ENOMEM instead of faulting).
"""

import os
import signal
import threading
import time
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest

from tests.conftest import line_trajectory
from tests.sandbox.test_os_layers import ISOLATIONS
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.sandbox.runner import Sandbox, SandboxLimits

SCAN = """
import ctypes
import numpy as np
libc = ctypes.CDLL(None, use_errno=True)
libc.sbrk.restype = ctypes.c_void_p
libc.sbrk.argtypes = [ctypes.c_ssize_t]
libc.madvise.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int]
PAGE = 4096
needle = bytes.fromhex('{masked}')  # the secret XOR 0x55: this job never holds the secret itself
hits, pages = 0, 0
address = (libc.sbrk(0) // PAGE) * PAGE - 2 * PAGE
while pages < 65536 and libc.madvise(address, 2 * PAGE, 0) == 0:  # the malloc heap, top down
    window = np.frombuffer(ctypes.string_at(address, 2 * PAGE), dtype=np.uint8) ^ 0x55
    hits += needle in window.tobytes()
    address, pages = address - PAGE, pages + 1
print('HITS', hits, 'PAGES', pages)
modified_trajectory = get_trajectory()
"""


@pytest.fixture(params=ISOLATIONS)
def bare(request: pytest.FixtureRequest) -> Iterator[Sandbox]:
    with Sandbox(
        SandboxLimits(cpu_s=5.0, wall_s=20.0, memory_mb=512), isolation=request.param, python_layers=False
    ) as box:
        yield box


def test_a_later_job_finds_no_byte_of_an_earlier_one(bare: Sandbox) -> None:
    secret = f"TOPSECRET{uuid.uuid4().hex}"
    masked = bytes(c ^ 0x55 for c in secret.encode()).hex()
    code = f"s = '{secret}' * 3\nmodified_trajectory = get_trajectory()"
    named = Scene((SceneObject(secret + "-" + "x" * 250, 0, 0, 0), SceneObject(secret, 0, 0, 0)))
    assert bare.run(code, line_trajectory(1500), named).ok  # a long line: its memory outlives a short one
    scan = bare.run(SCAN.format(masked=masked), line_trajectory(), Scene())
    assert scan.ok, scan.error
    assert "HITS" in scan.stdout
    hits = int(scan.stdout.split("HITS")[1].split()[0])
    assert hits == 0, scan.stdout


def _sandbox_children() -> list[int]:
    """Processes running the sandbox worker's code as the unprivileged user (the children)."""
    found = []
    for status in Path("/proc").glob("[0-9]*/status"):
        try:
            text = status.read_text()
            command = (status.parent / "cmdline").read_bytes()
        except OSError:
            continue
        uid = next((line.split()[1] for line in text.splitlines() if line.startswith("Uid:")), "")
        if uid == "65534" and b"trajadapt.sandbox.child" in command:
            found.append(int(status.parent.name))
    return found


@pytest.mark.skipif(os.geteuid() != 0, reason="children run as nobody only when trajadapt runs as root")
def test_no_child_outlives_its_worker(bare: Sandbox) -> None:
    running = threading.Thread(
        target=lambda: bare.run("import time\ntime.sleep(15)", line_trajectory(), Scene())
    )
    running.start()
    deadline = time.monotonic() + 5
    while not _sandbox_children() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert _sandbox_children(), "the sleeping child was not seen"
    assert bare._process is not None
    os.killpg(bare._process.pid, signal.SIGKILL)  # the CLI ends without closing its sandbox
    deadline = time.monotonic() + 5
    while _sandbox_children() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not _sandbox_children(), "a child outlived its worker"
    running.join()
    bare.close()

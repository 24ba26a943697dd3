"""The worker keeps its deadlines and reports what happened, whatever the child does with its pipe and signals."""

import time
from collections.abc import Iterator

import pytest

from tests.conftest import line_trajectory
from tests.sandbox.test_os_layers import ISOLATIONS
from trajadapt.model.scene import Scene
from trajadapt.sandbox.runner import ExecutionOptions, Sandbox, SandboxLimits


@pytest.fixture(scope="module", params=ISOLATIONS)
def bare(request: pytest.FixtureRequest) -> Iterator[Sandbox]:
    with Sandbox(
        SandboxLimits(cpu_s=1.0, wall_s=2.0, memory_mb=256), isolation=request.param, python_layers=False
    ) as box:
        yield box


def test_a_child_that_closes_its_result_pipe_and_sleeps_is_stopped_at_the_deadline(bare):
    code = "import os, time\nfor fd in range(3, 64):\n    try:\n        os.close(fd)\n    except OSError:\n        pass\ntime.sleep(30)\n"
    started = time.perf_counter()
    result = bare.run(code, line_trajectory(), Scene())
    assert time.perf_counter() - started < 20  # not the child's 30 s: the worker's deadline held
    assert result.error is not None and result.error.type == "Timeout"
    assert bare.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene()).ok


def test_a_child_that_ignores_sigxcpu_is_a_cpu_timeout(bare):
    code = "import signal\nsignal.signal(signal.SIGXCPU, signal.SIG_IGN)\nwhile True:\n    pass\n"
    result = bare.run(code, line_trajectory(), Scene())
    assert result.error is not None and result.error.type == "Timeout", result.error


def test_more_notes_than_the_protocol_carries_are_capped_not_malformed(bare):
    code = "t = get_trajectory()\n" + "shift(t, 'up')\n" * 25
    options = ExecutionOptions(skills=True, accept_last=True)
    result = bare.run(code, line_trajectory(), Scene(), options)
    assert result.ok, result.error
    assert len(result.notes) == 20 and "more notes" in result.notes[-1]


def test_a_worker_started_from_a_thread_outlives_that_thread(bare):
    import threading

    bare.close()
    starter = threading.Thread(
        target=lambda: bare.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene())
    )
    starter.start()
    starter.join()
    worker = bare._process
    assert worker is not None
    time.sleep(0.5)
    assert worker.poll() is None, "the worker died with the thread that started it"
    assert bare.run("modified_trajectory = get_trajectory()", line_trajectory(), Scene()).ok
    assert bare._process is worker

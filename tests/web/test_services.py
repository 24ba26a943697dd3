"""The review server's services: simulations yield the CPU to the model."""

from __future__ import annotations

import os
import platform
import threading

import pytest

from trajadapt.web.services import SIMULATION_NICENESS, yield_to_the_model


@pytest.mark.skipif(platform.system() != "Linux", reason="per-thread niceness is Linux's")
def test_a_simulation_thread_runs_below_the_other_threads() -> None:
    before = os.getpriority(os.PRIO_PROCESS, threading.get_native_id())
    seen: list[int] = []

    def job() -> None:
        yield_to_the_model()
        seen.append(os.getpriority(os.PRIO_PROCESS, threading.get_native_id()))

    worker = threading.Thread(target=job)
    worker.start()
    worker.join()
    assert seen == [max(before, SIMULATION_NICENESS)]
    assert os.getpriority(os.PRIO_PROCESS, threading.get_native_id()) == before  # this thread untouched

"""What the review server needs from the rest of trajadapt: sessions, case files, the log, the simulator."""

from __future__ import annotations

import contextlib
import os
import threading
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from trajadapt.backends.base import Backend
from trajadapt.chain import AdaptationChain
from trajadapt.checks.constraints import Constraints
from trajadapt.checks.robot_limits import robot_constraints
from trajadapt.errors import InputError
from trajadapt.files.store import SessionSummary, Store
from trajadapt.memory import MemoryBank
from trajadapt.model.case import Case, load_case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationResult, SessionSettings


@dataclass
class Services:
    """The backend, sandbox, log and folders one server uses for all its sessions."""

    backend: Backend
    sandbox: Sandbox
    store: Store | None  # None: logging is off; nothing is written and no earlier session is listed
    settings: SessionSettings
    work_dir: Path
    cases_dir: Path | None = None
    simulator: Callable[[AdaptationResult, str, Path], dict[str, Any]] | None = None
    memory: MemoryBank | None = None  # None: approved answers are neither recalled nor remembered

    def new_session(
        self, case: Case, limits: Constraints | None = None, robot: str | None = None
    ) -> AdaptationChain:
        """A session on ``case`` (a chain: corrections may build on its results), logged to the shared log.

        ``limits`` and ``robot`` (the page's) take the place of the server's where they set a value.

        Raises:
            InputError: no robot has the name ``robot``.
        """
        settings = self.settings
        if robot is not None:
            robot_constraints(robot)  # the name is checked here, before any LLM call
            settings = replace(settings, robot=robot)
        if limits is not None:
            own = settings.constraints or Constraints()
            settings = replace(settings, constraints=own.merged_with(limits))
        return AdaptationChain(case, self.backend, self.sandbox, settings, self.store, memory=self.memory)

    def forget(self, example_id: str) -> bool:
        """Forget a remembered example; False when memory is off or there is no such example."""
        return self.memory is not None and self.memory.forget(example_id)

    def case_names(self) -> list[str]:
        """Case files under the cases folder, as paths relative to it."""
        if self.cases_dir is None:
            return []
        return sorted(str(p.relative_to(self.cases_dir)) for p in self.cases_dir.rglob("*.json"))

    def load_named_case(self, name: str) -> Case:
        """A case file of the cases folder (never outside it).

        Raises:
            InputError: no cases folder, a name no file can have, a path outside the folder, or a
                bad case file.
        """
        if self.cases_dir is None:
            raise InputError("the server was started without --cases; upload a case file instead")
        root = self.cases_dir.resolve()
        try:
            path = (root / name).resolve()
            found = root in path.parents and path.is_file()
        except (ValueError, OSError):  # a NUL byte, a name too long for the file system
            found = False
        if not found:
            raise InputError(f"no case {name!r} in {self.cases_dir}")
        return load_case(path)

    def stored_sessions(self) -> list[SessionSummary]:
        """Sessions in the log (newest first)."""
        return self.store.recent_sessions() if self.store is not None else []

    def simulate(self, result: AdaptationResult, robot: str, folder: Path) -> dict[str, Any]:
        """Run ``result`` on ``robot``; the report with the picture and animation file names.

        Raises:
            InputError: the simulator is not installed.
        """
        if self.simulator is None:
            raise InputError("the simulator is not available on this server (install trajadapt[sim])")
        return self.simulator(result, robot, folder)


def pybullet_simulator(positive_x: str) -> Callable[[AdaptationResult, str, Path], dict[str, Any]]:
    """The simulator the server uses: pybullet, pictures into the session's folder."""

    def run(result: AdaptationResult, robot: str, folder: Path) -> dict[str, Any]:
        from trajadapt.sim import SimulationOptions, simulate

        yield_to_the_model()
        assert result.trajectory is not None
        image, animation = folder / f"{robot}.png", folder / f"{robot}.gif"
        options = SimulationOptions(image=image, animation=animation, positive_x=positive_x)
        report = simulate(
            result.trajectory, result.case.scene, robot, options, original=result.case.trajectory
        )
        data = report.to_dict()
        data.pop("executed")
        return {**data, "image": image.name, "animation": animation.name, "summary": report.summary_lines()}

    return run


SIMULATION_NICENESS = 10


def yield_to_the_model() -> None:
    """Run the calling thread (a simulation job) below the model's priority.

    On Linux niceness is per thread, so this leaves the server's other threads alone; the model's
    generating thread then gets a core first when a simulation and an answer run at once.
    """
    with contextlib.suppress(OSError, AttributeError):  # not Linux, or not permitted: run as is
        thread = threading.get_native_id()
        if os.getpriority(os.PRIO_PROCESS, thread) < SIMULATION_NICENESS:  # only ever lower it
            os.setpriority(os.PRIO_PROCESS, thread, SIMULATION_NICENESS)

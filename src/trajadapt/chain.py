"""Corrections on the current result or on the original: a chain of adaptation sessions.

After a result, a user either builds on it ("now also slow down near the lamp": ``on="current"``,
a new step whose input is the last adapted trajectory) or goes back to the start ("no, keep the
start where it was": ``on="original"``, the first step's conversation re-plans with everything said
since). Each step is an ``AdaptationSession``; versions count across steps, so undo works over both
kinds; the result records the chain (each step's instruction, code and trajectory).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Literal

from trajadapt.backends.base import Backend
from trajadapt.errors import SessionStateError
from trajadapt.files.store import Store
from trajadapt.llm.answer import Plan
from trajadapt.memory import MemoryBank
from trajadapt.model.case import Case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationResult, AdaptationSession, Outcome, ProgressCallback, SessionSettings

Target = Literal["current", "original"]


@dataclass(frozen=True)
class ChainStep:
    """One approved step: what was asked, the code that ran, the trajectory it gave."""

    instruction: str
    code: str
    trajectory: list[list[float]]

    def to_dict(self) -> dict[str, Any]:
        """The result file's form."""
        return {"instruction": self.instruction, "code": self.code, "trajectory": self.trajectory}


class AdaptationChain:
    """Sessions one after the other: feedback on the current result starts a new step on it."""

    def __init__(
        self,
        case: Case,
        backend: Backend,
        sandbox: Sandbox,
        settings: SessionSettings | None = None,
        store: Store | None = None,
        on_progress: ProgressCallback | None = None,
        memory: MemoryBank | None = None,
    ) -> None:
        self.case = case
        self.memory = memory
        self._parts = (backend, sandbox, settings, store, on_progress)
        self.steps: list[AdaptationSession] = [self._make(case)]
        self.results: list[AdaptationResult | None] = [None]
        self._versions: list[tuple[int, int]] = []  # (step, that step's version) of every plan, in order

    def _make(self, case: Case) -> AdaptationSession:
        backend, sandbox, settings, store, on_progress = self._parts
        return AdaptationSession(case, backend, sandbox, settings, store, on_progress, self.memory)

    @property
    def session(self) -> AdaptationSession:
        """The step being worked on."""
        return self.steps[-1]

    def report_progress_to(self, callback: ProgressCallback) -> None:
        """Send every step's progress messages (this one's and later ones') to ``callback``."""
        backend, sandbox, settings, store, _ = self._parts
        self._parts = (backend, sandbox, settings, store, callback)
        for step in self.steps:
            step.on_progress = callback

    @property
    def session_ids(self) -> list[str]:
        """The log's session id of every step."""
        return [step.session_id for step in self.steps if step.session_id]

    def preview(self) -> Outcome:
        """The current plan's code run once on this step's input, without repair (see AdaptationSession)."""
        return self.session.preview()

    def draft(self) -> Plan:
        """The first plan of the first step."""
        return self._remember(self.session.draft())

    def feedback(self, text: str, on: Target = "original") -> Plan:
        """A new plan: for the current result (a new step on it) or re-planned from the original.

        Raises:
            SessionStateError: ``current`` before any result, or an unknown target.
        """
        if on == "current":
            return self._on_current(text)
        if on != "original":
            raise SessionStateError(f"feedback goes on 'current' or 'original', not {on!r}")
        said = [session.case.instruction for session in self.steps[1:]] + [text]
        del self.steps[1:], self.results[1:]
        self.results[0] = None
        self._versions = [(step, local) for step, local in self._versions if step == 0]
        return self._remember(self.steps[0].feedback("; ".join(said)))

    def _on_current(self, text: str) -> Plan:
        last = self.results[-1]
        if last is None or last.trajectory is None:
            raise SessionStateError(
                "there is no result to build on yet; approve a plan first (or use 'original')"
            )
        step = replace(self.session.case, trajectory=last.trajectory).with_instruction(text)
        self.steps.append(self._make(step))
        self.results.append(None)
        return self._remember(self.session.draft())

    def approve(self) -> AdaptationResult:
        """Run the current step's plan; the result carries the whole chain."""
        result = self.session.approve()
        self.results[-1] = result
        return result

    def chain(self) -> list[ChainStep]:
        """The approved steps so far, first to last."""
        return [
            ChainStep(r.case.instruction, r.plan.code if r.plan else "", r.trajectory.to_rows())
            for r in self.results
            if r is not None and r.trajectory is not None
        ]

    def to_dict(self, result: AdaptationResult) -> dict[str, Any]:
        """The result file: the last step's result, the original trajectory of the first, and the chain."""
        data = result.to_dict()
        data["original_trajectory"] = self.case.trajectory.to_rows()
        data["instruction"] = "; ".join(step.instruction for step in self.chain()) or self.case.instruction
        data["chain"] = [step.to_dict() for step in self.chain()]
        return data

    @property
    def versions(self) -> list[Plan]:
        """Every plan so far, across steps, oldest first."""
        return [self.steps[step].versions[version] for step, version in self._versions]

    def rewind(self, version: int) -> Plan:
        """Go back to plan ``version`` (counted across steps); later steps and plans are dropped.

        Raises:
            SessionStateError: no such version.
        """
        if not 0 <= version < len(self._versions):
            raise SessionStateError(
                f"there is no plan version {version}; versions are 0..{len(self._versions) - 1}"
            )
        step, local = self._versions[version]
        del self.steps[step + 1 :], self.results[step + 1 :], self._versions[version + 1 :]
        self.results[step] = None
        return self.steps[step].rewind(local)

    def _remember(self, plan: Plan) -> Plan:
        self._versions.append((len(self.steps) - 1, len(self.session.versions) - 1))
        return plan

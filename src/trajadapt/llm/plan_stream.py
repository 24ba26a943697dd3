"""The plan's steps as the answer is written: each one passed on as soon as the next begins.

The answer is JSON (``{"high_level_plan": "1) ... 2) ...", "python_code": "..."}``) arriving in
pieces. ``PlanStream`` reads the plan's string as it grows and hands each numbered step on once it is
complete (the next number begins, or the string ends), so that the CLI and the review page can show
the plan while the code is still being written.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable

PLAN_KEY = re.compile(r'"high_level_plan"\s*:\s*"')
STEP_START = re.compile(r"(?:^|(?<=\s))(\d{1,2})[).] ")
STRING_END = re.compile(r'(?<!\\)(?:\\\\)*"')


class PlanStream:
    """Feed it the answer's pieces; ``on_step`` receives each complete plan step, in order."""

    def __init__(self, on_step: Callable[[str], None]) -> None:
        self.on_step = on_step
        self.text = ""
        self.shown = 0
        self.ended = False

    def feed(self, piece: str) -> None:
        """Add a piece of the answer; pass on the steps it completes."""
        if self.ended:
            return
        self.text += piece
        plan, ended = self._plan_so_far()
        if plan is None:
            return
        steps = _steps(plan)
        complete = steps if ended else steps[:-1]
        for step in complete[self.shown :]:
            self.on_step(step)
        self.shown = max(self.shown, len(complete))
        self.ended = ended

    def _plan_so_far(self) -> tuple[str | None, bool]:
        key = PLAN_KEY.search(self.text)
        if key is None:
            return None, False
        rest = self.text[key.end() :]
        end = STRING_END.search(rest)
        raw = rest[: end.end() - 1] if end else rest.rstrip("\\")
        return _unescape(raw), end is not None


def _steps(plan: str) -> list[str]:
    """The plan cut at its step numbers ('1) ...', '2. ...'); a plan without numbers is one step."""
    starts = [match.start() for match in STEP_START.finditer(plan)] or [0]
    if starts[0] != 0 and plan[: starts[0]].strip():
        starts.insert(0, 0)
    bounds = [*starts, len(plan)]
    steps = [plan[a:b].strip() for a, b in zip(bounds, bounds[1:], strict=False)]
    return [step for step in steps if step]


def _unescape(raw: str) -> str:
    try:
        value: str = json.loads(f'"{raw}"')
        return value
    except ValueError:
        return raw.replace("\\n", "\n").replace('\\"', '"')

"""A backend that, like the embedded model, answers one request at a time (for the parallel-bench tests).

It lives in its own module so that bench worker processes (started with spawn) can import it.
"""

from __future__ import annotations

import json
import os

from trajadapt.backends.base import Backend, ChatRequest, Completion

SHIFT_LEFT = json.dumps(
    {
        "high_level_plan": "1) Shift left.",
        "python_code": "modified_trajectory = shift(get_trajectory(), 'left')",
    }
)


class OneAtATimeBackend(Backend):
    """Always answers with a shift to the left; its model name tells which process answered."""

    name = "one-at-a-time"
    concurrent = False

    @property
    def model(self) -> str:
        """The answering process."""
        return f"pid-{os.getpid()}"

    def complete(self, request: ChatRequest) -> Completion:
        """The same answer every time."""
        return Completion(text=SHIFT_LEFT, model=self.model)

"""Backend that replays queued or recorded answers: for tests, demos and offline reproduction."""

from __future__ import annotations

import json
from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from trajadapt.backends.base import Backend, ChatRequest, Completion
from trajadapt.errors import BackendOptionError, EmptyCompletion, InputError
from trajadapt.model.trajectory import read_json_file


@dataclass(frozen=True)
class ScriptedOptions:
    """Options of the ``scripted`` backend.

    Attributes:
        answers: a JSON file holding the answers to replay in order: a list of strings, or an
            object ``{"answers": [...]}``; an answer that is itself a JSON object is sent as its
            JSON text.
        model: the model name to report.
    """

    answers: Path | None = None
    model: str = "scripted"


class ScriptedBackend(Backend):
    """Answers each request with the next queued answer; records every request it saw."""

    name = "scripted"
    Options = ScriptedOptions  # type: ignore[assignment]

    def __init__(self, options: Any = None, answers: Iterable[str] = ()) -> None:
        super().__init__(options)
        self.queue: deque[str] = deque(answers)
        if self.options.answers is not None:
            self.queue.extend(load_answers(Path(self.options.answers)))
        self.requests: list[ChatRequest] = []

    @property
    def model(self) -> str:
        """The reported model name."""
        return str(self.options.model)

    def describe(self) -> str:
        """How many answers are left."""
        return f"scripted: {len(self.queue)} answer(s) queued"

    def enqueue(self, *answers: str) -> None:
        """Add answers to the end of the queue."""
        self.queue.extend(answers)

    def complete(self, request: ChatRequest) -> Completion:
        """Return the next queued answer."""
        self.requests.append(request)
        if not self.queue:
            raise EmptyCompletion(
                "the scripted backend has no answers left; give it more with -o answers FILE"
            )
        return Completion(text=self.queue.popleft(), model=self.model)


def load_answers(path: Path) -> list[str]:
    """Read a file of answers to replay.

    Raises:
        BackendOptionError: the file is missing or has no list of answers.
    """
    try:
        data = read_json_file(path)
    except InputError as exc:
        raise BackendOptionError(f"scripted answers file: {exc}") from exc
    answers = data.get("answers") if isinstance(data, dict) else data
    if not isinstance(answers, list) or not answers:
        raise BackendOptionError(
            f'scripted answers file {path}: expected a non-empty list of answers or {{"answers": [...]}}'
        )
    return [a if isinstance(a, str) else json.dumps(a) for a in answers]

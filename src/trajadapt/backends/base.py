"""The backend interface: a ChatRequest in, a Completion out, and typed options per backend."""

from __future__ import annotations

import dataclasses
import types
import typing
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, ClassVar, Literal

from trajadapt.errors import BackendOptionError

Role = Literal["system", "user", "assistant"]
PrepareProgress = Callable[[str, int, int], None]  # (what, done, total)


@dataclass(frozen=True)
class ChatMessage:
    """One message of a conversation."""

    role: Role
    content: str


@dataclass(frozen=True)
class ChatRequest:
    """What is sent to a backend; backends ignore the fields they cannot honour."""

    messages: tuple[ChatMessage, ...]
    temperature: float = 0.0
    max_tokens: int = 1024
    seed: int | None = 0
    json_schema: Mapping[str, Any] | None = None
    grammar: str | None = None
    """GBNF text the answer must follow (llama.cpp's constrained decoding); ignored where unsupported."""
    on_text: Callable[[str], None] | None = field(default=None, compare=False)
    """Called with each piece of the answer as it is written, by backends that stream."""


@dataclass(frozen=True)
class Usage:
    """Token counts, when the backend reports them."""

    prompt_tokens: int | None = None
    completion_tokens: int | None = None
    cached_prompt_tokens: int | None = None


@dataclass(frozen=True)
class Completion:
    """A backend's answer: its text, the model that wrote it, token usage and timing."""

    text: str
    model: str
    usage: Usage = field(default_factory=Usage)
    duration_s: float = 0.0
    details: Mapping[str, Any] = field(default_factory=dict)


class Backend(ABC):
    """An LLM that completes chat requests. Subclasses set ``name`` and an ``Options`` dataclass."""

    name: ClassVar[str] = "backend"
    concurrent: ClassVar[bool] = True
    """False where one loaded model answers one request at a time: parallel jobs then need processes."""

    @dataclass(frozen=True)
    class Options:
        """A backend without options."""

    def __init__(self, options: Any = None) -> None:
        self.options: Any = options if options is not None else self.Options()

    @classmethod
    def from_options(cls, raw: Mapping[str, Any]) -> Backend:
        """Build the backend from string or typed options, refusing unknown ones."""
        return cls(parse_options(cls.Options, raw, cls.name))

    @property
    @abstractmethod
    def model(self) -> str:
        """The model name results and logs record."""

    @abstractmethod
    def complete(self, request: ChatRequest) -> Completion:
        """Answer ``request``.

        Raises:
            BackendError: or a subclass, with the next step in the message.
        """

    @property
    def follows_grammar(self) -> bool:
        """Whether answers keep to a request's grammar (constrained decoding).

        Then a request may admit only what one clause asks (``trajadapt.clauses``). Backends that send
        the grammar say so.
        """
        return False

    def describe(self) -> str:
        """One line for ``trajadapt backends``: where answers come from."""
        return f"{self.name}: model {self.model}"

    def prepare(self, progress: PrepareProgress | None = None) -> None:  # noqa: B027 - optional hook
        """Do slow one-time work (download, assemble, load) now, reporting progress, not on first use."""

    def close(self) -> None:  # noqa: B027 - optional hook, most backends hold nothing
        """Release resources held by the backend."""

    def process_options(self, processes: int) -> Any:
        """The options of one of ``processes`` copies of this backend running side by side."""
        return self.options


def parse_options(options_type: type[Any], raw: Mapping[str, Any], backend: str) -> Any:
    """Convert ``raw`` (values may be strings from the command line) into ``options_type``.

    Raises:
        BackendOptionError: an unknown option name or a value of the wrong type.
    """
    fields = {f.name: f for f in dataclasses.fields(options_type)}
    unknown = sorted(set(raw) - set(fields))
    if unknown:
        known = ", ".join(sorted(fields)) or "none"
        raise BackendOptionError(
            f"backend '{backend}' has no option {unknown[0]!r}; its options are: {known}"
        )
    hints = typing.get_type_hints(options_type)
    values = {name: _convert(value, hints[name], f"{backend} option {name!r}") for name, value in raw.items()}
    return options_type(**values)


def _convert(value: Any, hint: Any, where: str) -> Any:
    if typing.get_origin(hint) is Literal:
        choices = typing.get_args(hint)
        if value not in choices:
            raise BackendOptionError(f"{where}: {value!r} is not one of {', '.join(map(str, choices))}")
        return value
    if not isinstance(value, str):
        return value
    if value.lower() in ("none", "null") and _allows_none(hint):
        return None
    target = _concrete_type(hint)
    if target is str:
        return value
    try:
        if target is bool:
            return _parse_bool(value)
        return target(value) if target in (int, float, Path) else value
    except ValueError as exc:
        raise BackendOptionError(f"{where}: cannot read {value!r} as {target.__name__}") from exc


def _concrete_type(hint: Any) -> Any:
    args = [arg for arg in typing.get_args(hint) if arg is not type(None)]
    if isinstance(hint, types.UnionType) or typing.get_origin(hint) is typing.Union:
        return args[0] if args else str
    return hint


def _allows_none(hint: Any) -> bool:
    return type(None) in typing.get_args(hint)


def _parse_bool(value: str) -> bool:
    lowered = value.strip().lower()
    if lowered in ("1", "true", "yes", "on"):
        return True
    if lowered in ("0", "false", "no", "off"):
        return False
    raise ValueError(value)

"""The embedded default backend: Qwen2.5-Coder-1.5B-Instruct on llama.cpp, offline, on the CPU.

The model is loaded on first use and kept, one per process and settings, so that llama.cpp can
reuse the cached state of the prompt's fixed prefix from one request to the next.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from trajadapt.backends.base import Backend, ChatRequest, Completion, Usage
from trajadapt.errors import BackendUnavailable, DependencyNotInstalled, EmptyCompletion
from trajadapt.model_file import MODEL_FILENAME, ensure_model
from trajadapt.settings import default_home


@dataclass(frozen=True)
class LocalOptions:
    """Options of the ``local`` backend.

    Attributes:
        model_path: a GGUF file of your own; default: the embedded model, assembled on first use.
        cache_dir: where the embedded model is assembled (default: <trajadapt home>/models).
        n_threads: CPU threads for llama.cpp.
        n_ctx: context window in tokens.
        json_schema: constrain the answer to the plan/code JSON schema (slower per token).
    """

    model_path: Path | None = None
    cache_dir: Path | None = None
    n_threads: int = 2
    n_ctx: int = 4096
    json_schema: bool = False


ANSWER_SCHEMA = {
    "type": "object",
    "properties": {"high_level_plan": {"type": "string"}, "python_code": {"type": "string"}},
    "required": ["high_level_plan", "python_code"],
}

_models: dict[tuple[str, int, int], Any] = {}
_models_lock = threading.Lock()


def load_llama(model_path: Path, n_threads: int, n_ctx: int) -> Any:
    """Return the process's loaded model for these settings, loading it on first call.

    Raises:
        DependencyNotInstalled: llama-cpp-python is not installed.
        BackendUnavailable: the file cannot be loaded.
    """
    key = (str(model_path), n_threads, n_ctx)
    with _models_lock:
        if key not in _models:
            try:
                from llama_cpp import Llama
            except ImportError as exc:
                raise DependencyNotInstalled(
                    'the local backend needs llama-cpp-python; run: pip install "trajadapt[local]"'
                ) from exc
            try:
                _models[key] = Llama(
                    model_path=str(model_path), n_ctx=n_ctx, n_threads=n_threads, verbose=False
                )
            except (ValueError, RuntimeError) as exc:
                raise BackendUnavailable(f"llama.cpp cannot load {model_path}: {exc}") from exc
        return _models[key]


class LocalBackend(Backend):
    """Embedded Qwen2.5-Coder-1.5B on llama.cpp: no server, no key, no network."""

    name = "local"
    Options = LocalOptions  # type: ignore[assignment]

    def __init__(self, options: Any = None, llama: Any = None) -> None:
        super().__init__(options)
        self._llama = llama
        self._lock = threading.Lock()  # one llama.cpp context: one request at a time

    @property
    def model(self) -> str:
        """The GGUF file name."""
        path = self.options.model_path
        return Path(path).name if path else MODEL_FILENAME

    def describe(self) -> str:
        """Model and threads."""
        return f"local: {self.model} on llama.cpp, {self.options.n_threads} thread(s)"

    def model_path(self) -> Path:
        """The GGUF file to load: the user's (header-checked), or the verified embedded model."""
        if self.options.model_path is not None:
            path = Path(self.options.model_path).expanduser()
            if not path.is_file():
                raise BackendUnavailable(f"model_path {path} does not exist")
            return path
        cache_dir = Path(self.options.cache_dir or default_home() / "models")
        return ensure_model(cache_dir)

    def complete(self, request: ChatRequest) -> Completion:
        """Generate an answer with llama.cpp; timings split into prefill and generation."""
        llama = self._llama or load_llama(self.model_path(), self.options.n_threads, self.options.n_ctx)
        with self._lock:
            started = time.perf_counter()
            chunks, first_token_s = self._stream(llama, request)
            duration = time.perf_counter() - started
        text = "".join(chunks)
        if not text.strip():
            raise EmptyCompletion("the local model returned an empty answer; try again or rephrase")
        usage = _usage(llama, text)
        return Completion(
            text=text,
            model=self.model,
            usage=usage,
            duration_s=duration,
            details={"prefill_s": first_token_s, "generation_s": duration - first_token_s},
        )

    def _stream(self, llama: Any, request: ChatRequest) -> tuple[list[str], float]:
        arguments: dict[str, Any] = {
            "messages": [{"role": m.role, "content": m.content} for m in request.messages],
            "temperature": request.temperature,
            "max_tokens": request.max_tokens,
            "seed": request.seed if request.seed is not None else -1,
            "stream": True,
        }
        if self.options.json_schema:
            arguments["response_format"] = {"type": "json_object", "schema": ANSWER_SCHEMA}
        started = time.perf_counter()
        first_token_s = 0.0
        chunks: list[str] = []
        for chunk in llama.create_chat_completion(**arguments):
            piece = chunk["choices"][0]["delta"].get("content") or ""
            if piece and not chunks:
                first_token_s = time.perf_counter() - started
            if piece:
                chunks.append(piece)
        return chunks, first_token_s


def _usage(llama: Any, text: str) -> Usage:
    completion_tokens = len(llama.tokenize(text.encode("utf-8"), add_bos=False, special=True))
    context_tokens = int(getattr(llama, "n_tokens", 0))
    return Usage(
        prompt_tokens=max(context_tokens - completion_tokens, 0) or None,
        completion_tokens=completion_tokens,
    )

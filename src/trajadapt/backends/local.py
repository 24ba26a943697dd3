"""The embedded default backend: Qwen2.5-Coder-1.5B-Instruct on llama.cpp, offline, on the CPU.

The model is loaded on first use and kept, one per process and settings, so that llama.cpp can
reuse the cached state of the prompt's fixed prefix from one request to the next.
"""

from __future__ import annotations

import atexit
import os
import threading
import time
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any, Literal

from trajadapt.backends.base import Backend, ChatRequest, Completion, PrepareProgress, Usage
from trajadapt.backends.guided_decoding import decode_request, grammar_tokenizer
from trajadapt.backends.prompt_state import PromptStateCache
from trajadapt.errors import BackendRejected, BackendUnavailable, DependencyNotInstalled, EmptyCompletion
from trajadapt.llm.model_file import MODEL_FILENAME, ensure_model
from trajadapt.settings import default_home


@dataclass(frozen=True)
class LocalOptions:
    """Options of the ``local`` backend.

    Attributes:
        model_path: a GGUF file of your own; default: the embedded model, assembled on first use.
        cache_dir: where the embedded model is assembled (default: <trajadapt home>/models).
        n_threads: CPU threads that generate the answer (default: from the machine, see
            ``thread_layout``).
        n_threads_batch: CPU threads that read the prompt (default: every core).
        flash_attn: llama.cpp's flash attention (measured: no faster on CPU here, and it changes
            answers at temperature 0; off by default).
        n_ctx: context window in tokens.
        json_schema: constrain the answer to the plan/code JSON schema (slower per token).
        grammar: follow the request's grammar when it has one (skills mode: an answer made of this
            scene's objects and the skill library's calls); off: decode freely.
        prompt_cache: save llama.cpp's state after the fixed prompt to disk, so that a new process
            does not read the whole prompt again.
        decoder: who keeps the answer to the grammar: ``llguidance`` (the model's choice checked
            first, forced text fed in one batch; ``guided_decoding``) or ``llama.cpp`` (its grammar
            sampler, every token checked against the grammar and fed on its own: slower, kept to compare).
    """

    model_path: Path | None = None
    cache_dir: Path | None = None
    n_threads: int | None = None
    n_threads_batch: int | None = None
    flash_attn: bool = False
    n_ctx: int = 4096
    json_schema: bool = False
    grammar: bool = True
    prompt_cache: bool = True
    decoder: Literal["llguidance", "llama.cpp"] = "llguidance"


ANSWER_SCHEMA = {
    "type": "object",
    "properties": {"high_level_plan": {"type": "string"}, "python_code": {"type": "string"}},
    "required": ["high_level_plan", "python_code"],
}

_models: dict[tuple[str, ThreadLayout, int, bool], Any] = {}
_models_lock = threading.Lock()


@dataclass(frozen=True)
class ThreadLayout:
    """How many threads generate (one token at a time) and how many read the prompt (in batches)."""

    generate: int
    read_prompt: int


def thread_layout(
    cores: int | None = None, generate: int | None = None, read_prompt: int | None = None
) -> ThreadLayout:
    """The threads for this machine, unless given.

    Generating with a 1.5B Q4 model is bound by memory bandwidth, and llama.cpp's threads wait for each
    other at every token: with two threads on two cores, any other busy process (a simulation, the web
    server, a second bench process) stalls the answer threefold (measured: 20.5 -> 6.9 tokens/s), while
    one thread holds its speed (13.0 idle, 14.3 busy). So generation gets half the cores (one on two
    cores, at most four), and reading the prompt, which is compute-bound and short, gets them all.
    """
    count = cores or os.cpu_count() or 1
    return ThreadLayout(
        generate=generate or max(1, min(count // 2, 4)),
        read_prompt=read_prompt or count,
    )


@atexit.register
def _close_models() -> None:
    """Free loaded models before interpreter teardown (llama-cpp-python's __del__ fails late in it)."""
    with _models_lock:
        for llama in _models.values():
            llama.close()
        _models.clear()


def load_llama(model_path: Path, threads: ThreadLayout, n_ctx: int, flash_attn: bool = False) -> Any:
    """Return the process's loaded model for these settings, loading it on first call.

    Raises:
        DependencyNotInstalled: llama-cpp-python is not installed.
        BackendUnavailable: the file cannot be loaded.
    """
    key = (str(model_path), threads, n_ctx, flash_attn)
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
                    model_path=str(model_path),
                    n_ctx=n_ctx,
                    n_threads=threads.generate,
                    n_threads_batch=threads.read_prompt,
                    flash_attn=flash_attn,
                    verbose=False,
                )
            except (ValueError, RuntimeError) as exc:
                raise BackendUnavailable(f"llama.cpp cannot load {model_path}: {exc}") from exc
        return _models[key]


class LocalBackend(Backend):
    """Embedded Qwen2.5-Coder-1.5B on llama.cpp: no server, no key, no network."""

    name = "local"
    Options = LocalOptions  # type: ignore[assignment]
    concurrent = False

    def __init__(self, options: Any = None, llama: Any = None) -> None:
        super().__init__(options)
        self._llama = llama
        self._lock = threading.Lock()  # one llama.cpp context: one request at a time
        self._grammars: dict[str, Any] = {}
        self._prefix = ""  # the fixed first message the context was last used with

    @property
    def model(self) -> str:
        """The GGUF file name."""
        path = self.options.model_path
        return Path(path).name if path else MODEL_FILENAME

    @property
    def follows_grammar(self) -> bool:
        """llama.cpp constrains decoding to the request's grammar unless ``grammar`` is off."""
        return bool(self.options.grammar)

    @property
    def threads(self) -> ThreadLayout:
        """The thread layout this backend loads the model with."""
        return thread_layout(generate=self.options.n_threads, read_prompt=self.options.n_threads_batch)

    def process_options(self, processes: int) -> LocalOptions:
        """Options for one of ``processes`` model processes: the cores shared out, threads not given kept."""
        share = thread_layout(cores=max(1, (os.cpu_count() or 1) // max(processes, 1)))
        options: LocalOptions = self.options
        return replace(
            options,
            n_threads=options.n_threads or share.generate,
            n_threads_batch=options.n_threads_batch or share.read_prompt,
        )

    def describe(self) -> str:
        """Model and threads."""
        layout = self.threads
        return (
            f"local: {self.model} on llama.cpp, {layout.generate} thread(s) generating, "
            f"{layout.read_prompt} reading the prompt"
        )

    def model_path(self) -> Path:
        """The GGUF file to load: the user's, or the verified embedded model."""
        if self.options.model_path is not None:
            path = Path(self.options.model_path).expanduser()
            if not path.is_file():
                raise BackendUnavailable(f"model_path {path} does not exist")
            return path
        return ensure_model(self._cache_dir())

    def prepare(self, progress: PrepareProgress | None = None) -> None:
        """Assemble and verify the embedded model (first use only), then load it."""
        if self._llama is not None:
            return
        if self.options.model_path is None:
            report = (lambda done, total: progress("assembling the model", done, total)) if progress else None
            path = ensure_model(self._cache_dir(), report)
        else:
            path = self.model_path()
        if progress is not None:
            progress("loading the model", 0, 1)
        llama = self._load(path)
        if self.options.grammar and self.options.decoder == "llguidance":
            grammar_tokenizer(llama)
        if progress is not None:
            progress("loading the model", 1, 1)

    def _load(self, path: Path) -> Any:
        return load_llama(path, self.threads, self.options.n_ctx, self.options.flash_attn)

    def _cache_dir(self) -> Path:
        return Path(self.options.cache_dir or default_home() / "models")

    def _prompt_states(self, model: Path) -> PromptStateCache | None:
        if self._llama is not None or not self.options.prompt_cache:
            return None
        import llama_cpp

        key = f"{model.name}:{model.stat().st_size}:{self.options.n_ctx}:{llama_cpp.__version__}"
        return PromptStateCache(self._cache_dir() / "prompt-state", key)

    def complete(self, request: ChatRequest) -> Completion:
        """Generate an answer with llama.cpp; timings split into prefill and generation."""
        if self._llama is not None:
            llama, states = self._llama, None
        else:
            model = self.model_path()
            llama = self._load(model)
            states = self._prompt_states(model)
        prefix = request.messages[0].content if request.messages else ""
        with self._lock:
            started = time.perf_counter()
            if states and prefix != self._prefix and states.path_for(prefix).exists():
                llama.reset()  # back to a saved prefix (after an explanation): restore it, do not re-read it
            self._prefix = prefix
            restored = states.restore(llama, prefix) if states else 0
            if self._guided(request):
                text, usage, details = self._decode(llama, request)
            else:
                text, usage, details = self._stream(llama, request)
            duration = time.perf_counter() - started
            if states and not restored and not states.path_for(prefix).exists():
                states.save(llama, prefix)
        if not text.strip():
            raise EmptyCompletion("the local model returned an empty answer; try again or rephrase")
        return Completion(
            text=text,
            model=self.model,
            usage=usage,
            duration_s=duration,
            details={**details, "restored_prompt_tokens": restored},
        )

    def _guided(self, request: ChatRequest) -> bool:
        return bool(self.options.grammar and request.grammar and self.options.decoder == "llguidance")

    def _decode(self, llama: Any, request: ChatRequest) -> tuple[str, Usage, dict[str, Any]]:
        """The answer under the request's grammar with llguidance (``guided_decoding``)."""
        decoded = decode_request(llama, request)
        usage = Usage(prompt_tokens=decoded.prompt_tokens, completion_tokens=decoded.written_tokens)
        details = {
            "prefill_s": decoded.read_s,
            "generation_s": decoded.write_s,
            "fresh_prompt_tokens": decoded.fresh_tokens,
            "forced_tokens": decoded.forced_tokens,
            "decodes": decoded.decodes,
            "masked_steps": decoded.masked,
        }
        return decoded.text, usage, details

    def _compiled(self, grammar: str) -> Any:
        """llama.cpp's parsed grammar for this text, kept for the next request of the same scene."""
        if grammar not in self._grammars:
            from llama_cpp.llama_grammar import LlamaGrammar

            try:
                compiled = LlamaGrammar.from_string(grammar, verbose=False)
            except ValueError as exc:
                raise BackendRejected(f"llama.cpp cannot read the answer grammar: {exc}") from exc
            if len(self._grammars) >= 32:
                self._grammars.pop(next(iter(self._grammars)))
            self._grammars[grammar] = compiled
        return self._grammars[grammar]

    def _stream(self, llama: Any, request: ChatRequest) -> tuple[str, Usage, dict[str, Any]]:
        """The answer from llama-cpp-python's chat completion (free, JSON schema or its grammar sampler)."""
        arguments: dict[str, Any] = {
            "messages": [{"role": m.role, "content": m.content} for m in request.messages],
            "temperature": request.temperature,
            "max_tokens": request.max_tokens,
            "seed": request.seed if request.seed is not None else -1,
            "stream": True,
        }
        if self.options.grammar and request.grammar:
            arguments["grammar"] = self._compiled(request.grammar)
        elif self.options.json_schema:
            arguments["response_format"] = {"type": "json_object", "schema": ANSWER_SCHEMA}
        started = time.perf_counter()
        first_token_s = 0.0
        chunks: list[str] = []
        try:
            for chunk in llama.create_chat_completion(**arguments):
                piece = chunk["choices"][0]["delta"].get("content") or ""
                if piece and not chunks:
                    first_token_s = time.perf_counter() - started
                if piece:
                    chunks.append(piece)
                    if request.on_text is not None:
                        request.on_text(piece)
        except ValueError as exc:  # llama-cpp-python's only signal for a prompt longer than the context
            if "context window" not in str(exc):
                raise
            raise BackendRejected(
                f"the conversation is longer than the local model's context ({exc}); start a new session, "
                "or give the model a larger context with -o n_ctx 8192"
            ) from exc
        text = "".join(chunks)
        generation_s = time.perf_counter() - started - first_token_s
        return text, _usage(llama, text), {"prefill_s": first_token_s, "generation_s": generation_s}


def _usage(llama: Any, text: str) -> Usage:
    completion_tokens = len(llama.tokenize(text.encode("utf-8"), add_bos=False, special=True))
    context_tokens = int(getattr(llama, "n_tokens", 0))
    return Usage(
        prompt_tokens=max(context_tokens - completion_tokens, 0) or None,
        completion_tokens=completion_tokens,
    )

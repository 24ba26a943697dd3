"""Decoding under a grammar with llguidance: the model's own choice checked first, forced text fed at once.

llama.cpp's grammar sampler (in llama-cpp-python 0.3.36) checks every one of the 151,936 vocabulary
tokens against the grammar before each token it writes, and feeds the tokens one at a time even where
the grammar allows only one continuation (the JSON keys and ``t = get_trajectory()``). Here,
at temperature 0, the most likely token is taken and only checked (``validate_tokens``); the
vocabulary is masked only when the grammar refuses it, and the choice is the most likely token the
grammar accepts, as llama.cpp's sampler makes it.
Text the grammar forces (``compute_ff_tokens``) is then fed to the model as one batch: one decode
for several tokens. Above temperature 0 every step is masked before sampling.

Measured on six ovita-dev cases (2-core VM, one generating thread): writing a median 5.3 s instead
of 8.2 s, 52 model evaluations for 82 tokens (docs/benchmarks.md, "Issue #26").
"""

from __future__ import annotations

import codecs
import ctypes
import threading
import time
import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from trajadapt.backends.base import ChatRequest
from trajadapt.errors import BackendRejected, DependencyNotInstalled

_tokenizers: weakref.WeakKeyDictionary[Any, Any] = weakref.WeakKeyDictionary()
_tokenizers_lock = threading.Lock()


@dataclass(frozen=True)
class Sampling:
    """How tokens are chosen.

    Attributes:
        temperature: 0 takes the most likely allowed token; above 0 samples from the allowed ones.
        seed: the sampling seed (temperature above 0).
        check_first: at temperature 0, take the most likely token the grammar accepts (checked
            first, the mask computed only when it is refused: llama.cpp's sampler's choice, found
            faster); off takes the most likely token of llguidance's mask at every step, to compare.
        fast_forward: feed the text the grammar forces as one batch; off feeds it token by token
            as the model chooses it, to compare.
    """

    temperature: float = 0.0
    seed: int | None = None
    check_first: bool = True
    fast_forward: bool = True


@dataclass(frozen=True)
class Decoded:
    """One answer written under a grammar, and what it cost.

    Attributes:
        text: the answer.
        prompt_tokens: tokens of the whole prompt; ``fresh_tokens`` of them were read (the rest cached).
        written_tokens: tokens of the answer; ``forced_tokens`` of them were fed as forced text.
        decodes: model evaluations while writing (single tokens and forced batches).
        masked: steps where the vocabulary was masked (the model's first choice refused by the
            grammar; every step above temperature 0).
        read_s: reading the fresh prompt tokens; ``write_s``: writing the answer.
    """

    text: str
    prompt_tokens: int
    fresh_tokens: int
    written_tokens: int
    forced_tokens: int
    decodes: int
    masked: int
    read_s: float
    write_s: float


def grammar_tokenizer(llama: Any) -> Any:
    """The model's vocabulary as llguidance reads it, built once per loaded model (about 1 s).

    Raises:
        DependencyNotInstalled: llguidance is not installed.
    """
    with _tokenizers_lock:
        if llama not in _tokenizers:
            try:
                from llguidance import LLTokenizer
            except ImportError as exc:
                raise DependencyNotInstalled(
                    'decoding under a grammar needs llguidance; run: pip install "trajadapt[local]" '
                    "(or use -o decoder llama.cpp)"
                ) from exc
            import llama_cpp

            vocab = llama._model.vocab
            tokenize = ctypes.cast(llama_cpp.llama_cpp._lib.llama_tokenize, ctypes.c_void_p).value
            _tokenizers[llama] = LLTokenizer.from_llamacpp(  # type: ignore[attr-defined]
                tokens=_token_bytes(vocab),
                vocab_ptr=vocab,
                tokenize_fptr=tokenize,
                eos_token=llama_cpp.llama_vocab_eos(vocab),
                slices=None,
            )
        return _tokenizers[llama]


def _token_bytes(vocab: Any) -> list[bytes]:
    """Each token's bytes; control tokens marked with a leading 0xFF, as llguidance expects."""
    import llama_cpp

    buffer = ctypes.create_string_buffer(1024)
    tokens = []
    for token in range(llama_cpp.llama_vocab_n_tokens(vocab)):
        length = llama_cpp.llama_token_to_piece(vocab, token, buffer, len(buffer), 0, True)
        if length < 0:
            raise BackendRejected(f"token {token} of the model is longer than {len(buffer)} bytes")
        piece = buffer.raw[:length]
        attributes = llama_cpp.llama_vocab_get_attr(vocab, token)
        looks_special = piece.startswith(b"<") and piece.endswith(b">")
        special = attributes & llama_cpp.LLAMA_TOKEN_ATTR_CONTROL or (
            attributes & llama_cpp.LLAMA_TOKEN_ATTR_USER_DEFINED and looks_special
        )
        tokens.append(b"\xff" + piece if special else piece)
    return tokens


def grammar_matcher(tokenizer: Any, gbnf: str) -> Any:
    """A fresh llguidance matcher for a GBNF grammar.

    Raises:
        BackendRejected: the grammar cannot be read.
    """
    import llguidance

    try:
        grammar = llguidance.grammar_from("gbnf", gbnf)
    except ValueError as exc:
        raise BackendRejected(f"llguidance cannot read the answer grammar: {exc}") from exc
    matcher = llguidance.LLMatcher(tokenizer, grammar, log_level=0)
    if matcher.is_error():
        raise BackendRejected(f"llguidance cannot read the answer grammar: {matcher.get_error()}")
    return matcher


class DecodingModel(Protocol):
    """What decoding needs of a loaded model (``LlamaModel`` adapts llama-cpp-python's ``Llama``)."""

    context: int
    vocabulary: int
    end_token: int

    def read(self, prompt: Sequence[int]) -> tuple[int, np.ndarray]:
        """Keep the cached tokens that start ``prompt`` (never all) and read the rest.

        Returns how many were kept and the logits after the prompt.
        """
        ...

    def evaluate(self, tokens: list[int]) -> np.ndarray:
        """Feed written ``tokens`` (batched) and return the logits after the last of them."""
        ...

    @property
    def length(self) -> int:
        """Tokens in the context now."""
        ...


class LlamaModel:
    """llama-cpp-python's ``Llama`` as a ``DecodingModel`` (tied to the pinned version 0.3.36)."""

    def __init__(self, llama: Any) -> None:
        self.llama = llama
        self.context = int(llama.n_ctx())
        self.vocabulary = int(llama.n_vocab())
        self.end_token = int(llama.token_eos())

    @property
    def length(self) -> int:
        """Tokens in the context now."""
        return int(self.llama.n_tokens)

    def read(self, prompt: Sequence[int]) -> tuple[int, np.ndarray]:
        """Keep the context's tokens that start ``prompt`` (one at least is read), read the rest."""
        kept = 0
        for old, new in zip(self.llama.input_ids[: self.llama.n_tokens], prompt, strict=False):
            if old != new:
                break
            kept += 1
        kept = min(kept, len(prompt) - 1)
        self.llama.n_tokens = kept  # llama.eval drops the context past this point before it decodes
        self.llama.eval(list(prompt[kept:]))
        return kept, self._logits()

    def evaluate(self, tokens: list[int]) -> np.ndarray:
        """Feed written ``tokens`` (one batch per n_batch) with the generating threads only.

        llama.cpp would give any batch of two tokens or more the reading threads (every core), and
        a busy core beside the answer would then stall each batch of forced text.
        """
        import llama_cpp

        context = self.llama._ctx.ctx
        generate, read = (
            int(self.llama.context_params.n_threads),
            int(self.llama.context_params.n_threads_batch),
        )
        llama_cpp.llama_set_n_threads(context, generate, generate)
        try:
            self.llama.eval(tokens)
        finally:
            llama_cpp.llama_set_n_threads(context, generate, read)
        return self._logits()

    def _logits(self) -> np.ndarray:
        import llama_cpp

        pointer = llama_cpp.llama_get_logits_ith(self.llama._ctx.ctx, -1)
        return np.ctypeslib.as_array(pointer, shape=(self.vocabulary,))


def decode(
    model: DecodingModel,
    tokenizer: Any,
    prompt: Sequence[int],
    gbnf: str,
    max_tokens: int,
    sampling: Sampling = Sampling(),
    on_text: Callable[[str], None] | None = None,
) -> Decoded:
    """Write an answer to ``prompt`` (tokens) that keeps to the grammar ``gbnf``.

    The longest prefix of ``prompt`` already in the model's context is kept, the rest is read. Stops
    when the grammar is complete, at the end-of-text token where the grammar allows it, after
    ``max_tokens`` tokens, or when the context is full. ``on_text`` receives the answer as it grows.

    Raises:
        BackendRejected: the prompt does not fit the context, or the grammar cannot be read.
    """
    matcher = grammar_matcher(tokenizer, gbnf)
    if len(prompt) >= model.context:
        raise BackendRejected(
            f"the conversation ({len(prompt)} tokens) is longer than the local model's context "
            f"({model.context}); start a new session, or give the model a larger context with -o n_ctx 8192"
        )
    started = time.perf_counter()
    kept, logits = model.read(prompt)
    read_s = time.perf_counter() - started
    chooser = _Chooser(model.vocabulary, sampling)
    written: list[int] = []
    forced = decodes = 0
    text = _TextStream(tokenizer, on_text)
    while len(written) < max_tokens and model.length < model.context - 1:
        token = chooser.choose(logits, matcher)
        if token == model.end_token and matcher.is_accepting():
            break
        if not matcher.consume_token(token):
            break  # cannot happen for a token the mask allowed; stop rather than write past the grammar
        batch = [token, *(_forced(matcher) if sampling.fast_forward else [])]
        forced += len(batch) - 1
        written.extend(batch)
        text.add(batch)
        if matcher.is_stopped():
            break
        logits = model.evaluate(batch)
        decodes += 1
    return Decoded(
        text=text.finish(),
        prompt_tokens=len(prompt),
        fresh_tokens=len(prompt) - kept,
        written_tokens=len(written),
        forced_tokens=forced,
        decodes=decodes,
        masked=chooser.masked,
        read_s=read_s,
        write_s=time.perf_counter() - started - read_s,
    )


def decode_request(llama: Any, request: ChatRequest, sampling: Sampling | None = None) -> Decoded:
    """Answer ``request`` (messages, grammar, token limit, sampling, ``on_text``) with a loaded ``Llama``."""
    messages = [{"role": m.role, "content": m.content} for m in request.messages]
    return decode(
        LlamaModel(llama),
        grammar_tokenizer(llama),
        prompt_tokens(llama, messages),
        request.grammar or "",
        request.max_tokens,
        sampling or Sampling(request.temperature, request.seed),
        request.on_text,
    )


def _forced(matcher: Any) -> list[int]:
    """The tokens the grammar allows as the only continuation, consumed."""
    tokens: list[int] = matcher.compute_ff_tokens()
    if tokens and not matcher.consume_tokens(tokens):
        raise BackendRejected(f"llguidance refused its own forced tokens: {matcher.get_error()}")
    return tokens


class _Chooser:
    """Greedy (the first choice checked, masked only when refused) or sampled from the masked logits."""

    def __init__(self, vocabulary: int, sampling: Sampling) -> None:
        self.vocabulary = vocabulary
        self.sampling = sampling
        self.random = np.random.default_rng(sampling.seed)
        self.bitmask = np.zeros(((vocabulary + 31) // 32,), dtype=np.int32)
        self.masked = 0

    def choose(self, logits: np.ndarray, matcher: Any) -> int:
        if self.sampling.temperature <= 0:
            token = int(np.argmax(logits))
            if self.sampling.check_first and matcher.validate_tokens([token]) == 1:
                return token
            self.masked += 1
            best = int(np.argmax(self._masked(logits, matcher)))
            return self._best_accepted(logits, matcher, best) if self.sampling.check_first else best
        self.masked += 1
        scaled = self._masked(logits, matcher) / self.sampling.temperature
        weights = np.exp(scaled - scaled.max())
        return int(self.random.choice(self.vocabulary, p=weights / weights.sum()))

    @staticmethod
    def _best_accepted(logits: np.ndarray, matcher: Any, best: int) -> int:
        """The most likely token whose bytes the grammar accepts, as llama.cpp's sampler picks it.

        llguidance's mask keeps only the canonical tokens of text the grammar forces; a token that
        spells the same bytes otherwise is accepted too, and is taken where the model prefers it.
        """
        above = np.flatnonzero(logits > logits[best])
        for token in above[np.argsort(-logits[above], kind="stable")]:
            if matcher.validate_tokens([int(token)]) == 1:
                return int(token)
        return best

    def _masked(self, logits: np.ndarray, matcher: Any) -> np.ndarray:
        matcher.unsafe_compute_mask_ptr(self.bitmask.ctypes.data, self.bitmask.nbytes)
        allowed = np.unpackbits(self.bitmask.view(np.uint8), bitorder="little")[: self.vocabulary]
        return np.where(allowed.astype(bool), logits, -np.inf)


class _TextStream:
    """The answer's text from its tokens, passed on as it grows (UTF-8 split across tokens is kept whole)."""

    def __init__(self, tokenizer: Any, on_text: Callable[[str], None] | None) -> None:
        self.tokenizer = tokenizer
        self.on_text = on_text
        self.decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")
        self.parts: list[str] = []

    def add(self, tokens: list[int]) -> None:
        piece = self.decoder.decode(self.tokenizer.decode_bytes(tokens))
        if piece:
            self.parts.append(piece)
            if self.on_text is not None:
                self.on_text(piece)

    def finish(self) -> str:
        self.parts.append(self.decoder.decode(b"", final=True))
        return "".join(self.parts)


def prompt_tokens(llama: Any, messages: Sequence[dict[str, str]]) -> list[int]:
    """The chat prompt as llama-cpp-python's chat completion would tokenize it (the model's template)."""
    from llama_cpp.llama_chat_format import Jinja2ChatFormatter

    template = llama.metadata.get("tokenizer.chat_template")
    if not template:
        raise BackendRejected("this GGUF file has no chat template; use -o decoder llama.cpp")
    eos, bos = llama.token_eos(), llama.token_bos()
    formatter = Jinja2ChatFormatter(
        template=template,
        eos_token=llama._model.token_get_text(eos) if eos != -1 else "",
        bos_token=llama._model.token_get_text(bos) if bos != -1 else "",
        stop_token_ids=[eos],
    )
    result = formatter(messages=list(messages))  # type: ignore[arg-type]
    data = result.prompt.encode("utf-8")
    tokens: list[int] = llama.tokenize(data, add_bos=not result.added_special, special=True)
    return tokens


__all__ = [
    "Decoded",
    "DecodingModel",
    "LlamaModel",
    "Sampling",
    "decode",
    "decode_request",
    "grammar_matcher",
    "grammar_tokenizer",
    "prompt_tokens",
]

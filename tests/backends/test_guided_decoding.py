"""Decoding under a grammar with llguidance, against a scripted model over a small byte vocabulary."""

from __future__ import annotations

import hashlib
from collections.abc import Sequence

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.errors import BackendRejected
from trajadapt.llm.answer_grammar import answer_grammar

llguidance = pytest.importorskip("llguidance")

from trajadapt.backends.guided_decoding import Sampling, decode, grammar_matcher  # noqa: E402

WORDS = [
    b'{"high_level_plan": "', b'", "python_code": "', b"get_trajectory()", b"modified_trajectory",
    b"shift", b"scale_speed", b"detect_objects", b"(t, ", b"'left'", b"'up'", b"box", b"\\n", b" = ",
]  # fmt: skip
VOCABULARY = [bytes([value]) for value in range(256)] + WORDS + [b"<|end|>"]
END = len(VOCABULARY) - 1


class ByteTokenizer:
    """Longest match over VOCABULARY; what llguidance needs of a tokenizer."""

    eos_token_id = END
    bos_token_id = None
    tokens = [b"\xff" + VOCABULARY[END] if i == END else t for i, t in enumerate(VOCABULARY)]

    def __call__(self, data: bytes) -> list[int]:
        out, at = [], 0
        while at < len(data):
            best = max(
                (i for i, t in enumerate(VOCABULARY[:END]) if data.startswith(t, at)),
                key=lambda i: len(VOCABULARY[i]),
            )
            out.append(best)
            at += len(VOCABULARY[best])
        return out


def tokenizer() -> object:
    from llguidance._tokenizer import TokenizerWrapper

    return llguidance.LLTokenizer(TokenizerWrapper(ByteTokenizer()))


class ScriptedModel:
    """Wants to write ``wanted`` token by token, then random text; records every batch it is fed."""

    def __init__(self, wanted: Sequence[int] = (), seed: int = 0, context: int = 4096) -> None:
        self.wanted = list(wanted)
        self.seed = seed
        self.context = context
        self.vocabulary = len(VOCABULARY)
        self.end_token = END
        self.tokens: list[int] = []
        self.prompt_length = 0
        self.batches: list[list[int]] = []

    @property
    def length(self) -> int:
        return len(self.tokens)

    def read(self, prompt: Sequence[int]) -> tuple[int, np.ndarray]:
        kept = 0
        for old, new in zip(self.tokens, prompt, strict=False):
            if old != new:
                break
            kept += 1
        kept = min(kept, len(prompt) - 1)
        del self.tokens[kept:]
        self.prompt_length = len(prompt)
        return kept, self.evaluate(list(prompt[kept:]))

    def evaluate(self, tokens: list[int]) -> np.ndarray:
        self.batches.append(list(tokens))
        self.tokens.extend(tokens)
        written = self.tokens[self.prompt_length :]
        digest = hashlib.sha256(repr((self.seed, written)).encode()).digest()
        logits = np.random.default_rng(list(digest[:8])).normal(size=self.vocabulary).astype(np.float32)
        if len(written) < len(self.wanted) and written == self.wanted[: len(written)]:
            logits[self.wanted[len(written)]] = 50.0
        return logits


GRAMMAR = answer_grammar(("box",)).to_gbnf()
ANSWER = (
    '{"high_level_plan": "1) Go left.", "python_code": "t = get_trajectory()\\nt = shift(t, \'left\')'
    '\\nmodified_trajectory = t"}'
)


def test_a_model_that_wants_a_grammatical_answer_writes_it_with_forced_text_fed_in_batches() -> None:
    model = ScriptedModel(ByteTokenizer()(ANSWER.encode()) + [END])
    pieces: list[str] = []
    decoded = decode(model, tokenizer(), [1, 2, 3], GRAMMAR, 400, on_text=pieces.append)
    assert decoded.text == ANSWER and "".join(pieces) == ANSWER
    assert decoded.masked == 0 and decoded.forced_tokens > 0
    assert decoded.decodes < decoded.written_tokens  # forced tokens share a decode
    assert any(len(batch) > 1 for batch in model.batches[1:])
    assert decoded.fresh_tokens == 3 and decoded.prompt_tokens == 3


def test_text_outside_the_grammar_is_never_written() -> None:
    wrong = '{"high_level_plan": "1) Go.", "python_code": "import os'
    decoded = decode(ScriptedModel(ByteTokenizer()(wrong.encode())), tokenizer(), [1], GRAMMAR, 300)
    assert "import" not in decoded.text and decoded.masked > 0
    matcher = grammar_matcher(tokenizer(), GRAMMAR)
    assert matcher.consume_tokens(ByteTokenizer()(decoded.text.encode()))


@settings(max_examples=25, deadline=None)
@given(st.integers(min_value=0, max_value=10**6))
def test_each_chosen_token_is_the_most_likely_one_the_grammar_accepts(seed: int) -> None:
    """At temperature 0 the shortcut (check the argmax, mask only if refused) picks what llama.cpp's
    grammar sampler picks: the most likely token whose bytes the grammar accepts."""
    model = ScriptedModel(seed=seed)
    decode(model, tokenizer(), [5], GRAMMAR, 40)
    replay, matcher = ScriptedModel(seed=seed), grammar_matcher(tokenizer(), GRAMMAR)
    _, logits = replay.read([5])
    for batch in model.batches[1:]:
        accepted = [t for t in range(len(VOCABULARY)) if matcher.validate_tokens([t]) == 1]
        assert batch[0] == max(accepted, key=lambda t: logits[t])
        assert matcher.consume_tokens(batch)
        logits = replay.evaluate(batch)


@settings(max_examples=10, deadline=None)
@given(st.integers(min_value=0, max_value=10**6))
def test_masking_every_step_keeps_to_the_grammar(seed: int) -> None:
    masked = decode(ScriptedModel(seed=seed), tokenizer(), [5], GRAMMAR, 40, Sampling(check_first=False))
    assert grammar_matcher(tokenizer(), GRAMMAR).consume_tokens(ByteTokenizer()(masked.text.encode()))


@settings(max_examples=10, deadline=None)
@given(st.integers(min_value=0, max_value=10**6))
def test_sampling_keeps_to_the_grammar_and_repeats_with_its_seed(seed: int) -> None:
    sampling = Sampling(temperature=0.8, seed=seed)
    first = decode(ScriptedModel(seed=seed), tokenizer(), [5], GRAMMAR, 40, sampling)
    again = decode(ScriptedModel(seed=seed), tokenizer(), [5], GRAMMAR, 40, sampling)
    assert first.text == again.text
    assert grammar_matcher(tokenizer(), GRAMMAR).consume_tokens(ByteTokenizer()(first.text.encode()))


def test_the_cached_prompt_prefix_is_not_read_again() -> None:
    model = ScriptedModel(ByteTokenizer()(ANSWER.encode()))
    decode(model, tokenizer(), [1, 2, 3, 4], GRAMMAR, 400)
    before = len(model.batches)
    decoded = decode(model, tokenizer(), [1, 2, 3, 9, 9], GRAMMAR, 400)
    assert decoded.fresh_tokens == 2 and model.batches[before] == [9, 9]


def test_max_tokens_and_a_full_context_stop_the_answer() -> None:
    assert decode(ScriptedModel(seed=1), tokenizer(), [5], GRAMMAR, 7).written_tokens <= 7 + 20
    with pytest.raises(BackendRejected, match="-o n_ctx 8192"):
        decode(ScriptedModel(context=4), tokenizer(), [1, 2, 3, 4, 5], GRAMMAR, 10)
    short = decode(ScriptedModel(seed=1, context=12), tokenizer(), [1, 2], GRAMMAR, 400)
    assert short.prompt_tokens + short.decodes <= 12


def test_a_grammar_llguidance_cannot_read_is_a_backend_error() -> None:
    with pytest.raises(BackendRejected, match="llguidance cannot read"):
        grammar_matcher(tokenizer(), 'root ::= "a" missing-rule')


@pytest.mark.parametrize(
    "names",
    [("box",), ("Cancer magister", "book jacket"), ("O'Brien's mug", 'the "red" ball', "back\\slash"), ()],
)
def test_the_answer_grammars_of_odd_scenes_compile(names: tuple[str, ...]) -> None:
    from trajadapt.clauses import clause_answer_grammar, split_clauses

    matcher = grammar_matcher(tokenizer(), answer_grammar(names).to_gbnf())
    assert not matcher.is_error()
    clauses = split_clauses("go left by 0.2 and slow down near the box, then wait 3 steps", names)
    assert not grammar_matcher(tokenizer(), clause_answer_grammar(clauses, names).to_gbnf()).is_error()

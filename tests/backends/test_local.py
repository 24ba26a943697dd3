"""The local backend: message building and streaming against a fake llama.cpp; the real model when present."""

from __future__ import annotations

import importlib.util
import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.backends.conftest import needs_model
from trajadapt.backends.base import ChatMessage, ChatRequest
from trajadapt.backends.conformance import check_backend
from trajadapt.backends.local import ANSWER_SCHEMA, LocalBackend, LocalOptions
from trajadapt.errors import EmptyCompletion
from trajadapt.llm.model_file import PINNED_SHA256, verify_model_file
from trajadapt.model.case import Case
from trajadapt.sandbox.runner import Sandbox
from trajadapt.session import AdaptationSession, SessionSettings


class FakeLlama:
    """Records create_chat_completion calls and streams a canned answer in pieces."""

    def __init__(self, answer: str) -> None:
        self.answer = answer
        self.calls: list[dict[str, Any]] = []
        self.n_tokens = 0

    def create_chat_completion(self, **arguments: Any) -> Iterator[dict[str, Any]]:
        self.calls.append(arguments)
        self.n_tokens = 100 + len(self.answer.split())
        yield {"choices": [{"delta": {"role": "assistant"}}]}
        for word in self.answer.split(" "):
            yield {"choices": [{"delta": {"content": word + " "}}]}

    def tokenize(self, data: bytes, add_bos: bool = False, special: bool = False) -> list[int]:
        return list(range(len(data.split())))


REQUEST = ChatRequest(
    messages=(ChatMessage("system", "fixed"), ChatMessage("user", "go left")), temperature=0.0, seed=7
)


def test_messages_and_sampling_are_passed_through() -> None:
    fake = FakeLlama("OK then")
    completion = LocalBackend(LocalOptions(), llama=fake).complete(REQUEST)
    assert completion.text.strip() == "OK then"
    call = fake.calls[0]
    assert call["messages"] == [
        {"role": "system", "content": "fixed"},
        {"role": "user", "content": "go left"},
    ]
    assert call["temperature"] == 0.0 and call["seed"] == 7 and call["stream"] is True
    assert "response_format" not in call
    assert completion.usage.completion_tokens == 2 and completion.usage.prompt_tokens == 100
    assert set(completion.details) == {"prefill_s", "generation_s", "restored_prompt_tokens"}


def test_json_schema_mode() -> None:
    fake = FakeLlama("{}")
    LocalBackend(LocalOptions(json_schema=True), llama=fake).complete(REQUEST)
    assert fake.calls[0]["response_format"] == {"type": "json_object", "schema": ANSWER_SCHEMA}


class OverflowingLlama(FakeLlama):
    """Fails as llama-cpp-python 0.3.36 does when the prompt is longer than the context."""

    def create_chat_completion(self, **arguments: Any) -> Iterator[dict[str, Any]]:
        raise ValueError("Requested tokens (8532) exceed context window of 4096")


def test_a_prompt_longer_than_the_context_is_a_backend_error() -> None:
    from trajadapt.errors import BackendRejected

    with pytest.raises(BackendRejected, match="-o n_ctx 8192"):
        LocalBackend(LocalOptions(), llama=OverflowingLlama("")).complete(REQUEST)


def test_empty_answer() -> None:
    with pytest.raises(EmptyCompletion):
        LocalBackend(LocalOptions(), llama=FakeLlama("")).complete(REQUEST)


def test_conformance_with_fake() -> None:
    check_backend(LocalBackend(LocalOptions(), llama=FakeLlama("OK")))


def test_user_model_path_must_exist(tmp_path: Path) -> None:
    from trajadapt.errors import BackendUnavailable

    backend = LocalBackend(LocalOptions(model_path=tmp_path / "absent.gguf"))
    with pytest.raises(BackendUnavailable, match="does not exist"):
        backend.model_path()


@pytest.mark.local_model
@needs_model
def test_real_model_assembles_with_the_pinned_hash(real_model: Path) -> None:
    verify_model_file(real_model)
    assert real_model.stat().st_size > 1_000_000_000
    assert PINNED_SHA256 in (real_model.with_name(real_model.name + ".verified.json")).read_text()


@pytest.mark.local_model
@needs_model
def test_real_adaptation_parses_and_executes(simple_case: Case, real_model: Path) -> None:
    backend = LocalBackend(LocalOptions(model_path=real_model))
    with Sandbox() as sandbox:
        session = AdaptationSession(simple_case, backend, sandbox)
        plan = session.draft()
        assert plan.code.strip()
        result = session.approve()
    assert result.ok, result.error
    assert result.trajectory is not None and len(result.trajectory) >= 2
    assert json.dumps(result.to_dict())


def test_prepare_assembles_with_progress_then_loads(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import trajadapt.backends.local as local

    model = tmp_path / "m.gguf"
    model.write_bytes(b"GGUF")
    calls: list[str] = []

    def fake_ensure(cache_dir: Path, progress: Any = None) -> Path:
        if progress is not None:
            progress(50, 100)
            progress(100, 100)
        calls.append("ensure")
        return model

    monkeypatch.setattr(local, "ensure_model", fake_ensure)
    monkeypatch.setattr(local, "load_llama", lambda *args: calls.append("load"))
    monkeypatch.setattr(local, "grammar_tokenizer", lambda llama: calls.append("grammar tokenizer"))
    seen: list[tuple[str, int, int]] = []
    LocalBackend(LocalOptions(cache_dir=tmp_path)).prepare(
        lambda what, done, total: seen.append((what, done, total))
    )
    assert calls == ["ensure", "load", "grammar tokenizer"]  # the tokenizer is built while loading
    assert seen[:2] == [("assembling the model", 50, 100), ("assembling the model", 100, 100)]
    assert seen[-1] == ("loading the model", 1, 1)


def test_prepare_bar_prints_lines_off_a_terminal(capsys: pytest.CaptureFixture[str]) -> None:
    import sys

    from trajadapt.cli.console import PrepareBar

    bar = PrepareBar(sys.stderr)
    for done in range(0, 101, 5):
        bar("assembling the model", done, 100)
    lines = capsys.readouterr().err.splitlines()
    assert lines[0] == "assembling the model: 0%" and lines[-1] == "assembling the model: 100%"
    assert len(lines) == 11


def test_thread_layout_keeps_generation_off_half_the_cores() -> None:
    from trajadapt.backends.local import ThreadLayout, thread_layout

    assert thread_layout(cores=2) == ThreadLayout(generate=1, read_prompt=2)
    assert thread_layout(cores=1) == ThreadLayout(generate=1, read_prompt=1)
    assert thread_layout(cores=16) == ThreadLayout(generate=4, read_prompt=16)
    assert thread_layout(cores=2, generate=2, read_prompt=1) == ThreadLayout(generate=2, read_prompt=1)


def test_parallel_processes_share_the_cores() -> None:
    import os

    backend = LocalBackend(LocalOptions())
    shared = backend.process_options(processes=max(os.cpu_count() or 1, 1))
    assert shared.n_threads == 1 and shared.n_threads_batch == 1
    own = LocalBackend(LocalOptions(n_threads=3)).process_options(processes=2)
    assert own.n_threads == 3  # what the user set is kept


@pytest.mark.local_model
@needs_model
def test_bench_with_two_model_processes_gives_the_serial_results(
    real_model: Path, ovita_dir: Path, tmp_path: Path
) -> None:
    import shutil

    from trajadapt.bench.runner import BenchConfig, discover_cases, run_benchmark

    folder = tmp_path / "cases"
    folder.mkdir()
    for name in ("latte_10", "latte_0", "latte_32"):
        shutil.copy(ovita_dir / "latte_subset" / f"{name}.json", folder / f"{name}.json")
    cases = discover_cases([folder])
    options = LocalOptions(
        model_path=real_model, n_threads=1, n_threads_batch=1, cache_dir=tmp_path / "cache"
    )
    # Both runs start from the saved prompt state: a fresh context reads the fixed prefix together with
    # the first case in one batch, which can tip a near-tie token (seen: set_speed 0.5 vs 0.6).
    run_benchmark(
        cases[:1],
        LocalBackend(options),
        BenchConfig(out_dir=tmp_path / "warm", session=SessionSettings(repair_attempts=0)),
    )
    serial = run_benchmark(
        cases,
        LocalBackend(options),
        BenchConfig(out_dir=tmp_path / "serial", session=SessionSettings(repair_attempts=0)),
    )
    parallel = run_benchmark(
        cases,
        LocalBackend(options),
        BenchConfig(out_dir=tmp_path / "parallel", session=SessionSettings(repair_attempts=0), jobs=2),
    )
    assert [r["code"] for r in serial] == [r["code"] for r in parallel]
    assert [r["modified_trajectory"] for r in serial] == [r["modified_trajectory"] for r in parallel]


@pytest.mark.skipif(importlib.util.find_spec("llama_cpp") is None, reason="llama-cpp-python not installed")
def test_a_request_grammar_constrains_decoding_unless_turned_off() -> None:
    from dataclasses import replace

    from llama_cpp.llama_grammar import LlamaGrammar

    from trajadapt.llm.answer_grammar import answer_grammar

    request = replace(REQUEST, grammar=answer_grammar(("box",)).to_gbnf())
    fake = FakeLlama("{}")
    backend = LocalBackend(LocalOptions(json_schema=True, decoder="llama.cpp"), llama=fake)
    backend.complete(request)
    backend.complete(request)
    assert isinstance(fake.calls[0]["grammar"], LlamaGrammar) and "response_format" not in fake.calls[0]
    assert fake.calls[1]["grammar"] is fake.calls[0]["grammar"]  # parsed once per scene
    free = FakeLlama("{}")
    LocalBackend(LocalOptions(grammar=False), llama=free).complete(request)
    assert "grammar" not in free.calls[0]


def test_llama_cpp_streams_its_pieces_to_the_request() -> None:
    from dataclasses import replace

    pieces: list[str] = []
    LocalBackend(LocalOptions(), llama=FakeLlama("go left now")).complete(
        replace(REQUEST, on_text=pieces.append)
    )
    assert "".join(pieces).split() == ["go", "left", "now"]


def test_the_decoder_option_names_its_choices() -> None:
    from trajadapt.errors import BackendOptionError

    assert LocalBackend.from_options({"decoder": "llama.cpp"}).options.decoder == "llama.cpp"
    with pytest.raises(BackendOptionError, match="llguidance, llama.cpp"):
        LocalBackend.from_options({"decoder": "xgrammar"})


@pytest.mark.local_model
@needs_model
def test_llguidance_writes_what_llama_cpps_grammar_sampler_writes(
    simple_case: Case, real_model: Path
) -> None:
    """Checking the first choice and feeding forced text at once change no token of the answer."""
    from trajadapt.llm.answer_grammar import answer_grammar
    from trajadapt.model.geometry import AXIS_CONVENTIONS
    from trajadapt.prompts import first_messages

    messages = first_messages(simple_case, AXIS_CONVENTIONS["paper"], "skills", examples=3)
    grammar = answer_grammar(tuple(simple_case.scene.names())).to_gbnf()
    request = ChatRequest(messages=messages, max_tokens=300, grammar=grammar)
    answers = {}
    for decoder in ("llguidance", "llama.cpp"):
        backend = LocalBackend(LocalOptions(model_path=real_model, decoder=decoder, prompt_cache=False))
        answers[decoder] = backend.complete(request)
    assert answers["llguidance"].text == answers["llama.cpp"].text
    assert answers["llguidance"].details["forced_tokens"] > 0
    assert answers["llguidance"].details["decodes"] < (answers["llguidance"].usage.completion_tokens or 0)

"""The openai backend against a real HTTP server on 127.0.0.1: answers and every failure mapped."""

from __future__ import annotations

import socket
from collections.abc import Iterator

import pytest

from tests.mock_openai_server import MockServer, Reply, mock_openai_server
from trajadapt.backends.base import ChatMessage, ChatRequest
from trajadapt.backends.conformance import check_backend
from trajadapt.backends.openai_compat import OpenAICompatBackend
from trajadapt.backends.registry import get_backend
from trajadapt.errors import (
    BackendOptionError,
    BackendRejected,
    BackendTimeout,
    BackendUnavailable,
    EmptyCompletion,
)

REQUEST = ChatRequest(messages=(ChatMessage("system", "s"), ChatMessage("user", "u")), seed=3)


@pytest.fixture
def server() -> Iterator[MockServer]:
    with mock_openai_server() as state:
        yield state


def backend_for(server: MockServer, **options: str) -> OpenAICompatBackend:
    backend = get_backend("openai", {"base_url": server.base_url, "model": "qwen-test", **options})
    assert isinstance(backend, OpenAICompatBackend)
    return backend


def test_answer_usage_and_wire_format(server: MockServer) -> None:
    server.enqueue("hello")
    completion = backend_for(server).complete(REQUEST)
    assert completion.text == "hello" and completion.model == "qwen-test"
    assert completion.usage.prompt_tokens == 11 and completion.usage.completion_tokens == 7
    sent = server.requests[0]
    assert sent["messages"] == [{"role": "system", "content": "s"}, {"role": "user", "content": "u"}]
    assert sent["temperature"] == 0.0 and sent["seed"] == 3 and sent["model"] == "qwen-test"


def test_conformance(server: MockServer) -> None:
    server.enqueue("OK")
    check_backend(backend_for(server))


def test_openai_key_is_never_sent_to_another_server(
    server: MockServer, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("OPENAI_API_KEY", "sk-secret")
    server.enqueue("x")
    backend_for(server).complete(REQUEST)
    assert "sk-secret" not in server.headers[0].get("authorization", "")


def test_custom_key_variable(server: MockServer, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("MY_KEY", "abc")
    server.enqueue("x")
    backend_for(server, api_key_env="MY_KEY").complete(REQUEST)
    assert server.headers[0]["authorization"] == "Bearer abc"


def test_official_server_without_key_names_the_variable() -> None:
    with pytest.raises(BackendOptionError, match="OPENAI_API_KEY"):
        get_backend("openai", {}).complete(REQUEST)


@pytest.mark.parametrize(
    ("reply", "error", "words"),
    [
        (Reply(status=500), BackendUnavailable, "HTTP 500"),
        (Reply(status=503), BackendUnavailable, "HTTP 503"),
        (Reply(status=401), BackendRejected, "API key"),
        (Reply(status=404), BackendRejected, "model name"),
        (Reply(status=400, error="context too long"), BackendRejected, "context too long"),
        (Reply(status=429), BackendUnavailable, "rate-limiting"),
        (Reply(""), EmptyCompletion, "empty answer"),
        (Reply(None), EmptyCompletion, "empty answer"),
    ],
)
def test_failures_are_mapped(server: MockServer, reply: Reply, error: type[Exception], words: str) -> None:
    server.enqueue(reply)
    with pytest.raises(error, match=words):
        backend_for(server).complete(REQUEST)


def test_timeout(server: MockServer) -> None:
    server.enqueue(Reply("late", delay_s=1.5))
    with pytest.raises(BackendTimeout, match="did not answer within 0.3 s"):
        backend_for(server, timeout_s="0.3").complete(REQUEST)


def test_connection_refused() -> None:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    backend = get_backend("openai", {"base_url": f"http://127.0.0.1:{port}/v1"})
    with pytest.raises(BackendUnavailable, match="is the server running"):
        backend.complete(REQUEST)


def test_the_grammar_goes_in_the_named_field_only_when_asked(server: MockServer) -> None:
    from dataclasses import replace

    server.enqueue("a")
    server.enqueue("b")
    constrained = replace(REQUEST, grammar='root ::= "x"')
    backend_for(server).complete(constrained)
    backend_for(server, grammar_field="guided_grammar").complete(constrained)
    assert "grammar" not in server.requests[0] and "guided_grammar" not in server.requests[0]
    assert server.requests[1]["guided_grammar"] == 'root ::= "x"'

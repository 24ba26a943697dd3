"""Backend for any OpenAI-compatible chat server: OpenAI, Ollama, vLLM, the llama.cpp server."""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from typing import Any

import openai

from trajadapt.backends.base import Backend, ChatRequest, Completion, Usage
from trajadapt.errors import (
    BackendError,
    BackendOptionError,
    BackendRejected,
    BackendTimeout,
    BackendUnavailable,
    EmptyCompletion,
)

OPENAI_BASE_URL = "https://api.openai.com/v1"
CUSTOM_SERVER_KEY_ENV = "TRAJADAPT_API_KEY"


@dataclass(frozen=True)
class OpenAICompatOptions:
    """Options of the ``openai`` backend.

    Attributes:
        base_url: the server's ``/v1`` URL, e.g. ``http://127.0.0.1:11434/v1`` for Ollama.
        model: the model name the server knows.
        api_key_env: environment variable holding the key. Default: OPENAI_API_KEY for OpenAI
            itself, TRAJADAPT_API_KEY for other servers (your OpenAI key is never sent elsewhere).
        timeout_s: seconds to wait for an answer.
        json_mode: ask the server for a JSON object (response_format); not every server has it.
        grammar_field: send the request's answer grammar (GBNF) in this request field, for servers
            that constrain decoding with it: ``grammar`` for llama.cpp's server and llama-cpp-python's,
            ``guided_grammar`` for vLLM (xgrammar reads GBNF). Unset: no grammar is sent (OpenAI's
            API and Ollama have no such field).
    """

    base_url: str = OPENAI_BASE_URL
    model: str = "gpt-4o"
    api_key_env: str | None = None
    timeout_s: float = 120.0
    json_mode: bool = False
    grammar_field: str | None = None


class OpenAICompatBackend(Backend):
    """Chat completions over HTTP through the ``openai`` client."""

    name = "openai"
    Options = OpenAICompatOptions  # type: ignore[assignment]

    def __init__(self, options: Any = None) -> None:
        super().__init__(options)
        self._client: openai.OpenAI | None = None

    @property
    def model(self) -> str:
        """The model name sent to the server."""
        return str(self.options.model)

    def describe(self) -> str:
        """Server and model."""
        return f"openai: model {self.model} at {self.options.base_url}"

    @property
    def follows_grammar(self) -> bool:
        """A server follows the grammar only when ``grammar_field`` says where to send it."""
        return bool(self.options.grammar_field)

    def complete(self, request: ChatRequest) -> Completion:
        """Send ``request`` as one chat completion and map every failure to a BackendError."""
        started = time.perf_counter()
        try:
            response = self._get_client().chat.completions.create(**self._arguments(request))
        except openai.APIError as exc:
            raise self._map_error(exc) from exc
        text = (response.choices[0].message.content or "") if response.choices else ""
        if not text.strip():
            raise EmptyCompletion(
                f"{self.options.base_url} returned an empty answer for model '{self.model}'; "
                "try again, or raise max_tokens if the answer was cut"
            )
        return Completion(
            text=text,
            model=response.model or self.model,
            usage=_usage(response.usage),
            duration_s=time.perf_counter() - started,
        )

    def close(self) -> None:
        """Close the HTTP connection pool."""
        if self._client is not None:
            self._client.close()
            self._client = None

    def _arguments(self, request: ChatRequest) -> dict[str, Any]:
        arguments: dict[str, Any] = {
            "model": self.model,
            "messages": [{"role": m.role, "content": m.content} for m in request.messages],
            "temperature": request.temperature,
            "max_tokens": request.max_tokens,
        }
        if request.seed is not None:
            arguments["seed"] = request.seed
        if self.options.json_mode:
            arguments["response_format"] = {"type": "json_object"}
        if self.options.grammar_field and request.grammar:
            arguments["extra_body"] = {self.options.grammar_field: request.grammar}
        return arguments

    def _get_client(self) -> openai.OpenAI:
        if self._client is None:
            self._client = openai.OpenAI(
                base_url=self.options.base_url,
                api_key=self._api_key(),
                timeout=self.options.timeout_s,
                max_retries=0,
            )
        return self._client

    def _api_key(self) -> str:
        official = self.options.base_url.rstrip("/") == OPENAI_BASE_URL
        variable = self.options.api_key_env or ("OPENAI_API_KEY" if official else CUSTOM_SERVER_KEY_ENV)
        key = os.environ.get(variable, "")
        if key:
            return key
        if official:
            raise BackendOptionError(
                f"the openai backend needs an API key: set {variable}, or point it at your own "
                "server with -o base_url http://127.0.0.1:PORT/v1"
            )
        return "no-key"  # local servers (Ollama, llama.cpp, vLLM) accept any key

    def _map_error(self, exc: openai.APIError) -> BackendError:
        where = f"{self.options.base_url} (model '{self.model}')"
        if isinstance(exc, openai.APITimeoutError):
            return BackendTimeout(
                f"{where} did not answer within {self.options.timeout_s:g} s; "
                "raise -o timeout_s or check the server's load"
            )
        if isinstance(exc, openai.APIConnectionError):
            return BackendUnavailable(
                f"cannot reach {where}: {exc}; is the server running and the URL right?"
            )
        if isinstance(exc, openai.APIStatusError):
            return _map_status(exc, where)
        return BackendUnavailable(f"{where} failed: {exc}")


def _map_status(exc: openai.APIStatusError, where: str) -> BackendError:
    status = exc.status_code
    detail = str(exc.message)[:300]
    if status in (401, 403):
        return BackendRejected(f"{where} refused the API key (HTTP {status}): {detail}")
    if status == 404:
        return BackendRejected(
            f"{where} answered HTTP 404: {detail}; check the model name and that base_url ends in /v1"
        )
    if status == 429:
        return BackendUnavailable(f"{where} is rate-limiting (HTTP 429): {detail}; wait and retry")
    if status >= 500:
        return BackendUnavailable(f"{where} failed with HTTP {status}: {detail}; check the server log")
    return BackendRejected(f"{where} rejected the request (HTTP {status}): {detail}")


def _usage(usage: Any) -> Usage:
    if usage is None:
        return Usage()
    details = getattr(usage, "prompt_tokens_details", None)
    return Usage(
        prompt_tokens=getattr(usage, "prompt_tokens", None),
        completion_tokens=getattr(usage, "completion_tokens", None),
        cached_prompt_tokens=getattr(details, "cached_tokens", None) if details else None,
    )

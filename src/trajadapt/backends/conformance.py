"""Conformance kit for backends (like Gymnasium's check_env): run it on every backend you write."""

from __future__ import annotations

import time

from trajadapt.backends.base import Backend, ChatMessage, ChatRequest, Completion

PROBE_REQUEST = ChatRequest(
    messages=(
        ChatMessage("system", "You answer with one short word."),
        ChatMessage("user", "Say OK."),
    ),
    max_tokens=8,
)


def check_backend(backend: Backend) -> Completion:
    """Send the probe request and check that the answer has the promised shape.

    Raises:
        AssertionError: the backend broke its contract (wrong types, missing name or model).
        BackendError: the backend failed in the documented way.
    """
    assert isinstance(backend.name, str) and backend.name, "backend.name must be a non-empty str"
    assert isinstance(backend.model, str) and backend.model, "backend.model must be a non-empty str"
    completion = backend.complete(PROBE_REQUEST)
    assert isinstance(completion, Completion), f"complete() returned {type(completion).__name__}"
    assert isinstance(completion.text, str) and completion.text.strip(), "empty completion text"
    assert isinstance(completion.model, str), "Completion.model must be a str"
    assert completion.duration_s >= 0, "Completion.duration_s must be >= 0"
    return completion


def probe_backend(backend: Backend) -> str:
    """One line for ``trajadapt backends --check``: did the backend answer, and how fast."""
    started = time.perf_counter()
    completion = check_backend(backend)
    elapsed = time.perf_counter() - started
    return f"ok: {backend.describe()} answered {completion.text.strip()[:20]!r} in {elapsed:.1f} s"

"""Backend registry and options: names, suggestions, typed options with unknown ones refused."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from trajadapt.backends.base import ChatMessage, ChatRequest
from trajadapt.backends.conformance import check_backend
from trajadapt.backends.registry import get_backend, registered_backends
from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.errors import BackendOptionError, EmptyCompletion, UnknownBackend

REQUEST = ChatRequest(messages=(ChatMessage("user", "u"),))


def test_builtin_backends_are_registered() -> None:
    assert {"local", "openai", "scripted"} <= set(registered_backends())


def test_unknown_backend_suggests_the_closest() -> None:
    with pytest.raises(UnknownBackend, match="Did you mean 'openai'?"):
        get_backend("opnai")


def test_unknown_option_is_refused() -> None:
    with pytest.raises(BackendOptionError, match="has no option 'temprature'"):
        get_backend("openai", {"temprature": "0.1"})


def test_option_values_are_typed() -> None:
    backend = get_backend("openai", {"timeout_s": "12.5", "json_mode": "yes", "api_key_env": "none"})
    assert backend.options.timeout_s == 12.5 and backend.options.json_mode is True
    assert backend.options.api_key_env is None
    with pytest.raises(BackendOptionError, match="cannot read 'soon' as float"):
        get_backend("openai", {"timeout_s": "soon"})


def test_scripted_backend_from_file(tmp_path: Path) -> None:
    path = tmp_path / "answers.json"
    path.write_text(json.dumps({"answers": ["OK", {"high_level_plan": "1) a", "python_code": "x"}]}))
    backend = get_backend("scripted", {"answers": str(path)})
    assert isinstance(backend, ScriptedBackend)
    check_backend(backend)
    assert json.loads(backend.complete(REQUEST).text)["python_code"] == "x"
    with pytest.raises(EmptyCompletion, match="no answers left"):
        backend.complete(REQUEST)


def test_scripted_backend_bad_file(tmp_path: Path) -> None:
    with pytest.raises(BackendOptionError, match="scripted answers file: .*absent.json: file not found"):
        get_backend("scripted", {"answers": str(tmp_path / "absent.json")})

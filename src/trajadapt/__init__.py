"""trajadapt: adapt robot trajectories to natural-language instructions.

The public API is imported lazily so that light parts (the sandbox worker, the geometry) do not
pull in the LLM clients.
"""

from __future__ import annotations

import importlib
from typing import Any

__version__ = "0.1.0"

_EXPORTS = {
    "Trajectory": "trajadapt.model.trajectory",
    "Scene": "trajadapt.model.scene",
    "SceneObject": "trajadapt.model.scene",
    "Case": "trajadapt.model.case",
    "load_case": "trajadapt.model.case",
    "AdaptationSession": "trajadapt.session",
    "AdaptationResult": "trajadapt.session",
    "get_backend": "trajadapt.backends.registry",
    "Sandbox": "trajadapt.sandbox.runner",
    "TrajadaptError": "trajadapt.errors",
}

__all__ = sorted(_EXPORTS) + ["__version__"]


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(importlib.import_module(_EXPORTS[name]), name)
    raise AttributeError(f"module 'trajadapt' has no attribute {name!r}")

"""Run generated code isolated from the host: static check, restricted namespace, child process.

``Sandbox`` (``sandbox.runner``) is the host side; the child process imports only this package's
light modules, so the names below are imported when first used.
"""

from __future__ import annotations

import importlib
from typing import Any

_EXPORTS = {
    "Sandbox": "trajadapt.sandbox.runner",
    "SandboxLimits": "trajadapt.sandbox.runner",
    "SandboxResult": "trajadapt.sandbox.runner",
    "ExecutionOptions": "trajadapt.sandbox.runner",
    "check_code": "trajadapt.sandbox.guard",
    "check_skill_program": "trajadapt.sandbox.skill_program",
}
__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        return getattr(importlib.import_module(_EXPORTS[name]), name)
    raise AttributeError(f"module 'trajadapt.sandbox' has no attribute {name!r}")

"""The backend registry: names mapped to lazy ``module:Class`` entry points, plus plugins."""

from __future__ import annotations

import difflib
import importlib
from collections.abc import Mapping
from importlib.metadata import entry_points
from typing import Any

from trajadapt.backends.base import Backend
from trajadapt.errors import DependencyNotInstalled, UnknownBackend

ENTRY_POINT_GROUP = "trajadapt.backends"

BUILTIN_BACKENDS: dict[str, str] = {
    "local": "trajadapt.backends.local:LocalBackend",
    "openai": "trajadapt.backends.openai_compat:OpenAICompatBackend",
    "scripted": "trajadapt.backends.scripted:ScriptedBackend",
}


def registered_backends() -> dict[str, str]:
    """Every backend name and its entry point: the built-in ones and installed plugins.

    The built-ins are declared as entry points in trajadapt's own metadata, the way a plugin is;
    ``BUILTIN_BACKENDS`` keeps them when that metadata is missing (a source tree on PYTHONPATH).
    """
    backends = dict(BUILTIN_BACKENDS)
    for entry in entry_points(group=ENTRY_POINT_GROUP):
        backends.setdefault(entry.name, entry.value)
    return backends


def backend_class(name: str) -> type[Backend]:
    """Import and return the class registered under ``name``.

    Raises:
        UnknownBackend: with the closest registered name.
        DependencyNotInstalled: the backend's extra is not installed.
    """
    backends = registered_backends()
    if name not in backends:
        close = difflib.get_close_matches(name, backends, n=1)
        hint = f" Did you mean '{close[0]}'?" if close else ""
        raise UnknownBackend(f"Unknown backend '{name}'.{hint} Registered: {', '.join(sorted(backends))}.")
    module_name, _, class_name = backends[name].partition(":")
    try:
        module = importlib.import_module(module_name)
    except ImportError as exc:
        raise DependencyNotInstalled(
            f"backend '{name}' needs a package that is not installed ({exc.name}); "
            f'for the built-in ones run: pip install "trajadapt[local]"'
        ) from exc
    cls: type[Backend] = getattr(module, class_name)
    return cls


def get_backend(name: str, options: Mapping[str, Any] | None = None) -> Backend:
    """Build the backend registered under ``name`` with ``options``.

    Raises:
        UnknownBackend, BackendOptionError, DependencyNotInstalled: with the next step.
    """
    return backend_class(name).from_options(dict(options or {}))

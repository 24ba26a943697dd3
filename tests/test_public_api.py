"""The public API resolves, and importing the package stays light (no LLM client at import)."""

from __future__ import annotations

import subprocess
import sys

import trajadapt


def test_every_export_resolves() -> None:
    for name in trajadapt.__all__:
        assert getattr(trajadapt, name) is not None


def test_import_is_light() -> None:
    code = "import sys, trajadapt, trajadapt.sandbox.child; print('openai' in sys.modules, 'llama_cpp' in sys.modules)"
    output = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert output.split() == ["False", "False"]


def test_the_packages_export_what_callers_use() -> None:
    import trajadapt.backends as backends
    import trajadapt.sandbox as sandbox

    for module in (backends, sandbox):
        for name in module.__all__:
            assert getattr(module, name) is not None


def test_the_built_in_backends_are_registered_as_entry_points() -> None:
    from importlib.metadata import entry_points

    declared = {entry.name for entry in entry_points(group="trajadapt.backends")}
    assert {"local", "openai", "scripted"} <= declared

"""The restricted namespace generated code runs in: curated builtins, module proxies, bounded print.

Second layer of the sandbox, after the static check in ``guard``. Imports resolve only to the allowed
modules, and those are wrapped so that an attribute access hands back only a member on the module's
allow-list (``allowed_names``): no module that was not allowed, no file, memory or random-state helper.
"""

from __future__ import annotations

import builtins
import io
import math
import sys
from collections.abc import Callable, Mapping
from types import ModuleType
from typing import Any

import numpy as np

from trajadapt.sandbox.allowed_names import MODULE_MEMBERS
from trajadapt.sandbox.guard import ALLOWED_MODULES

SAFE_BUILTIN_NAMES = (
    "abs", "all", "any", "bool", "callable", "complex", "dict", "divmod", "enumerate", "filter",
    "float", "format", "frozenset", "int", "isinstance", "issubclass", "iter", "len", "list",
    "map", "max", "min", "next", "pow", "range", "repr", "reversed", "round", "set", "slice",
    "sorted", "str", "sum", "tuple", "zip", "True", "False", "None", "Ellipsis",
    "NotImplemented", "ArithmeticError", "AssertionError", "AttributeError", "Exception",
    "IndexError", "KeyError", "LookupError", "NameError", "NotImplementedError", "OverflowError",
    "RuntimeError", "StopIteration", "TypeError", "ValueError", "ZeroDivisionError",
)  # fmt: skip


class SafeModule:
    """A read-only view of an allowed module that serves only the members on its allow-list."""

    def __init__(self, module: ModuleType, name: str) -> None:
        object.__setattr__(self, "_module", module)
        object.__setattr__(self, "_name", name)

    def __getattr__(self, attribute: str) -> Any:
        name = object.__getattribute__(self, "_name")
        if attribute not in MODULE_MEMBERS[name]:
            raise AttributeError(f"{name}.{attribute} is not available in the sandbox")
        value = getattr(object.__getattribute__(self, "_module"), attribute)
        if isinstance(value, ModuleType):
            return _wrap_submodule(value, f"{name}.{attribute}")
        return value

    def __setattr__(self, attribute: str, value: Any) -> None:
        raise AttributeError("modules are read-only in the sandbox")

    def __dir__(self) -> list[str]:
        return sorted(MODULE_MEMBERS[object.__getattribute__(self, "_name")])

    def __repr__(self) -> str:
        return f"<sandboxed module {object.__getattribute__(self, '_name')}>"


def _wrap_submodule(module: ModuleType, name: str) -> SafeModule:
    if name not in ALLOWED_MODULES:
        raise AttributeError(f"module {name} is not available in the sandbox")
    return SafeModule(module, name)


def preload_modules() -> dict[str, SafeModule]:
    """Import every allowed module now (numpy loads some lazily) and wrap each one."""
    loaded: dict[str, SafeModule] = {}
    for name in sorted(ALLOWED_MODULES):
        module: ModuleType = math if name == "math" else np
        for part in name.split(".")[1:]:
            module = getattr(module, part)
        loaded[name] = SafeModule(module, name)
    return loaded


def make_import(modules: Mapping[str, SafeModule]) -> Callable[..., Any]:
    """Return an ``__import__`` that serves only the preloaded, wrapped modules.

    numpy's C code imports its own internal helpers lazily (``numpy._core._methods`` on the first
    ``.sum()``) through whatever ``__import__`` the running frame sees, so already-loaded numpy
    internals are passed through. Generated code cannot ask for them itself: the static check
    refuses import statements of those names and any use of ``__import__``.
    """

    def restricted_import(
        name: str,
        globals: Any = None,
        locals: Any = None,
        fromlist: Any = (),
        level: int = 0,
    ) -> Any:
        if not level and name.startswith("numpy._") and name in sys.modules:
            return builtins.__import__(name, globals, locals, fromlist, level)
        if level or name not in modules:
            raise ImportError(f"import of {name!r} is not allowed; only numpy and math")
        if fromlist:
            return modules[name]
        return modules[name.split(".")[0]]

    return restricted_import


class BoundedOutput:
    """Collects printed text up to a limit, then notes that the rest was cut."""

    def __init__(self, limit_chars: int) -> None:
        self.limit_chars = limit_chars
        self.buffer = io.StringIO()
        self.truncated = False

    def print(self, *values: Any, sep: str | None = " ", end: str | None = "\n", **_: Any) -> None:
        """Stand-in for ``print`` that writes into the bounded buffer."""
        if self.truncated:
            return
        text = (sep if sep is not None else " ").join(str(v) for v in values)
        text += end if end is not None else "\n"
        room = self.limit_chars - self.buffer.tell()
        if len(text) > room:
            self.buffer.write(text[: max(room, 0)])
            self.truncated = True
            return
        self.buffer.write(text)

    def text(self) -> str:
        """Everything printed, with a note when output was cut."""
        note = f"\n[output cut at {self.limit_chars} characters]" if self.truncated else ""
        return self.buffer.getvalue() + note


def make_builtins(modules: Mapping[str, SafeModule], output: BoundedOutput) -> dict[str, Any]:
    """The builtins generated code sees: safe names, the restricted import and the bounded print."""
    safe = {name: getattr(builtins, name) for name in SAFE_BUILTIN_NAMES}
    safe["__import__"] = make_import(modules)
    safe["print"] = output.print
    return safe

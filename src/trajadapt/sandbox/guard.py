"""Static check of generated code: the first of the sandbox's layers, run before anything executes.

It refuses imports other than the allowed modules, any name or attribute that starts with an
underscore (dunders, private members), any attribute outside the allow-list of ``allowed_names``
(array maths; no file, memory, random-state, frame or module access), dynamic evaluation (eval,
exec, getattr with built strings) and format strings that reach attributes.
Every place the syntax names an attribute or binds a name is looked at: ``a.b``, ``match`` class
patterns (``case C(__x__=v)``), capture names, keyword arguments, and format fields nested at any
depth inside format specs (``'{0:{1.x}}'``).

This layer is a convenience that gives the model a clear message; it is not the boundary. What passes
still runs with restricted builtins, in a child process under an unprivileged user, resource limits and
a seccomp allow-list that hold on their own (see ``lockdown`` and ``seccomp``).
"""

from __future__ import annotations

import ast
import string
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.sandbox.allowed_names import ALLOWED_ATTRIBUTES, MODULE_MEMBERS

ALLOWED_MODULES = frozenset(MODULE_MEMBERS)

FORBIDDEN_NAMES = frozenset(
    {
        "eval", "exec", "compile", "open", "input", "breakpoint", "help", "globals", "locals",
        "vars", "getattr", "setattr", "delattr", "hasattr", "memoryview", "super", "object",
        "type", "classmethod", "staticmethod", "property", "exit", "quit", "copyright",
        "credits", "license", "dir", "id",
    }
)  # fmt: skip

FORMAT_METHODS = frozenset({"format", "format_map"})


@dataclass(frozen=True)
class Violation:
    """Why the code was refused, and on which line."""

    line: int
    message: str


def check_code(source: str) -> Violation | None:
    r"""Return the first reason to refuse ``source``, or None when it may run.

    >>> check_code("import numpy as np\\nx = np.zeros(3)") is None
    True
    >>> check_code("import os").message
    "import of 'os' is not allowed; only numpy and math can be imported"
    """
    try:
        tree = ast.parse(source, filename="<generated>")
    except SyntaxError as exc:
        return Violation(exc.lineno or 0, f"syntax error: {exc.msg}")
    literal_format_calls = {
        id(node.func) for node in ast.walk(tree) if isinstance(node, ast.Call) and _is_format_call(node)
    }
    for node in ast.walk(tree):
        message = _node_violation(node, literal_format_calls)
        if message is not None:
            return Violation(getattr(node, "lineno", 0), message)
    return None


def _node_violation(node: ast.AST, literal_format_calls: set[int]) -> str | None:
    if isinstance(node, ast.Import | ast.ImportFrom):
        return _import_violation(node)
    if isinstance(node, ast.Name):
        return _name_violation(node.id)
    if isinstance(node, ast.Attribute):
        if node.attr in FORMAT_METHODS and id(node) not in literal_format_calls:
            return _format_violation(node) or "str.format may only be called, not passed around"
        return _attribute_violation(node.attr)
    if isinstance(node, ast.ClassDef):
        return "class definitions are not available in the sandbox; use functions"
    if isinstance(node, ast.MatchClass):
        return _first(_attribute_violation(attribute) for attribute in node.kwd_attrs)
    return _first(_name_violation(name) for name in _bound_names(node) if name.startswith("_"))


def _bound_names(node: ast.AST) -> list[str]:
    """The names a node binds or passes by keyword: definitions, arguments, imports, captures."""
    if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.MatchStar | ast.MatchAs):
        return [node.name] if node.name else []
    if isinstance(node, ast.arg):
        return [node.arg]
    if isinstance(node, ast.alias):
        return [node.name, node.asname or ""]
    if isinstance(node, ast.keyword):
        return [node.arg] if node.arg else []
    if isinstance(node, ast.MatchMapping):
        return [node.rest] if node.rest else []
    if isinstance(node, ast.Global | ast.Nonlocal):
        return list(node.names)
    return []


def _first(messages: Iterable[str | None]) -> str | None:
    return next((message for message in messages if message is not None), None)


def _import_violation(node: ast.Import | ast.ImportFrom) -> str | None:
    if isinstance(node, ast.ImportFrom):
        if node.level:
            return "relative imports are not allowed"
        if any(alias.name == "*" for alias in node.names):
            return f"'from {node.module} import *' is not allowed; import the names you use"
        imported = _first(_attribute_violation(alias.name) for alias in node.names)
        if imported is not None:  # 'from numpy import save' reads an attribute of the module
            return imported
        modules = [node.module or ""]
    else:
        modules = [alias.name for alias in node.names]
    for module in modules:
        if module not in ALLOWED_MODULES:
            return f"import of {module!r} is not allowed; only numpy and math can be imported"
    return None


def _name_violation(name: str) -> str | None:
    if name.startswith("_"):
        return f"names starting with '_' are not allowed: {name!r}"
    if name in FORBIDDEN_NAMES:
        return f"{name!r} is not available in the sandbox"
    return None


def _attribute_violation(attribute: str) -> str | None:
    if attribute.startswith("_"):
        return f"attributes starting with '_' are not allowed: '.{attribute}'"
    if attribute not in ALLOWED_ATTRIBUTES:
        return (
            f"'.{attribute}' is not available in the sandbox: numpy and math are limited to array "
            "maths, and no file, memory, frame or module access is allowed"
        )
    return None


def _is_format_call(node: ast.Call) -> bool:
    func = node.func
    return isinstance(func, ast.Attribute) and func.attr in FORMAT_METHODS and not _format_violation(func)


def _format_violation(attribute: ast.Attribute) -> str:
    """Explain why a ``.format`` use is refused; '' means it is a safe literal template."""
    template = attribute.value
    if not isinstance(template, ast.Constant) or not isinstance(template.value, str):
        return "str.format may only be called on a literal string; use an f-string"
    try:
        fields = _format_fields(template.value)
    except (ValueError, RecursionError) as exc:
        return f"bad format string: {exc}"
    if any("." in field or "[" in field for field in fields):
        return "format fields may not access attributes or items; use an f-string"
    return ""


def _format_fields(template: str, depth: int = 0) -> list[str]:
    """Every field name of a format template, including those nested in format specs."""
    if depth > 2:  # str.format itself refuses deeper nesting ("Max string recursion exceeded")
        raise ValueError("format specs nested too deep")
    fields: list[str] = []
    for _, field, spec, _ in string.Formatter().parse(template):
        if field is not None:
            fields.append(field)
        if spec and "{" in spec:
            fields += _format_fields(spec, depth + 1)
    return fields

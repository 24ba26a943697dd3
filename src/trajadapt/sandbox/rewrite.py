"""Repairs of generated code whose intent is unambiguous, applied to its syntax tree before it runs.

A small model often calls a skill and drops its result (``spiral(t, 0.1)`` instead of
``t = spiral(t, 0.1)``); skills return a new trajectory, so the call would do nothing. Such a bare
call whose first argument is a plain variable is rewritten to assign the result back to that
variable, and a note tells the reviewer.
"""

from __future__ import annotations

import ast
from collections.abc import Collection


def assign_discarded_results(tree: ast.Module, functions: Collection[str]) -> list[str]:
    """Rewrite ``f(var, ...)`` statements (f in ``functions``) to ``var = f(var, ...)`` in place.

    Returns:
        One note per rewritten statement.
    """
    notes: list[str] = []
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if not isinstance(body, list):
            continue
        for index, statement in enumerate(body):
            target = _discarded_skill_call(statement, functions)
            if target is None:
                continue
            assign = ast.Assign(targets=[ast.Name(target, ast.Store())], value=statement.value)
            body[index] = ast.copy_location(assign, statement)
            notes.append(
                f"line {statement.lineno}: the result of {_name(statement)}() was not kept; "
                f"assigned it to '{target}'"
            )
    ast.fix_missing_locations(tree)
    return notes


def _discarded_skill_call(statement: ast.stmt, functions: Collection[str]) -> str | None:
    if not isinstance(statement, ast.Expr) or not isinstance(statement.value, ast.Call):
        return None
    call = statement.value
    if not isinstance(call.func, ast.Name) or call.func.id not in functions or not call.args:
        return None
    first = call.args[0]
    return first.id if isinstance(first, ast.Name) else None


def _name(statement: ast.stmt) -> str:
    call = statement.value  # type: ignore[attr-defined]
    return str(call.func.id)

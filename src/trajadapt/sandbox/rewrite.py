"""Repairs of generated code whose intent is unambiguous, applied to its syntax tree before it runs.

A small model often calls a skill and drops its result (``spiral(t, 0.1)`` instead of
``t = spiral(t, 0.1)``); skills return a new trajectory, so the call would do nothing. Such a bare
call whose first argument is a plain variable is rewritten to assign the result back to that
variable, and a note tells the reviewer.

A shift and a closer/further step in one program ask both ("go up by 0.2 and a bit closer to the
table"), but run one after the other the second undoes part of the first: closer to a table below
pulls the path down again; "the path up a little, the goal down a little" left the goal where it
was. ``measure_from_original`` runs such steps after the shifts, measured from the original path:
distances promised from it and reached across the shift, an end moved beyond where it was.
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


SHIFTS = frozenset({"shift"})
MEASURED = frozenset({"move_closer", "move_away", "shift_goal", "shift_start"})
"""Steps that take ``reference=``: their promise is kept from the original path across a shift."""


def measure_from_original(tree: ast.Module) -> list[str]:
    """Run closer/further and end steps after the whole-path shifts they sit beside, from the original.

    Applies to a run of consecutive ``t = skill(t, ...)`` statements on one variable, made of
    ``shift`` and ``MEASURED`` steps only (both present): the measured steps move after the last
    shift and get ``reference=get_trajectory()``. Anything else is left as written.

    Returns:
        One note per step changed.
    """
    notes: list[str] = []
    for start, end in _step_runs(tree.body):
        run = tree.body[start:end]
        names = [_skill(statement) for statement in run]
        if not (SHIFTS & set(names) and MEASURED & set(names)):
            continue
        measured = [s for s, name in zip(run, names, strict=True) if name in MEASURED]
        if any(_has_keyword(s, "reference") for s in measured):
            continue
        for statement in measured:
            call = statement.value  # type: ignore[attr-defined]
            reference = ast.Call(ast.Name("get_trajectory", ast.Load()), [], [])
            call.keywords.append(ast.keyword("reference", reference))
            notes.append(
                f"line {statement.lineno}: {call.func.id}() measured from the original path, after "
                "the shift, so that neither undoes the other"
            )
        tree.body[start:end] = [s for s in run if s not in measured] + measured
    ast.fix_missing_locations(tree)
    return notes


def _step_runs(body: list[ast.stmt]) -> list[tuple[int, int]]:
    """[start, end) of each run of shift / measured steps on one variable.

    Lines that neither assign nor read the variable (``table = detect_objects('table')``) may sit
    between the steps; a run starts and ends with a step.
    """
    runs: list[tuple[int, int]] = []
    index = 0
    while index < len(body):
        variable = _step_variable(body[index])
        if variable is None:
            index += 1
            continue
        end = last = index + 1
        while end < len(body) and (_step_variable(body[end]) == variable or _apart(body[end], variable)):
            end += 1
            if _step_variable(body[end - 1]) == variable:
                last = end
        runs.append((index, last))
        index = last
    return runs


def _apart(statement: ast.stmt, variable: str) -> bool:
    """Whether a line leaves ``variable`` alone: it assigns another name and does not read it."""
    return (
        isinstance(statement, ast.Assign)
        and all(isinstance(target, ast.Name) and target.id != variable for target in statement.targets)
        and not any(isinstance(node, ast.Name) and node.id == variable for node in ast.walk(statement.value))
    )


def _step_variable(statement: ast.stmt) -> str | None:
    """``t`` for ``t = skill(t, ...)`` with skill a shift or a measured step, else None."""
    if _skill(statement) not in SHIFTS | MEASURED:
        return None
    target = statement.targets[0]  # type: ignore[attr-defined]
    first = statement.value.args[0]  # type: ignore[attr-defined]
    if isinstance(target, ast.Name) and isinstance(first, ast.Name) and target.id == first.id:
        return target.id
    return None


def _skill(statement: ast.stmt) -> str | None:
    """The skill a ``name = skill(arg, ...)`` statement calls, else None."""
    if not (isinstance(statement, ast.Assign) and len(statement.targets) == 1):
        return None
    call = statement.value
    if isinstance(call, ast.Call) and isinstance(call.func, ast.Name) and call.args:
        return call.func.id
    return None


def _has_keyword(statement: ast.stmt, name: str) -> bool:
    return any(k.arg == name for k in statement.value.keywords)  # type: ignore[attr-defined]

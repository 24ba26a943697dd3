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

"Fly over the cycle, then finish 0.3 further right" came back as ``pass_over`` then ``shift_goal``:
the goal's move dragged the pass off the cycle. A step that puts the path through a point keeps its
promise only when nothing moves the path after it: ``passes_last`` runs such steps after the moves
beside them.

"Stay at least 1 m away from the bottle and route a bit closer to the table" came back as ``avoid``
of the bottle then ``move_closer`` to the table, which brought the path back to 0.29 from the bottle.
A limit (a clearance, a height bound) keeps its promise only when no move runs after it:
``limits_last`` runs such steps after the moves beside them that name none of their objects.

"Smooth out the wiggles and bring it nearer to the quill" came back as ``smooth`` then
``move_closer``, and the move's bend left the path rougher than the original. A smoothing keeps its
promise only when nothing reshapes the path after it: ``smoothing_last`` runs it after the moves
beside it (a limit, a pass or a weave still runs after the smoothing, which would blunt them).
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Collection

from trajadapt.code_parse import SPEED_STEPS, detected_names


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
    for start, end in _step_runs(tree.body, SHIFTS | MEASURED):
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


PASSES = frozenset({"pass_through", "pass_over"})
"""Steps that put the path through a point: a move after them takes the path off it."""
MOVES = frozenset(
    {"shift", "shift_goal", "shift_start", "shift_part", "lift_middle", "reach", "move_closer", "move_away"}
)
"""Steps that move the path (or an end) by an amount or to an end point, and so may run before a pass."""
SPEEDS = frozenset(SPEED_STEPS)
"""Steps that change the speed alone: they may sit among the others in any order."""


def passes_last(tree: ast.Module) -> list[str]:
    """Run the steps that pass through a point after the moves that follow them (see the module).

    Applies to a run of consecutive ``t = skill(t, ...)`` statements on one variable made of
    ``PASSES``, ``MOVES`` and ``SPEEDS`` steps only, where a move follows a pass: the passes go to
    the end of the run, in their order. Anything else is left as written.

    Returns:
        One note per step moved.
    """
    return _last_in_their_runs(tree, PASSES, MOVES, "the path still passes the point")


LIMITS = frozenset({"avoid", "stay_above", "stay_below"})
"""Steps that set a limit: a clearance from objects, a height bound."""
FREE_MOVES = frozenset(
    {"shift", "shift_goal", "shift_start", "shift_part", "lift_middle", "move_closer", "move_away"}
    | {"zigzag", "smooth", "scale_about", "rotate", "exaggerate_curve"}
)
"""Moves that may run before a limit: none ends the path at a point or puts it through one (a smoothing
after a clearance pulls the path back into it: "keep 0.2 from the cake and smooth the path out")."""


def limits_last(tree: ast.Module) -> list[str]:
    """Run the limit steps after the moves that follow them (see the module).

    Applies to a run of consecutive ``t = skill(t, ...)`` statements on one variable made of
    ``LIMITS``, ``FREE_MOVES`` and ``SPEEDS`` steps only, where a move follows a limit and no move
    names an object a limit keeps clear of (``avoid`` of the box, then ``move_closer`` to the box,
    contradict each other and are left as written): the limits go to the end of the run, in their
    order. Anything else is left as written.

    Returns:
        One note per step moved.
    """
    return _last_in_their_runs(tree, LIMITS, FREE_MOVES, "its limit still holds", _names_a_kept_clear_object)


def _names_a_kept_clear_object(run: list[ast.stmt], limits: list[ast.stmt]) -> bool:
    """Whether a step of the run other than the limits names an object a limit keeps clear of."""
    kept_clear = {name for statement in limits for name in detected_names(statement)}
    return any(kept_clear & set(detected_names(s)) for s in run if s not in limits)


def _last_in_their_runs(
    tree: ast.Module,
    last: frozenset[str],
    moves: frozenset[str],
    so_that: str,
    left_as_written: Callable[[list[ast.stmt], list[ast.stmt]], bool] = lambda run, steps: False,
) -> list[str]:
    """Move the ``last`` steps of each run (with ``moves`` and speed steps) after a move that follows them."""
    notes: list[str] = []
    for start, end in _step_runs(tree.body, last | moves | SPEEDS):
        run = tree.body[start:end]
        names = [_skill(statement) for statement in run]
        first = next((i for i, name in enumerate(names) if name in last), None)
        if first is None or not any(name in moves for name in names[first:]):
            continue
        moved = [s for s, name in zip(run, names, strict=True) if name in last]
        if left_as_written(run, moved):
            continue
        notes += [
            f"line {statement.lineno}: {_skill(statement)}() runs after the moves written after it, "
            f"so that {so_that}"
            for statement in moved
        ]
        tree.body[start:end] = [s for s in run if s not in moved] + moved
    ast.fix_missing_locations(tree)
    return notes


def _step_runs(body: list[ast.stmt], skills: frozenset[str]) -> list[tuple[int, int]]:
    """[start, end) of each run of ``skills`` steps on one variable.

    Lines that neither assign nor read the variable (``table = detect_objects('table')``) may sit
    between the steps; a run starts and ends with a step.
    """
    runs: list[tuple[int, int]] = []
    index = 0
    while index < len(body):
        variable = _step_variable(body[index], skills)
        if variable is None:
            index += 1
            continue
        end = last = index + 1
        while end < len(body) and (
            _step_variable(body[end], skills) == variable or _apart(body[end], variable)
        ):
            end += 1
            if _step_variable(body[end - 1], skills) == variable:
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


def _step_variable(statement: ast.stmt, skills: frozenset[str]) -> str | None:
    """``t`` for ``t = skill(t, ...)`` with skill one of ``skills``, else None."""
    if _skill(statement) not in skills:
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


SMOOTHING = frozenset({"smooth"})
"""Steps that smooth the path out: a move after them brings its bends back."""
RESHAPING = MOVES | frozenset({"rotate", "scale_about"})
"""Moves a smoothing runs after. Not a pass, a weave or a curve asked more (``pass_through``,
``pass_over``, ``zigzag``, ``exaggerate_curve``): each is a shape asked on purpose, which a smoothing
after it would blunt (a pass would miss its point, a stated gap over an object close in)."""


def smoothing_last(tree: ast.Module) -> list[str]:
    """Run the smoothing steps after the moves that follow them (see the module).

    Applies to a run of consecutive ``t = skill(t, ...)`` statements on one variable made of
    ``SMOOTHING``, ``RESHAPING`` and ``SPEEDS`` steps only, where a move follows a smoothing: the
    smoothings go to the end of the run. A limit step or a pass ends a run, so it stays after the
    smoothing (run this after ``limits_last``).

    Returns:
        One note per step moved.
    """
    return _last_in_their_runs(tree, SMOOTHING, RESHAPING, "the path it leaves is smooth")

"""Parsing generated code from several threads at once.

CPython 3.11 before 3.11.8 can fail ``ast.parse`` called from several threads at the same time
("AST constructor recursion depth mismatch", python/cpython#106905); the review server reads plans
on many threads. Every host-side reader of generated code parses through ``parse_code``.
"""

from __future__ import annotations

import ast
import re
import threading
from collections.abc import Collection

from trajadapt.model.geometry import DIRECTION_SYNONYMS

_PARSE_LOCK = threading.Lock()


MAX_DEPTH = 200
"""Deeper syntax trees are refused: skill code is a few levels deep, and the readers walk trees
recursively (3,000 chained ``+`` or 50,000 unary minus would overflow the stack)."""


def parse_code(source: str) -> ast.Module:
    """``ast.parse(source)``, one thread at a time, refused past ``MAX_DEPTH`` levels.

    Raises:
        SyntaxError: the source is not Python, or too deeply nested to read.
    """
    with _PARSE_LOCK:
        try:
            tree = ast.parse(source)
        except (RecursionError, MemoryError) as exc:
            raise SyntaxError(f"the code is too deeply nested to read ({type(exc).__name__})") from exc
    if _depth(tree) > MAX_DEPTH:
        raise SyntaxError(f"the code is nested more than {MAX_DEPTH} levels deep")
    return tree


def _depth(tree: ast.AST) -> int:
    """The deepest level of the tree, counted without recursion."""
    deepest, stack = 0, [(tree, 1)]
    while stack:
        node, level = stack.pop()
        deepest = max(deepest, level)
        if level <= MAX_DEPTH:
            stack.extend((child, level + 1) for child in ast.iter_child_nodes(node))
    return deepest


def assigned_call(line: str) -> tuple[ast.Module, ast.Call, str] | None:
    """The parsed line, its call and the called name, for a line ``name = function(...)``; else None."""
    try:
        tree = parse_code(line.strip())
    except SyntaxError:
        return None
    if len(tree.body) != 1 or not isinstance(tree.body[0], ast.Assign):
        return None
    call = tree.body[0].value
    if isinstance(call, ast.Call) and isinstance(call.func, ast.Name):
        return tree, call, call.func.id
    return None


def called_name(line: str) -> str | None:
    """The function a line ``name = function(...)`` calls, or None for any other line."""
    found = assigned_call(line)
    return found[2] if found is not None else None


def call_of(line: str, names: tuple[str, ...]) -> ast.Call | None:
    """The call of a line ``name = function(...)`` when ``function`` is one of ``names``."""
    found = assigned_call(line)
    return found[1] if found is not None and found[2] in names else None


def direction_argument(call: ast.Call | None) -> str | None:
    """The canonical direction of a call's second argument ('upwards' -> 'up'), if it is a direction word."""
    if call is None or len(call.args) < 2 or not isinstance(call.args[1], ast.Constant):
        return None
    return DIRECTION_SYNONYMS.get(str(call.args[1].value).strip().lower())


def named_argument(call: ast.Call, name: str, position: int) -> ast.expr | None:
    """The argument a call passes as ``name=`` or at ``position``, if it passes one."""
    keyword = next((k.value for k in call.keywords if k.arg == name), None)
    return keyword if keyword is not None else call.args[position] if len(call.args) > position else None


def written_factor(call: ast.Call) -> tuple[ast.Constant, float] | None:
    """A ``scale_speed`` factor (second argument or ``factor=``) written as a plain number, and its value."""
    node = named_argument(call, "factor", 1)
    if not isinstance(node, ast.Constant) or (value := signed_number(node)) is None:
        return None
    return node, value


def extension_direction(call: ast.Call | None) -> str | None:
    """The canonical direction an ``extend`` call gives (third argument or ``direction=``), if a word."""
    node = None if call is None else named_argument(call, "direction", 2)
    return DIRECTION_SYNONYMS.get(str(node.value).strip().lower()) if isinstance(node, ast.Constant) else None


def part_argument(call: ast.Call) -> str | None:
    """The part word a ``shift_part`` call names (its fourth argument or ``part=``), if a word."""
    node = named_argument(call, "part", 3)
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None


def detected_name(node: ast.expr) -> str | None:
    """The name in ``detect_objects('<name>')``, or None for any other expression.

    The midpoint of an object and itself (``midpoint(detect_objects('loaf'), detect_objects('loaf'))``,
    written for "slow down around the loaf") is that object.
    """
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "midpoint":
        pair = {detected_name(arg) for arg in node.args} if len(node.args) == 2 else {None}
        return pair.pop() if len(pair) == 1 else None
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id == "detect_objects"
        and len(node.args) == 1
        and isinstance(node.args[0], ast.Constant)
    ):
        return str(node.args[0].value)
    return None


def number_arguments(call: ast.Call | None) -> list[float]:
    """The plain numbers among the call's positional arguments after the trajectory."""
    if call is None:
        return []
    return [
        float(arg.value)
        for arg in call.args[1:]
        if isinstance(arg, ast.Constant)
        and isinstance(arg.value, int | float)
        and not isinstance(arg.value, bool)
    ]


def signed_number(node: ast.expr) -> float | None:
    """The value of a plain number written as an argument (``12``, ``-0.5``), else None."""
    value = node.operand if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) else node
    if not isinstance(value, ast.Constant) or not isinstance(value.value, int | float):
        return None
    if isinstance(value.value, bool):
        return None
    return -float(value.value) if value is not node else float(value.value)


def profile_kind(call: ast.Call | None) -> ast.Constant | None:
    """The kind of a ``speed_profile`` call ('decelerate', 'accelerate', ...) as its constant node.

    None where the call writes no constant kind. The node itself, so that a reader may turn the kind
    ("constant" where the words ask slower); read positionally or as ``kind=``.
    """
    if call is None:
        return None
    keyword = next((k.value for k in call.keywords if k.arg == "kind"), None)
    kind = keyword if keyword is not None else (call.args[1] if len(call.args) > 1 else None)
    return kind if isinstance(kind, ast.Constant) and isinstance(kind.value, str) else None


def sole_speed_profile(lines: list[str]) -> tuple[int, str] | None:
    """The index and kind of the code's one speed step, where it is a ``speed_profile`` of a constant kind."""
    speed = [index for index, line in enumerate(lines) if called_name(line) in SPEED_STEPS]
    kind = profile_kind(call_of(lines[speed[0]], ("speed_profile",))) if len(speed) == 1 else None
    return None if kind is None else (speed[0], str(kind.value))


def detected_names(node: ast.AST) -> list[str]:
    """The names passed to ``detect_objects`` anywhere in ``node`` (a call, a statement, a program)."""
    return [
        name for inner in ast.walk(node) if isinstance(inner, ast.expr) and (name := detected_name(inner))
    ]


def skill_program(
    lines: list[str], skills: Collection[str], *, empty: bool = False
) -> tuple[int, str] | None:
    """Where a program of skill calls alone reads the trajectory: that line's index and its variable.

    None when a line is neither blank, ``name = name``, ``get_trajectory``, ``detect_objects`` nor a
    call of one of ``skills`` (a reader cannot follow what it moves), when no line calls a skill (the
    program keeps the path) unless ``empty`` allows that, or when nothing reads the trajectory.
    """
    followed = (*skills, "get_trajectory", "detect_objects")
    if not all(_plain(line, followed) for line in lines):
        return None
    if not empty and not any(called_name(x) in skills for x in lines):
        return None
    start = next((i for i, line in enumerate(lines) if called_name(line) == "get_trajectory"), None)
    return None if start is None else (start, lines[start].split("=")[0].strip())


def after_last_step(lines: list[str], skills: Collection[str]) -> int:
    """The index just after the program's last skill call (after ``get_trajectory`` when it has none)."""
    return 1 + max(i for i, line in enumerate(lines) if called_name(line) in (*skills, "get_trajectory"))


def _plain(line: str, callables: Collection[str]) -> bool:
    if not line.strip() or called_name(line) in callables:
        return True
    return bool(re.fullmatch(r"\s*[A-Za-z_]\w*\s*=\s*[A-Za-z_]\w*\s*", line))


def in_place_of(line: str, new: str) -> str:
    """``new`` with the indentation of ``line``: a line of code replaced where it stands."""
    return line[: len(line) - len(line.lstrip())] + new


DISTANCE_STEPS = ("avoid", "move_away", "move_closer")
SPEED_STEPS = ("scale_speed", "set_speed", "speed_profile")
"""Steps that change the distance to an object, and steps that change the speed."""
PLACED_SPEED_STEPS = ("scale_speed", "set_speed")
"""Speed steps that take a place (``near=``)."""


def objects_of(call: ast.Call | None) -> list[str]:
    """The object names of the call's point argument: one ``detect_objects`` or a list of them."""
    if call is None or len(call.args) < 2:
        return []
    point = call.args[1]
    items = point.elts if isinstance(point, ast.List | ast.Tuple) else [point]
    return [detected_name(item) or "" for item in items]


def placed_near(call: ast.Call | None) -> str | None:
    """The object a ``scale_speed`` / ``set_speed`` step is placed near (its ``near`` point), if named."""
    if call is None or not isinstance(call.func, ast.Name) or call.func.id not in PLACED_SPEED_STEPS:
        return None
    point = near_point(call)
    return None if point is None else detected_name(point)


def near_point(call: ast.Call) -> ast.expr | None:
    """The expression a speed step is placed near: its ``near=`` keyword, else its third argument."""
    near = next((k.value for k in call.keywords if k.arg == "near"), None)
    return near if near is not None else (call.args[2] if len(call.args) > 2 else None)


def step_on_object(line: str, name: str) -> bool:
    """Whether ``line`` is a distance step (``avoid``, ``move_away``, ``move_closer``) on object ``name``."""
    return on_object(call_of(line, DISTANCE_STEPS), name)


def on_object(call: ast.Call | None, name: str) -> bool:
    """Whether the call's point argument names object ``name``."""
    return any(found.casefold() == name.casefold() for found in objects_of(call))


def same_program(first: str, second: str) -> bool:
    """Whether two programs are equal up to blank lines and spaces at line ends."""

    def lines(code: str) -> list[str]:
        return [line.rstrip() for line in code.strip().splitlines() if line.strip()]

    return lines(first) == lines(second)

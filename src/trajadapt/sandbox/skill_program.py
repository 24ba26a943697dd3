"""The language of a skill program, as an allow-list: what the answer grammar admits, nothing else.

In skills mode with the grammar, an answer is a skill program: ``name = <expression>`` lines whose
expressions are calls of the skills, ``get_trajectory``, ``detect_objects`` and ``len``; literals;
``+ - * / //`` and unary minus on them; lists and tuples; ``t[i]`` with a literal index; and names
assigned before. Everything else (an attribute, an import, a lambda, a comprehension, a subscript
with a computed index, ``**kwargs``) is refused before the code runs, whatever wrote it: a served
model may ignore the grammar. This is a layer on top of the sandbox, not instead of it.
"""

from __future__ import annotations

import ast
from typing import NoReturn

from trajadapt.code_parse import parse_code
from trajadapt.errors import CodeRejected
from trajadapt.skills import SKILLS

CALLABLE = frozenset({function.__name__ for function in SKILLS} | {"get_trajectory", "detect_objects", "len"})
OPERATORS = (ast.Add, ast.Sub, ast.Mult, ast.Div, ast.FloorDiv)
LITERALS = (str, int, float, bool, type(None))


def check_skill_program(code: str) -> None:
    """Refuse code that is not a skill program.

    Raises:
        CodeRejected: what is outside the language, with its line.
    """
    try:
        tree = parse_code(code)
    except SyntaxError as exc:
        raise CodeRejected(f"the code is not Python: {exc.msg} (line {exc.lineno})") from None
    assigned: set[str] = set()
    for statement in tree.body:
        if not (
            isinstance(statement, ast.Assign)
            and len(statement.targets) == 1
            and isinstance(target := statement.targets[0], ast.Name)
        ):
            _refuse(statement, "each line must assign one name: name = skill(...)")
        _check(statement.value, assigned)
        if target.id.startswith("_") or target.id in CALLABLE:
            _refuse(statement, f"the name {target.id!r} cannot be assigned")
        assigned.add(target.id)


def _check(node: ast.expr, assigned: set[str]) -> None:
    if isinstance(node, ast.Constant):
        if not isinstance(node.value, LITERALS):
            _refuse(node, "only numbers, strings, True, False and None are literals here")
    elif isinstance(node, ast.Name):
        if node.id not in assigned:
            _refuse(node, f"{node.id!r} is not a name assigned before")
    elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub | ast.UAdd):
        _check(node.operand, assigned)
    elif isinstance(node, ast.BinOp) and isinstance(node.op, OPERATORS):
        _check(node.left, assigned)
        _check(node.right, assigned)
    elif isinstance(node, ast.List | ast.Tuple):
        for element in node.elts:
            _check(element, assigned)
    elif isinstance(node, ast.Subscript):
        _check_waypoint(node, assigned)
    elif isinstance(node, ast.Call):
        _check_call(node, assigned)
    else:
        _refuse(node, f"{type(node).__name__} is not part of a skill program")


def _check_waypoint(node: ast.Subscript, assigned: set[str]) -> None:
    index = node.slice
    if isinstance(index, ast.UnaryOp) and isinstance(index.op, ast.USub):
        index = index.operand
    literal = isinstance(index, ast.Constant) and type(index.value) is int
    if not (isinstance(node.value, ast.Name) and node.value.id in assigned and literal):
        _refuse(node, "only a waypoint t[i] with a whole number i can be indexed")


def _check_call(node: ast.Call, assigned: set[str]) -> None:
    if not (isinstance(node.func, ast.Name) and node.func.id in CALLABLE):
        _refuse(node, "only the skills, get_trajectory, detect_objects and len can be called")
    for argument in node.args:
        if isinstance(argument, ast.Starred):
            _refuse(argument, "*arguments are not part of a skill program")
        _check(argument, assigned)
    for keyword in node.keywords:
        if keyword.arg is None or keyword.arg.startswith("_"):
            _refuse(node, "**arguments and private keywords are not part of a skill program")
        _check(keyword.value, assigned)


def _refuse(node: ast.AST, why: str) -> NoReturn:
    raise CodeRejected(f"line {getattr(node, 'lineno', '?')}: {why}")

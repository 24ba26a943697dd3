"""Amounts the user gave for a direction, put back where the code wrote a vague word instead.

A small model writes ``shift(t, 'up', 'slightly')`` for "go upwards by 0.2 walking slightly closer to
the table": the vague word belongs to another part of the sentence, the user's number is lost. Each
clause (split by ``clause_split.split_clauses``) with exactly one direction word and exactly one
number given to a direction (``clause_amounts.direction_amounts``: "by 0.2", "0.2 to the left") gives that
direction its amount; the one directional step in that direction (``shift``, ``shift_goal``,
``shift_start``, ``shift_part``) whose amount is a word or missing gets the number. A step with a
number of its own keeps it (``unstated_amounts`` judges numbers), and a clause with two directions
or two numbers is left alone. A review note says so.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, call_of, direction_argument, in_place_of
from trajadapt.readers.clause_amounts import direction_amounts

DIRECTIONAL_STEPS = ("shift", "shift_goal", "shift_start", "shift_part")


def use_stated_amounts(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each direction's stated amount in its one vague step (see the module docstring)."""
    amounts = direction_amounts(" ".join(asked))
    lines, notes = code.splitlines(), []
    for direction, amount in amounts.items():
        vague = [i for i, line in enumerate(lines) if _vague_step(line) == direction]
        if len(vague) != 1:
            continue
        line = lines[vague[0]]
        tree, call, _ = assigned_call(line)  # type: ignore[misc]
        if len(call.args) > 2:
            call.args[2] = ast.Constant(amount)
        else:
            call.args.append(ast.Constant(amount))
        changed = ast.unparse(tree)
        notes.append(
            f"`{line.strip()}` -> `{changed}`: the instruction gives {direction} the amount {amount:g}"
        )
        lines[vague[0]] = in_place_of(line, changed)
    return "\n".join(lines), notes


def _vague_step(line: str) -> str | None:
    """The direction of a directional step whose amount is a word or missing; None for other lines."""
    call = call_of(line, DIRECTIONAL_STEPS)
    if call is None or any(k.arg == "amount" for k in call.keywords):
        return None
    amount = call.args[2] if len(call.args) > 2 else None
    if amount is not None and not (isinstance(amount, ast.Constant) and isinstance(amount.value, str | None)):
        return None
    return direction_argument(call)

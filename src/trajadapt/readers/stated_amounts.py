"""Amounts the user gave for a direction, put back where the code wrote a vague word instead.

A small model writes ``shift(t, 'up', 'slightly')`` for "go upwards by 0.2 walking slightly closer to
the table": the vague word belongs to another part of the sentence, the user's number is lost. Each
clause (split by ``clause_split.split_clauses``) with exactly one direction word and exactly one
number given to a direction (``clause_amounts.direction_amounts``: "by 0.2", "0.2 to the left") gives that
direction its amount; the one directional step in that direction (``shift``, ``shift_goal``,
``shift_start``, ``shift_part``; else ``lift_middle``) whose amount is a word or missing (or the
number negated: ``'back', -0.4`` for "40 cm backward") gets the number. A step with a number of its
own keeps it (``unstated_amounts`` judges numbers), and a clause with two directions or two numbers
is left alone. A number the words give only to another direction ("go a bit higher
through the middle, and after the goal continue 0.1 further back" answered with ``shift(t, 'up',
0.1)``) is borrowed: the step gets the amount word of its own direction's clause, or the default (a
step in a direction the words never say is left to the readers of directions: "back up by 1.5"
answered ``shift(t, 'up', 1.5)`` is the step for "back"). Where two clauses give one direction two
amounts, a clause that moves one end (``part_words.ENDS_MOVED``: "end 0.2 higher than now") gives
its amount to that end's one vague step (``shift_goal``). A review note says so.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    assigned_call,
    call_of,
    called_name,
    direction_argument,
    in_place_of,
    signed_number,
)
from trajadapt.readers.clause_amounts import direction_amounts
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.part_words import ENDS_MOVED
from trajadapt.readers.words import intensity_word, stated_numbers

DIRECTIONAL_STEPS = ("shift", "shift_goal", "shift_start", "shift_part", "lift_middle")
UNTIL_THE_END = re.compile(r"\b(?:to|until|till|through)\s+the\s+(?:very\s+)?end\b", re.I)
"""A span that runs to the end ("0.3 higher until the end"): no move of the goal itself."""


def use_stated_amounts(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each direction's stated amount in its one vague step (see the module docstring)."""
    words = " ".join(asked)
    amounts = direction_amounts(words)
    code, notes = _without_borrowed_numbers(code, words, amounts)
    lines = code.splitlines()
    for direction, amount in amounts.items():
        vague = [
            i
            for i, line in enumerate(lines)
            if _vague_step(line) == direction or _sign_slip(line, direction, amount)
        ]
        shifts = [i for i in vague if called_name(lines[i]) != "lift_middle"]
        vague = shifts or vague  # a bow of the middle takes the amount only where no shift could
        if len(vague) == 1:
            notes.append(_given(lines, vague[0], direction, amount))
    notes += _end_amounts(lines, words, set(amounts))
    return "\n".join(lines), notes


def _end_amounts(lines: list[str], words: str, read: set[str]) -> list[str]:
    """Each end move's own amount, where two clauses give one direction two amounts (see the module).

    "Stay 0.3 above the floor through the middle, and end 0.2 higher than now": up has two numbers,
    but the clause that moves the goal gives its one ``shift_goal`` up 0.2.
    """
    notes: list[str] = []
    for clause in split_clauses(words):
        given = direction_amounts(clause)
        ends = [skill for skill, named in ENDS_MOVED.items() if named.search(UNTIL_THE_END.sub(" ", clause))]
        if len(given) != 1 or len(ends) != 1 or set(given) <= read:
            continue
        ((direction, amount),) = given.items()
        vague = [i for i, x in enumerate(lines) if _vague_step(x) == direction and called_name(x) == ends[0]]
        if len(vague) == 1:
            notes.append(_given(lines, vague[0], direction, amount))
    return notes


def _given(lines: list[str], index: int, direction: str, amount: float) -> str:
    """``lines[index]``, a vague directional step, given ``amount``; the note saying so."""
    line = lines[index]
    tree, call, _ = assigned_call(line)  # type: ignore[misc]
    if len(call.args) > 2:
        call.args[2] = ast.Constant(amount)
    else:
        call.args.append(ast.Constant(amount))
    changed = ast.unparse(tree)
    lines[index] = in_place_of(line, changed)
    return f"`{line.strip()}` -> `{changed}`: the instruction gives {direction} the amount {amount:g}"


def _sign_slip(line: str, direction: str, amount: float) -> bool:
    """Whether a directional step gives its direction the stated amount negated (``'back', -0.4``).

    "Shift the middle section 40 cm backward" came back as ``shift_part(t, 'back', -0.4, 'middle')``:
    the direction word already says which way, so the minus turned the move round.
    """
    call = call_of(line, DIRECTIONAL_STEPS)
    given = call.args[2] if call is not None and len(call.args) > 2 else None
    stated_way = direction_argument(call) == direction  # "lower by 0.1" as shift(t, 'up', -0.1) is right
    return given is not None and stated_way and signed_number(given) == -amount and amount > 0


def _vague_step(line: str) -> str | None:
    """The direction of a directional step whose amount is a word or missing; None for other lines."""
    call = call_of(line, DIRECTIONAL_STEPS)
    if call is None or any(k.arg == "amount" for k in call.keywords):
        return None
    amount = call.args[2] if len(call.args) > 2 else None
    if amount is not None and not (isinstance(amount, ast.Constant) and isinstance(amount.value, str | None)):
        return None
    return direction_argument(call)


def _without_borrowed_numbers(code: str, words: str, amounts: dict[str, float]) -> tuple[str, list[str]]:
    """``code`` with a directional step's number, given once by the words to another direction, made vague."""
    numbers, said = stated_numbers(words), said_directions(words)
    lines, notes = code.splitlines(), []
    for index, line in enumerate(lines):
        call = call_of(line, DIRECTIONAL_STEPS)
        direction = direction_argument(call)
        amount = call.args[2] if call is not None and len(call.args) > 2 else None
        if call is None or direction not in said - set(amounts) or not isinstance(amount, ast.Constant):
            continue
        given = amount.value
        owners = [d for d, n in amounts.items() if n == given and d != direction]
        if not isinstance(given, int | float) or len(owners) != 1 or numbers.count(float(given)) != 1:
            continue
        own = [c for c in split_clauses(words) if direction in said_directions(c)]
        amount.value = intensity_word(own[0]) if len(own) == 1 else None
        if amount.value is None and len(call.args) == 3:
            call.args.pop()  # the skill's default amount
        changed = f"{line.split('=')[0].strip()} = {ast.unparse(call)}"
        notes.append(
            f"`{line.strip()}` -> `{changed}`: the words give that number to {owners[0]}, not {direction}"
        )
        lines[index] = in_place_of(line, changed)
    return "\n".join(lines), notes

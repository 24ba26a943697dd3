"""Shifts the words ask to alternate in blocks of waypoints: one shift that flips every block.

"Shift the first 10 points left, the next 10 points right, the next 10 left and so on" asks a
square wave: the direction flips every 10 waypoints along the whole path. A small model writes
the directions it read, one whole-path shift each (``shift(t, 'left', 0.1)``, ``shift(t, 'right',
0.1)``, ...), and they cancel; ``repeated-steps`` and ``part-scope`` keep the first two, one of them
on the first 10 waypoints. The skill that makes the wave is ``shift(t, 'left', 0.1, alternate=10)``
(a keyword the prompt does not show).

The words ask it when they say that the shifts go on alternating ("alternate", "alternating",
"and so on", "back and forth", "every other", "continue like this"), give a block of waypoints
("blocks of 10", "the first 10 points", "the next ten waypoints", "waypoints 1-10", "every 10
points") and say two opposite directions (left and right, up and down, front and back). When the
code shifts the path (``shift`` or ``shift_part``) in those directions, those steps become the one
alternating shift, in the direction the words say first, with the first such step's amount. Code
that is not made of skill calls alone is left alone. A review note says what changed and why.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable

from trajadapt.code_parse import call_of, direction_argument, in_place_of, skill_program
from trajadapt.model.geometry import OPPOSITE_DIRECTIONS
from trajadapt.readers.direction_words import alternation
from trajadapt.skills import SKILL_NAMES

SHIFTS = ("shift", "shift_part")


def alternate_shifts(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its shifts in the two directions made one alternating shift (see the module)."""
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES)
    asked_wave = alternation(" ".join(asked))
    if program is None or asked_wave is None:
        return code, []
    direction, block = asked_wave
    directions = {direction, OPPOSITE_DIRECTIONS[direction]}
    shifts = [i for i, line in enumerate(lines) if direction_argument(call_of(line, SHIFTS)) in directions]
    if not shifts:
        return code, []
    variable = program[1]
    amount = _amount(call_of(lines[shifts[0]], SHIFTS))
    given = f", {amount}" if amount else ""
    step = f"{variable} = shift({variable}, {direction!r}{given}, alternate={block})"
    notes = [
        f"`{'; '.join(lines[i].strip() for i in shifts)}` -> `{step}`: the words ask the shifts to "
        f"alternate {direction} and {OPPOSITE_DIRECTIONS[direction]} every {block} waypoints"
    ]
    kept = [line for i, line in enumerate(lines) if i not in shifts[1:]]
    kept[shifts[0]] = in_place_of(lines[shifts[0]], step)
    return "\n".join(kept), notes


def _amount(call: ast.Call | None) -> str | None:
    """The amount a shift step was given, as written (None: the default)."""
    if call is None:
        return None
    given = call.args[2:3] + [k.value for k in call.keywords if k.arg == "amount"]
    return ast.unparse(given[0]) if given else None

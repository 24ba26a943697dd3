"""A pace the words state near an object, held over the stretch nearest it.

"Halve the speed in the vicinity of the lemon" came back as ``scale_speed(t, 0.5,
near=detect_objects('lemon'))``, which is right; but the near zone puts the whole change at the
path's closest pass and fades beyond it, so the arm went by the lemon at 0.68 of its speed, not half.
A vague pace ("slow down near the lemon") asks no number, and the fading zone is what it means; a
stated one asks that number where the path is near the object. When a clause that names the object
states a factor of the pace ("half", "a third of", "40% slower", "twice as fast":
``paces.stated_factor``) and the step's factor is that one, the step gets ``held=True``: the factor
holds over the stretch nearest the object (``skills.speed.held_zone``). A clause that only gives the
amount ("slow right down near the glue, to half speed or less") counts with the clause before it;
one that also names a part of the path ("cut the speed over the final 30 percent") states no pace
near the object.
"""

from __future__ import annotations

import ast
import math
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, in_place_of, placed_near, written_factor
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.paces import stated_factor
from trajadapt.readers.words import names_in, part_named


def hold_stated_paces(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each ``scale_speed`` near an object whose factor the words state held there, noted."""
    words, names = " ".join(asked), list(names)
    clauses = split_clauses(words, names)
    lines, notes = code.splitlines(), list[str]()
    for index, line in enumerate(lines):
        parsed = assigned_call(line)
        if parsed is None or parsed[2] != "scale_speed":
            continue
        tree, call, _ = parsed
        name, factor = placed_near(call), _factor(call)
        if name is None or factor is None or factor == 1:
            continue
        if any(k.arg in ("radius", "held") for k in call.keywords):
            continue
        stated = [
            stated_factor(c, factor > 1) for c in _clauses_of(name, clauses, names) if part_named(c) is None
        ]
        if not any(s is not None and math.isclose(s, factor, rel_tol=1e-3) for s in stated):
            continue
        call.keywords.append(ast.keyword("held", ast.Constant(True)))
        before, after = line.strip(), ast.unparse(tree)
        lines[index] = in_place_of(line, after)
        notes.append(f"`{before}` -> `{after}`: the words state the pace near {name}, so it holds there")
    return "\n".join(lines), notes


def _factor(call: ast.Call) -> float | None:
    """The factor a ``scale_speed`` call writes as a plain number (second argument or ``factor=``)."""
    written = written_factor(call)
    return written[1] if written is not None else None


def _clauses_of(name: str, clauses: tuple[str, ...], names: list[str]) -> list[str]:
    """The clauses that name ``name``, each with the next clause when that one names no object."""
    found = []
    for index, clause in enumerate(clauses):
        if not names_in(clause, [name]):
            continue
        found.append(clause)
        following = clauses[index + 1] if index + 1 < len(clauses) else ""
        if following and not names_in(following, names):
            found.append(following)
    return found

"""A pace the words hold the whole way, written for one part of the path: held over the whole path.

"Drive at a steady 0.4 m/s the whole way, no slowing down in the middle" came back as ``set_speed(t,
0.4, part='middle')``: the part named in the negated clause, not where the pace holds. Where one
clause about the pace spans the whole path (``words.ALL_ALONG``: "the whole way", "throughout",
"from start to finish") and names no object and no part, and every other pace clause is negated,
the code's one speed step (``scale_speed`` or ``set_speed`` placed by ``part=`` alone) loses its
``part=``. A review note says so.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable

from trajadapt.code_parse import PLACED_SPEED_STEPS, SPEED_STEPS, assigned_call, called_name, in_place_of
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import ALL_ALONG, EVEN_PACE, NEGATED, SPEED_UNIT, asks_pace, names_in, part_named


def whole_way_paces(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its one speed step kept to a part made whole, where the pace holds the whole way.

    Where: one pace clause spans the whole path and names no object and no part, and every other
    pace clause is negated (see the module).
    """
    words, names = " ".join(asked), list(names)
    paced = [
        c for c in split_clauses(words, names) if asks_pace(c) or EVEN_PACE.search(c) or SPEED_UNIT.search(c)
    ]
    whole = [c for c in paced if ALL_ALONG.search(c) and not names_in(c, names) and not _names_a_part(c)]
    lines = code.splitlines()
    speeds = [i for i, line in enumerate(lines) if called_name(line) in SPEED_STEPS]
    if len(whole) != 1 or any(not NEGATED.search(c) for c in paced if c != whole[0]) or len(speeds) != 1:
        return code, []
    found = assigned_call(lines[speeds[0]])
    if found is None or found[2] not in PLACED_SPEED_STEPS or [k.arg for k in found[1].keywords] != ["part"]:
        return code, []
    tree, call, _ = found
    call.keywords = []
    before, after = lines[speeds[0]].strip(), ast.unparse(tree)
    lines[speeds[0]] = in_place_of(lines[speeds[0]], after)
    return "\n".join(lines), [f"`{before}` -> `{after}`: {whole[0].strip()!r} holds the pace the whole way"]


def _names_a_part(clause: str) -> bool:
    """Whether the clause names a part of the path besides its words for the whole of it."""
    return part_named(ALL_ALONG.sub(" ", clause)) is not None

"""A speed step near an object that goes against the pace its clause asks there, turned the asked way.

"Go faster near the kettle and slower near the lamp" came back as ``scale_speed(t, 0.65,
near=kettle)`` and ``scale_speed(t, 1.4, near=lamp)``: each object got the other's pace. The request
as a whole asks both ways, so a reading of its one direction (``unstated_amounts``) cannot tell which
is meant where; the clauses can. Where every clause that asks a pace (a request, not negated) names
exactly one scene object and asks exactly one way (``FASTER`` or ``SLOWER``; not a pace compared,
"half as fast", nor one placed elsewhere, "except near", "once clear of"), each asks that way near
its object; an object two clauses ask different ways of is left alone. A factor the clause itself
states ("half as fast": 0.5) is left as written. A ``scale_speed`` step placed
near such an object whose literal factor goes the other way takes the factor its clause states in
the asked way ("20% slower": 0.8, ``paces.stated_factor``), else the phrase table's for the clause's
amount word (``paces.speed_factor``). A review note says so. Code that is not made of skill calls
alone is left alone.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, in_place_of, placed_near, skill_program, written_factor
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.paces import PERCENT, speed_factor, stated_factor
from trajadapt.readers.request_words import is_statement
from trajadapt.readers.words import FASTER, NEGATED, SLOWER, asks_pace, longest_names, names_in
from trajadapt.skills import SKILL_NAMES

NOT_THERE = re.compile(
    r"\b(?:except|other\s+than|apart\s+from|away\s+from|clear\s+of|beyond|once\s+past|after\s+passing)\b",
    re.I,
)
"""Words that put the pace elsewhere than by the object they name ("faster once clear of the lamp")."""
COMPARED = re.compile(r"\b(?:as|less|too)\s+(?:fast|quick|slow)\w*", re.I)
"""A pace compared, not asked one way: "half as fast", "less quick", "too slow"."""


def turn_paces_as_asked(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each speed step near an object turned the way its clause asks, and a note each."""
    lines, names = code.splitlines(), list(names)
    if skill_program(lines, SKILL_NAMES) is None:
        return code, []
    paces = asked_paces_near(" ".join(asked), names)
    notes: list[str] = []
    for index, line in enumerate(lines):
        parsed = assigned_call(line)
        if parsed is None or parsed[2] != "scale_speed":
            continue
        tree, call, _ = parsed
        written = _literal_factor(call)
        name = placed_near(call)
        ask = next((paces[key] for key in paces if name and key.casefold() == name.casefold()), None)
        if ask is None or written is None or written[1] == 1 or (written[1] > 1) == ask[0]:
            continue
        faster, clause = ask
        if not PERCENT.search(clause) and any(stated_factor(clause, w) == written[1] for w in (True, False)):
            continue  # a factor the clause states ("half as fast" reads as faster, and is 0.5)
        stated = stated_factor(clause, faster)
        written[0].value = stated if stated is not None else speed_factor(clause, faster)
        before, after = line.strip(), ast.unparse(tree)
        lines[index] = in_place_of(line, after)
        way = "faster" if faster else "slower"
        notes.append(f"`{before}` -> `{after}`: the words ask {way} near {name} ({clause.strip()!r})")
    return ("\n".join(lines), notes) if notes else (code, [])


def asked_paces_near(words: str, names: list[str]) -> dict[str, tuple[bool, str]]:
    """Each object a pace clause asks one way near, as (faster, the clause).

    Empty unless every pace clause names exactly one object and asks exactly one way.
    """
    asks: dict[str, tuple[bool, str]] = {}
    torn: set[str] = set()
    for clause in split_clauses(words, names):
        if not asks_pace(clause) or is_statement(clause) or NEGATED.search(clause):
            continue
        named = longest_names(names_in(clause, names))
        faster, slower = bool(FASTER.search(clause)), bool(SLOWER.search(clause))
        if len(named) != 1 or faster == slower or NOT_THERE.search(clause) or COMPARED.search(clause):
            return {}
        if named[0] in asks and asks[named[0]][0] != faster:
            torn.add(named[0])
        asks.setdefault(named[0], (faster, clause))
    return {name: ask for name, ask in asks.items() if name not in torn}


def _literal_factor(call: ast.Call) -> tuple[ast.Constant, float] | None:
    """A ``scale_speed`` call's factor and its value, when it is written as a plain positive number."""
    written = written_factor(call)
    return written if written is not None and written[1] > 0 else None

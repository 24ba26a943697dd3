"""A speed change the instruction ties to one object, written for the whole path: made local to it.

A small model writes ``scale_speed(t, 1.65)`` for "walk a lot faster in the proximity of the
spaniel": the whole path speeds up, not the part near the spaniel. When the user's words have
exactly one clause about speed, that clause names exactly one of the scene's objects and says
where ("near", "close to", "passing", "in the proximity of", "within", ...), and the code has
exactly one speed step with no place of its own (no ``near=``, ``radius=`` or ``part=``), the
step gets ``near=detect_objects('<that object>')``, and the clause's reach ("within 0.1 of the
screw") as ``radius=``. A ``part=`` the words never ask for (no word names a part or an end of
the path: "within 0.1 of the screw, slow down" came back as ``part='second half'``) is no place of
its own either: it gives way to the object. A review note says so. Measured on stored answers in
docs/benchmarks.md.
"""

from __future__ import annotations

import ast
from collections.abc import Iterable

from trajadapt.code_parse import PLACED_SPEED_STEPS, assigned_call, in_place_of
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.object_words import WITHIN
from trajadapt.readers.words import PART_OR_END, PLACE_WORDS, SPEED_WORDS, longest_names, names_in


def scoped_object(words: str, names: Iterable[str]) -> str | None:
    """The one object the one speed clause of ``words`` places the speed change at, if there is one."""
    scoped = _scoped_clause(words, list(names))
    return None if scoped is None else scoped[1]


def _scoped_clause(words: str, names: list[str]) -> tuple[str, str] | None:
    """The one speed clause of ``words`` and the one object it places the speed change at, if any."""
    speed_clauses = [c for c in split_clauses(words, names) if SPEED_WORDS.search(c)]
    if len(speed_clauses) != 1 or not PLACE_WORDS.search(speed_clauses[0]):
        return None
    longest = longest_names(names_in(speed_clauses[0], names))
    return (speed_clauses[0], longest[0]) if len(longest) == 1 else None


def localize_speed(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its one unplaced speed step placed near the object the words name, and a note."""
    words = " ".join(asked)
    scoped = _scoped_clause(words, list(names))
    if scoped is None:
        return code, []
    clause, target = scoped
    parts_said = PART_OR_END.search(words) is not None
    lines = code.splitlines()
    unplaced = [i for i, line in enumerate(lines) if _unplaced_speed_call(line, parts_said) is not None]
    if len(unplaced) != 1:
        return code, []
    index = unplaced[0]
    tree, call = _unplaced_speed_call(lines[index], parts_said)  # type: ignore[misc]
    point = ast.Call(ast.Name("detect_objects", ast.Load()), [ast.Constant(target)], [])
    call.keywords = [k for k in call.keywords if k.arg != "part"] + [ast.keyword("near", point)]
    reach = WITHIN.search(clause)
    if reach is not None:
        call.keywords.append(ast.keyword("radius", ast.Constant(float(reach.group(1)))))
    before, after = lines[index].strip(), ast.unparse(tree)
    lines[index] = in_place_of(lines[index], after)
    note = f"`{before}` -> `{after}`: the instruction changes the speed near {target}, not everywhere"
    return "\n".join(lines), [note]


def _unplaced_speed_call(line: str, parts_said: bool) -> tuple[ast.Module, ast.Call] | None:
    """The parsed line and its call for ``t = scale_speed(t, x)`` or ``set_speed`` with no place.

    A ``part=`` is a place only where the words name a part or an end (``parts_said``).
    """
    found = assigned_call(line)
    if found is None or found[2] not in PLACED_SPEED_STEPS:
        return None
    tree, call, _ = found
    places = ("near", "radius", "part") if parts_said else ("near", "radius")
    if len(call.args) > 2 or any(k.arg in places for k in call.keywords):
        return None
    return tree, call

"""A step about an object the user's words never name: no clause asks for it.

The retrieved examples and the scene list put object names in front of the model, and it uses them
where the words name none: "increase velocity through the middle section" came back as
``scale_speed(t, 1.4, near=detect_objects('lemon'))``, "move the path 0.3 over to the right" as
``pass_over(t, [plectrum, Sealyham, crib])``. A scene object counts as named when the words hold its
name or one of its words ("the husky" names "Siberian husky"); when they speak of objects in
general ("the nearest obstacle", "the most cluttered region", "any object") every object may be
meant and the reader stands aside. For an object no word names:

- a speed step placed near it (``near=``, with its ``radius=``) keeps its speed change and loses the
  place: the words asked a pace, not where; a spiral placed at it (``at=``) is made at the goal, its
  default;
- a step that moves the path relative to it alone (``move_closer``, ``move_away``, ``avoid``,
  ``pass_over``) is left out: it serves no clause.

Steps that stop or pause at an object (``wait``, ``stop_at``: no default place stands for it), a
place given by position rather than keyword, and steps that also name a named object are left
alone. A review note says what changed and why. Measured on stored answers in docs/benchmarks.md.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, detected_name, in_place_of, parse_code
from trajadapt.readers.words import whole_words

GENERAL_OBJECTS = re.compile(
    r"\b(?:objects?|obstacles?|items?|anything|clutter\w*|landmarks?|entit(?:y|ies))\b",
    re.I,
)
"""Words for objects in general: any scene object may be the one meant ("the whole thing" and
"everything" are the path)."""
MOVES_BY_OBJECT = ("move_closer", "move_away", "avoid", "pass_over")
"""Steps that move the path relative to their objects and nothing else."""
PLACES = {"scale_speed": ("near", ("radius",)), "set_speed": ("near", ("radius",)), "spiral": ("at", ())}
"""Steps placed at an object by a keyword, and the keywords that go with the place."""
SHORTEST_WORD = 3  # a name's word shorter than this ("of", "a") names nothing by itself


def leave_out_unnamed(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` without the steps and speed places about objects the words never name, and notes."""
    words = " ".join(asked)
    if GENERAL_OBJECTS.search(words):
        return code, []
    try:
        parse_code(code)
    except SyntaxError:
        return code, []
    unnamed = {name.casefold() for name in names if not _named(name, words)}
    if not unnamed:
        return code, []
    lines: list[str] = []
    notes: list[str] = []
    for line in code.splitlines():
        kept, note = _read_line(line, unnamed)
        lines += [kept] if kept is not None else []
        notes += [note] if note else []
    return ("\n".join(lines), notes) if notes else (code, [])


def _named(name: str, words: str) -> bool:
    """Whether ``words`` name the object: its whole name or one of its longer words."""
    text = whole_words(words)
    parts = whole_words(name).split()
    return whole_words(name) in text or any(len(p) >= SHORTEST_WORD and f" {p} " in text for p in parts)


def _read_line(line: str, unnamed: set[str]) -> tuple[str | None, str]:
    """The line as kept (None: left out) and the note for a change ('' for none)."""
    found = assigned_call(line)
    if found is None:
        return line, ""
    tree, call, skill = found
    if skill in MOVES_BY_OBJECT:
        objects = _objects(call.args[1:2])
        if objects and all(o.casefold() in unnamed for o in objects):
            return None, f"left out `{line.strip()}`: the words never name {_listed(objects)}"
        return line, ""
    place, dropped = PLACES.get(skill, ("", ()))
    found_place = next((k for k in call.keywords if k.arg == place), None)
    objects = _objects([found_place.value]) if found_place is not None else []
    if not objects or not all(o.casefold() in unnamed for o in objects):
        return line, ""
    call.keywords = [k for k in call.keywords if k.arg not in (place, *dropped)]
    after = ast.unparse(tree)
    note = f"`{line.strip()}` -> `{after}`: the words never name {_listed(objects)}: not placed there"
    return in_place_of(line, after), note


def _objects(nodes: list[ast.expr]) -> list[str]:
    """The object names of every ``detect_objects('...')`` inside ``nodes``."""
    return [
        name
        for node in nodes
        for inner in ast.walk(node)
        if isinstance(inner, ast.Call) and (name := detected_name(inner)) is not None
    ]


def _listed(objects: list[str]) -> str:
    return ", ".join(dict.fromkeys(objects))

"""A step that moves the path by an object the words only place a pace near, left out.

"increase the speed while passing in the surrounding of the toy terrier" came back as
``pass_through(t, detect_objects('toy terrier'), 1)`` beside ``scale_speed(t, 1.4,
near=detect_objects('toy terrier'))``: the clause says where the speed changes; nothing asks the
path to go anywhere. When every clause that names an object asks only a pace near it (a pace and a
place word: ``object_words.object_asks``; no distance, no side, nothing to go through, over, round
or to), and the code changes the speed near that object, each step that moves the path by that
object alone (a distance step, ``pass_through``, ``pass_over``, ``reach``, ``circle_around``,
``keep_side``) is left out, with a review note. Without a speed step near it the step is left to
``object_asks``, which makes it the asked pace.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    DISTANCE_STEPS,
    PLACED_SPEED_STEPS,
    call_of,
    called_name,
    detected_name,
    objects_of,
    placed_near,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.object_words import PACES, object_asks
from trajadapt.readers.words import asks_distance, longest_names, names_in

MOVING_STEPS = (*DISTANCE_STEPS, "pass_through", "pass_over", "reach", "circle_around", "keep_side")
"""Steps that move the path by an object."""

GOING_BY = re.compile(
    r"\b(?:through|thru|via|over|above|under|below|round|reach\w*|visit\w*|touch\w*|circl\w*|loop\w*"
    r"|orbit\w*|end\w*|stop\w*|arriv\w*|hit\w*|toward\w*"
    r"|(?:go|goes|going|head\w*|mov\w*|travel\w*|drive|fly|walk)\s+(?:straight\s+)?to)\b",
    re.I,
)
"""Words that ask the path to go through, over, round or to an object, not only past it."""

SIDES = re.compile(r"\b(?:side|left|right|in front|behind)\b", re.I)
POINTING = re.compile(r"\b(?:it|them|that|this|there)\b", re.I)


def _moves_by_a_pointed_object(clause: str, names: list[str]) -> bool:
    """A clause that names no object but points to one and asks a move by it ("stay left of it")."""
    if names_in(clause, names) or not POINTING.search(clause):
        return False
    return bool(asks_distance(clause) or GOING_BY.search(clause) or SIDES.search(clause))


def leave_out_moves_of_paced_places(
    code: str, asked: Iterable[str], names: Iterable[str]
) -> tuple[str, list[str]]:
    """``code`` without the steps that move the path by an object only a pace is placed near, noted."""
    words, names = " ".join(asked), list(names)
    lines, notes = code.splitlines(), list[str]()
    for name in _only_paced(words, names):
        key = name.casefold()
        if not any((placed_near(call_of(x, PLACED_SPEED_STEPS)) or "").casefold() == key for x in lines):
            continue
        for index in reversed(range(len(lines))):
            if _moved_by(lines[index]) == [key]:
                notes.append(f"left out `{lines[index].strip()}`: the instruction only places a pace "
                             f"near {name}, it asks no move by it")  # fmt: skip
                del lines[index]
    return "\n".join(lines), notes


def _moved_by(line: str) -> list[str]:
    """The objects (casefolded) a step that moves the path by objects names; ``keep_side`` names its third."""
    call = call_of(line, MOVING_STEPS)
    if call is not None and called_name(line) == "keep_side" and len(call.args) > 2:
        return [(detected_name(call.args[2]) or "").casefold()]
    return [found.casefold() for found in objects_of(call)]


def _only_paced(words: str, names: list[str]) -> list[str]:
    """The objects every clause naming them asks only a pace near.

    None when a clause that names no object asks a move by one it points to ("and keep away from it").
    """
    paced = [a.name for a in object_asks(words, names).values() if a.relation in PACES]
    clauses = split_clauses(words, names)
    if any(_moves_by_a_pointed_object(c, names) for c in clauses):
        return []
    only = []
    for name in paced:
        naming = [
            c for c in clauses if name.casefold() in (n.casefold() for n in longest_names(names_in(c, names)))
        ]
        if naming and not any(GOING_BY.search(c) for c in naming):
            only.append(name)
    return only

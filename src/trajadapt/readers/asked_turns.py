"""A turn of the whole path whose angle or sense differs from the clause that asks it: made as said.

``rotate(t, degrees)`` turns clockwise seen from above for a positive angle. A small model writes the
angle it sees in its examples: ``rotate(t, 90)`` for "a quarter turn counter-clockwise as seen from
above" turned the path the other way. The clause that asks the turn (a verb of turning and a sense
or a size: ``TURN_VERB``, ``SENSE``, ``SIZE``) gives the angle: its degrees, or a quarter turn (90),
a half turn (180), a right angle (90); its sense gives the sign ("clockwise" +, "counter-clockwise",
"anticlockwise" -; "to the left" is counter-clockwise seen from above, "to the right" clockwise; not
"about its left end", a place).
What the clause does not say (the size or the sense) stays as the model wrote it. Only a program with
one ``rotate`` step, and words with one clause that asks a turn, are read. A review note says what
changed.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, in_place_of, signed_number
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import NUMBER_TEXT

TURN_VERB = re.compile(
    r"\b(?:rotat\w*|turn\w*|tilt\w*|pivot\w*|spin\w*|swivel\w*|yaw\w*|revolv\w*)\b",
    re.I,
)
"""Verbs (and nouns) of turning: a clause without one asks no turn ("keep clockwise of the box")."""
SENSE = re.compile(
    r"\b(?P<against>counter[\s-]?clockwise|anti[\s-]?clockwise|ccw)\b|\b(?P<with>clockwise|cw)\b"
    r"|\b(?:to|towards?)\s+(?:the\s+)?(?P<side>left|right)\b(?!\s+(?:of|end|side|edge)\b)",
    re.I,
)
"""The sense of a turn seen from above: against the clock, with it, or towards a side."""
SIZE = re.compile(
    rf"(?<![\w.])(?P<degrees>{NUMBER_TEXT})\s*(?:°|deg(?:ree)?s?\b)"
    r"|(?<!three\s)(?<!three-)\b(?P<share>quarter|half|third)[\s-]+(?:(?:of\s+)?an?\s+)?turn\b"
    r"|\b(?P<right>right)[\s-]+angle\b",
    re.I,
)
"""The size of a turn: "30 degrees", "45°", "a quarter turn", "half a turn", "a right angle"."""
SHARE_DEGREES = {"quarter": 90.0, "half": 180.0, "third": 120.0}


def turn_as_asked(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its one ``rotate`` step given the angle and sense its clause says, and a note."""
    lines = code.splitlines()
    turns = [i for i, line in enumerate(lines) if (found := assigned_call(line)) and found[2] == "rotate"]
    clauses = [c for c in split_clauses(" ".join(asked)) if TURN_VERB.search(c) and _said(c) != (None, None)]
    if len(turns) != 1 or len(clauses) != 1:
        return code, []
    found = assigned_call(lines[turns[0]])
    assert found is not None
    tree, call, _ = found
    written = _written_degrees(call)
    if written is None:
        return code, []
    size, sign = _said(clauses[0])
    degrees = (size if size is not None else abs(written)) * (
        sign if sign is not None else (1 if written >= 0 else -1)
    )
    if degrees == written:
        return code, []
    _set_degrees(call, ast.Constant(round(degrees, 6) if degrees != int(degrees) else int(degrees)))
    before, after = lines[turns[0]].strip(), ast.unparse(tree)
    lines[turns[0]] = in_place_of(lines[turns[0]], after)
    note = (
        f"`{before}` -> `{after}`: the words ask {clauses[0]!r};"
        " a positive angle turns clockwise seen from above"
    )
    return "\n".join(lines), [note]


def _said(clause: str) -> tuple[float | None, int | None]:
    """The size in degrees and the sign (+1 clockwise, -1 against) a clause says, each None if unsaid."""
    sizes = {_degrees(found) for found in SIZE.finditer(clause)}
    senses = {_sign(found) for found in SENSE.finditer(clause) if not _is_the_right_angle(found, clause)}
    return (sizes.pop() if len(sizes) == 1 else None), (senses.pop() if len(senses) == 1 else None)


def _degrees(found: re.Match[str]) -> float:
    """The degrees of one size of a turn."""
    if found.group("degrees"):
        return float(found.group("degrees"))
    return SHARE_DEGREES[found.group("share").lower()] if found.group("share") else 90.0


def _sign(found: re.Match[str]) -> int:
    """+1 for a clockwise sense (or towards the right), -1 against the clock (or towards the left)."""
    if found.group("against"):
        return -1
    return 1 if found.group("with") or found.group("side").lower() == "right" else -1


def _is_the_right_angle(found: re.Match[str], clause: str) -> bool:
    """Whether a "right" is the one of "a right angle" (a size, not a sense)."""
    return bool(found.group("side")) and bool(re.match(r"[\s-]+angle\b", clause[found.end() :], re.I))


def _written_degrees(call: ast.Call) -> float | None:
    """The angle a ``rotate(t, degrees)`` call was given as a plain number, else None."""
    given = call.args[1:2] + [k.value for k in call.keywords if k.arg == "degrees"]
    if len(given) != 1:
        return None
    return signed_number(given[0])


def _set_degrees(call: ast.Call, value: ast.expr) -> None:
    """Give a ``rotate`` call a new angle where it had one (by position or keyword)."""
    if len(call.args) >= 2:
        call.args[1] = value
    for keyword in call.keywords:
        if keyword.arg == "degrees":
            keyword.value = value

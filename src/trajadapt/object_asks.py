"""What the user's words ask about each object, and a step on it that does something else, replaced.

A small model reaches for ``avoid`` whatever the words say about an object: ``avoid(t,
detect_objects('chair'), 0.3)`` for "keeping a smaller distance from the chair", ``avoid(t,
detect_objects('paddle'), 0.2)`` for "go slower if paddle is within 0.2", ``avoid(t,
detect_objects('bottle'), 0.5)`` for "do not go left of the bottle". Each clause of the user's words
(split at punctuation, "and", "then", "but", "also"; "while" stays inside) that names exactly one of
the scene's objects asks one thing of it:

- a speed change near it ("slower", "faster", ... with a place word: "near", "within 0.2 of", "if
  X is within"), when the code changes no speed anywhere: the one distance step on that object
  becomes ``scale_speed(t, <calibrated factor>, near=X)`` (with ``radius=`` when the clause says
  "within <number>"); in an ``avoid`` of several objects, the object leaves the list and the speed
  step follows it;
- a side ("do not go left of X" -> the right side, "stay to the right of X") -> ``keep_side``;
- closer ("closer", "nearer", "a smaller distance", "approach") or away ("further", "away", "a
  greater distance") -> a step the other way (``move_away`` for closer, ``move_closer`` for away),
  or an ``avoid`` of that one object with a clearance the clause does not state, becomes
  ``move_closer`` / ``move_away`` with the clause's vague word.

A ``midpoint`` of an object the words name and one they do not (with no "middle" or "between" in
them) is the named object itself.

When the words name no object at all, a side is a side of the scene ("stay on the left", "stay on
the front part"): a ``keep_side`` about an object the user never named becomes a ``shift`` to that
side with the clause's vague word.

An object that two clauses ask different things of is left alone, and so is every step the words
agree with. A review note says what was replaced and why. Measured on stored answers in
docs/benchmarks.md.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.code_parse import (
    assigned_call,
    call_of,
    detected_name,
    direction_argument,
    in_place_of,
    parse_code,
)
from trajadapt.geometry import DIRECTION_SYNONYMS, OPPOSITE_DIRECTIONS
from trajadapt.speed_scope import CLAUSES, PLACE_WORDS
from trajadapt.unstated_amounts import intensity_word, is_stated, speed_factor, stated_numbers
from trajadapt.wording import FASTER, SLOWER, asks_pace, longest_names, names_in

CLOSER = re.compile(
    r"\b(?:closer|nearer|approach\w*|toward[s]?|(?:smaller|shorter|less(?:er)?|reduced?) distance)\b", re.I
)
AWAY = re.compile(
    r"\b(?:away|further|farther|(?:greater|larger|bigger|more|increased?|wider) (?:distance|berth|space))\b",
    re.I,
)
NOT_SIDE = re.compile(r"\b(?:not|never|n't|avoid)\b.*?\b([a-z]+)\s+(?:side\s+)?of\b", re.I)
KEEP_SIDE = re.compile(
    r"\b(?:stay|keep|remain|pass|go|drive|walk|fly)\w*\b.*?\b([a-z]+)\s+(?:side\s+)?of\b", re.I
)
WITHIN = re.compile(r"\bwithin\s+((?:\d+\.?\d*|\.\d+))", re.I)
DISTANCE_STEPS = ("avoid", "move_away", "move_closer")
SPEED_STEPS = ("scale_speed", "set_speed", "speed_profile")


@dataclass(frozen=True)
class ObjectAsk:
    """What one clause asks of one object: 'faster', 'slower', 'closer', 'away' or 'side'."""

    name: str
    relation: str
    clause: str
    side: str = ""  # for 'side': the side to keep to
    radius: float | None = None  # for a speed change: "within 0.2"


def object_asks(words: str, names: Iterable[str]) -> dict[str, ObjectAsk]:
    """The one thing the clauses of ``words`` ask of each object they name (none where two clauses differ)."""
    asks: dict[str, list[ObjectAsk]] = {}
    for clause in CLAUSES.split(words):
        named = longest_names(names_in(clause, names))
        ask = _clause_ask(clause, named[0]) if len(named) == 1 else None
        if ask is not None:
            asks.setdefault(ask.name, []).append(ask)
    return {name: found[0] for name, found in asks.items() if len({a.relation for a in found}) == 1}


def _clause_ask(clause: str, name: str) -> ObjectAsk | None:
    side = _side(clause.replace(name, " "))
    if side:
        return ObjectAsk(name, "side", clause, side=side)
    if asks_pace(clause):
        if not PLACE_WORDS.search(clause) or bool(FASTER.search(clause)) == bool(SLOWER.search(clause)):
            return None
        if CLOSER.search(clause) or AWAY.search(clause):  # "approach the lamp slowly": both, or a place?
            return None
        within = WITHIN.search(clause)
        radius = float(within.group(1)) if within else None
        return ObjectAsk(name, "faster" if FASTER.search(clause) else "slower", clause, radius=radius)
    closer, away = bool(CLOSER.search(clause)), bool(AWAY.search(clause))
    if closer == away:
        return None
    return ObjectAsk(name, "closer" if closer else "away", clause)


def _side(clause: str) -> str:
    for pattern, flip in ((NOT_SIDE, True), (KEEP_SIDE, False)):
        found = pattern.search(clause)
        word = DIRECTION_SYNONYMS.get(found.group(1).lower(), "") if found else ""
        if word:
            return OPPOSITE_DIRECTIONS[word] if flip else word
    return ""


def replace_object_steps(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each step on an object that does not do what the words ask of it replaced, noted."""
    words, names = " ".join(asked), list(names)
    asks = object_asks(words, names)
    lines, notes = code.splitlines(), []
    changes_speed = any(call_of(line, SPEED_STEPS) is not None for line in lines)
    for ask in asks.values():
        if ask.relation in ("faster", "slower") and changes_speed:
            continue
        steps = [i for i, line in enumerate(lines) if _on_object(call_of(line, DISTANCE_STEPS), ask.name)]
        if len(steps) != 1 or (ask.relation == "side" and any(call_of(x, ("keep_side",)) for x in lines)):
            continue
        replaced = _replacement(lines[steps[0]], ask)
        if replaced is None:
            continue
        notes.append(f"`{lines[steps[0]].strip()}` -> `{'; '.join(replaced)}`: the instruction asks "
                     f"{asked_words(ask)} {ask.name}")  # fmt: skip
        lines[steps[0] : steps[0] + 1] = [in_place_of(lines[steps[0]], line) for line in replaced]
    _unnamed_midpoints(lines, notes, words, names)
    return _sides_of_the_scene(lines, notes, words, names)


def _unnamed_midpoints(lines: list[str], notes: list[str], words: str, names: list[str]) -> None:
    """``midpoint(a, b)`` where the words name only ``a`` (and no middle or between): ``a`` alone."""
    if re.search(r"\b(?:mid\w*|middle|between|cent(?:re|er))\b", words, re.I):
        return
    named = {n.casefold() for n in names_in(words, names)}
    for index, line in enumerate(lines):
        tree = assigned_call(line)
        if tree is None:
            continue
        for node in ast.walk(tree[0]):
            if not (
                isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "midpoint"
            ):
                continue
            ends = [detected_name(a) or "" for a in node.args]
            kept = [a for a, name in zip(node.args, ends, strict=False) if name.casefold() in named]
            if len(node.args) == 2 and len(kept) == 1:
                node.func, node.args = ast.Name("detect_objects", ast.Load()), [kept[0].args[0]]  # type: ignore[attr-defined]
        changed = ast.unparse(tree[0])
        if changed != line.strip():
            notes.append(
                f"`{line.strip()}` -> `{changed}`: the instruction names only one of the two objects"
            )
            lines[index] = in_place_of(line, changed)


def _sides_of_the_scene(
    lines: list[str], notes: list[str], words: str, names: list[str]
) -> tuple[str, list[str]]:
    """``keep_side`` about an object the words do not name, when they name none, as a shift to that side."""
    if names_in(words, names):
        return "\n".join(lines), notes
    for index, line in enumerate(lines):
        call = call_of(line, ("keep_side",))
        side = direction_argument(call)
        if side is None:
            continue
        word = intensity_word(words)
        shifted = f"t = shift(t, {side!r}{f', {word!r}' if word else ''})"
        notes.append(f"`{line.strip()}` -> `{shifted}`: the instruction names no object, so {side} is a "
                     f"side of the scene")  # fmt: skip
        lines[index] = in_place_of(line, shifted)
    return "\n".join(lines), notes


def asked_words(ask: ObjectAsk) -> str:
    """What the ask wants, in words that read before the object's name ('to come closer to')."""
    return {
        "faster": "for a faster pace near",
        "slower": "for a slower pace near",
        "side": f"to stay {ask.side} of",
        "closer": "to come closer to",
        "away": "to keep further from",
    }[ask.relation]


def _replacement(line: str, ask: ObjectAsk) -> list[str] | None:
    """The lines that replace ``line`` (a distance step on ``ask.name``), or None to keep it."""
    _, call, skill = assigned_call(line)  # type: ignore[misc]
    point = f"detect_objects({ask.name!r})"
    if ask.relation in ("faster", "slower"):
        factor = speed_factor(ask.clause, faster=ask.relation == "faster")
        radius = f", radius={ask.radius}" if ask.radius is not None else ""
        speed = f"t = scale_speed(t, {factor}, near={point}{radius})"
        rest = _without_object(call, ask.name) if skill == "avoid" else None
        return [speed] if rest is None else [rest, speed]
    if ask.relation == "side":
        return [f"t = keep_side(t, {ask.side!r}, {point})"]
    wanted = "move_closer" if ask.relation == "closer" else "move_away"
    if skill == wanted or len(_objects(call)) != 1:
        return None
    if skill == "avoid" and _clearance_stated(call, ask.clause):
        return None
    word = intensity_word(ask.clause)
    amount = f", {word!r}" if word else ""
    return [f"t = {wanted}(t, {point}{amount})"]


def _objects(call: ast.Call | None) -> list[str]:
    """The object names of the call's point argument: one ``detect_objects`` or a list of them."""
    if call is None or len(call.args) < 2:
        return []
    point = call.args[1]
    items = point.elts if isinstance(point, ast.List | ast.Tuple) else [point]
    return [detected_name(item) or "" for item in items]


def step_on_object(line: str, name: str) -> bool:
    """Whether ``line`` is a distance step (``avoid``, ``move_away``, ``move_closer``) on object ``name``."""
    return _on_object(call_of(line, DISTANCE_STEPS), name)


def _on_object(call: ast.Call | None, name: str) -> bool:
    return any(found.casefold() == name.casefold() for found in _objects(call))


def _without_object(call: ast.Call, name: str) -> str | None:
    """``t = avoid(t, <the other objects>, ...)`` when the avoid names others too; None when only ``name``."""
    others = [n for n in _objects(call) if n.casefold() != name.casefold()]
    if not others:
        return None
    points = [_expression(f"detect_objects({n!r})") for n in others]
    call.args[1] = points[0] if len(points) == 1 else ast.List(points, ast.Load())
    return f"t = {ast.unparse(call)}"


def _expression(source: str) -> ast.expr:
    statement = parse_code(source).body[0]
    assert isinstance(statement, ast.Expr)
    return statement.value


def _clearance_stated(call: ast.Call, clause: str) -> bool:
    clearance = call.args[2] if len(call.args) > 2 else next((k.value for k in call.keywords), None)
    if not isinstance(clearance, ast.Constant) or not isinstance(clearance.value, int | float):
        return True
    return is_stated(float(clearance.value), stated_numbers(clause))

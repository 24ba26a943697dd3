"""What the user's words ask about each object, and a step on it that does something else, replaced.

A small model reaches for ``avoid`` whatever the words say about an object: ``avoid(t,
detect_objects('chair'), 0.3)`` for "keeping a smaller distance from the chair", ``avoid(t,
detect_objects('paddle'), 0.2)`` for "go slower if paddle is within 0.2", ``avoid(t,
detect_objects('bottle'), 0.5)`` for "do not go left of the bottle". Each clause of the user's words
(split at punctuation, "and", "then", "but", "also"; "while" stays inside) that names exactly one of
the scene's objects asks one thing of it:

- a speed change near it ("slower", "faster", ... with a place word: "near", "within 0.2 of", "if
  X is within", "around"), when the code changes no speed anywhere: the one distance step on that
  object (or ``circle_around`` it, when no word asks to go round: "speed up around X") becomes
  ``scale_speed(t, <calibrated factor>, near=X)`` (with ``radius=`` when the clause says "within
  <number>"); in an ``avoid`` of several objects, the object leaves the list and the speed
  step follows it;
- a side ("do not go left of X" -> the right side, "stay to the right of X") -> ``keep_side``;
- closer ("closer", "nearer", "a smaller distance", "approach") or away ("further", "away", "a
  greater distance") -> a step the other way (``move_away`` for closer, ``move_closer`` for away),
  or an ``avoid`` of that one object with a clearance the clause does not state, becomes
  ``move_closer`` / ``move_away`` with the clause's vague word (``avoid`` of the least distance the
  clause states, where it states one: "pass the chair with at least a metre to spare");
- to pass close by it ("swing by X", "fly close past X", "come close to X") -> the one distance step
  on it (or ``reach`` / ``stop_at`` of it, where the clause does not end there) becomes ``pass_through``.

A ``keep_side`` of an object whose clause asks no side but a distance or a pace ("it should stay
nearer to the chair than it does now" answered with ``keep_side(t, 'front', chair)``) does another
job: it is replaced like a distance step.

A ``midpoint`` of an object the words name and one they do not (with no "middle" or "between" in
them) is the named object itself.

Crossed objects: when one clause asks a pace near one object and another asks a distance to a
second, and the code places its one speed step near the second object and none near the first
("go faster within 0.3 of the ear and move closer to the tin opener" -> ``move_closer(ear)``,
``scale_speed(t, 1.4, near=tin opener)``), the speed step moves to the first object (with the
clause's radius), and a distance step on the first object goes to the second, or leaves when the
second has its own. More generally, a distance step on an object no clause asks a distance of goes
to the one object a clause asks one of and no step moves by, or leaves where that object's pace is
already placed; a step against the asked way beside one that goes it leaves; a pace's stated reach
("within 0.2", "no more than 0.2 away") is given to its speed step.

An object that two clauses ask different things of is left alone, and so is every step the words
agree with. A review note says what was replaced and why. Measured on stored answers in
docs/benchmarks.md.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    DISTANCE_STEPS,
    SPEED_STEPS,
    assigned_call,
    call_of,
    called_name,
    detected_name,
    in_place_of,
    objects_of,
    on_object,
    parse_code,
    placed_near,
    step_on_object,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.least_distances import come_within_stated_reaches, keep_stated_clearances
from trajadapt.readers.object_words import (
    PACES,
    WITHIN,
    ObjectAsk,
    asked_words,
    ends_at_the_place,
    object_asks,
)
from trajadapt.readers.paces import asked_factor
from trajadapt.readers.words import (
    MINIMUM_DISTANCE,
    asks_distance,
    intensity_word,
    is_stated,
    names_in,
    stated_numbers,
)

CIRCLING = re.compile(
    r"\b(?:circl\w*|encircl\w*|revolv\w*|orbit\w*|loop\w*|spin\w*|full\s+(?:turn|circle)"
    r"|go(?:es|ing)?\s+(?:all\s+the\s+way\s+)?round)\b",
    re.I,
)
"""Words that ask to go round an object; without them, "speed up around X" places a speed."""


def _steps_for_place(ask: ObjectAsk, words: str) -> tuple[str, ...]:
    """The steps on an object that may stand where the clause asks something of it."""
    if ask.relation in PACES and not CIRCLING.search(words):
        return (*DISTANCE_STEPS, "circle_around")
    if ask.relation == "by" and not ends_at_the_place(ask.clause, words):  # "detour by X": no reach(X)
        return (*DISTANCE_STEPS, "reach", "stop_at")
    return DISTANCE_STEPS


def replace_object_steps(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each step on an object that does not do what the words ask of it replaced, noted."""
    words, names = " ".join(asked), list(names)
    asks = object_asks(words, names)
    lines, notes = code.splitlines(), list[str]()
    _crossed_objects(lines, notes, asks)
    _distance_steps_where_asked(lines, notes, asks, words, names)
    _opposite_steps(lines, notes, asks)
    _reach_of_paces(lines, notes, asks)
    changes_speed = any(call_of(line, SPEED_STEPS) is not None for line in lines)
    for ask in asks.values():
        if ask.relation in PACES and changes_speed:
            continue
        written = _steps_for_place(ask, words)
        steps = [
            i
            for i, line in enumerate(lines)
            if on_object(call_of(line, written), ask.name) or _side_of_unsided(line, ask)
        ]
        if len(steps) != 1 or (ask.relation == "side" and any(call_of(x, ("keep_side",)) for x in lines)):
            continue
        replaced = _replacement(lines[steps[0]], ask)
        if replaced is None:
            continue
        notes.append(f"`{lines[steps[0]].strip()}` -> `{'; '.join(replaced)}`: the instruction asks "
                     f"{asked_words(ask)} {ask.name}")  # fmt: skip
        lines[steps[0] : steps[0] + 1] = [in_place_of(lines[steps[0]], line) for line in replaced]
    _unnamed_midpoints(lines, notes, words, names)
    keep_stated_clearances(lines, notes, words, names)
    come_within_stated_reaches(lines, notes, words, names)
    return "\n".join(lines), notes


def _crossed_objects(lines: list[str], notes: list[str], asks: dict[str, ObjectAsk]) -> None:
    """A speed step near the object a distance is asked of, when a pace is asked near another: swapped."""
    paced = [a for a in asks.values() if a.relation in PACES]
    placed = [a for a in asks.values() if a.relation in ("closer", "away")]
    if len(paced) != 1 or len(placed) != 1:
        return
    pace, place = paced[0], placed[0]

    def speed_near(name: str) -> list[int]:
        return [i for i, x in enumerate(lines) if _paced_object(x) == name.casefold()]

    crossed = speed_near(place.name)
    if speed_near(pace.name) or len(crossed) != 1:
        return
    index, before = crossed[0], lines[crossed[0]].strip()
    lines[index] = in_place_of(lines[index], _placed_near(lines[index], pace))
    notes.append(f"`{before}` -> `{lines[index].strip()}`: the instruction asks {asked_words(pace)} "
                 f"{pace.name}, and {asked_words(place)} {place.name}")  # fmt: skip
    _moved_distance_steps(lines, notes, pace, place)


def _placed_near(line: str, pace: ObjectAsk) -> str:
    """``line`` (a speed step) placed near ``pace``'s object, with its radius, going the asked way."""
    _, call, skill = assigned_call(line)  # type: ignore[misc]
    keywords = [k for k in call.keywords if k.arg not in ("near", "radius")]
    call.args = call.args[:2]
    call.keywords = [*keywords, ast.keyword("near", _expression(f"detect_objects({pace.name!r})"))]
    if pace.radius is not None:
        call.keywords.append(ast.keyword("radius", ast.Constant(pace.radius)))
    factor = call.args[1] if len(call.args) > 1 else None
    faster = pace.relation == "faster"
    if skill == "scale_speed" and isinstance(factor, ast.Constant) and isinstance(factor.value, int | float):
        if (float(factor.value) > 1.0) != faster:
            call.args[1] = ast.Constant(asked_factor(pace.clause, faster))
    return f"t = {ast.unparse(call)}"


def _moved_distance_steps(lines: list[str], notes: list[str], pace: ObjectAsk, place: ObjectAsk) -> None:
    """Distance steps on the object only a pace is asked near: onto ``place``'s object, or left out."""
    steps = [i for i, x in enumerate(lines) if _sole_object(x) == pace.name.casefold()]
    has_own = any(step_on_object(x, place.name) for x in lines)
    for index in reversed(steps):
        if has_own:
            notes.append(
                f"left out `{lines[index].strip()}`: the instruction asks only a pace near {pace.name}"
            )
            del lines[index]
        else:
            _retarget(lines, notes, index, place)


def _retarget(lines: list[str], notes: list[str], index: int, place: ObjectAsk) -> None:
    """The distance step at ``index`` made the one ``place`` asks, on its object.

    A step that goes the asked way (an ``avoid`` or ``move_away`` for "further", a ``move_closer``
    for "closer") with only amounts the clause states keeps them and changes its object; any other
    becomes the asked step with the clause's vague word.
    """
    before = lines[index].strip()
    _, call, skill = assigned_call(lines[index])  # type: ignore[misc]
    if skill in WAYS[place.relation] and _amounts_stated(call, place.clause):
        call.args[1] = _expression(f"detect_objects({place.name!r})")
        after = f"t = {ast.unparse(call)}"
    else:
        word = intensity_word(place.clause)
        amount = f", {word!r}" if word else ""
        after = f"t = {WAYS[place.relation][-1]}(t, detect_objects({place.name!r}){amount})"
    lines[index] = in_place_of(lines[index], after)
    notes.append(f"`{before}` -> `{after}`: the instruction asks {asked_words(place)} {place.name}")


WAYS = {"closer": ("move_closer",), "away": ("avoid", "move_away")}
"""The distance steps that go the way each relation asks."""


def _sole_object(line: str) -> str:
    """The one object a distance step is on (casefolded), or '' for any other line."""
    found = objects_of(call_of(line, DISTANCE_STEPS))
    return found[0].casefold() if len(found) == 1 else ""


def _paced_object(line: str) -> str:
    """The object a speed step is placed near (casefolded), or '' for any other line."""
    return (placed_near(call_of(line, SPEED_STEPS)) or "").casefold()


def _distance_steps_where_asked(
    lines: list[str], notes: list[str], asks: dict[str, ObjectAsk], words: str, names: list[str]
) -> None:
    """Distance steps on objects no clause asks a distance of: moved, or left out beside a pace.

    Such a step goes to the one object a clause asks a distance of and no step moves by ("halt
    near the fan, keep a greater distance from the bottle" -> ``avoid(fan)`` becomes
    ``move_away(bottle)``); on an object a clause asks only a pace near, with its speed step there,
    it leaves. A distance asked with no object named ("keep away from it") leaves every step alone.
    """
    clauses = split_clauses(words, names)
    if any(_asks_a_distance(c) and not names_in(c, names) for c in clauses):
        return
    asked = {n.casefold() for c in clauses if _asks_a_distance(c) for n in names_in(c, names)}

    def strays() -> list[int]:
        return [i for i, x in enumerate(lines) if _sole_object(x) and _sole_object(x) not in asked]

    for place in (a for a in asks.values() if a.relation in WAYS):
        if not any(step_on_object(x, place.name) for x in lines) and len(strays()) == 1:
            _retarget(lines, notes, strays()[0], place)
    paced = {a.name.casefold() for a in asks.values() if a.relation in PACES}
    placed = {_paced_object(x) for x in lines}
    for index in reversed(strays()):
        if _sole_object(lines[index]) in paced & placed:
            notes.append(
                f"left out `{lines[index].strip()}`: the instruction asks only a pace near that object"
            )
            del lines[index]


def _reach_of_paces(lines: list[str], notes: list[str], asks: dict[str, ObjectAsk]) -> None:
    """A speed step near an object with no radius, where the clause gives one ("within 0.2"): given it."""
    for pace in (a for a in asks.values() if a.radius is not None):
        for index, line in enumerate(lines):
            call = call_of(line, SPEED_STEPS)
            if call is None or _paced_object(line) != pace.name.casefold():
                continue
            if any(k.arg == "radius" for k in call.keywords) or len(call.args) > 3:
                continue
            call.keywords.append(ast.keyword("radius", ast.Constant(pace.radius)))
            after = f"t = {ast.unparse(call)}"
            notes.append(f"`{line.strip()}` -> `{after}`: the instruction gives the reach {pace.radius:g}")
            lines[index] = in_place_of(line, after)


def _asks_a_distance(clause: str) -> bool:
    """Whether a clause asks to come closer, further or a least distance ("within 0.2" is a place)."""
    return asks_distance(WITHIN.sub(" ", clause)) or MINIMUM_DISTANCE.search(clause) is not None


def _opposite_steps(lines: list[str], notes: list[str], asks: dict[str, ObjectAsk]) -> None:
    """Steps on an object that go against what its clause asks, beside one that goes the asked way: out."""
    for place in (a for a in asks.values() if a.relation in WAYS):
        other = WAYS["away" if place.relation == "closer" else "closer"]
        on = place.name.casefold()
        if not any(_sole_object(x) == on and called_name(x) in WAYS[place.relation] for x in lines):
            continue
        for index in reversed(range(len(lines))):
            if _sole_object(lines[index]) == on and called_name(lines[index]) in other:
                notes.append(f"left out `{lines[index].strip()}`: the instruction asks {asked_words(place)} "
                             f"{place.name}, and another step does")  # fmt: skip
                del lines[index]


def _amounts_stated(call: ast.Call, clause: str) -> bool:
    """Whether every argument of a distance step after its point is a number the clause states."""
    given = [*call.args[2:], *(k.value for k in call.keywords)]
    numbers = stated_numbers(clause)
    return all(
        isinstance(v, ast.Constant)
        and isinstance(v.value, int | float)
        and is_stated(float(v.value), numbers)
        for v in given
    )


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


def _side_of_unsided(line: str, ask: ObjectAsk) -> bool:
    """Whether ``line`` keeps to a side of the object whose clause asks a distance or a pace, no side."""
    call = call_of(line, ("keep_side",))
    if call is None or ask.relation == "side" or len(call.args) < 3:
        return False
    return (detected_name(call.args[2]) or "").casefold() == ask.name.casefold()


def _replacement(line: str, ask: ObjectAsk) -> list[str] | None:
    """The lines that replace ``line`` (a distance step on ``ask.name``), or None to keep it."""
    _, call, skill = assigned_call(line)  # type: ignore[misc]
    point = f"detect_objects({ask.name!r})"
    if ask.relation in PACES:
        factor = asked_factor(ask.clause, ask.relation == "faster")
        radius = f", radius={ask.radius}" if ask.radius is not None else ""
        speed = f"t = scale_speed(t, {factor}, near={point}{radius})"
        rest = _without_object(call, ask.name) if skill == "avoid" else None
        return [speed] if rest is None else [rest, speed]
    if ask.relation == "side":
        return [f"t = keep_side(t, {ask.side!r}, {point})"]
    if ask.relation == "by":  # to pass close by it: the path visits the object
        return [f"t = pass_through(t, {point})"] if len(objects_of(call)) == 1 else None
    wanted = "move_closer" if ask.relation == "closer" else "move_away"
    if skill == wanted or len(objects_of(call)) != 1:
        return None
    if skill == "avoid" and _clearance_stated(call, ask.clause):
        return None
    least = MINIMUM_DISTANCE.search(ask.clause) if ask.relation == "away" else None
    if least is not None:  # "pass the chair with at least a metre to spare" answered avoid(..., 0.4)
        return [f"t = avoid(t, {point}, {least.group(1)})"]
    word = intensity_word(ask.clause)
    amount = f", {word!r}" if word else ""
    return [f"t = {wanted}(t, {point}{amount})"]


def _without_object(call: ast.Call, name: str) -> str | None:
    """``t = avoid(t, <the other objects>, ...)`` when the avoid names others too; None when only ``name``."""
    others = [n for n in objects_of(call) if n.casefold() != name.casefold()]
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

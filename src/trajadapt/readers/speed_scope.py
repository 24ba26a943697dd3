"""A speed change the instruction ties to one object, written for the whole path: made local to it.

A small model writes ``scale_speed(t, 1.65)`` for "walk a lot faster in the proximity of the
spaniel": the whole path speeds up, not the part near the spaniel. When the user's words have
exactly one clause about speed, that clause names exactly one of the scene's objects and says
where ("near", "close to", "passing", "in the proximity of", "within", ...), and the code has
exactly one speed step with no place of its own (no ``near=``, ``radius=`` or ``part=``), the
step gets ``near=detect_objects('<that object>')``, and the clause's reach ("within 0.1 of the
screw") as ``radius=``. A ``part=`` the words never ask for (no word names a part or an end of
the path: "within 0.1 of the screw, slow down" came back as ``part='second half'``) is no place of
its own either: it gives way to the object. A speed step placed near an end of the path the words
never name (``near=detect_objects('goal')`` for "speed up in the middle of the trajectory": an
example's place, not the user's) is placed where the words say: the part they name, else the whole
path. A review note says so. Measured on stored answers in docs/benchmarks.md.

A speed step placed at an object that only clauses asking no pace name, beside another speed step,
serves no clause and is left out.

A slowing or speeding profile (``speed_profile(t, 'decelerate')``) as the code's one speed step,
where that clause places the pace at its object, the words name no part of the path for the pace
(``paces.part_said_for_the_pace``) and no stop ("slow down on the approach to the person", "go
slower as you near the lamp"), changes the speed towards the goal, not near the object: it becomes
``scale_speed`` of the clause's factor (``paces.asked_factor``: a stated one first) placed there.
(The one speed clause is the one clause with a speed word, or where none has one, the one that asks a
pace by a word of faster or slower: "really crawl past the fan", ``words.asks_pace``.)
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    PLACED_SPEED_STEPS,
    SPEED_STEPS,
    assigned_call,
    call_of,
    called_name,
    in_place_of,
    near_point,
    placed_near,
    signed_number,
    sole_speed_profile,
)
from trajadapt.model.scene import name_key
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.end_words import without_kept_ends
from trajadapt.readers.object_words import WITHIN
from trajadapt.readers.paces import asked_factor, part_said_for_the_pace, stated_factor
from trajadapt.readers.stop_words import COMING_TO_REST
from trajadapt.readers.words import (
    ALL_ALONG,
    EVEN_PACE,
    FASTER,
    PLACE_WORDS,
    SLOWER,
    SPEED_WORDS,
    asks_distance,
    asks_pace,
    asks_visit,
    is_stated,
    longest_names,
    names_in,
    part_named,
    stated_numbers,
)
from trajadapt.sandbox.api import GOAL_NAMES, START_NAMES

END_NAMES = {"goal": {name_key(n) for n in GOAL_NAMES}, "start": {name_key(n) for n in START_NAMES}}
"""The names ``detect_objects`` reads as the path's own ends."""
ENDS_SAID = {
    "goal": re.compile(r"\b(?:goal|end\w*|final\w*|finish\w*|arriv\w*|destination|target|last)\b", re.I),
    "start": re.compile(r"\b(?:start\w*|begin\w*|initial\w*|depart\w*|first|origin)\b", re.I),
}
"""Words that name each end of the path: where the words say none, a speed placed near it is a guess."""
PART_UNPLACED = re.compile(
    r"\b(?:(?:right\s+)?from\s+the\s+(?:very\s+)?(?:start|beginning|outset)|than\s+(?:at|in|near)\s+the\s+\w+"
    r"|(?:is|are|gets?)\s+reached)\b",
    re.I,
)
"""Words naming a part that place no pace there: "slow down right from the start" (all of it), "slower
than at the start" (a comparison); and so do words that keep an end ("keeping the same final pose")."""
KEEPS_A_SIDE = re.compile(r"\b(?:left|right|front|behind|side)\s+of\b", re.I)
"""A side of an object a clause keeps ("stay left of the box"): something asked of it besides a pace."""


def scoped_object(words: str, names: Iterable[str]) -> str | None:
    """The one object the one speed clause of ``words`` places the speed change at, if there is one."""
    scoped = _scoped_clause(words, list(names))
    return None if scoped is None else scoped[1]


def _scoped_clause(words: str, names: list[str]) -> tuple[str, str] | None:
    """The one speed clause of ``words`` and the one object it places the speed change at, if any."""
    clauses = split_clauses(words, names)
    speed_clauses = [c for c in clauses if SPEED_WORDS.search(c)] or [c for c in clauses if asks_pace(c)]
    if len(speed_clauses) != 1 or not PLACE_WORDS.search(speed_clauses[0]):
        return None
    longest = longest_names(names_in(speed_clauses[0], names))
    return (speed_clauses[0], longest[0]) if len(longest) == 1 else None


def localize_speed(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its speed steps placed where the words place them (see the module), and a note each."""
    words = " ".join(asked)
    code, notes = _unsaid_ends_as_places(code, words)
    placed, found = _placed_near_the_named_object(code, words, list(names))
    placed, in_part = _placed_in_the_named_part(placed, words, list(names))
    placed, unpaced = _paces_at_unpaced_objects(placed, words, list(names))
    return placed, notes + found + in_part + unpaced


def _paces_at_unpaced_objects(code: str, words: str, names: list[str]) -> tuple[str, list[str]]:
    """``code`` without speed steps placed at an object only clauses of no pace name, beside another.

    "Swing out wider around the rocker, run the whole thing at a steady 0.4" came back with
    ``set_speed(t, 0.4)`` and ``scale_speed(t, 0.65, near=rocker)``: the rocker's clause asks a
    distance (or a visit, a side), and the pace clause is served by the other speed step.
    """
    clauses = split_clauses(words, names)
    paced = {n for c in clauses if asks_pace(c) for n in names_in(c, names)}
    other_asks = [c for c in clauses if asks_distance(c) or asks_visit(c) or KEEPS_A_SIDE.search(c)]
    unpaced_names = {n for c in other_asks for n in names_in(c, names)} - paced
    lines = code.splitlines()
    speeds = [i for i, line in enumerate(lines) if called_name(line) in SPEED_STEPS]
    places = {i: placed_near(call_of(lines[i], PLACED_SPEED_STEPS)) for i in speeds}
    unpaced = [i for i in speeds if places[i] in unpaced_names]
    if len(unpaced) == len(speeds) == 1:
        return _to_the_paced_part(lines, unpaced[0], clauses, names)
    if not unpaced or len(unpaced) == len(speeds):
        return code, []
    notes = [f"left out `{lines[i].strip()}`: no clause asks a pace near {places[i]}" for i in unpaced]
    return "\n".join(x for i, x in enumerate(lines) if i not in unpaced), notes


def _to_the_paced_part(
    lines: list[str], index: int, clauses: tuple[str, ...], names: list[str]
) -> tuple[str, list[str]]:
    """The one speed step, placed at an object no pace clause names, in the part the pace clauses name.

    "Give the marmoset a wider margin; the last stretch should also run slower" came back as
    ``scale_speed(t, 0.45, near=marmoset)``: the pace is the last stretch's.
    """
    paced = " ".join(c for c in clauses if asks_pace(c))
    part = part_named(PART_UNPLACED.sub(" ", without_kept_ends(paced)))
    found = assigned_call(lines[index])
    if part is None or names_in(paced, names) or found is None:
        return "\n".join(lines), []
    tree, call, _ = found
    _placed_in(call, part)
    before, after = lines[index].strip(), ast.unparse(tree)
    lines[index] = in_place_of(lines[index], after)
    note = (
        f"`{before}` -> `{after}`: no clause asks a pace near that object; the pace clause names the {part}"
    )
    return "\n".join(lines), [note]


def _placed_in_the_named_part(code: str, words: str, names: list[str]) -> tuple[str, list[str]]:
    """``code`` with its one unplaced speed step placed in the one part the one pace clause names.

    "Fly the first part at half speed" came back as ``scale_speed(t, 0.5)``: the whole path slowed.
    A pace clause that names no object and one part of the path ("the start", "the middle", "the
    first half") places the code's one speed step with no place of its own there (``part=``); not
    where the words slow to a stop (a profile's matter) or span the whole path ("from start to finish").
    """
    paced = [c for c in split_clauses(words, names) if asks_pace(c)]
    whole = len(paced) != 1 or names_in(paced[0], names) or ALL_ALONG.search(paced[0])
    part = None if whole else part_named(PART_UNPLACED.sub(" ", without_kept_ends(paced[0])))
    part = None if part in ("goal", "destination", "target") else part  # an end is a place, not a part
    lines = code.splitlines()
    unplaced = [i for i, line in enumerate(lines) if _unplaced_speed_call(line, True) is not None]
    if part is None or len(unplaced) != 1 or COMING_TO_REST.search(words):
        return code, []
    index = unplaced[0]
    tree, call = _unplaced_speed_call(lines[index], True)  # type: ignore[misc]
    _placed_in(call, part)
    before, after = lines[index].strip(), ast.unparse(tree)
    lines[index] = in_place_of(lines[index], after)
    return "\n".join(lines), [
        f"`{before}` -> `{after}`: the instruction changes the speed in the {part} only"
    ]


def _unsaid_ends_as_places(code: str, words: str) -> tuple[str, list[str]]:
    """Each speed step placed near an end of the path the words never name, placed where they say.

    ``scale_speed(t, 1.4, near=detect_objects('goal'))`` for "speed up in the middle": the part the
    words name (``part='middle'``), else the whole path; where a pace clause names that end as a
    stretch ("speed up the start"), that stretch. A place at the path's own last or first
    waypoint (``near=t[-1]`` for "pick up the pace over the final stretch") is, where the words name
    that end, the part the pace clause names, else ``'end'`` / ``'start'``.
    """
    lines, notes = code.splitlines(), []
    for index, line in enumerate(lines):
        found = assigned_call(line)
        if found is None or found[2] not in PLACED_SPEED_STEPS:
            continue
        tree, call, name = found
        waypoint = _end_waypoint(call)
        end = waypoint or _end_named(placed_near(call))
        own = _stating_clause(call, words) if name == "scale_speed" else None
        said = end is not None and ENDS_SAID[end].search(own or words) is not None
        if end is None or (said and waypoint is None and not _end_as_a_part(end, words)):
            continue
        part = part_named(own or " ".join(c for c in split_clauses(words) if asks_pace(c)))
        if said:
            part = part or ("end" if end == "goal" else "start")
        _placed_in(call, part)
        before, after = line.strip(), ast.unparse(tree)
        lines[index] = in_place_of(line, after)
        where = f"in the {part}" if part else "everywhere"
        never = (
            f"its clause ({own.strip()!r}) never names the {end}"
            if own
            else f"the words never name the {end}"
        )
        placed = "a waypoint" if waypoint else f"the {end} point"
        why = f"{placed} is no place for a pace said of the {end}" if said else never
        notes.append(f"`{before}` -> `{after}`: {why}; the words change the speed {where}")
    return "\n".join(lines), notes


END_AS_A_PART = {
    "start": re.compile(
        r"(?<!near\s)(?<!around\s)(?<!by\s)(?<!at\s)(?<!to\s)(?<!from\s)(?<!past\s)\bthe\s+(?:start|beginning)\b"
        r"(?!\s+(?:point|position|pose|location|waypoint))",
        re.I,
    ),
    "goal": re.compile(
        r"(?<!near\s)(?<!around\s)(?<!by\s)(?<!at\s)(?<!to\s)(?<!from\s)(?<!past\s)\bthe\s+end\b"
        r"(?!\s+(?:point|position|pose|location|waypoint))",
        re.I,
    ),
}
"""An end said as a stretch of the path, not a place near which ("speed up the start", "slow the end";
"the opening section" is read as "the start"; not "near the start", "at the end point")."""


def _placed_in(call: ast.Call, part: str | None) -> None:
    """``call`` (a speed step) placed in ``part`` (None: everywhere), its own place taken away.

    A place given in order (near, radius, part) goes with the keywords.
    """
    call.args = call.args[:2]
    call.keywords = [k for k in call.keywords if k.arg not in ("near", "radius", "part")]
    if part:
        call.keywords.append(ast.keyword("part", ast.Constant(part)))


def _end_as_a_part(end: str, words: str) -> bool:
    """Whether a pace clause names the end as a stretch of the path (``END_AS_A_PART``)."""
    return any(END_AS_A_PART[end].search(c) for c in split_clauses(words) if asks_pace(c))


def _stating_clause(call: ast.Call, words: str) -> str | None:
    """The one clause that states a ``scale_speed``'s factor ("halve the speed through the middle": 0.5).

    That clause places the step: "halve the speed through the middle third, then ease down to a stop
    by the goal" names the goal only in the other clause.
    """
    factor = signed_number(call.args[1]) if len(call.args) > 1 else None
    if factor is None or factor <= 0 or factor == 1:
        return None
    stating = [c for c in split_clauses(words) if stated_factor(c, factor > 1) == factor]
    return stating[0] if len(stating) == 1 else None


def _end_waypoint(call: ast.Call) -> str | None:
    """'goal' or 'start' where the speed step's place is the path's own last or first waypoint (``t[-1]``)."""
    near, variable = near_point(call), call.args[0] if call.args else None
    if not isinstance(near, ast.Subscript) or not isinstance(near.value, ast.Name):
        return None
    if not isinstance(variable, ast.Name) or near.value.id != variable.id:
        return None  # a point of another list ("pts[-1]"), not the path's own end
    index = near.slice.elts[0] if isinstance(near.slice, ast.Tuple) and near.slice.elts else near.slice
    try:
        value = ast.literal_eval(index)
    except ValueError:
        return None
    return {-1: "goal", 0: "start"}.get(value) if isinstance(value, int) else None


def _end_named(name: str | None) -> str | None:
    """'goal' or 'start' where ``name`` is how ``detect_objects`` calls the path's own end, else None."""
    if name is None:
        return None
    return next((end for end, spellings in END_NAMES.items() if name_key(name) in spellings), None)


def _placed_near_the_named_object(code: str, words: str, names: list[str]) -> tuple[str, list[str]]:
    """``code`` with its one unplaced speed step placed near the object the words name, and a note."""
    scoped = _scoped_clause(words, names)
    if scoped is None:
        return code, []
    clause, target = scoped
    if EVEN_PACE.search(clause) and asks_distance(clause):
        return code, []  # "hold a constant 0.2 as you move nearer to the drake": the whole way, and closer
    parts_said = part_said_for_the_pace(clause, words, names)
    lines = code.splitlines()
    unplaced = [
        i
        for i, line in enumerate(lines)
        if _unplaced_speed_call(line, parts_said) is not None and not _said_elsewhere(line, clause, words)
    ]
    if not unplaced and not parts_said and not COMING_TO_REST.search(words):
        return _profile_placed(lines, clause, target)
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


def _profile_placed(lines: list[str], clause: str, target: str) -> tuple[str, list[str]]:
    """``lines`` with their one speed step, a slowing or speeding profile, made a scale near ``target``."""
    profile = sole_speed_profile(lines)
    slower, faster = bool(SLOWER.search(clause)), bool(FASTER.search(clause))
    if profile is None or profile[1] not in ("decelerate", "accelerate") or slower == faster:
        return "\n".join(lines), []
    index = profile[0]
    variable = lines[index].split("=")[0].strip()
    reach = WITHIN.search(clause)
    radius = f", radius={float(reach.group(1)):g}" if reach is not None else ""
    step = (
        f"{variable} = scale_speed({variable}, {asked_factor(clause, faster):g}, "
        f"near=detect_objects({target!r}){radius})"
    )
    before = lines[index].strip()
    lines[index] = in_place_of(lines[index], step)
    note = f"`{before}` -> `{step}`: the instruction changes the speed near {target}, not towards the goal"
    return "\n".join(lines), [note]


def _said_elsewhere(line: str, clause: str, words: str) -> bool:
    """Whether the step's speed is a number another clause states, not the speed clause.

    "Drive at 0.3 and go slower near the bed": ``set_speed(t, 0.3)`` is the first clause's, for the
    whole path; only the slowing belongs near the bed.
    """
    found = assigned_call(line)
    if found is None or found[2] != "set_speed" or not found[1].args[1:2]:
        return False  # a factor is no speed another clause states
    value = signed_number(found[1].args[1])
    return (
        value is not None
        and not is_stated(value, stated_numbers(clause))
        and is_stated(value, stated_numbers(words))
    )


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

"""A move the user's words place on one part of the path, written for all of it: moved to that part.

A small model writes ``shift(t, 'left')`` for "shift the starting position to the left" (the whole
path moves, the start stays), ``shift_goal(t, 'back', 1.5)`` or ``move_closer(t,
detect_objects('goal'))`` for "move backwards by 1.5 after reaching the goal position" (the path
never goes past its goal), and ``move_away(t, detect_objects('goal'))`` for "the goal position a
little downwards". Each clause of the user's words (split by ``clause_split.split_clauses``)
that names one part of the path and one direction asks for a move of that part:

- the start ("the start", "starting position", "initial point", "beginning") -> ``shift_start``;
- the goal ("the goal", "goal position", "end point", "final position", "destination") ->
  ``shift_goal``, unless the clause keeps it ("keeping the goal the same");
- past the goal ("after reaching the goal", "beyond the end", "once at the destination") ->
  ``extend`` (also with no direction when the clause says "further", "more", "continue": along the
  final heading), unless the code already goes on past the goal;
- the first N waypoints ("first 6 points") -> ``shift_part(..., part=(0, N))``; moved closer to or
  away from an object the clause names, with no direction -> that object's one ``move_closer`` /
  ``move_away`` takes ``part=(0, N)`` (a keyword the prompt does not show: the reader sets it);
- a new goal ("the new goal position is the midpoint of ...", "the goal should be the lamp", "end at
  the lamp"): a ``pass_through`` or ``move_closer`` of a point the code computes from the scene's
  objects -> ``reach`` of that point (the path ends there instead of passing by).

The one step written for it is replaced: a whole-path ``shift`` in that direction (or, past the
goal, a ``shift_goal``), else a ``move_closer``/``move_away`` to the path's own start or goal (a
landmark, not a place to approach). The step keeps its amount; a landmark step takes the clause's
number or vague word. A going-on past the goal that the clause says ("keep going for another 0.8")
and no step was written for is added. Nothing else changes, and a review note says what was
replaced and why. The reading of the words is ``part_words``. Measured in docs/benchmarks.md.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    after_last_step,
    call_of,
    called_name,
    detected_name,
    direction_argument,
    in_place_of,
    parse_code,
    part_argument,
    skill_program,
)
from trajadapt.model.geometry import DIRECTION_SYNONYMS, OPPOSITE_DIRECTIONS
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.part_words import PartMove, first_count, part_moves
from trajadapt.readers.stop_words import COUNT
from trajadapt.readers.words import AWAY, CLOSER, PART_OR_END, names_in
from trajadapt.sandbox.api import GOAL_NAMES, START_NAMES
from trajadapt.skills import SKILL_NAMES

SENTENCES = re.compile(r"[;!?]|\.(?!\d)|\b(?:then|but)\b", re.I)
NEW_GOAL_STEPS = ("pass_through", "move_closer", "stop_at")
"""Steps a model writes for "end at X" that leave the path ending elsewhere: ``stop_at`` stops where the
path passes nearest X, not at X."""
NEW_GOAL = re.compile(
    r"\bnew\s+(?:goal|end|destination)|\b(?:goal|destination)(?:\s+(?:position|point))?\s+(?:is|should be"
    r"|becomes|will be|must be)\b"
    r"|\b(?:end|finish|terminate)\s+(?:(?:exactly|right|directly|precisely|just)\s+)?(?:at|on|in)\b"
    r"|\b(?:set|make|move|change|put|place|relocate)\s+(?:the\s+|its\s+)?(?:goal|destination)"
    r"(?:\s+(?:position|point))?\s+(?:to|at|be|as|onto)\b|\bas\s+(?:the\s+|its\s+)?(?:new\s+)?(?:goal|destination)\b",
    re.I,
)
"""Words that give the path a new goal: "the new goal", "the goal should be", "end at", "set the goal
to", "use X as the goal"."""
SHIFTS = ("shift", "shift_goal")
REGION = re.compile(
    r"\b(?:top|bottom|upper|lower|left|right|front|back|rear|far|near)(?:most)?\s+(?:part|side|region|area|half)\b",
    re.I,
)
"""A region of the scene named like a part ("the bottom part", "the left side"): no part of the path."""
LANDMARK_STEPS = ("move_closer", "move_away", "append_segment")
"""Steps a small model writes with the path's own start or goal as their point (a segment appended
to the goal goes nowhere)."""
GOALS = frozenset(name.casefold() for name in GOAL_NAMES)
LANDMARKS = GOALS | {name.casefold() for name in START_NAMES}


def scope_to_parts(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with the one step written for each part move replaced by that move, and a note each."""
    words = " ".join(asked)
    said = said_directions(words)
    lines = code.splitlines()
    notes: list[str] = []
    if NEW_GOAL.search(words):
        _reach_the_new_goal(lines, notes, words)
    _object_moves_of_first_waypoints(lines, notes, words)
    _moves_of_no_part(lines, notes, words)
    _whole_shifts_beside_part_moves(lines, notes, words)
    _stops_at_the_goal(lines, notes)
    for move in part_moves(words):
        if move.part == "past the goal" and any(_goes_on(line) for line in lines):
            continue
        index, amount = _step_for(move, lines, said)
        if index is None:
            _add_going_on(move, lines, notes)
            continue
        if move.named and _stretch_read_twice(lines, index, move, amount, notes):
            continue
        before = lines[index].strip()
        replaced = [f"t = {step}" for step in _against_the_rest(move, lines, index, move.call(amount))]
        lines[index : index + 1] = [in_place_of(lines[index], line) for line in replaced]
        why = f"the instruction moves {move.part}, not the whole path"
        against = f", and {move.part} against the rest's shift" if len(replaced) > 1 else ""
        notes.append(f"`{before}` -> `{'; '.join(replaced)}`: {why}{against}")
    return "\n".join(lines), notes


def _whole_shifts_beside_part_moves(lines: list[str], notes: list[str], words: str) -> None:
    """A whole-path shift repeating a part move's way and amount, said only by clauses naming a part: out.

    "Dip the middle 0.1 lower, ending at the same spot" came back as ``shift_part(t, 'down', 0.1,
    'middle')`` and ``shift(t, 'down', 0.1)``: the one clause read twice, the middle moved twice. A
    going-on past the goal is such a part move too ("extend the flight 0.5 further left past the
    end" answered ``extend(t, 0.5, 'left')`` and ``shift(t, 'left', 0.5)``).
    """
    unplaced = " ".join(c for c in split_clauses(words) if not PART_OR_END.search(c))
    moved = {(direction_argument(call), _amount(call)) for _, call in _calls(lines, ("shift_part",))}
    moved |= {_going_on(call) for _, call in _calls(lines, ("extend",))}
    for index, call in reversed(_calls(lines, ("shift",))):
        direction = direction_argument(call)
        if (direction, _amount(call)) in moved and direction not in said_directions(unplaced):
            notes.append(
                f"left out `{lines[index].strip()}`: the words move only a part of the path {direction}"
            )
            del lines[index]


def _stretch_read_twice(
    lines: list[str], index: int, move: PartMove, amount: ast.expr | None, notes: list[str]
) -> bool:
    """Whether another step already moves the stretch that way: the whole shift is then left out.

    "Bow the middle of the path about 0.15 to the left" came back as ``shift(t, 'left', 0.15)`` and
    ``lift_middle(t, 'left')``: one clause read twice. The whole shift leaves, and its amount goes to
    the stretch's own step where that has none.
    """
    own = ("lift_middle", "shift_part") if move.named in ("middle", "center") else ("shift_part",)
    for other, call in _calls(lines, own):
        same_part = called_name(lines[other]) == "lift_middle" or part_argument(call) == move.named
        if other == index or direction_argument(call) != move.direction or not same_part:
            continue
        if len(call.args) < 3 and amount is not None and not any(k.arg == "amount" for k in call.keywords):
            call.args.append(amount)
            lines[other] = in_place_of(lines[other], f"t = {ast.unparse(call)}")
        notes.append(f"left out `{lines[index].strip()}`: the words move only {move.part} {move.direction}")
        del lines[index]
        return True
    return False


def _going_on(call: ast.Call) -> tuple[str | None, str]:
    """An ``extend`` step's way and amount as written (``extend(t, 0.5, 'left')``: ('left', '0.5'))."""
    given = {k.arg: k.value for k in call.keywords}
    distance = call.args[1] if len(call.args) > 1 else given.get("distance")
    direction = call.args[2] if len(call.args) > 2 else given.get("direction")
    way = (
        DIRECTION_SYNONYMS.get(str(direction.value).strip().lower())
        if isinstance(direction, ast.Constant)
        else None
    )
    empty = distance is None or (isinstance(distance, ast.Constant) and distance.value is None)
    return way, "" if empty or distance is None else ast.unparse(distance)


def _amount(call: ast.Call) -> str:
    """A shift's amount as written (its third argument), '' where it has none (or ``None``)."""
    given = call.args[2] if len(call.args) > 2 else None
    return (
        ""
        if given is None or (isinstance(given, ast.Constant) and given.value is None)
        else ast.unparse(given)
    )


def _add_going_on(move: PartMove, lines: list[str], notes: list[str]) -> None:
    """The going-on a clause asks past the goal, added when no step was written for it.

    "Once you reach the goal keep going for another 0.8" came back with the clause dropped. Only a
    clause that says to go on ("keep going", "another 0.8", "carry on") asks one; one that only places
    something after the goal ("hover above it once at the goal") does not.
    """
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if move.part != "past the goal" or program is None or not move.goes_on:
        return
    t = program[1]
    amount = [] if move.amount is None else [repr(move.amount)]
    direction = [] if move.direction is None else [f"direction={move.direction!r}"]
    step = f"{t} = extend({', '.join([t, *amount, *direction])})"
    lines.insert(after_last_step(lines, SKILL_NAMES), step)
    notes.append(f"added `{step}`: the instruction goes on past the goal and no step does")


def _against_the_rest(move: PartMove, lines: list[str], index: int, call: str) -> list[str]:
    """The steps for ``move`` when the rest of the path shifts the other way: none of that at the end.

    "Shift the path a little up but the goal a little down": the goal ends lower than it was and
    the middle higher, so at the goal's end of the path the rise is taken back and the goal moves
    down there (``shift_part(..., part='end')``); ``[call]`` alone when there is no such shift.
    """
    if move.part not in ("the start", "the goal") or move.direction is None:
        return [call]
    opposite = OPPOSITE_DIRECTIONS[move.direction]
    shifts = [(i, c) for i, c in _calls(lines, ("shift",)) if direction_argument(c) == opposite]
    if len(shifts) != 1 or shifts[0][0] == index:
        return [call]
    part = "start" if move.part == "the start" else "end"
    whole = shifts[0][1].args[2] if len(shifts[0][1].args) > 2 else None
    amount = _amount_argument(call)
    return [
        f"shift_part(t, {move.direction!r}, {ast.unparse(whole) if whole else None}, part={part!r})",
        f"shift_part(t, {move.direction!r}, {amount}, part={part!r})",
    ]


def _amount_argument(call: str) -> str:
    """The amount written in a ``shift_start``/``shift_goal`` call's source ('None' when none)."""
    parsed = parse_code(call).body[0]
    assert isinstance(parsed, ast.Expr) and isinstance(parsed.value, ast.Call)
    arguments = parsed.value.args
    return ast.unparse(arguments[2]) if len(arguments) > 2 else "None"


def _stops_at_the_goal(lines: list[str], notes: list[str]) -> None:
    """``stop_at`` the path's own goal asks nothing (the path ends there) or undoes a going-on: left out.

    "Move left by 0.2 after you reach the goal" came back as ``extend(t, 0.2, 'left')`` then
    ``stop_at(t, detect_objects('goal'))``, which cut the extension off again.
    """
    for line in [
        x for x in lines if (call := call_of(x, ("stop_at",))) is not None and _on_landmark(call, GOALS)
    ]:
        lines.remove(line)
        notes.append(f"left out `{line.strip()}`: the path ends at its goal already")


WHOLE_PATH = re.compile(
    r"\b(?:whole|entire|complete|full)\s+(?:path|route|trajectory|motion|movement|flight|run|thing|way)\b"
    r"|\ball\s+of\s+(?:the\s+)?(?:path|route|trajectory|it)\b|\beverything\b"
    r"|\b(?:every|each|all(?:\s+the)?)\s+(?:single\s+)?(?:point|waypoint|position|sample)s?\b"
    r"(?!\s+(?:near|nearest|between|around|close|closest|next|beside|within|inside|past|in|at|on|from|after|before)\b)",
    re.I,
)
"""Words that move the path as a whole, ends included ("the whole trajectory", "all of it", "every
point of the path")."""
PAUSE_LENGTH = re.compile(rf"\bfor\s+(?:a\s+)?(?:{COUNT.pattern})", re.I)
"""How long a pause lasts ("hold still for a few waypoints"): no part of the path."""


def _moves_of_no_part(lines: list[str], notes: list[str], words: str) -> None:
    """A move of the start or the goal where the words name no part or end: the whole path's move.

    "Lift the route up 0.2" came back as ``shift_goal(t, 'up', 0.2)``: the goal rises, the start
    stays, the middle rises half as much; "move to the bottom part" as ``shift_part(t, 'down',
    part='end')``. Where no word names a part or an end of the path (``words.PART_OR_END``: "the
    start", "the goal", "the end", "the first half", "waypoints"; "the bottom part" is a region of
    the scene, not of the path), a ``shift_goal`` / ``shift_start`` / ``shift_part`` in a direction
    the words say is ``shift`` with its amount; so is a ``lift_middle`` (which keeps the ends) where
    the words say the whole path ("lift the whole trajectory 15 cm", ``WHOLE_PATH``).
    """
    if PART_OR_END.search(PAUSE_LENGTH.sub(" ", WHOLE_PATH.sub(" ", REGION.sub(" ", words)))):
        return  # "every waypoint", "pause for 3 waypoints" name no part
    said = said_directions(words)
    whole = ("lift_middle",) if WHOLE_PATH.search(words) else ()  # "lift the whole trajectory 15 cm"
    for index, call in _calls(lines, ("shift_goal", "shift_start", "shift_part", *whole)):
        if direction_argument(call) not in said:
            continue
        before = lines[index].strip()
        kept = [keyword for keyword in call.keywords if keyword.arg != "part"]
        after = "t = " + ast.unparse(ast.Call(ast.Name("shift", ast.Load()), call.args[:3], kept))
        lines[index] = in_place_of(lines[index], after)
        notes.append(
            f"`{before}` -> `{after}`: the instruction names no part of the path, so all of it moves"
        )


def _reach_the_new_goal(lines: list[str], notes: list[str], words: str) -> None:
    """The one ``pass_through``/``move_closer``/``stop_at`` of the new goal's objects, as ``reach`` of it.

    The clause that says "new goal" and the words after it (to the end of their sentence or a
    "then"/"but") must name every object the point is made of: "make the midpoint of the box and
    the lamp the new goal" gives one, "go closer to the box and end at the goal" gives none.
    """
    detected = [name for _, call in _calls(lines, NEW_GOAL_STEPS) for name in _detected_names(call)]
    saying = [clause for clause in split_clauses(words, detected) if NEW_GOAL.search(clause)]
    following = [SENTENCES.split(words[m.end() :])[0] for m in NEW_GOAL.finditer(words)]
    given = " ".join(saying + following)
    passing = [
        (i, call)
        for i, call in _calls(lines, NEW_GOAL_STEPS)
        if _scene_point(call) and all(names_in(given, [n]) for n in _detected_names(call))
    ]
    if len(passing) != 1 or any(called_name(line) in ("reach", "append_segment") for line in lines):
        return
    index, call = passing[0]
    before = lines[index].strip()
    after = f"t = reach(t, {ast.unparse(call.args[1])})"
    lines[index] = in_place_of(lines[index], after)
    notes.append(f"`{before}` -> `{after}`: the instruction gives a new goal, so the path ends there")


def _object_moves_of_first_waypoints(lines: list[str], notes: list[str], words: str) -> None:
    """A clause that brings the first N waypoints closer to an object (or away): its step, on them.

    "Shift the first 6 points closer to the chair" answered with ``move_closer(t, chair)`` moves the
    path where it passes the chair, not its first points: the one ``move_closer`` (``move_away``)
    of an object the clause names, written for the whole path, gets ``part=(0, N)``.
    """
    for clause in split_clauses(words):
        count = first_count(clause)
        closer, away = bool(CLOSER.search(clause)), bool(AWAY.search(clause))
        if not count or closer == away:
            continue
        skill = "move_closer" if closer else "move_away"
        written = [
            (i, call)
            for i, call in _calls(lines, (skill,))
            if _scene_point(call)
            and all(names_in(clause, [n]) for n in _detected_names(call))
            and not any(k.arg == "part" for k in call.keywords)
        ]
        if len(written) != 1:
            continue
        index, call = written[0]
        before = lines[index].strip()
        call.keywords.append(
            ast.keyword("part", ast.Tuple([ast.Constant(0), ast.Constant(count)], ast.Load()))
        )
        after = f"t = {ast.unparse(call)}"
        lines[index] = in_place_of(lines[index], after)
        notes.append(
            f"`{before}` -> `{after}`: the instruction moves the first {count} waypoints, not the path"
        )


def _detect_calls(node: ast.expr) -> list[ast.Call]:
    """Every ``detect_objects(...)`` call inside ``node``."""
    return [
        n
        for n in ast.walk(node)
        if isinstance(n, ast.Call) and isinstance(n.func, ast.Name) and n.func.id == "detect_objects"
    ]


def _detected_names(call: ast.Call) -> list[str]:
    """The names the call's point argument passes to ``detect_objects``."""
    found = _detect_calls(call.args[1])
    return [str(n.args[0].value) for n in found if n.args and isinstance(n.args[0], ast.Constant)]


def _scene_point(call: ast.Call) -> bool:
    """Whether the call's point comes from ``detect_objects`` of scene objects (not the path's ends)."""
    return len(call.args) >= 2 and not _on_landmark(call) and bool(_detect_calls(call.args[1]))


def _step_for(move: PartMove, lines: list[str], said: set[str]) -> tuple[int | None, ast.expr | None]:
    """The line written for ``move`` and the amount it gave, or (None, None) when none or several.

    A move past the goal takes any shift in its direction (``shift_start(t, 'back')`` for "once the
    goal is reached, retreat back"); with no direction, or none in its direction, one in a direction
    the words never say ("have it back up by 1.5" answered with ``shift(t, 'up', 1.5)``).
    """
    shifts = (*SHIFTS, "shift_start", "shift_part") if move.part == "past the goal" else SHIFTS[:1]
    found = [(i, call, direction_argument(call)) for i, call in _calls(lines, shifts)]
    written = [(i, call) for i, call, direction in found if direction == move.direction]
    if move.direction is None or (not written and move.part == "past the goal"):
        written = [(i, call) for i, call, direction in found if direction not in (*said, None)]
    if not written:
        written = [(i, call) for i, call in _calls(lines, LANDMARK_STEPS) if _on_landmark(call)]
        return (written[0][0], None) if len(written) == 1 else (None, None)
    if len(written) != 1:
        return None, None
    index, call = written[0]
    return index, call.args[2] if len(call.args) > 2 else None


def _goes_on(line: str) -> bool:
    """Whether the step goes on past the goal: ``extend``, or a segment to somewhere else than the goal."""
    call = call_of(line, ("extend", "append_segment"))
    return call is not None and (called_name(line) == "extend" or not _on_landmark(call))


def _calls(lines: list[str], skills: tuple[str, ...]) -> list[tuple[int, ast.Call]]:
    found = [(i, call_of(line, skills)) for i, line in enumerate(lines)]
    return [(i, call) for i, call in found if call is not None]


def _on_landmark(call: ast.Call, landmarks: frozenset[str] = LANDMARKS) -> bool:
    """Whether the call's point is ``detect_objects('<the path's start or goal>')`` (one of ``landmarks``)."""
    name = detected_name(call.args[1]) if len(call.args) > 1 else None
    return name is not None and name.casefold() in landmarks

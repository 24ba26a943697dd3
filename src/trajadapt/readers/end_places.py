"""A place the words ask the path to end at: the step that ends it there, in place of those written for it.

"Finish at the lamp", "wrap up at the red cup", "land on the mat", "set down at the cycle", "park at
the box", "make the quill your end point": the path's end goes to the object, ``reach(t, lamp)``.
"Stop where it comes closest to the chair": the path ends where it passes nearest the object,
``stop_at(t, chair)``; so does "wind up next to the chair", "end beside the sofa" (as "stop near the
stinkhorn" is read). "End right next to the chair", "park right by the lamp": it ends there too, and
where that pass is further from the object than a small gap it goes on to beside it,
``stop_at(t, chair, beside=True)`` (a ``stop_at`` of the object written for such words gets
``beside=True``); "come to rest within 0.4 of the person" ends beside it at most that far from it,
``stop_at(t, person, within=0.4)`` (the words: ``end_place_words``). A small model answers such words with
a step for another job (a side kept, the end part shifted, the object put in a pass over a list) or
with no step of the object at all.

A clause asks an end place (``asked_end``) when an ending verb (a word of coming to rest too: "come
to a halt", "bring the arm to rest") is followed by a word of place and then by the one scene object
the rest of the clause names ("finish right at", "end up beside", "arrive at", "come to rest on"),
or when it names the object as the end ("make X your end point", "use X as the final position", "the
end point should be X"), or goes to it to finish ("down onto the soap to finish", "at the end go to
the box"). An ending word used as a noun ("at the end near the box") asks none; neither does "stop
at" (``stop_at``'s own words, read as the model reads them).

Unless a step already ends there (``reach`` or ``append_segment`` of the object; ``stop_at`` of it
for an end beside it), the steps written for the clause leave the code: a step on the object alone
when no other clause names the object, and the object's entry in a step's list of objects; the
end step is added after the last step that moves the path (speed steps after it stay after it;
``stop_at``, which leaves the robot at rest there, goes after them all). Code that is not made of
skill calls alone is left alone. An end at the object that the words leave at rest (its clause, or
the next one where it names no object, says a word of stopping: "and be at rest when it gets
there", "fully stopped there", "not moving at the end") also slows to a stop, ``speed_profile(t,
'decelerate', start=0.6)`` last, as a stop at the end is read, unless a step already ends at rest
(``reach`` keeps the speed: "finish right at the quill and come to a complete rest there" arrived at
full speed). An end above the object ("finish about 0.1 directly above the bowl", "end just above
the mug") ends at it and then raises the goal by that height (``shift_goal(t, 'up', 0.1)``, or
'slightly'), in place of the model's own raise of the goal. A review note says what changed and why.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.code_parse import (
    SPEED_STEPS,
    after_last_step,
    assigned_call,
    call_of,
    called_name,
    detected_names,
    direction_argument,
    in_place_of,
    number_arguments,
    objects_of,
    profile_kind,
    skill_program,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.end_place_words import (
    ABOVE_PLACE,
    AT_PLACE,
    BESIDE_PLACE,
    FINISHING,
    NAMED_AS_END,
    NEAREST_PLACE,
    ONTO,
    RIGHT_BESIDE,
    THERE_PLACE,
    WITHIN_PLACE,
)
from trajadapt.readers.paces import STOP_RAMP_START
from trajadapt.readers.stop_words import AT_REST
from trajadapt.readers.words import longest_names, names_in
from trajadapt.skills import SKILL_NAMES

NEGATION = re.compile(r"\b(?:not|never|no)\b|n't\b", re.I)
"""A negation before "end there" ("but don't finish there"): no end there."""
OPENING = re.compile(r"^\s*(?:(?:the|a|an|your|its|that|this)\s+)?", re.I)
ALTERNATIVE = re.compile(r"\s*,?\s*(?:and|or|&|/)\s", re.I)
"""A second object joined to the first ("at the lamp or the box"): no one place."""
MOVES_THE_PATH = frozenset(SKILL_NAMES) - frozenset(SPEED_STEPS)
BESIDE_THE_STOP = tuple(name for name in SKILL_NAMES if name not in ("stop_at", "reach"))
"""Steps on an object that move the path's nearest pass to it: beside an end where the path passes
nearest the object (the words place the end on the path as it was), one on that object alone serves
no clause (a pass through it, a clearance from it)."""


@dataclass(frozen=True)
class AskedEnd:
    """An end the words ask: the clause, the object, and the step that ends the path there."""

    clause: str
    place: str
    skill: str  # 'reach' (at the object) or 'stop_at' (where the path passes nearest it)
    at_rest: bool = False  # the words leave the robot at rest there
    above: str = ""  # a height over the object to end at: a number, or 'slightly' ("just above")
    beside: bool = False  # "end next to": a stop beside the object, not only where the path passes
    within: str = ""  # "come to rest within 0.4 of": a stop beside it, at most that far from it
    named_before: str = ""  # for "end there": the clause before that names the object


def asked_end(clause: str, names: list[str], before: str = "") -> AskedEnd | None:
    """The end place ``clause`` asks, if it asks one (see the module).

    "There" after an ending verb ("and end there") is the one object named just before it, in the
    clause or in the clause ``before`` it ("bring the gripper to the mug and end there").

    >>> asked_end("then wrap up at the red cup", ["cup", "red cup"]).skill
    'reach'
    >>> asked_end("wind up next to the chair", ["chair"]).skill
    'stop_at'
    >>> asked_end("slow down at the end near the box", ["box"]) is None
    True
    """
    places = (
        (AT_PLACE, "reach"),
        (ABOVE_PLACE, "reach"),
        (BESIDE_PLACE, "stop_at"),
        (WITHIN_PLACE, "stop_at"),
        (NEAREST_PLACE, "stop_at"),
    )
    for pattern, skill in places:
        found = pattern.search(clause)
        place = _one_name(clause[found.end() :], names) if found else None
        if found is not None and place is not None:
            above = (found.group("amount") or "slightly") if pattern is ABOVE_PLACE else ""
            within = found.group("within") if pattern is WITHIN_PLACE else ""
            beside = bool(within) or (pattern is BESIDE_PLACE and bool(RIGHT_BESIDE.search(found.group(0))))
            return AskedEnd(clause, place, skill, above=above, beside=beside, within=within)
    there = THERE_PLACE.search(clause)
    if there is not None and not NEGATION.search(clause[: there.start()]):
        inside = _gone_to(clause[: there.start()], names)
        place = inside or _gone_to(before, names)
        return (
            None if place is None else AskedEnd(clause, place, "reach", named_before="" if inside else before)
        )
    named = NAMED_AS_END.search(clause)
    place = _one_name(named.group("named") or named.group("then"), names) if named else None
    if place is None and FINISHING.search(clause):
        reached = [found for found in ONTO.finditer(clause) if _one_name(clause[found.end() :], names)]
        place = _one_name(clause[reached[0].end() :], names) if len(reached) == 1 else None
    return None if place is None else AskedEnd(clause, place, "reach")


def _gone_to(text: str, names: list[str]) -> str | None:
    """The one object ``text`` goes to ("bring the gripper *to the mug*"; not "closest to the fan")."""
    named = longest_names(names_in(text, names))
    gone = [found for found in ONTO.finditer(text) if _one_name(text[found.end() :], names)]
    return _one_name(text[gone[-1].end() :], names) if len(named) == 1 and gone else None


def _one_name(text: str, names: list[str]) -> str | None:
    """The scene object ``text`` opens with ("the red cup, then ..."); not a point made of objects."""
    text = OPENING.sub("", text)
    named = longest_names(names_in(text, names))
    opening = [name for name in named if text.casefold().startswith(name.casefold())]
    if len(opening) != 1 or (ALTERNATIVE.match(text[len(opening[0]) :]) and len(named) > 1):
        return None
    return opening[0]


def end_at_asked_places(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` ending at each place the words ask it to end at, at rest where they ask (see the module)."""
    names = list(names)
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    clauses = [clause for words in asked for clause in split_clauses(words, names)]
    read = [
        asked_end(clause, names, clauses[index - 1] if index else "") for index, clause in enumerate(clauses)
    ]
    ends = [end for end in read if end is not None]
    ends = [
        end for end in ends if not end.named_before or all(e.place != end.place for e in ends if e is not end)
    ]
    if len(ends) != 1:
        return code, []
    end, variable = ends[0], program[1]
    notes: list[str] = []
    if not any(_ends_there(line, end) for line in lines):
        lines, notes = _ended_there(lines, end, clauses, variable)
    elif end.skill == "stop_at" and not names_in(_other_clauses(clauses, end), [end.place]):
        lines, notes = _without_steps_for(lines, end, BESIDE_THE_STOP)  # the nearest pass as it was
    if end.beside:
        lines, notes = _stopped_beside(lines, end, notes)
    raised, step = _raised_end(lines, end, variable) if end.above else (lines, "")
    if raised != lines:
        said = end.clause.strip()
        notes.append(f"`{step}` after the end at the {end.place}: the words ask the end above it ({said!r})")
        lines = raised
    if _rests_there(end, clauses, names) and not _ends_at_rest(lines):
        step = f"{variable} = speed_profile({variable}, 'decelerate', start={STOP_RAMP_START})"
        at = after_last_step(lines, SKILL_NAMES)
        lines = [*lines[:at], step, *lines[at:]]
        said = end.clause.strip()
        notes.append(f"added `{step}`: the words ask the robot at rest at the {end.place} ({said!r})")
    return "\n".join(lines), notes


def _ended_there(
    lines: list[str], end: AskedEnd, clauses: list[str], variable: str
) -> tuple[list[str], list[str]]:
    """``lines`` with the step that ends the path at ``end`` (and less the steps written for it)."""
    notes: list[str] = []
    if not names_in(_other_clauses(clauses, end), [end.place]):
        lines, notes = _without_steps_for(lines, end)
    beside = ", {}={!r}".format(*_beside_argument(end)) if end.beside else ""
    step = f"{variable} = {end.skill}({variable}, detect_objects({end.place!r}){beside})"
    at = after_last_step(
        lines, SKILL_NAMES if end.skill == "stop_at" else MOVES_THE_PATH
    )  # a stop stays last, before a pause there (which it would cut off)
    pauses = [i for i, line in enumerate(lines) if called_name(line) == "wait" and end.place in line]
    at = min([at, *pauses]) if end.skill == "stop_at" else at
    how = {"reach": "ends there", "stop_at": "ends where it passes nearest it"}[end.skill]
    said = end.clause.strip()
    how = f"ends within {end.within} of it" if end.within else how
    notes.append(f"added `{step}`: the words ask the path to end at the {end.place} ({said!r}), so it {how}")
    return [*lines[:at], step, *lines[at:]], notes


def _stopped_beside(lines: list[str], end: AskedEnd, notes: list[str]) -> tuple[list[str], list[str]]:
    """``lines`` with each ``stop_at`` of the end's object stopping beside it (or within), noted."""
    how = f"within {end.within} of" if end.within else "beside"
    why = f"the words ask the end {how} the {end.place} ({end.clause.strip()!r})"
    stopped, noted = [], list(notes)
    for line in lines:
        if _plain_stop_at(line, end.place):
            beside = _beside(line, end)
            noted.append(f"`{line.strip()}` -> `{beside.strip()}`: {why}")
            line = beside
        stopped.append(line)
    return stopped, noted


def _plain_stop_at(line: str, place: str) -> bool:
    """Whether ``line`` is a ``stop_at`` of ``place`` alone that does not stop beside it yet."""
    call = call_of(line, ("stop_at",))
    if call is None or any(k.arg in ("beside", "within") for k in call.keywords):
        return False
    return [name.casefold() for name in objects_of(call)] == [place.casefold()]


def _beside(line: str, end: AskedEnd) -> str:
    """``line``'s ``stop_at`` stopping beside the object (``beside=True``, or ``within=`` the distance)."""
    parsed = assigned_call(line)
    assert parsed is not None
    tree, call, _ = parsed
    name, value = _beside_argument(end)
    call.keywords.append(ast.keyword(name, ast.Constant(value)))
    return in_place_of(line, ast.unparse(tree))


def _beside_argument(end: AskedEnd) -> tuple[str, bool | float]:
    """The keyword of a stop beside the end's object: ``within=<distance>`` where the words give one."""
    return ("within", float(end.within)) if end.within else ("beside", True)


def _other_clauses(clauses: list[str], end: AskedEnd) -> str:
    """The clauses that do not ask the end (nor name its object for an "end there")."""
    return " ".join(clause for clause in clauses if clause not in (end.clause, end.named_before))


def _raised_end(lines: list[str], end: AskedEnd, variable: str) -> tuple[list[str], str]:
    """``lines`` with the goal raised by ``end.above`` right after its end at the object; and the raise.

    Another ``shift_goal`` up is the model's try at the height: the reach after it would undo it. Its
    number stands where the words give none ("end just above the mug" answered with 0.05).
    """
    ups = [i for i, line in enumerate(lines) if direction_argument(call_of(line, ("shift_goal",))) == "up"]
    kept = [line for i, line in enumerate(lines) if i not in ups]
    ending = [index for index, line in enumerate(kept) if _ends_there(line, end)]
    if not ending:
        return lines, ""
    stated = end.above[:1].isdigit() or end.above[:1] == "."
    step = f"{variable} = shift_goal({variable}, 'up', {end.above if stated else repr(end.above)})"
    if not stated and len(ups) == 1 and number_arguments(call_of(lines[ups[0]], ("shift_goal",))):
        step = lines[ups[0]].strip()
    at = ending[-1] + 1
    return [*kept[:at], in_place_of(kept[at - 1], step), *kept[at:]], step


def _rests_there(end: AskedEnd, clauses: list[str], names: list[str]) -> bool:
    """Whether the end's clause, or the next one where it names no object, leaves the robot at rest."""
    index = clauses.index(end.clause)
    after = clauses[index + 1 : index + 2]
    said = [end.clause, *(clause for clause in after if not names_in(clause, names))]
    return any(AT_REST.search(clause) for clause in said)


def _ends_at_rest(lines: list[str]) -> bool:
    """Whether a step leaves the robot at rest at the end: a ``stop_at`` or a slowing to 0."""
    for line in lines:
        kind = profile_kind(call_of(line, ("speed_profile",)))
        if called_name(line) == "stop_at" or (kind is not None and kind.value == "decelerate"):
            return True
    return False


def _ends_there(line: str, end: AskedEnd) -> bool:
    """Whether ``line`` already ends the path at the asked place."""
    enders = ("reach", "append_segment") if end.skill == "reach" else ("stop_at", "reach")
    call = call_of(line, enders)
    return call is not None and [name.casefold() for name in objects_of(call)] == [end.place.casefold()]


def _without_steps_for(
    lines: list[str], end: AskedEnd, skills: Iterable[str] = SKILL_NAMES
) -> tuple[list[str], list[str]]:
    """``lines`` less the steps (of ``skills``) on the end's object alone, and the object in a list.

    A speed step or a pause there ("and hold still there for a few steps") stays.
    """
    kept: list[str] = []
    notes: list[str] = []
    for line in lines:
        call = call_of(line, tuple(skills))
        named = [name.casefold() for name in detected_names(call)] if call is not None else []
        if call is None or end.place.casefold() not in named or called_name(line) in (*SPEED_STEPS, "wait"):
            kept.append(line)
        elif len(named) == 1 or not isinstance(call.args[1], ast.List | ast.Tuple):
            notes.append(f"left out `{line.strip()}`: the words ask the {end.place} as the path's end")
        else:
            kept.append(in_place_of(line, _less_object(line, end.place)))
            change = f"`{line.strip()}` -> `{kept[-1].strip()}`"
            notes.append(f"{change}: the {end.place} is the path's end, not a place it passes")
    return kept, notes


def _less_object(line: str, place: str) -> str:
    """The statement of ``line`` with ``place`` taken out of its call's list of objects."""
    parsed = assigned_call(line)
    assert parsed is not None
    tree, call, _ = parsed
    points = call.args[1]
    assert isinstance(points, ast.List | ast.Tuple)
    left = [
        item
        for item, name in zip(points.elts, objects_of(call), strict=True)
        if name.casefold() != place.casefold()
    ]
    call.args[1] = left[0] if len(left) == 1 else ast.List(left, ast.Load())
    return ast.unparse(tree)

"""A shift in a direction the user never said: the model's guess at something else the words ask.

A small model that cannot place a change writes a shift in some direction: ``shift(t, 'down')`` for
"drive further away from the soap", ``shift_part(t, 'right', part='middle')`` for "go faster in
the middle of the trajectory". When none of the user's words is a direction word (``left``, ``up``,
``backwards``, ...) of that shift and the words ask for something no step makes, the one such shift
becomes that step:

- a clause asks to come closer to / go away from an object and no step touches the object ->
  ``move_closer`` / ``move_away`` of it with the clause's vague word;
- the words ask for a faster or slower pace near one object, and the code changes no speed ->
  ``scale_speed`` near that object with the calibrated factor for the clause's words;
- the words ask for a faster or slower pace in no particular object's place, and the code changes no
  speed -> ``scale_speed`` with the calibrated factor, in the shift's part (``part=``) or the part
  the words name ("in the middle", "at the start", "towards the end"), else everywhere; where they
  slow to a stop ("over the final fifth bring the speed down to a stop"), ``speed_profile(t,
  'decelerate')`` from the share of the path they close with, else from the product's stop ramp.

When the words ask nothing that no step makes, name no direction and no part or end of the path,
and another step changes the path or its pace, the one such shift serves no clause and is left out
("halve the speed and stay further from the bird" answered with a shift down beside the two asked
steps). Where the words say no direction at all, several such shifts are read one by one, first to
last: the first becomes what no step makes, the others serve no clause and are left out ("slow down
whenever the paddle is within 0.2, and stay 0.2 from the marmoset" answered with a shift up, a shift
right and ``move_away`` of the marmoset). Several unsaid shifts beside a said direction (which one
guesses what?), and a shift the words give a direction for, are left alone. A review note says what
changed.
Measured on stored answers in docs/benchmarks.md.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import (
    SPEED_STEPS,
    assigned_call,
    call_of,
    called_name,
    direction_argument,
    extension_direction,
    in_place_of,
    parse_code,
    step_on_object,
)
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.object_words import PACES, asked_words, object_asks
from trajadapt.readers.paces import STOP_RAMP_START, asked_factor, closing_share_start
from trajadapt.readers.stop_words import COMING_TO_REST
from trajadapt.readers.words import FASTER, PART_OR_END, SLOWER, intensity_word, part_named

SHIFTS = ("shift", "shift_part", "shift_goal", "shift_start")
MOVING = re.compile(
    r"\b(?:mov\w*|shift\w*|offset\w*|displac\w*|push\w*|pull\w*|nudg\w*|translat\w*|relocat\w*"
    r"|bring\w*|brought|put\w*|plac\w*|set|sets|lift\w*|rais\w*|lower\w*|drop\w*|tilt\w*|bend\w*)\b",
    re.I,
)
"""Verbs that move something: with a part of the path named, a shift may be what they ask of it."""


def replace_unasked_shifts(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its one shift in an unsaid direction made into what the words ask, and a note."""
    try:
        parse_code(code)
    except SyntaxError:
        return code, []  # code the parser refuses (absurdly nested) is left as it is
    words, names = " ".join(asked), list(names)
    lines = code.splitlines()
    unsaid = _unsaid_shifts(lines, words)
    if len(unsaid) > 1 and said_directions(words):
        return code, []  # some directions said, others not: which shift guesses what cannot be told
    notes: list[str] = []
    while unsaid:
        lines, found = _read_one(lines, unsaid[0], words, names)
        if not found:
            break
        notes += found
        unsaid = _unsaid_shifts(lines, words)
    return ("\n".join(lines), notes) if notes else (code, [])


def _unsaid_shifts(lines: list[str], words: str) -> list[int]:
    """The indexes of the shifts in a direction none of ``words`` says."""
    said = said_directions(words)
    return [i for i, line in enumerate(lines) if _shift_direction(line) not in (None, *said)]


def _read_one(lines: list[str], index: int, words: str, names: list[str]) -> tuple[list[str], list[str]]:
    """``lines`` with the shift at ``index`` made into the asked step or left out, and the note."""
    replaced, reason = _asked_instead(lines, index, words, names)
    if replaced is None:
        return _left_out_beside_others(lines, index, words)
    before = lines[index]
    lines = [*lines[:index], in_place_of(before, replaced), *lines[index + 1 :]]
    return lines, [f"`{before.strip()}` -> `{replaced}`: the instruction names no such direction; {reason}"]


def _asked_instead(lines: list[str], index: int, words: str, names: list[str]) -> tuple[str | None, str]:
    """The step the words ask for in place of the shift at ``index``, and why; (None, '') for none."""
    asks = object_asks(words, names).values()
    for ask in asks:
        if ask.relation in ("closer", "away") and not any(step_on_object(x, ask.name) for x in lines):
            word = intensity_word(ask.clause)
            skill = "move_closer" if ask.relation == "closer" else "move_away"
            step = f"t = {skill}(t, detect_objects({ask.name!r}){f', {word!r}' if word else ''})"
            return step, f"it asks {asked_words(ask)} {ask.name}"
    if any(called_name(x) in SPEED_STEPS for x in lines):
        return None, ""
    paces = [ask for ask in asks if ask.relation in PACES]
    if len(paces) == 1:
        ask = paces[0]
        factor = asked_factor(ask.clause, ask.relation == "faster")
        step = f"t = scale_speed(t, {factor}, near=detect_objects({ask.name!r}))"
        return step, f"it asks for a {ask.relation} pace near {ask.name}"
    faster, slower = bool(FASTER.search(words)), bool(SLOWER.search(words))
    if faster == slower or paces:
        return None, ""
    if slower and COMING_TO_REST.search(words):  # "over the final fifth bring the speed down to a stop"
        start = closing_share_start(words) or STOP_RAMP_START
        return f"t = speed_profile(t, 'decelerate', start={start:g})", "it asks to slow to a stop"
    part = _shift_part(lines[index]) or part_named(words)
    where = f", part={part!r}" if part else ""
    step = f"t = scale_speed(t, {asked_factor(words, faster):g}{where})"
    return step, f"it asks for a {'faster' if faster else 'slower'} pace"


def _left_out_beside_others(lines: list[str], index: int, words: str) -> tuple[list[str], list[str]]:
    """The code without the shift at ``index`` when the other steps make all the words ask.

    That is when every direction the words name is made by another shift or extension (none named: none to
    make; "back the route up by 3" answered with a shift back and a shift up) and they move no part
    or end of the path (a part named for a pause or a pace, "halfway, stop and wait", moves
    nothing), and another step changes the path or its pace: the shift serves no clause (a guess
    copied from an example).
    """
    steps = [i for i, line in enumerate(lines) if called_name(line) not in (None, "get_trajectory")]
    moves_a_part = PART_OR_END.search(words) and MOVING.search(words)
    made = {
        _shift_direction(lines[i]) or extension_direction(call_of(lines[i], ("extend",)))
        for i in steps
        if i != index
    }
    if not said_directions(words) <= made or moves_a_part or steps == [index]:
        return lines, []
    before = lines[index].strip()
    said = "no direction" if not made & said_directions(words) else "no such direction"
    note = f"left out `{before}`: the instruction names {said}, and the other steps make what it asks"
    return [*lines[:index], *lines[index + 1 :]], [note]


def _shift_direction(line: str) -> str | None:
    return direction_argument(call_of(line, SHIFTS))


def _shift_part(line: str) -> str | None:
    """The ``part='...'`` word of a ``shift_part`` line, if it gives one."""
    found = assigned_call(line)
    if found is None:
        return None
    part = next((k.value for k in found[1].keywords if k.arg == "part"), None)
    if part is None and found[2] == "shift_part" and len(found[1].args) > 3:
        part = found[1].args[3]
    return str(part.value) if isinstance(part, ast.Constant) and isinstance(part.value, str) else None

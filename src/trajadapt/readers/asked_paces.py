"""A pace a clause asks and no step makes: the step added.

A small model drops the speed clause of a compound instruction: "move up a little, keeping the
speed constant at 0.1" came back as the shift alone, "as the goal position is reached, reduce the
speed uniformly" as ``stop_at`` of the goal (which the unnamed-objects reader leaves out). Each
clause of the request that is no statement and no negation asks a pace (a pace word of a request
itself, "quick one: go left", asks none) when it

- states a speed ("at a constant speed of 0.2", "the speed constant at 0.1", "set the velocity to
  0.3"; not a limit: "no faster than 2", "cap the speed at 2", "by 0.2") -> ``set_speed(t, 0.1)``;
- asks slower at the goal or the end ("as the goal is reached"), or to decelerate -> ``speed_profile(t,
  'decelerate', start=0.7)`` (the prompt's example); to accelerate -> ``speed_profile(t, 'accelerate')``;
- asks faster or slower -> ``scale_speed(t, <factor>)``: the factor the clause states ("by half")
  or the phrase table's for its amount word ("a lot slower": 0.45); a number that is no factor
  ("raise the speed by 0.2") asks an amount no factor makes, and nothing is added.

A clause that states the speed to keep, answered with a ``scale_speed`` whose factor is that very
number ("slow to a speed of 0.2 near the chair" -> ``scale_speed(t, 0.2, near=chair)``: the speed
taken for a factor), gets the stated speed's step in that line's place.

A clause that names one scene object with a word of place ("near the lamp", "while passing the
box") places the step there (``near=``); one that names a part ("the first half", "the middle")
gives ``part=``. The clause is served when a speed step already makes it: any speed step for a
clause with no object; for a clause with an object, a step placed at that object or one placed
nowhere or at a part of the path (the speed-scope reader places one placed nowhere); a step
placed at another object serves it not. Otherwise the step is added after the last step, and a
review note says which words asked it. Code that is not made of skill calls alone is left alone.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.code_parse import (
    SPEED_STEPS,
    after_last_step,
    call_of,
    called_name,
    detected_names,
    in_place_of,
    number_arguments,
    placed_near,
    skill_program,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.object_words import object_asks
from trajadapt.readers.paces import STOP_RAMP_START, speed_factor, stated_factor
from trajadapt.readers.request_words import is_statement
from trajadapt.readers.stop_words import COMING_TO_REST, ENDING_THERE
from trajadapt.readers.words import (
    FASTER,
    GOAL,
    NEGATED,
    NUMBER_TEXT,
    PLACE_WORDS,
    SLOWER,
    asks_pace,
    longest_names,
    names_in,
    part_named,
)
from trajadapt.sandbox.api import GOAL_NAMES, START_NAMES
from trajadapt.skills import SKILL_NAMES
from trajadapt.skills.core import NUMBER

_CONNECTIVES = (
    r"(?:constant|steady|uniform|fixed|kept|held|set|exactly|about|around|roughly|approximately|equal"
    r"|always|stays?|remains?|is|be|should|of|at|to|=|:)"
)
STATED_SPEED = re.compile(
    rf"\b(?:speed|velocity|pace)\s+(?:{_CONNECTIVES}\s*){{0,4}}({NUMBER_TEXT})(?!\s*(?:%|times\b|x\b|per\s*cent))"
    rf"|\bat\s+({NUMBER_TEXT})\s+(?:units?\s+)?(?:speed|velocity|pace)\b"
    rf"|\b(?:at|with|hold\w*|keep\w*|maintain\w*)\s+(?:a\s+|an\s+)?(?:constant|steady|uniform|even|fixed"
    rf"|unchanging|consistent)\s+"
    rf"({NUMBER_TEXT})(?![\d.])(?!\s*(?:%|times\b|x\b|per\s*cent|\w*\s*(?:height|altitude|elevation|above|high|off)\b))"
    rf"|(?<![\w.])({NUMBER_TEXT})\s*(?:m\s*/\s*s\b|mps\b|met(?:er|re)s?\s+(?:per|a|an|each)\s+second\b)",
    re.I,
)
"""A speed said as a value: "at a speed of 0.1", "speed constant at 0.1", "at 0.3 speed", "at a
steady 0.4", "hold a constant 0.5" (a steady number with no height word after it is a pace), a number
with a unit of speed ("take the last stretch at 0.3 m/s", "0.5 metres per second")."""
LIMIT = re.compile(
    r"\b(?:than|at\s+most|at\s+least|max\w*|min\w*|cap\w*|limit\w*|exceed\w*|under|below|beyond"
    r"|up\s+to|no\s+more|by(?=\s+(?:about\s+|around\s+|roughly\s+|some\s+)?[\d.])|factor)\b",
    re.I,
)
"""Words that make a stated speed a limit or a change by an amount ("by 0.2"), not the speed to keep."""
PAST = re.compile(r"\bpast\b", re.I)  # "crawl past the lamp" places a pace, as "while passing" does
NOT_A_PACE = re.compile(
    r"\bquick\s+(?:one|question|thing|request|favou?r|note|tweak|change|fix|ask|edit|update|word)\b", re.I
)
"""A pace word that asks nothing of the path: "quick one: go to the left", "a quick tweak"."""
PART_ARGUMENT = re.compile(r"\bpart\s*=\s*['\"]([^'\"]+)['\"]")
PROFILE = "profile"
"""Where a speed profile acts, for ``_served``: along the path towards its end."""
END_PLACES = tuple(name.casefold() for name in (*GOAL_NAMES, *START_NAMES))
"""A speed step placed at an end of the path, not at a scene object."""
MOVES = ("side", "closer", "away")
"""What a clause may ask of an object besides a pace: a step placed at it for a pace answers no clause."""
TAKEN_FOR = {"scale_speed": "not a factor", "set_height": "not a height"}
"""What a stated speed was taken for, by the step that took it (the review note says it)."""
HEIGHT_WORDS = re.compile(r"\b(?:height|altitude|elevation|high|low|above|below|up|down|level)\b", re.I)
"""Words of a height: a number beside them may be a level."""
TOWARDS_THE_END = re.compile(
    r"\b(?:towards?|near(?:ing)?|approach\w*|reach\w*|at|by)\s+(?:the\s+)?(?:end|finish)\b"
    r"|\b(?:end|last\s+(?:part|stretch|bit|section))\s+of\s+the\s+(?:path|route|trajectory)\b",
    re.I,
)
AT_THE_END = re.compile(
    r"^(?!.*\b(?:there|(?:at|by|on|beside|to|near)\s+(?:it|that))\b).*\b(?:end|ends|ending|goal|finish\w*|destination)\b",
    re.I,
)
"""A stop the clause places at the path's end, pointing back to no place said before."""
ELSEWHERE = re.compile(r"\b(?:from|before|midway|halfway|partway|part\s+way|middle|briefly|for)\b", re.I)
"""Words that put a stop elsewhere than at the path's end ("from a standstill", "halfway", "for 3 steps")."""
STOPPING_STEPS = ("stop_at", "wait")
"""Steps that bring the robot to rest: a stop asked is made by them."""
DECELERATE = re.compile(r"\bdecelerat\w*", re.I)
ACCELERATE = re.compile(r"\baccelerat\w*", re.I)
PARTS = (
    (re.compile(r"\bfirst\s+half\b", re.I), "first half"),
    (re.compile(r"\b(?:second|last|latter)\s+half\b", re.I), "second half"),
    (re.compile(r"\b(?:the\s+)?(?:middle|halfway|midway)\b", re.I), "middle"),
    (re.compile(r"\b(?:the\s+)?(?:start|beginning)\b(?!\s+(?:position|point))", re.I), "start"),
    (
        re.compile(
            r"\b(?:on|in|for|over|along|during|through|tak\w+|took)\s+the\s+end\b(?!\s+(?:position|point))",
            re.I,
        ),
        "end",
    ),
)
"""Parts of the path a clause names, and the ``part=`` word of the speed skills ("slower on the end",
"take the end gently"; "at the end" says where a slowing ends: a profile)."""
END_PARTS = frozenset({"end", "final", "goal"})
"""The words of the skills' part at the end of the path."""
WHOLE_RUN = re.compile(
    r"\b(?:from|between)\s+(?:the\s+)?(?:start|beginning|outset|takeoff)\s+(?:to|till|until|and)\s+"
    r"(?:the\s+)?(?:finish|end|goal|landing)\b",
    re.I,
)
""""From start to finish": the whole path, no part of it."""


@dataclass(frozen=True)
class AskedPace:
    """What one clause asks of the speed: the step that makes it, and the object it is placed at."""

    clause: str
    step: str
    near: str | None


def add_asked_paces(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with a speed step for each pace a clause asks and no step makes (see the module)."""
    names = list(names)
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    variable = program[1]
    asked = list(asked)
    clauses = [clause for words in asked for clause in split_clauses(words, names)]
    lines, notes = _without_crossed_places(lines, asked, clauses, names)
    places = [_place(line) for line in lines if call_of(line, SPEED_STEPS) is not None]
    lines, notes = _stops_at_other_clauses_objects(lines, clauses, names, notes)
    stopping = any(called_name(line) in STOPPING_STEPS for line in lines)
    added: list[str] = []
    for clause in clauses:
        pace = asked_pace(clause, names, variable)
        taken = _speed_taken_as_factor(lines, pace)
        if pace is not None and taken is not None:
            why = TAKEN_FOR.get(called_name(lines[taken]) or "", "with its value")
            notes.append(f"`{lines[taken].strip()}` -> `{pace.step}`: the words state the speed to keep "
                         f"({clause.strip()!r}), {why}")  # fmt: skip
            lines[taken] = in_place_of(lines[taken], pace.step)
            continue
        if pace is None or _served(pace, places) or (_stops_at_the_end(clause) and stopping):
            continue
        added.append(pace.step)
        places.append(pace.near.casefold() if pace.near else "")  # serves no other clause
        notes.append(f"added `{pace.step}`: the words ask it ({clause.strip()!r}) and no step makes it")
    if not notes:
        return code, []
    end = after_last_step(lines, SKILL_NAMES)
    return "\n".join([*lines[:end], *added, *lines[end:]]), notes


def _without_crossed_places(
    lines: list[str], asked: list[str], clauses: list[str], names: list[str]
) -> tuple[list[str], list[str]]:
    """``lines`` less each speed step placed at an object the words ask something else of, and a note each.

    "Ease off the speed around the piano, and stay on the back side of the chair" came back with
    ``scale_speed(t, 0.65, near=chair)``: the pace went to the other clause's object. A step placed
    at an object goes when the clauses ask a move of that object (a side, closer, further:
    ``object_asks``), none of the clauses naming it asks a pace, and every clause that asks a pace
    names another object ("slow down near it" keeps a step at the object named before).
    """
    pacing = [clause for clause in clauses if asks_pace(clause)]
    asks = object_asks(" ".join(asked), names)
    moves = {name.casefold() for name, ask in asks.items() if ask.relation in MOVES}
    kept: list[str] = []
    notes: list[str] = []
    for line in lines:
        near = placed_near(call_of(line, SPEED_STEPS))
        naming = [clause for clause in clauses if near and names_in(clause, [near])]
        crossed = (
            near is not None
            and near.casefold() in moves
            and pacing
            and not any(clause in pacing for clause in naming)
            and all(longest_names(names_in(clause, names)) or part_named(clause) for clause in pacing)
        )
        if crossed:
            notes.append(f"left out `{line.strip()}`: the words ask no pace near the {near} "
                         f"({' / '.join(repr(c.strip()) for c in pacing)} place it elsewhere)")  # fmt: skip
            continue
        kept.append(line)
    return kept, notes


def _stops_at_other_clauses_objects(
    lines: list[str], clauses: list[str], names: list[str], notes: list[str]
) -> tuple[list[str], list[str]]:
    """``lines`` less a ``stop_at`` of an object no clause ends at, where a clause asks to end at rest.

    "Give the sofa a wider berth, and coast to a standstill at the end" came back with
    ``stop_at(sofa)``: the stop asked is the end's, at no place, and the asked profile makes it.
    """
    if not any(_stops_at_the_end(c) and AT_THE_END.search(c) and not names_in(c, names) for c in clauses):
        return lines, notes
    kept = []
    for line in lines:
        stop = call_of(line, ("stop_at",))
        near = [n for n in detected_names(stop) if n.casefold() not in END_PLACES] if stop else []
        if near and not any(names_in(c, near) and ENDING_THERE.search(c) for c in clauses):
            notes = [*notes, f"left out `{line.strip()}`: the words stop at the end, not at the {near[0]}"]
            continue
        kept.append(line)
    return kept, notes


def _speed_taken_as_factor(lines: list[str], pace: AskedPace | None) -> int | None:
    """The one step that took the clause's stated speed for another quantity or left it out, else None.

    "Slow to a speed of 0.2 near the chair" came back as ``scale_speed(t, 0.2, near=...)`` (the
    speed to keep, taken for a factor), "fly at a constant 0.5" as ``set_height(t, 0.5)`` (for a
    level, where the clause says no height), "hold a steady speed of 0.3" as ``speed_profile(t,
    'constant')`` or ``set_speed`` of another value in the same place (the value left out). None
    when a speed step already keeps the stated value.
    """
    value = _stated_value(pace.clause) if pace is not None else None
    if value is None or pace is None or any(_keeps(line, value) for line in lines):
        return None
    taken = [index for index, line in enumerate(lines) if _took(line, value, pace)]
    return taken[0] if len(taken) == 1 else None


def _keeps(line: str, value: float) -> bool:
    """Whether ``line`` sets the speed to ``value`` (``set_speed`` or a profile with that value)."""
    call = call_of(line, ("set_speed", "speed_profile"))
    return any(abs(number - value) < 1e-9 for number in number_arguments(call))


def _took(line: str, value: float, pace: AskedPace) -> bool:
    """Whether ``line`` took the stated speed for another quantity or left it out (see the caller)."""
    name = called_name(line)
    numbers = number_arguments(call_of(line, (name,)) if name else None)
    if name == "scale_speed" or (name == "set_height" and not HEIGHT_WORDS.search(pace.clause)):
        return any(abs(number - value) < 1e-9 for number in numbers)
    if name == "speed_profile":
        return "'constant'" in line and _object_place(line) == _placed(pace)
    return name == "set_speed" and _object_place(line) == _placed(pace)


def _placed(pace: AskedPace) -> str | None:
    return pace.near.casefold() if pace.near else None


def asked_pace(clause: str, names: list[str], variable: str = "t") -> AskedPace | None:
    """The speed step ``clause`` asks, if it asks one (see the module).

    >>> asked_pace("keeping the speed constant at 0.1", []).step
    't = set_speed(t, 0.1)'
    >>> asked_pace("go a lot slower near the lamp", ["lamp"]).step
    "t = scale_speed(t, 0.45, near=detect_objects('lamp'))"
    """
    clause = NOT_A_PACE.sub(" ", clause)
    if is_statement(clause) or NEGATED.search(clause):
        return None
    near = _placed_object(clause, names)
    where = f", near=detect_objects({near!r})" if near else _part_argument(clause)
    call = _stated_speed(clause, variable, where) or _changed_pace(clause, variable, where)
    return None if call is None else AskedPace(clause, f"{variable} = {call}", near)


def _stated_speed(clause: str, t: str, where: str) -> str | None:
    """``set_speed`` of the speed the clause states as the one to keep (not a limit), if it states one."""
    value = _stated_value(clause)
    return None if value is None else f"set_speed({t}, {value:g}{where})"


def _stated_value(clause: str) -> float | None:
    """The speed the clause states as the one to keep ("at a speed of 0.2"; not a limit), if any."""
    stated = STATED_SPEED.search(clause)
    if stated is None or LIMIT.search(clause):
        return None
    return float(next(value for value in stated.groups() if value is not None))


def _changed_pace(clause: str, t: str, where: str) -> str | None:
    """The profile or scale for a clause that asks only faster or only slower, else None."""
    if _stops_at_the_end(clause) and not where and not FASTER.search(clause):
        return f"speed_profile({t}, 'decelerate', start={STOP_RAMP_START})"
    slower, faster = bool(SLOWER.search(clause)), bool(FASTER.search(clause))
    if slower == faster:
        return None
    towards_the_end = GOAL.search(clause) or TOWARDS_THE_END.search(clause) or DECELERATE.search(clause)
    if slower and towards_the_end and "near=" not in where:
        return f"speed_profile({t}, 'decelerate', start={STOP_RAMP_START})"
    if faster and ACCELERATE.search(clause) and not where:
        return f"speed_profile({t}, 'accelerate')"
    unplaced = _without_parts(clause)  # "speed up in the first half": no factor of a half
    stated = stated_factor(unplaced, faster)
    if stated is None and NUMBER.search(unplaced):
        return None  # "raise the speed by 0.2": an amount no factor makes
    factor = stated or speed_factor(unplaced, faster)
    return f"scale_speed({t}, {factor:g}{where})"


def _stops_at_the_end(clause: str) -> bool:
    """Whether the clause asks the motion to end at rest and puts the stop nowhere else.

    "Glide to a halt", "come to a standstill there", "roll to a gradual stop at the end"
    (``stop_words.COMING_TO_REST``), not "halfway" nor a pause "for 3 steps": the speed runs down to 0 at
    the goal.
    """
    return COMING_TO_REST.search(clause) is not None and ELSEWHERE.search(clause) is None


def _served(pace: AskedPace, places: list[str | None]) -> bool:
    """Whether a speed step makes ``pace`` already (see the module).

    For no object and no part, any speed step; for a part of the path ("hurry through the middle"),
    a step on that part (the end is also the 'final' part), on all of it or at an end (the speed-scope
    reader places those), not a profile, which changes the speed towards the end (it serves the
    second half and the end); for an object, a step not placed at another object.
    """
    part = PART_ARGUMENT.search(pace.step)
    if pace.near is not None:
        near = pace.near.casefold()
        return any(place in (None, PROFILE, near) or place.startswith("part:") for place in places)
    if part is None:
        return bool(places)
    asked = part.group(1)
    same = {asked} | (END_PARTS if asked in END_PARTS else set())
    own = any(place in (None, *END_PLACES) or place in {f"part:{p}" for p in same} for place in places)
    return own or ((asked == "second half" or asked in END_PARTS) and PROFILE in places)


def _object_place(line: str) -> str | None:
    """The object a speed step is placed at (casefolded), None for none."""
    near = placed_near(call_of(line, SPEED_STEPS))
    return None if near is None else near.casefold()


def _place(line: str) -> str | None:
    """Where a speed step acts: its object (casefolded), ``part:<part>``, ``PROFILE``, or None (all of it)."""
    near = _object_place(line)
    if near is not None:
        return near
    part = PART_ARGUMENT.search(line)
    if part is not None:
        return f"part:{part.group(1)}"
    return PROFILE if called_name(line) == "speed_profile" else None


def _placed_object(clause: str, names: list[str]) -> str | None:
    """The one scene object the clause places its pace at ("near the lamp"), if it names one."""
    if not (PLACE_WORDS.search(clause) or PAST.search(clause)):
        return None
    named = longest_names(names_in(clause, names))
    return named[0] if len(named) == 1 else None


def _without_parts(clause: str) -> str:
    """``clause`` less the parts of the path it names."""
    for pattern, _ in PARTS:
        clause = pattern.sub(" ", clause)
    return clause


def _part_argument(clause: str) -> str:
    """``, part='<part>'`` for the one part of the path the clause names, else nothing."""
    clause = WHOLE_RUN.sub(" ", clause)
    found = [part for pattern, part in PARTS if pattern.search(clause)]
    return f", part={found[0]!r}" if len(found) == 1 else ""

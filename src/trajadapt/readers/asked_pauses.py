"""A pause a clause asks for, with its count of timesteps, and no step that pauses.

The pause twin of ``asked_relations`` (issue #24 item 1, "every clause gets its step"): "hold
position at the trajectory midpoint for five timesteps" came back as two shifts, "stop near the fan
for 10 timesteps" as ``stop_at(t, fan)``, which ends the path there (a stop for a count of timesteps
is a pause: the path goes on after it). A clause asks a pause when it has a word for stopping or
staying ("pause", "wait", "hold", "halt", "stop", "stay still", "keep the position", "hover",
"linger", "idle", "dwell") and a count of timesteps ("for 10 timesteps", "5 steps", "3 waypoints");
its place is the one scene object it names, or the one part of the path it names
(``words.PLACE_GROUPS``: "the midpoint", "halfway", "the destination"), or, when it points back
("hold there"), follows a lead-in ("once at the destination, hold ...") or a pause with no count
("stop at the midpoint and idle for 5 timesteps"), that of the clause before. A length said without
a count ("for a while", "for some time", "briefly") is ``SOME_TIME_STEPS`` timesteps. When no
``wait`` step is in the code, the clause's ``stop_at`` at that place becomes ``wait`` there, else
``wait(t, <place>, <count>)`` is added as the last step; where the words ask one pause and the code
has one ``wait`` with another count ("hold still for a moment" answered ``wait(t, plate, 1)``), it
takes the asked one. Code that is not made of skill calls alone is left alone. A review note says
so.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable
from dataclasses import dataclass

from trajadapt.code_parse import (
    after_last_step,
    assigned_call,
    called_name,
    detected_name,
    in_place_of,
    skill_program,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.stop_words import COUNT, STOPPING
from trajadapt.readers.words import PLACE_GROUPS, longest_names, names_in, whole_count, whole_words
from trajadapt.skills import SKILL_NAMES
from trajadapt.skills.events import POSITION_WORDS

PAUSE_WORDS = re.compile(
    r"\b(?:paus\w*|wait\w*|halt\w*|stop\w*|hover\w*|linger\w*|freez\w*|idl\w*|dwell\w*|hang\w*|standstill"
    r"|hold(?:s|ing)?(?!\s+(?:the|this|that|its|your|a|an)\s+(?!position|place|spot|station|pose)\w)"
    r"|(?:stay|remain|keep|stand)\w*\s+(?:still|stationary|put|motionless|in place|in the air|aloft)"
    r"|(?:keep|maintain)\w*\s+(?:the\s+|its\s+|your\s+|a\s+)?(?:position|place|spot))\b",
    re.I,
)
"""Words for stopping or staying in place ("hold" but not "hold the height": a level kept, not a place)."""
_SHORT = r"(?:brief|short|quick|momentary|little)"
SOME_TIME = re.compile(
    r"\b(?:for\s+(?:a\s+(?:little\s+|short\s+|brief\s+)?(?:while|moment|bit|time|period(?:\s+of\s+time)?)"
    r"|some\s+(?:time|moments?)|a\s+few\s+(?:moments|seconds|instants))|briefly|momentarily"
    r"|(?:wait|paus|hold|hover|linger|stay|rest|stop|halt|freez|idl|dwell)\w*(?:\s+(?:it|there|still|here|on)){0,2}"
    r"\s+a\s+(?:little\s+|short\s+|brief\s+)?(?:moment|while|beat|spell)(?!\s+(?:ago|later|earlier))"
    rf"|an?\s+{_SHORT}\s+(?:pause|wait|hold|breather|hover|dwell|rest|break)"
    r"|(?:make|makes|made|making|take|takes|took|taking|have|has|had|do|does|did|add|adds|added|adding"
    r"|build|builds|building|insert\w*|put|puts|putting|includ\w*|fit|fits|fitting|work|schedul\w*)"
    rf"(?:\s+in)?\s+an?\s+{_SHORT}\s+(?:stop|halt|standstill))\b",
    re.I,
)
"""A pause's length said without a count: "for a while", "briefly", "wait a moment" (right after the
word for pausing: "stop at the vase in a moment" is no pause), "a brief hover", "build in a short
stop" (a short stop with a verb that adds it: "come to a quick stop" ends the path)."""
SOME_TIME_STEPS = 10
"""The timesteps of a pause said without a count."""
POINTING_BACK = re.compile(r"\b(?:there|it|that spot|that point|the same place)\b", re.I)
LEAD_IN = re.compile(
    r"^\s*(?:once|when\w*|after|upon|on|at|in|as soon as|halfway|mid-?way|near|by|close to|beside|next to)\b",
    re.I,
)
"""A clause that sets where the next one applies ("once at the destination, hold ...")."""


@dataclass(frozen=True)
class AskedPause:
    """A pause one clause asks for: where (an object's name or a part) and for how many timesteps."""

    place: str
    steps: int
    is_object: bool
    clause: str
    opened_by: str = ""  # the clause before it that began the pause with no count ("stop")


def asked_pauses(words: str, names: Iterable[str]) -> list[AskedPause]:
    """The pauses the clauses of ``words`` ask for, in order (see the module)."""
    names = list(names)
    found: list[AskedPause] = []
    previous: tuple[str, bool] | None = None
    carries = False  # the clause before sets the place of this one
    opening = ""  # the clause before, when it began a pause and gave no count
    for clause in split_clauses(words, names):
        place = _place(clause, names)
        carried = place is None and bool(carries or POINTING_BACK.search(clause))
        if carried:
            place = previous
        count = _count(clause)
        pauses = bool(PAUSE_WORDS.search(clause))
        if pauses and count and place is not None:
            found.append(AskedPause(place[0], count, place[1], clause, opening if carried else ""))
        previous, carries = place, bool(LEAD_IN.search(clause)) or (pauses and not count)
        opening = clause if pauses and not count else ""
    return found


def add_asked_pauses(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with a ``wait`` for each pause the words ask and no step makes, and a note each.

    Where every word for stopping belongs to a pause ("halfway, stop and wait for 5 timesteps"), a
    ``stop_at`` left beside the ``wait`` (which ends the path there) serves no clause and leaves.
    """
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    words = " ".join(asked)
    pauses = asked_pauses(words, names)
    notes: list[str] = []
    if not any(called_name(line) == "wait" for line in lines):
        _add_waits(lines, notes, pauses, program[1])
    elif len(pauses) == 1:
        _placed_as_asked(lines, notes, pauses[0], words)
        _count_as_asked(lines, notes, pauses[0])
    if pauses and not _stops_for_good(words, names, pauses):
        for line in [x for x in lines if called_name(x) == "stop_at"]:
            lines.remove(line)
            notes.append(f"left out `{line.strip()}`: the words stop only to pause, and the path goes on")
    return ("\n".join(lines), notes) if notes else (code, [])


def _stops_for_good(words: str, names: Iterable[str], pauses: list[AskedPause]) -> bool:
    """Whether a clause asks to stop (end the path) that is not part of one of the pauses."""
    pausing = {clause for pause in pauses for clause in (pause.clause, pause.opened_by)}
    return any(STOPPING.search(c) and c not in pausing for c in split_clauses(words, list(names)))


def _add_waits(lines: list[str], notes: list[str], pauses: list[AskedPause], variable: str) -> None:
    """A ``wait`` for each pause (a ``stop_at`` at its place becomes it), added to ``lines``."""
    for pause in pauses:
        where = f"detect_objects({pause.place!r})" if pause.is_object else repr(pause.place)
        step = f"{variable} = wait({variable}, {where}, {pause.steps})"
        said = pause.clause.strip()
        stop = next((i for i, line in enumerate(lines) if _stops_at(line, where)), None)
        if stop is not None:
            notes.append(f"`{lines[stop].strip()}` -> `{step}`: {said!r} pauses, then goes on")
            lines[stop] = in_place_of(lines[stop], step)
            continue
        lines.insert(after_last_step(lines, SKILL_NAMES), step)
        notes.append(f"added `{step}`: the words ask a pause ({said!r}) and no step pauses")


def _one_wait(lines: list[str]) -> tuple[int, ast.Module, ast.Call] | None:
    """The code's one ``wait`` written with place and count in order: its line, parsed line and call."""
    waits = [index for index, line in enumerate(lines) if called_name(line) == "wait"]
    found = assigned_call(lines[waits[0]]) if len(waits) == 1 else None
    if found is None or len(found[1].args) != 3:
        return None
    return waits[0], found[0], found[1]


def _placed_as_asked(lines: list[str], notes: list[str], pause: AskedPause, words: str) -> None:
    """The one ``wait`` at a part the words never name, or at another object, at the pause's object.

    "When it gets alongside the ribbed toad, hold still for five waypoints" came back as ``wait(t,
    'middle', 5)``: the example's place, not the user's; "pause next to the couch, and keep a metre
    from the cupboard" as ``wait(t, detect_objects('cupboard'), 3)``: the object of another clause.
    """
    found = _one_wait(lines)
    if found is None or not pause.is_object:
        return
    index, tree, call = found
    place = call.args[1]
    if isinstance(place, ast.Constant):
        if _position_said(str(place.value), words):
            return
    elif (waited := detected_name(place)) is None or waited.casefold() == pause.place.casefold():
        return
    before = lines[index].strip()
    call.args[1] = ast.Call(ast.Name("detect_objects", ast.Load()), [ast.Constant(pause.place)], [])
    after = ast.unparse(tree)
    lines[index] = in_place_of(lines[index], after)
    notes.append(
        f"`{before}` -> `{after}`: the words ask the pause at the {pause.place} ({pause.clause.strip()!r})"
    )


def _position_said(position: str, words: str) -> bool:
    """Whether the words name the part a ``wait`` position word stands for ('middle': "halfway")."""
    said = set(whole_words(words).split())
    return any(said & group for group, code_names in PLACE_GROUPS if position.strip().lower() in code_names)


def _count_as_asked(lines: list[str], notes: list[str], pause: AskedPause) -> None:
    """The one ``wait`` at the pause's place given the pause's count, where it has another number.

    A length said without a count ("briefly", "for a moment") corrects only a wait shorter than 2
    steps: a model's 5 for "pause briefly" is a reading of its own, not a mistake.
    """
    found = _one_wait(lines)
    if found is None or not _waits_at(found[2].args[1], pause):
        return
    index, tree, call = found
    count = call.args[2]
    if not isinstance(count, ast.Constant) or type(count.value) is not int or count.value == pause.steps:
        return
    if COUNT.search(pause.clause) is None and count.value >= 2:
        return
    before = lines[index].strip()
    call.args[2] = ast.Constant(pause.steps)
    after = ast.unparse(tree)
    lines[index] = in_place_of(lines[index], after)
    notes.append(
        f"`{before}` -> `{after}`: the words ask a pause of {pause.steps} timesteps "
        f"({pause.clause.strip()!r})"
    )


def _waits_at(place: ast.expr, pause: AskedPause) -> bool:
    """Whether a ``wait``'s place argument is the pause's place (its object, or its position word)."""
    if pause.is_object:
        return (detected_name(place) or "").casefold() == pause.place.casefold()
    return isinstance(place, ast.Constant) and str(place.value).strip().lower() == pause.place


GOING_ON_AFTER = re.compile(
    r"\b(?:before|then|and\s+then|until)\s+(?:carry\w*|continu\w*|mov\w*|head\w*|go\w*|driv\w*|fly\w*"
    r"|resum\w*|proceed\w*)\s+(?:on|to|towards?|back)\b.*$",
    re.I,
)
"""Where the path goes on to after the pause ("hold still before carrying on to the same goal"): no
place of the pause (read after the pause's own words only)."""


def _place(clause: str, names: list[str]) -> tuple[str, bool] | None:
    """The one object the clause names, else the one part of the path it names, else None.

    What follows the pause ("... before carrying on to the goal", ``GOING_ON_AFTER``) places nothing.
    """
    pause = PAUSE_WORDS.search(clause)
    after = GOING_ON_AFTER.search(clause, pause.end()) if pause else None
    clause = clause[: after.start()] if after else clause
    named = longest_names(names_in(clause, names))
    if len(named) == 1:
        return named[0], True
    if named:
        return None
    said = set(whole_words(clause).split())
    parts = [_position(code_names) for words, code_names in PLACE_GROUPS if said & words]
    parts = [part for part in parts if part]
    return (parts[0], False) if len(parts) == 1 else None


def _position(code_names: frozenset[str]) -> str:
    """The ``wait`` position word among a place's code names ('' for the whole path: no position)."""
    return next((word for word in POSITION_WORDS if word in code_names), "")


def _count(clause: str) -> int:
    """The clause's count of timesteps (``SOME_TIME_STEPS`` for "for a while"), or 0."""
    found = COUNT.search(clause)
    if found is not None:
        return whole_count(found.group(1) or found.group(2))
    return SOME_TIME_STEPS if SOME_TIME.search(clause) else 0


def _stops_at(line: str, where: str) -> bool:
    """Whether ``line`` is ``stop_at`` at the place written ``where``."""
    return called_name(line) == "stop_at" and where.replace(" ", "") in line.replace(" ", "")

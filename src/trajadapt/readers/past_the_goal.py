"""A place the words ask the robot to go once it has reached the goal: a segment appended to it.

"After reaching the goal position, approach the lantern and hover above it for some time" asks
nothing of the path before its goal: the robot goes on from the goal to the lantern. A small model
answers such words with a step on the path it has: ``move_closer(t, detect_objects('goal'))``,
``move_closer(t, detect_objects('lantern'))``, ``pass_over(t, lantern)``, ``extend(t, 'a bit',
'up')`` or ``shift(t, 'up')`` (for "above it"), and none of them goes to the lantern after the
goal. The skill that does is ``append_segment``.

The clauses after the goal (``after_goal``) are the one that says so ("after reaching the goal",
"once at the destination", "upon arrival at the goal", "when you get to the goal": ``words.
PAST_THE_GOAL``) and, when those words open it, the clauses after it in the same sentence (or the
next, after "First reach the goal.") until one speaks of the path as a whole or of its start; a
clause that lengthens the path by no number ("extend it smoothly until it reaches the clock") is
one too, and so is one that goes on by a further amount and names no object ("don't stop at the
current end: continue another 0.1 forward", ``words.GOES_FURTHER``). When those clauses say to go
to one scene object ("approach", "head to", "fly over to", "go straight for", "extend it to") and
name no other, that object is the new end. When no ``append_segment`` goes there, the steps written
for those words leave the code and ``append_segment(t, detect_objects(<object>))`` is added as the
last step (before a step that pauses or spirals there):

- a step that moves the path by that object (``move_closer``, ``pass_over``, ``reach``, ``avoid``,
  ...; not a speed step, a pause or a spiral there), when no clause before the goal names it;
- a move relative to the goal itself (``move_closer(t, detect_objects('goal'))``), or an
  ``extend`` (the path goes on, but not to the object);
- a whole-path shift in a direction that only the after-goal clauses say ("above it"; not a
  lengthening clause, which may say the path's own: "move it left and lengthen it to the clock").

Where those clauses go to no object, the one ``extend`` of the code goes the one direction they say,
and a whole-path or goal shift that way that no clause before the goal says leaves the code (the
extension written twice). Code that is not made of skill calls alone is left alone. A review note
says what changed and why.
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
    extension_direction,
    in_place_of,
    named_argument,
    on_object,
    skill_program,
)
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.words import GOES_FURTHER, PAST_THE_GOAL, SENTENCE_END, longest_names, names_in
from trajadapt.sandbox.api import GOAL_NAMES
from trajadapt.skills import SKILL_NAMES

GO_TO = re.compile(
    r"\b(?:approach\w*|(?:go|goes|going|head\w*|fly|flies|flying|move\w*|travel\w*|proceed\w*|walk\w*"
    r"|drive\w*|return\w*|come|coming|continu\w*|carry\w*\s+on|steer\w*|navigat\w*|make\s+\w+\s+way)"
    r"(?:\s+\w+){0,2}?\s+(?:to|towards?|for|into)\b"
    r"|\w+\s+(?:over|across|straight|directly|right|on|back)\s+(?:to|towards?|into)\b"
    r"|(?:extend\w*|lengthen\w*|prolong\w*)(?:\s+\w+){0,5}?\s+(?:to|towards?|until|till|reach\w*)\b)",
    re.I,
)
"""Words that say where to go: "approach", "head over to", "fly up to", "go straight for", any verb
with "over/across/straight/back to" ("swing over to", "cut across to"), "extend it
until it reaches"."""
EXTENDING = re.compile(r"\b(?:extend\w*|lengthen\w*|prolong\w*)\b(?!.*\d)", re.I)
"""A clause that lengthens the path, with no number: the path goes on past its goal, where it says."""
WHOLE_PATH = re.compile(r"\b(?:path|trajectory|route|whole|entire|start\w*|first)\b", re.I)
"""A clause that speaks of the path as a whole or of its beginning is no longer after the goal."""
MOVED_TO_GOAL = ("move_closer", "move_away", "pass_through", "pass_over", "reach", "stop_at")
SHIFTS = ("shift", "shift_goal")
AT_THE_END = ("wait", "spiral", "circle_around")
"""Steps that act at the place the words go to: they come after the segment that gets there."""


@dataclass(frozen=True)
class AfterGoal:
    """What the words place after the goal: their clauses, and the object they go to (or None)."""

    clauses: tuple[str, ...]
    destination: str | None


def after_goal(words: str, names: Iterable[str]) -> AfterGoal:
    """The clauses of ``words`` placed after the goal and the one object they go to (module docstring)."""
    names = list(names)
    found: list[str] = []
    carrying = False
    for sentence in SENTENCE_END.split(words):
        carrying = carrying and _only_arrives(found[-1])  # "First reach the goal. Then go to the lamp."
        for clause in split_clauses(sentence, names) if sentence.strip() else ():
            said = PAST_THE_GOAL.search(clause)
            if said is not None:
                found.append(clause)
                carrying = not clause[: said.start()].strip(" ,")
            elif EXTENDING.search(clause) or (GOES_FURTHER.search(clause) and not names_in(clause, names)):
                found.append(clause)  # "extend it smoothly to the clock": this clause alone
                carrying = False
            elif carrying and not WHOLE_PATH.search(clause):
                found.append(clause)
            else:
                carrying = False
    places = {
        name for clause in found if GO_TO.search(clause) for name in longest_names(names_in(clause, names))
    }
    others = {name for clause in found for name in longest_names(names_in(clause, names))} - places
    return AfterGoal(tuple(found), places.pop() if len(places) == 1 and not others else None)


def add_destination(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` going on from the goal to the object the words place after it (see the module)."""
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    words = " ".join(asked)
    names = list(names)
    asked_after = after_goal(words, names)
    place = asked_after.destination
    if program is not None and place is None:
        return _directed_extension(
            lines, asked_after.clauses, _before_goal(words, names, asked_after.clauses)
        )
    if program is None or place is None or any(_appends_to(line, place) for line in lines):
        return code, []
    before = _before_goal(words, names, asked_after.clauses)
    written_for = [i for i, line in enumerate(lines) if _written_for(line, place, before, asked_after)]
    variable = program[1]
    step = f"{variable} = append_segment({variable}, detect_objects({place!r}))"
    end = after_last_step(lines, SKILL_NAMES)
    kept = [line for i, line in enumerate(lines[:end]) if i not in written_for]
    at = next(
        (i for i, x in enumerate(kept) if called_name(x) in AT_THE_END and _detects(x, place)), len(kept)
    )
    said = ", ".join(repr(clause.strip()) for clause in asked_after.clauses)
    notes = [
        f"left out `{lines[i].strip()}`: {said} ask(s) for the {place} after the goal" for i in written_for
    ]
    notes.append(f"added `{step}`: {said} go(es) on from the goal to the {place}")
    return "\n".join([*kept[:at], step, *kept[at:], *lines[end:]]), notes


def _directed_extension(lines: list[str], after: tuple[str, ...], before: str) -> tuple[str, list[str]]:
    """The one ``extend`` going the one direction the after-goal clauses say, and no shift that way too.

    "After reaching the end point, keep flying forward another 0.5" came back as ``extend(t, 0.5)``,
    which goes on along the final heading, not forward: it gets the direction. "Don't stop at the
    current end: continue another 0.1 forward" came back as ``extend(t, 0.1)`` beside ``shift(t,
    'front', 0.1)``: a shift of the whole path or of its goal the way only the going-on words say
    (no clause before the goal says it) is the extension written twice, and leaves the code.
    """
    directions = said_directions(" ".join(after))
    extends = [(i, call) for i, line in enumerate(lines) if (call := call_of(line, ("extend",))) is not None]
    if len(directions) != 1 or len(extends) != 1:
        return "\n".join(lines), []
    (index, call), direction = extends[0], directions.pop()
    said = ", ".join(repr(clause.strip()) for clause in after)
    notes = []
    if not _directed(call):
        parsed = assigned_call(lines[index])
        assert parsed is not None
        tree, found, _ = parsed
        found.keywords.append(ast.keyword("direction", ast.Constant(direction)))
        before_line, after_line = lines[index].strip(), ast.unparse(tree)
        lines[index] = in_place_of(lines[index], after_line)
        notes.append(f"`{before_line}` -> `{after_line}`: {said} go(es) on {direction} past the goal")
    elif extension_direction(call) != direction:
        return "\n".join(lines), notes
    if direction in said_directions(before):
        return "\n".join(lines), notes
    twice = [i for i, line in enumerate(lines) if direction_argument(call_of(line, SHIFTS)) == direction]
    notes += [f"left out `{lines[i].strip()}`: {said} go(es) on {direction} past the goal" for i in twice]
    return "\n".join(line for i, line in enumerate(lines) if i not in twice), notes


def _directed(call: ast.Call) -> bool:
    """Whether an ``extend`` call gives a direction (third argument or ``direction=``)."""
    return named_argument(call, "direction", 2) is not None


def _only_arrives(clause: str) -> bool:
    """Whether the clause says no more than reaching the goal ("First reach the goal position")."""
    rest = PAST_THE_GOAL.sub(" ", clause)
    return not re.sub(r"\b(?:position|point|pose|location|is|has|been|reached|first)\b", " ", rest).strip(
        " ,."
    )


def _before_goal(words: str, names: list[str], after: tuple[str, ...]) -> str:
    """The words of the clauses not placed after the goal."""
    return " ".join(clause for clause in split_clauses(words, names) if clause not in after)


def _appends_to(line: str, place: str) -> bool:
    """Whether ``line`` appends a segment whose end names the object ``place``."""
    return called_name(line) == "append_segment" and _detects(line, place)


def _written_for(line: str, place: str, before: str, after: AfterGoal) -> bool:
    """Whether a step answers the after-goal words with a move of the path it has (module docstring)."""
    name = called_name(line)
    if name is None or name in SPEED_STEPS or name not in SKILL_NAMES:
        return False
    if name == "extend":
        return True
    call = call_of(line, (name,))
    if name in MOVED_TO_GOAL and any(on_object(call, goal) for goal in GOAL_NAMES):
        return True
    if name in MOVED_TO_GOAL + ("avoid",) and _detects(line, place):
        return not names_in(before, [place])  # a pause or a spiral there is what the words may ask
    if name in SHIFTS:
        direction = direction_argument(call_of(line, SHIFTS))
        placed = " ".join(clause for clause in after.clauses if not EXTENDING.search(clause))
        only_after = said_directions(placed) - said_directions(before)  # a lengthening's are the path's
        return direction in only_after
    return False


def _detects(line: str, place: str) -> bool:
    """Whether the line detects the object ``place`` anywhere in its arguments."""
    call = call_of(line, SKILL_NAMES)
    return call is not None and place.casefold() in (name.casefold() for name in detected_names(call))

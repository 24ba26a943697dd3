"""A closer, further or side a clause asks of an object, and no step that moves the path relative to it.

The object twin of ``asked_directions`` (issue #24 item 1, "every clause gets its step"): a small
model drops a clause of a compound instruction, and the request for an object is lost with it: "cut
the speed in half, and keep more distance from the ptarmigan" came back as a speed change alone.
For each object that one clause asks to come closer to or keep further from
(``object_words.object_asks``: a clause of ``split_clauses`` that names that one object and asks
one relation of it), when no line of the code but a speed step names the object (a speed step's
``near=`` says where the speed changes, not where the path goes), the reader adds
``move_closer`` / ``move_away`` with the clause's vague word as the last step (``avoid`` with the
clearance when the clause states a least distance: "stay at least 0.2 from it"; ``pass_through``
when the clause asks to pass close by it: "swing by the lamp", "fly close past the box"; ``keep_side``
when it asks to stay on one side of it: "stay on the back side of the chair"); a clause that places
its request at a part or an end of the path ("after reaching the goal, approach the lamp") asks
something else and is left to the model. A step that names
the object in any other way (``avoid``, ``reach``, ``pass_through``, ``circle_around``, a
``detect_objects`` kept in a variable) is an answer to that clause, right or wrong, which
``object_asks`` reads. Code that is not made of skill calls alone is left alone, and so is code
with no step at all (it keeps the path). A review note says what was added and why.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from trajadapt.code_parse import SPEED_STEPS, after_last_step, called_name, skill_program
from trajadapt.readers.object_words import asked_words, object_asks
from trajadapt.readers.words import MINIMUM_DISTANCE, PART_OR_END, intensity_word
from trajadapt.skills import SKILL_NAMES

STEP_OF = {"closer": "move_closer", "away": "move_away", "by": "pass_through", "side": "keep_side"}
"""The step that answers each relation this reader adds."""


def add_asked_relations(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with a closer/further step for each object a clause asks one of and no step moves by."""
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES)
    if program is None:
        return code, []
    variable = program[1]
    added: list[str] = []
    notes: list[str] = []
    for ask in object_asks(" ".join(asked), list(names)).values():
        if ask.relation not in STEP_OF or PART_OR_END.search(ask.clause):
            continue  # "after reaching the goal, approach the lamp" asks for more than the whole path closer
        if any(_names(line, ask.name) for line in lines):
            continue
        word, least = intensity_word(ask.clause), MINIMUM_DISTANCE.search(ask.clause)
        amount = f", {word!r}" if word and ask.relation != "by" else ""
        step = f"{variable} = {STEP_OF[ask.relation]}({variable}, detect_objects({ask.name!r}){amount})"
        if least is not None and ask.relation == "away":  # "at least 0.2 from it": a clearance to keep
            step = f"{variable} = avoid({variable}, detect_objects({ask.name!r}), {least.group(1)})"
        if ask.relation == "side":  # "stay on the back side of the chair"
            step = f"{variable} = keep_side({variable}, {ask.side!r}, detect_objects({ask.name!r}))"
        added.append(step)
        notes.append(
            f"added `{step}`: the words ask {asked_words(ask)} {ask.name} ({ask.clause.strip()!r}) "
            "and no step moves the path by it"
        )
    if not added:
        return code, []
    end = after_last_step(lines, SKILL_NAMES)
    return "\n".join([*lines[:end], *added, *lines[end:]]), notes


def _names(line: str, name: str) -> bool:
    """Whether a line other than a speed step names the object (as a string in quotes)."""
    if called_name(line) in SPEED_STEPS:
        return False
    quoted = re.findall(r"""(['"])(.*?)\1""", line)
    return any(text.casefold() == name.casefold() for _, text in quoted)

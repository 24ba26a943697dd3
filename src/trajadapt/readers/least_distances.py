"""A step on an object that a clause keeps a stated least distance from, made the clearance it states.

"Stay at least 0.2 away from the marmoset" came back as ``move_away(t, marmoset)``, which moves the
path a vague amount and may stay closer than 0.2; "detour around the table so the robot never gets
closer than 1.5 m to it" as ``pass_over(t, table, clearance=1.5)``, which a ground robot cannot fly
and which passes over the table, not 1.5 from it. A clause that names one object, states a least
distance (``words.MINIMUM_DISTANCE``) and asks no pace makes the one step on that object that does
not keep it (``move_away`` by no number, ``move_closer`` or ``pass_through`` where the clause asks
to come no closer nor past, ``pass_over`` where it says nothing of over or above) ``avoid(t, X,
<the distance>)``. Used by object-asks.

The other way round, a clause that asks to come within a stated distance of the one object it names
("detour to within about 10 cm of the wall lamp", "swing by the box, within 0.2 of it"; no negation,
no least distance, no pace, no keeping near it all along: "go around the lamp, staying within 0.2")
is no clearance: the one ``avoid`` of that object, which keeps the path that far away (or the one
``move_closer``, which comes a vague way closer: "past the fan, no more than about 25 cm from it"), becomes
``pass_through(t, X)`` (the path then passes the object closer than any stated distance), or
``reach(t, X)`` where the path ends there ("come to rest within 0.1 of the
orange": ``object_words.ends_at_the_place``).
"""

from __future__ import annotations

import ast
import re

from trajadapt.code_parse import call_of, in_place_of, on_object
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.end_words import without_kept_ends
from trajadapt.readers.object_words import ends_at_the_place
from trajadapt.readers.words import (
    CLOSER,
    MINIMUM_DISTANCE,
    NUMBER_TEXT,
    asks_pace,
    asks_visit,
    longest_names,
    names_in,
)

_ROUGHLY = r"(?:(?:about|around|roughly|approximately|some|just)\s+)?"
COME_WITHIN = re.compile(
    rf"\bwithin\s+{_ROUGHLY}{NUMBER_TEXT}\b"
    rf"|\b(?:(?:no|not)\s+(?:more|further|farther)\s+than|at\s+most)\s+{_ROUGHLY}{NUMBER_TEXT}\b"
    r"(?=\s*(?:away\s+)?(?:from|of)\b)",
    re.I,
)
"""A most distance the words state: "within 0.1", "within about 0.2", "no more than about 0.25 from",
"at most 0.3 from" (lengths are in metres here)."""
SHORT_OF_A_VISIT = ("avoid", "move_closer")
"""Steps that keep away from an object, or come a vague way closer: no visit within a distance."""
KEEPING_AROUND = re.compile(
    r"\b(?:around|round|circl\w*|orbit\w*|stay\w*|keep\w*|remain\w*|hold\w*|throughout|whole)\b", re.I
)
"""Words of keeping near an object all along ("go around the lamp, staying within 0.2 of it"): a band
to stay in, not a visit."""
NEGATION = re.compile(r"\b(?:no|not|never|without|nor|avoid\w*)\b|n't\b", re.I)
OVER = re.compile(r"\b(?:over|above|on\s+top|overhead|across\s+the\s+top)\b", re.I)
"""Words that ask to pass over an object: there ``pass_over`` keeps its clearance above it."""
SHORT_OF_A_CLEARANCE = ("move_away", "move_closer", "pass_through", "pass_over")


def keep_stated_clearances(lines: list[str], notes: list[str], words: str, names: list[str]) -> None:
    """Each step on an object that falls short of the least distance its clause states: ``avoid`` (above)."""
    clauses = split_clauses(words, names)
    for clause in clauses:
        named, least = longest_names(names_in(clause, names)), MINIMUM_DISTANCE.search(clause)
        if len(named) != 1 or least is None or asks_pace(clause):
            continue
        said_of_it = " ".join(c for c in clauses if names_in(c, named))  # "hop over the box, and ..."
        steps = [i for i, x in enumerate(lines) if _falls_short(x, named[0], said_of_it)]
        if len(steps) != 1:
            continue
        before = lines[steps[0]].strip()
        after = f"t = avoid(t, detect_objects({named[0]!r}), {least.group(1)})"
        lines[steps[0]] = in_place_of(lines[steps[0]], after)
        notes.append(
            f"`{before}` -> `{after}`: the instruction keeps at least {least.group(1)} from {named[0]}"
        )


def _falls_short(line: str, name: str, clause: str) -> bool:
    """Whether ``line`` is a step on object ``name`` that ``clause`` (all said of it) asks no more of."""
    call = call_of(line, SHORT_OF_A_CLEARANCE)
    if not on_object(call, name) or call is None or not isinstance(call.func, ast.Name):
        return False
    if call.func.id == "move_away":
        return not _amount_is_a_number(call)
    if call.func.id == "pass_over":
        return OVER.search(clause) is None
    return not (asks_visit(clause) or CLOSER.search(clause))  # "come closer, but no closer than 0.2"


def _amount_is_a_number(call: ast.Call) -> bool:
    """Whether a ``move_away`` step was given its amount as a number (by position or keyword)."""
    given = call.args[2:3] + [k.value for k in call.keywords if k.arg == "amount"]
    plain = [value.operand if isinstance(value, ast.UnaryOp) else value for value in given]  # -0.3 too
    return any(isinstance(value, ast.Constant) and isinstance(value.value, int | float) for value in plain)


def come_within_stated_reaches(lines: list[str], notes: list[str], words: str, names: list[str]) -> None:
    """The one ``avoid`` of an object a clause asks to come within a distance of: ``pass_through`` (above)."""
    for clause in split_clauses(words, names):
        named = longest_names(names_in(clause, names))
        within = COME_WITHIN.search(clause)
        if len(named) != 1 or within is None or asks_pace(clause) or MINIMUM_DISTANCE.search(clause):
            continue
        if NEGATION.search(clause[: within.start()]) or KEEPING_AROUND.search(without_kept_ends(clause)):
            continue
        steps = [i for i, x in enumerate(lines) if on_object(call_of(x, SHORT_OF_A_VISIT), named[0])]
        if len(steps) != 1:
            continue
        before, t = lines[steps[0]].strip(), lines[steps[0]].split("=")[0].strip()
        skill = "reach" if ends_at_the_place(without_kept_ends(clause), words) else "pass_through"
        after = f"{t} = {skill}({t}, detect_objects({named[0]!r}))"
        lines[steps[0]] = in_place_of(lines[steps[0]], after)
        reach = re.findall(NUMBER_TEXT, within.group(0))[-1]
        notes.append(f"`{before}` -> `{after}`: the instruction asks to come within {reach} of {named[0]}")

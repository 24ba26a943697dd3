"""The grammar of the step (or two) written for one clause: what its words give, nothing else.

The whole-answer grammar (``answer_grammar``) admits any object of the scene, any number and any
place on the path in every step, so a small model can give one clause's step another clause's
object ("faster near the kettle and slower near the lamp" -> one speed step on the lamp), copy an
example's number, or put a pace asked for the whole path "near" the start. Here a step may name:

- objects: those its clause refers to (``clause_objects``);
- numbers: the clause's own, the phrase table's speed factors and 0, 0.5, 1, 2;
- places: the parts and positions of the path the clause speaks of (``said_places``: "halfway" gives
  'middle', "once you reach the destination" gives 'goal' and the landmark ``detect_objects('goal')``).

With nothing to point at, no skill that needs a point is offered, and no ``near=``.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import lru_cache

from trajadapt.llm.answer_grammar import (
    LANDMARKS,
    NEWLINE,
    PLAN_TEXT,
    POINT_RULES,
    call_rule,
    is_statement_skill,
    quoted_words,
    usable_names,
    value_rules,
)
from trajadapt.llm.gbnf import Alt, Grammar, Lit, Node, Opt, Ref, alt, renamed, seq
from trajadapt.model.geometry import PART_WORDS
from trajadapt.readers.clause_split import only_keeps
from trajadapt.readers.words import PLACE_GROUPS, names_in, whole_words
from trajadapt.sandbox.api import RESULT_VARIABLE
from trajadapt.skills import SKILLS
from trajadapt.skills.events import POSITION_WORDS
from trajadapt.skills.speed import SPEED_FACTORS

MAX_STEPS_PER_CLAUSE = 2
"""A clause may ask two things at once ("go up by 0.1 at a constant speed of 0.2")."""

PLAIN_NUMBERS = ("0", "0.5", "1", "2")
NUMBER = re.compile(r"(?<![\w.])-?(?:\d+(?:\.\d+)?|\.\d+)(?![\w.]*[a-z])", re.I)
POINTING_BACK = re.compile(r"\b(?:it|its|there|them|that|this|these|those|the same)\b", re.I)
POINT_KINDS = frozenset({"point", "points"})

HALVES = re.compile(r"\b(first|second) half\b", re.I)


def stated_numbers(words: str) -> tuple[str, ...]:
    """The numbers in the words as a model writes them ('.5' -> '0.5', '20' stays '20')."""
    found = []
    for match in NUMBER.finditer(words):
        text = match.group(0).lstrip("-")
        found.append(f"0{text}" if text.startswith(".") else text)
    return tuple(dict.fromkeys(found))


def allowed_numbers(clause: str) -> tuple[str, ...]:
    """The clause's numbers, the speed factors of the phrase table and the plain ones, each once."""
    factors = [f"{factor:g}" for table in SPEED_FACTORS.values() for factor in table.values()]
    return tuple(dict.fromkeys([*stated_numbers(clause), *factors, *PLAIN_NUMBERS]))


def said_places(clause: str) -> frozenset[str]:
    """The part and position words (``geometry.PART_WORDS``, ``events.POSITION_WORDS``) the clause gives."""
    words = set(whole_words(clause).split())
    places = {name for said, names in PLACE_GROUPS if words & said for name in names}
    places |= {f"{which.lower()} half" for which in HALVES.findall(clause)}
    return frozenset(places)


def clause_objects(clauses: Sequence[str], index: int, names: Sequence[str]) -> tuple[str, ...]:
    """The scene objects the clause at ``index`` may name in its step.

    Those it names (whole words, or the last word of a longer name: "the mug" for "red mug"), and if
    it points back ("wait there"), those of the clause before. A clause that names none may use none:
    "go slower by half" is no speed change near some object.
    """
    clause = clauses[index]
    named = _referred(clause, names)
    if POINTING_BACK.search(clause) and index > 0:
        named += _referred(clauses[index - 1], names)
    return tuple(dict.fromkeys(named))


def _referred(clause: str, names: Sequence[str]) -> list[str]:
    exact = names_in(clause, names)
    if exact:
        return exact
    words = whole_words(clause)
    return [name for name in names if len(head := name.split()[-1]) > 2 and whole_words(head) in words]


@lru_cache(maxsize=256)
def step_grammar(
    object_names: tuple[str, ...], numbers: tuple[str, ...], places: frozenset[str] = frozenset()
) -> Grammar:
    """One or two lines ``t = <skill>(t, ...)`` with these objects, numbers and places (cached)."""
    step: Node = seq("t = ", Ref("call"))
    root = seq(step, Opt(seq("\n", step))) if MAX_STEPS_PER_CLAUSE == 2 else step
    grammar = Grammar({"root": root, **_step_rules(object_names, numbers, places)})
    grammar.check()
    return grammar


MAX_CLAUSES = 6
"""An instruction of more clauses than this is answered under the scene's plain answer grammar."""


@lru_cache(maxsize=64)
def clause_answer_grammar(clauses: tuple[str, ...], names: tuple[str, ...]) -> Grammar:
    """A whole answer (the plan, then the code) with one or two lines for each clause, in order.

    Line by line the code keeps to its own clause's objects, numbers and places: every clause gets
    a step, no step goes without a clause, and no clause's object or number reaches another's step.
    A clause that only keeps something (``split.only_keeps``) gets no line.
    """
    asking = _asking(clauses, names)
    rules: dict[str, Node] = {
        "root": seq('{"high_level_plan": "', Ref("plan"), '", "python_code": "', Ref("code"), '"}'),
        "plan": PLAN_TEXT,
        "code": seq(
            "t = get_trajectory()" + NEWLINE,
            *(Ref(f"steps-c{index}") for index in asking),
            f"{RESULT_VARIABLE} = t",
        ),
    }
    for index in asking:
        suffix = f"-c{index}"
        rules |= renamed(_step_rules(*_given_by(clauses, index, names)), suffix)
        line = seq("t = ", Ref(f"call{suffix}"), NEWLINE)
        rules[f"steps{suffix}"] = seq(line, Opt(line))
    grammar = Grammar(rules)
    grammar.check()
    return grammar


def _asking(clauses: Sequence[str], names: Sequence[str]) -> list[int]:
    """The indices of the clauses that ask for a step (not those that only keep something)."""
    return [index for index, clause in enumerate(clauses) if not only_keeps(clause, names)]


def _given_by(
    clauses: Sequence[str], index: int, names: Sequence[str]
) -> tuple[tuple[str, ...], tuple[str, ...], frozenset[str]]:
    """What the words of clause ``index`` give its step: its objects, numbers and places."""
    clause = clauses[index]
    return clause_objects(clauses, index, names), allowed_numbers(clause), said_places(clause)


def _step_rules(
    object_names: tuple[str, ...], numbers: tuple[str, ...], places: frozenset[str]
) -> dict[str, Node]:
    """The rules of one clause's skill call (``call``)."""
    landmarks = [name for name in LANDMARKS if name in places]
    objects = [name for name in usable_names(object_names) if name not in LANDMARKS] + landmarks
    unavailable = frozenset() if objects else POINT_KINDS
    calls = {
        f"call-{f.__name__.replace('_', '-')}": rule
        for f in SKILLS
        if is_statement_skill(f) and (rule := call_rule(f, unavailable)) is not None
    }
    rules: dict[str, Node] = {
        "call": alt(*(Ref(name) for name in calls)),
        **calls,
        **value_rules(object_names),
    }
    rules["number"] = seq(Opt(Lit("-")), alt(*sorted(numbers, key=lambda n: (-len(n), n))))
    said_parts = [word for word in PART_WORDS if word in places]
    span = seq("(", Ref("number"), ", ", Ref("number"), ")")
    rules["part"] = alt(quoted_words(said_parts), span) if said_parts else span
    positions = [word for word in POSITION_WORDS if word in places]
    rules["waypoint"] = alt(
        *(
            choice
            for choice in _choices(rules["waypoint"])
            if not (unavailable and _points(choice)) and choice != quoted_words(POSITION_WORDS)
        ),
        *((quoted_words(positions),) if positions else ()),
    )
    if objects:
        rules["object"] = alt(*sorted(objects, key=lambda n: (-len(n), n)))
    else:
        for kind in {*POINT_KINDS, *POINT_RULES, "object"}:
            del rules[kind]
    return rules


def _choices(node: Node) -> tuple[Node, ...]:
    return node.choices if isinstance(node, Alt) else (node,)


def _points(node: Node) -> bool:
    """Whether a choice writes a point (``point`` itself, or a call with one)."""
    return node == Ref("point") or Ref("point") in getattr(node, "parts", ())


def attribute_lines(
    lines: Sequence[str], clauses: Sequence[str], names: Sequence[str]
) -> list[tuple[str, tuple[str, ...]]] | None:
    """Which of ``lines`` (an answer's steps, in order) each clause got: one or two lines each.

    A line belongs to a clause when it keeps to that clause's rules (``step_grammar``); clauses that
    only keep something get none. None when the lines cannot be divided so (another grammar wrote them).
    """
    asking = _asking(clauses, names)

    def fits(index: int, part: Sequence[str]) -> bool:
        return step_grammar(*_given_by(clauses, index, names)).matches("\n".join(part))

    def divide(k: int, start: int) -> list[tuple[str, tuple[str, ...]]] | None:
        if k == len(asking):
            return [] if start == len(lines) else None
        for take in (1, 2):
            part = tuple(lines[start : start + take])
            if len(part) == take and fits(asking[k], part):
                rest = divide(k + 1, start + take)
                if rest is not None:
                    return [(clauses[asking[k]], part), *rest]
        return None

    return divide(0, 0)

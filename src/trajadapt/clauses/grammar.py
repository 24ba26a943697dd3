"""The grammar of the step (or two) written for one clause: its objects and numbers, no others.

The whole-answer grammar (``answer_grammar``) admits any object of the scene and any number in
every step, so a small model can give one clause's step another clause's object ("faster near the
kettle and slower near the lamp" -> one speed step on the lamp) or copy an example's number. Here a
step's points may name only the objects its own clause refers to (``clause_objects``), and its
numbers are the clause's own, the phrase table's speed factors and a few plain ones (0, 0.5, 1, 2).
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import lru_cache

from trajadapt.answer_grammar import call_rule, is_statement_skill, value_rules
from trajadapt.gbnf import Alt, Grammar, Lit, Node, Opt, Ref, alt, seq
from trajadapt.sandbox.api import GOAL_NAMES, START_NAMES
from trajadapt.skills import SKILLS
from trajadapt.skills.speed import SPEED_FACTORS
from trajadapt.wording import names_in, whole_words

MAX_STEPS_PER_CLAUSE = 2
"""A clause may ask two things at once ("go up by 0.1 at a constant speed of 0.2")."""

PLAIN_NUMBERS = ("0", "0.5", "1", "2")
NUMBER = re.compile(r"(?<![\w.])-?(?:\d+(?:\.\d+)?|\.\d+)(?![\w.]*[a-z])", re.I)
LANDMARK_WORDS = re.compile(
    r"\b(?:"
    + "|".join(sorted({n.split()[0] for n in START_NAMES + GOAL_NAMES}, key=len, reverse=True))
    + r")\w*",
    re.I,
)
"""Words that name the path's own start or goal ('starting', 'end', 'destination')."""
POINTING_BACK = re.compile(r"\b(?:it|its|there|them|that|this|these|those|the same)\b", re.I)


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


def clause_objects(clauses: Sequence[str], index: int, names: Sequence[str]) -> tuple[str, ...]:
    """The scene objects the clause at ``index`` may name in its step.

    Those it names (whole words, or the last word of a longer name: "the mug" for "red mug"), and if
    it points back ("wait there"), those of the clause before. A clause that names none may use none
    (only the path's own start and goal): "go slower by half" is no speed change near some object.
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


def names_landmarks(clause: str) -> bool:
    """Whether the clause speaks of the path's start or goal, so that a step may point at them."""
    return bool(LANDMARK_WORDS.search(clause))


POINT_KINDS = frozenset({"point", "points"})


def _step_rules(object_names: tuple[str, ...], numbers: tuple[str, ...], landmarks: bool) -> dict[str, Node]:
    """The rules of one clause's skill call (``call``) with its objects and numbers.

    With no object and no ``landmarks`` there is no point to write: skills that need one are not
    offered, and no optional ``near=`` either.
    """
    unavailable = POINT_KINDS if not object_names and not landmarks else frozenset()
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
    if unavailable:
        for kind in (*unavailable, "object"):
            del rules[kind]
        waypoint = rules["waypoint"]
        assert isinstance(waypoint, Alt)
        rules["waypoint"] = Alt(tuple(c for c in waypoint.choices if not _points_at_something(c)))
    return rules


def _points_at_something(node: Node) -> bool:
    return node == Ref("point") or Ref("point") in getattr(node, "parts", ())


@lru_cache(maxsize=256)
def step_grammar(object_names: tuple[str, ...], numbers: tuple[str, ...], landmarks: bool = True) -> Grammar:
    """One or two lines ``t = <skill>(t, ...)`` with these objects and numbers (cached)."""
    step: Node = seq("t = ", Ref("call"))
    root = seq(step, Opt(seq("\n", step))) if MAX_STEPS_PER_CLAUSE == 2 else step
    grammar = Grammar({"root": root, **_step_rules(object_names, numbers, landmarks)})
    grammar.check()
    return grammar

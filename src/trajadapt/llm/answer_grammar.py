"""The grammar of a skills-mode answer for one scene, generated from the skill library itself.

An answer is the JSON object the prompt asks for, and its code is a sequence of skill calls:

    t = get_trajectory()
    t = <skill>(t, <typed arguments>)      (any number of these)
    modified_trajectory = t

Each argument follows its parameter's kind (``skills.core.ArgKind`` or its Python type): a point is
``detect_objects('<a name of THIS scene>')``, a ``midpoint`` of points, a literal ``[x, y, z]`` or a
waypoint ``t[i]``; a direction is one of the six words; a distance is a number or an amount word; a
number is a number. So a local model constrained by it cannot invent an object, put a word where a
number belongs, call a function that does not exist, or forget ``modified_trajectory``. Code that
needs more than skill calls (raw numpy) is outside it by design. Every repetition in it is bounded
(steps, the plan's characters, digits, listed points, midpoints of midpoints), so every answer it
admits is finite: a model caught in a loop is made to close what it loops in, and its answer can
still be read, where an unbounded one ran out of tokens mid-code and could not.
"""

from __future__ import annotations

import inspect
import types
import typing
from collections.abc import Callable, Sequence
from functools import lru_cache
from typing import Annotated, Any

from trajadapt.llm.gbnf import PLAIN_TEXT_CHAR, Alt, Grammar, Lit, Node, Opt, Ref, Upto, alt, seq
from trajadapt.model.geometry import DIRECTIONS, PART_WORDS
from trajadapt.sandbox.api import GOAL_NAMES, RESULT_VARIABLE, START_NAMES
from trajadapt.skills import SKILLS
from trajadapt.skills.core import AMOUNT_WORDS, ArgKind
from trajadapt.skills.events import POSITION_WORDS
from trajadapt.skills.objects import CLOSER_FRACTIONS
from trajadapt.skills.speed import PROFILES

PLAIN_KINDS = {float: "number", int: "count", bool: "flag"}
LANDMARKS = (START_NAMES[0], GOAL_NAMES[0])  # 'start' and 'goal' resolve to the path's own ends
NEWLINE = "\\n"  # a newline inside the JSON string of the code
MAX_STEPS = 8  # skill calls per answer: a small model can repeat a line until it runs out of tokens
MAX_PLAN_CHARS = 600
"""Characters of the plan: the longest seen was 280; a small model that loops in its plan ("1) Shift
the path left... 20) Shift the path right...") ran out of tokens before the code and its answer could
not be read. At the bound the grammar closes the plan and the code follows."""
PLAN_TEXT = seq(PLAIN_TEXT_CHAR, Upto(PLAIN_TEXT_CHAR, MAX_PLAN_CHARS - 1))
"""The plan: one JSON string of plain characters, at most ``MAX_PLAN_CHARS``."""
MAX_DIGITS = 6
"""Digits of a whole number and of a fraction: the longest written was 0.000271; unbounded, a small
model can write digits until it runs out of tokens."""
MAX_POINTS = 6
"""Points in one list argument (``pass_over(t, [a, b])``): unbounded, the model once listed two objects
in turn until it ran out of tokens, so the answer could not be read (session 17)."""


def parameter_kind(hint: Any) -> str:
    """The grammar kind of a parameter from its type hint.

    Raises:
        TypeError: a hint with no kind (a new skill parameter needs one: see ``ArgKind``).
    """
    if typing.get_origin(hint) is Annotated:
        kinds = [meta.name for meta in hint.__metadata__ if isinstance(meta, ArgKind)]
        if kinds:
            return kinds[0]
    arguments = [arg for arg in typing.get_args(hint) if arg is not type(None)]
    if typing.get_origin(hint) in (typing.Union, types.UnionType) and arguments:
        return parameter_kind(arguments[0])
    if hint in PLAIN_KINDS:
        return PLAIN_KINDS[hint]
    raise TypeError(f"no grammar kind for a parameter of type {hint!r}; annotate it with an ArgKind")


def skill_parameters(function: Callable[..., Any]) -> list[tuple[inspect.Parameter, str]]:
    """The parameters code passes (the axis convention is bound by the sandbox), with their kinds."""
    hints = typing.get_type_hints(function, include_extras=True)
    return [
        (parameter, parameter_kind(hints[parameter.name]))
        for parameter in inspect.signature(function).parameters.values()
        if parameter.kind is not inspect.Parameter.KEYWORD_ONLY
    ]


def is_statement_skill(function: Callable[..., Any]) -> bool:
    """Whether a skill takes the trajectory first and returns a new one (``t = skill(t, ...)``)."""
    parameters = skill_parameters(function)
    returns = typing.get_type_hints(function).get("return")
    return bool(parameters) and parameters[0][1] == "trajectory" and returns not in (int, float)


def quoted_words(words: Sequence[str]) -> Node:
    """One of the words, in single quotes (longest first, so that a longer word is tried first)."""
    return seq("'", alt(*sorted({w for w in words if w}, key=lambda w: (-len(w), w))), "'")


def usable_names(names: Sequence[str]) -> list[str]:
    """Object names that can be written inside ``'...'`` in a JSON string, plus 'start' and 'goal'.

    Each name also in lower case: ``detect_objects`` ignores case, and a model that read "the siberian
    husky" in the instruction must be able to write it so (with only 'Siberian husky' allowed, the
    model, already committed to a lower-case 's', wrote 'start').
    """
    safe = [n for n in names if n and not any(c in n for c in "'\"\\") and n.isprintable()]
    keys = {n.casefold() for n in safe}
    spellings = dict.fromkeys(spelling for n in safe for spelling in (n, n.lower()))
    return list(spellings) + [landmark for landmark in LANDMARKS if landmark not in keys]


POINT_RULES = ("point", "inner-point", "plain-point")
"""The rules that make a point: a plain one, or a midpoint of two, at most two midpoints deep."""


def midpoint_of(rule: str) -> Node:
    """``midpoint(a, b)`` of two points of ``rule``."""
    return seq("midpoint(", Ref(rule), ", ", Ref(rule), ")")


def value_rules(object_names: Sequence[str]) -> dict[str, Node]:
    """One rule per argument kind, plus numbers and the scene's object names."""
    digit = alt(*"0123456789")
    return {
        "digit": digit,
        "int": alt("0", seq(alt(*"123456789"), Upto(Ref("digit"), MAX_DIGITS - 1))),
        "fraction-digits": seq(Ref("digit"), Upto(Ref("digit"), MAX_DIGITS - 1)),
        "number": seq(Opt(Lit("-")), Ref("int"), Opt(seq(".", Ref("fraction-digits")))),
        "count": alt(seq(Ref("int"), Opt(Lit(" * len(t)"))), "len(t)", seq("len(t) // ", Ref("int"))),
        "flag": alt("True", "False"),
        "object": alt(*sorted(usable_names(object_names), key=lambda n: (-len(n), n))),
        "point": alt(Ref("plain-point"), midpoint_of("inner-point")),
        "inner-point": alt(Ref("plain-point"), midpoint_of("plain-point")),
        "plain-point": alt(
            seq("detect_objects('", Ref("object"), "')"),
            seq("[", Ref("number"), ", ", Ref("number"), ", ", Ref("number"), "]"),
            seq("t[", Opt(Lit("-")), Ref("int"), "]"),
        ),
        "points": alt(
            Ref("point"), seq("[", Ref("point"), Upto(seq(", ", Ref("point")), MAX_POINTS - 1), "]")
        ),
        "direction": quoted_words(DIRECTIONS),
        "distance": alt(Ref("number"), quoted_words(list(AMOUNT_WORDS))),
        "fraction": alt(Ref("number"), quoted_words(list(CLOSER_FRACTIONS))),
        "part": alt(quoted_words(list(PART_WORDS)), seq("(", Ref("number"), ", ", Ref("number"), ")")),
        "waypoint": alt(
            Ref("int"),
            quoted_words(POSITION_WORDS),
            Ref("point"),
            seq("closest_waypoint(t, ", Ref("point"), ")"),
        ),
        "profile": quoted_words(PROFILES),
        "height": Ref("number"),
        "factor": Ref("number"),
    }


def call_rule(function: Callable[..., Any], unavailable: frozenset[str] = frozenset()) -> Node | None:
    """``name(t, required..., optional...)``: optional ones positional in order, then by keyword.

    ``unavailable`` kinds cannot be written (a clause that names no object has no point): a skill
    that needs one has no rule (None), and optional arguments of it are left out, the others then
    given by keyword only.
    """
    parameters = skill_parameters(function)[1:]
    required = [(p, kind) for p, kind in parameters if p.default is inspect.Parameter.empty]
    optional = [(p, kind) for p, kind in parameters if p.default is not inspect.Parameter.empty]
    if any(kind in unavailable for _, kind in required):
        return None
    parts: list[Node | str] = [f"{function.__name__}(t"]
    parts += [seq(", ", Ref(kind)) for _, kind in required]
    if any(kind in unavailable for _, kind in optional):
        keywords = [(p, kind) for p, kind in optional if kind not in unavailable]
        tail: Node | None = (
            seq(*(Opt(seq(f", {p.name}=", Ref(k))) for p, k in keywords)) if keywords else None
        )
    else:
        tail = _optional_tail(optional)
    if tail is not None:
        parts.append(tail)
    parts.append(")")
    return seq(*parts)


def _optional_tail(optional: list[tuple[inspect.Parameter, str]]) -> Node | None:
    """Optional arguments: the first few by position, any later ones by keyword, in signature order."""
    if not optional:
        return None
    (_, kind), rest = optional[0], optional[1:]
    after = _optional_tail(rest)
    positional = seq(", ", Ref(kind), after) if after is not None else seq(", ", Ref(kind))
    by_keyword = seq(*(Opt(seq(f", {p.name}=", Ref(k))) for p, k in optional))
    return Alt((positional, by_keyword))


@lru_cache(maxsize=64)
def answer_grammar(object_names: tuple[str, ...], steps: tuple[int, int] = (0, MAX_STEPS)) -> Grammar:
    """The grammar of an answer for a scene with these objects (cached by the names).

    ``steps``: the fewest and the most skill calls the code may have.
    """
    statements = [f for f in SKILLS if is_statement_skill(f)]
    least, most = steps
    step = seq("t = ", Ref("call"), NEWLINE)
    rules: dict[str, Node] = {
        "root": seq('{"high_level_plan": "', Ref("plan"), '", "python_code": "', Ref("code"), '"}'),
        "plan": PLAN_TEXT,
        "code": seq(
            "t = get_trajectory()" + NEWLINE,
            *[step] * least,
            Upto(step, most - least),
            f"{RESULT_VARIABLE} = t",
        ),
        "call": alt(*(Ref(f"call-{f.__name__.replace('_', '-')}") for f in statements)),
        **{f"call-{f.__name__.replace('_', '-')}": rule for f in statements if (rule := call_rule(f))},
        **value_rules(object_names),
    }
    grammar = Grammar(rules)
    grammar.check()
    return grammar

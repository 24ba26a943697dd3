"""Amounts nobody gave: a distance the model made up is replaced by the instruction's own vague word.

Rule 3 of the prompt says to use the numbers the user gives and a vague word otherwise, yet a small
model writes ``shift(t, 'left', 0.2)`` for "go to the left": 0.2 is its guess, in units it cannot
know (latte-dev's paths are 0.6 wide: a third of the scene). In skills code, a numeric literal passed
where a skill takes a *distance* (an amount of movement: ``shift``'s amount, ``move_away``'s,
``extend``'s distance, ...) that matches no number in the user's words that may be a length (also
read as cm or mm converted to m and back; a share of the path, a factor or a count is none:
``clause_amounts.stated_lengths``, "raise the second half by 5 cm" answered with 0.5) is replaced by the
intensity word the user did say ('a bit', 'a lot', ...),
or removed so that the skill's calibrated default applies; so is an amount word passed as a distance
where the words say none at all (``extend(t, 'a bit', 'back')`` for "move back some distance": an
example's word, and no argument should come from an example), and a made-up ``radius`` of a speed
change (``set_speed(t, 5, near=box, radius=1.0)`` on a 100-unit map reached no waypoint). A speed
factor the user never gave (``scale_speed(t, 0.65)`` for "a lot slower") becomes the calibrated
factor of the prompt's phrase table for the words of the speed's own clause ('a bit', none, 'a
lot'), in the direction the words ask when they ask only one ("pick up the pace" with a factor
below 1), else in the one the model chose; "by 20%", "twice", "half as fast" are stated factors, and
a factor the model made up where the speed clause states one ("go slower by half" answered with
0.45) becomes the stated one. Where a slowing down to a stop begins (``speed_profile(t,
'decelerate', start=0.7)``: the prompt's example) is a share of the path: one the words never give
(as a share, a percentage or a part said by its fraction, "the last third") becomes the product's stop
ramp (``readers.paces.STOP_RAMP_START``). A review note says so.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import assigned_call, in_place_of, named_argument, profile_kind, signed_number
from trajadapt.llm.answer_grammar import skill_parameters
from trajadapt.readers.clause_amounts import stated_lengths
from trajadapt.readers.paces import AT_LEAST, STOP_RAMP_START, speed_factor, stated_factor
from trajadapt.readers.words import (
    FASTER,
    INTENSITY,
    NUMBER_TEXT,
    SLOWER,
    SPEED_UNIT,
    intensity_word,
    is_stated,
    stated_numbers,
)
from trajadapt.skills import SKILLS

BY_NAME = {function.__name__: function for function in SKILLS}
UNIT_SLIPS = (1000.0, 100.0)
"""How far off a length written in the user's unit is: centimetres or millimetres copied as metres."""
LENGTH_KINDS = ("distance", "height")
LENGTH_NAMES = ("clearance", "margin")
"""Parameters that take a length: kinds of the skills' parameters, and numbers by their name."""
RADII = ("radius",)  # how far a speed change reaches: a number, not an amount word; made up -> the default


def is_stated_factor(value: float, numbers: list[float], faster: bool | None = None) -> bool:
    """Whether a speed factor comes from the user's numbers: n, 1/n, or 1 +- n% ('20% faster').

    ``faster``: the way the words say their percentages go (``percent_way``); a percentage then
    counts only that way ("30% faster" states 1.3, not 0.7).
    """
    candidates = list(numbers) + [1 / n for n in numbers if n]
    if faster is not False:
        candidates += [1 + n / 100 for n in numbers]
    if faster is not True:
        candidates += [1 - n / 100 for n in numbers if n < 100]
    return any(abs(value - c) <= 1e-6 * max(1.0, c) for c in candidates)


def replace_unstated_amounts(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with made-up distances replaced (see the module docstring), and a note per change."""
    words = " ".join(asked)
    numbers, lengths, word = stated_numbers(words), stated_lengths(words), intensity_word(words)
    lines, notes = [], []
    for line in code.splitlines():
        if _made_up_height(line, lengths):
            notes.append(f"left out `{line.strip()}`: the instruction gives no such height")
            continue
        if (in_metres := _lengths_in_metres(line, numbers)) is not None:
            notes.append(
                f"`{line.strip()}` -> `{in_metres}`: the step wrote the instruction's length in another"
                " unit (the scene is in metres)"
            )
            line = in_place_of(line, in_metres)
        replaced = _replace_in_line(line, lengths, word)
        changed, what = replaced if replaced is not None else (None, "number")
        used = repr(word) if word else "the default amount"
        if changed is None and (calibrated := _calibrate_factor(line, numbers, words)):
            changed, stated = calibrated
            used = "the factor the words state" if stated else used
        if changed is None and (scaled := _factor_set_as_a_speed(line, words)):
            changed, what, used = scaled, "speed (it states a factor)", "that factor"
        if changed is None and (paced := _made_up_speed(line, numbers, words)):
            changed, what, used = paced, "speed", "the pace its words ask"
        if changed is None and (ramp := _stop_ramp(line, numbers, words)):
            changed, what, used = ramp, "share of the path", "the product's stop ramp"
        if changed is not None and changed != line.strip():
            notes.append(
                f"`{line.strip()}` -> `{changed}`: the instruction gives no such {what}, so {used} is used"
            )
            line = in_place_of(line, changed)
        lines.append(line)
    return "\n".join(lines), notes


def _skill_call(line: str) -> tuple[ast.Module, ast.Call, str] | None:
    """The parsed line, its skill call and the skill's name, for a line ``name = skill(...)``."""
    found = assigned_call(line)
    return found if found is not None and found[2] in BY_NAME else None


def _made_up_height(line: str, numbers: list[float]) -> bool:
    """A step that sets an absolute height the user never gave (``set_height(t, 0.2923)``)."""
    found = _skill_call(line)
    if found is None:
        return False
    _, call, name = found
    parameters = [(p.name, kind) for p, kind in skill_parameters(BY_NAME[name])]
    given = list(zip(parameters, call.args, strict=False)) + [
        ((k.arg, dict(parameters).get(k.arg or "")), k.value) for k in call.keywords
    ]
    return any(kind == "height" and _literal_unstated(value, numbers) for (_, kind), value in given)


def _literal_unstated(node: ast.expr, numbers: list[float]) -> bool:
    value = node.operand if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub) else node
    return (
        isinstance(value, ast.Constant)
        and isinstance(value.value, int | float)
        and not isinstance(value.value, bool)
        and not is_stated(float(value.value), numbers)
    )


def _replace_in_line(line: str, numbers: list[float], word: str | None) -> tuple[str, str] | None:
    """The line with its made-up values replaced, and what was made up: an 'amount word' or a 'number'."""
    found = _skill_call(line)
    if found is None:
        return None
    tree, call, name = found
    kinds = {p.name: kind for p, kind in skill_parameters(BY_NAME[name])}
    names = list(kinds)
    replaced: list[ast.expr] = []
    for index, argument in enumerate(call.args):
        if index < len(names) and _made_up(argument, names[index], kinds[names[index]], numbers, word):
            replaced.append(argument)
            call.args[index] = _unstated_value(names[index], word)
    for keyword in call.keywords:
        if keyword.arg in kinds and _made_up(keyword.value, keyword.arg, kinds[keyword.arg], numbers, word):
            replaced.append(keyword.value)
            keyword.value = _unstated_value(keyword.arg, word)
    if not replaced:
        return None
    _drop_trailing_defaults(call, BY_NAME[name])
    return ast.unparse(tree), "amount word" if any(_amount_word(node) for node in replaced) else "number"


PERCENT_AND_WAY = re.compile(
    rf"{NUMBER_TEXT}\s*(?:%|per\s*cent\b)\s+(\w+)"
    rf"|(\w+)\s+by\s+(?:about\s+|roughly\s+|some\s+)?{NUMBER_TEXT}\s*(?:%|per\s*cent\b)",
    re.I,
)
"""A percentage with the word of its way beside it: "30% quicker", "slower by 20 percent"."""


def percent_way(words: str) -> bool | None:
    """The one way the words' percentages go, said beside them (True: faster), or None."""
    ways = set()
    for found in PERCENT_AND_WAY.finditer(words):
        word = found.group(1) or found.group(2)
        if not (FASTER.fullmatch(word) or SLOWER.fullmatch(word)):
            return None
        ways.add(bool(FASTER.fullmatch(word)))
    return ways.pop() if len(ways) == 1 else None


def _calibrate_factor(line: str, numbers: list[float], words: str) -> tuple[str, bool] | None:
    """The line with a made-up speed factor replaced, and whether the words stated the new one.

    The new factor is the one the speed clause states ("slower by half"), else the calibrated one for
    its amount word.
    """
    found = _skill_call(line)
    if found is None:
        return None
    tree, call, name = found
    kinds = [kind for _, kind in skill_parameters(BY_NAME[name])]
    given = [(kinds[i] if i < len(kinds) else "", a) for i, a in enumerate(call.args)]
    for kind, argument in given:
        if kind != "factor" or not isinstance(argument, ast.Constant):
            continue
        value = argument.value
        if not isinstance(value, int | float) or isinstance(value, bool) or value <= 0 or value == 1:
            continue
        faster, slower = bool(FASTER.search(words)), bool(SLOWER.search(words))
        asked = faster if faster != slower else value > 1
        stated = stated_factor(words, asked)
        if is_stated_factor(float(value), numbers, percent_way(words)) and (
            stated is None or AT_LEAST.search(words) is None
        ):
            continue
        if stated is not None and abs(stated - value) <= 1e-6:
            continue
        argument.value = stated or speed_factor(words, asked)
        return ast.unparse(tree), stated is not None
    return None


def _set_speed(line: str) -> tuple[ast.Module, ast.Call, float] | None:
    """The parsed line, its ``set_speed`` call and the plain number it sets, for such a line."""
    found = _skill_call(line)
    if found is None or found[2] != "set_speed" or not found[1].args[1:2]:
        return None
    value = signed_number(found[1].args[1])
    return None if value is None else (found[0], found[1], value)


def _factor_set_as_a_speed(line: str, words: str) -> str | None:
    """``set_speed`` of a factor the words state, where they give no speed: ``scale_speed`` of it.

    "Fly the first part at half speed" came back as ``set_speed(t, 0.5)``: half the speed, not 0.5.
    """
    found = _set_speed(line)
    if found is None:
        return None
    tree, call, value = found
    if SPEED_UNIT.search(words):
        return None  # "half a metre a second" is a speed
    digits = [float(n) for n in re.findall(r"\d+\.?\d*|\.\d+", words)]
    stated = {stated_factor(words, faster) for faster in (False, True)} - {None}
    if value in digits or not any(abs(value - f) <= 1e-6 for f in stated if f):
        return None
    call.func = ast.Name("scale_speed", ast.Load())
    return ast.unparse(tree)


def _made_up_speed(line: str, numbers: list[float], words: str) -> str | None:
    """``set_speed`` of a speed the words never give, where they ask one pace: ``scale_speed`` of it.

    "Come in slower over the final stretch" came back as ``set_speed(t, 0.319, part='end')``: the
    path's own speed copied, no slower. The words ask slower (or faster) and no speed, so the step
    scales the speed by the phrase table's factor for their amount word, in the same place.
    """
    found = _set_speed(line)
    if found is None:
        return None
    tree, call, value = found
    faster, slower = bool(FASTER.search(words)), bool(SLOWER.search(words))
    if value == 0 or faster == slower or is_stated(value, numbers):
        return None  # 0: a halt there, no pace
    call.func = ast.Name("scale_speed", ast.Load())
    call.args[1] = ast.Constant(speed_factor(words, faster))
    return ast.unparse(tree)


def _stop_ramp(line: str, numbers: list[float], words: str) -> str | None:
    """The line with a slowing to a stop started at the product's stop ramp, where the words give no share."""
    found = _skill_call(line)
    if found is None or found[2] != "speed_profile" or SHARE_WORDS.search(words):
        return None
    tree, call, _ = found
    kind = profile_kind(call)
    start = named_argument(call, "start", 3)
    if kind is None or kind.value != "decelerate" or not isinstance(start, ast.Constant):
        return None
    value = start.value
    if not isinstance(value, int | float) or isinstance(value, bool) or value in (0, STOP_RAMP_START):
        return None
    if any(abs(value - share) <= 1e-6 for n in numbers for share in (n, 1 - n, n / 100, 1 - n / 100)):
        return None
    start.value = STOP_RAMP_START
    return ast.unparse(tree)


SHARE_WORDS = re.compile(r"\b(?:halfway|half|thirds?|quarters?|fifths?|tenths?)\b|%|\bper\s*cent\b", re.I)
"""Words that say a share of the path: where they are, a slowing's start may be the user's."""


def _drop_trailing_defaults(call: ast.Call, function: object) -> None:
    """Remove arguments now None where None is the default: ``shift(t, 'left')``, not ``..., None)``."""
    defaults = {p.name: p.default for p, _ in skill_parameters(function)}  # type: ignore[arg-type]
    names = list(defaults)
    while call.args and isinstance(call.args[-1], ast.Constant) and call.args[-1].value is None:
        if defaults.get(names[len(call.args) - 1]) is not None:
            break
        call.args.pop()
    call.keywords = [k for k in call.keywords if not _none_by_default(k, defaults)]


def _none_by_default(keyword: ast.keyword, defaults: dict[str, object]) -> bool:
    given_none = isinstance(keyword.value, ast.Constant) and keyword.value.value is None
    return given_none and defaults.get(keyword.arg or "") is None


def _lengths_in_metres(line: str, numbers: list[float]) -> str | None:
    """The line with each length the model wrote in the user's centimetres or millimetres in metres."""
    found = _skill_call(line)
    if found is None:
        return None
    tree, call, name = found
    kinds = {p.name: kind for p, kind in skill_parameters(BY_NAME[name])}
    given = list(zip(kinds, call.args, strict=False)) + [(k.arg or "", k.value) for k in call.keywords]
    changed = False
    for parameter, node in given:
        metres = _in_centimetres(node, numbers)
        if metres is None or not (kinds.get(parameter) in LENGTH_KINDS or parameter in LENGTH_NAMES):
            continue
        target = node.operand if isinstance(node, ast.UnaryOp) else node
        assert isinstance(target, ast.Constant)
        target.value, changed = metres, True
    return ast.unparse(tree) if changed else None


def _in_centimetres(node: ast.expr, numbers: list[float]) -> float | None:
    """The user's length where the model wrote it in centimetres or millimetres, else None.

    The readers read a length the user gives with a metric unit in metres ("12 cm" is 0.12), as the
    scene's numbers are; a model that copies the number without its unit writes 12, a hundred times
    the asked distance. A length that is no number of the words, but 100 or 1000 times exactly one of
    them, is that number (a sign before it stays).
    """
    written = signed_number(node)
    if written is None:
        return None
    given = abs(written)
    if given == 0 or any(abs(given - n) <= 1e-6 * max(1.0, n) for n in numbers):
        return None
    meant = {n for n in numbers for f in UNIT_SLIPS if abs(given - n * f) <= 1e-6 * given}
    if len(meant) != 1:
        return None
    return meant.pop()


def _made_up(node: ast.expr, name: str, kind: str, numbers: list[float], word: str | None) -> bool:
    """A distance or radius no number of the words gives, or an amount word where the words say none."""
    if kind == "distance" and word is None and _amount_word(node):
        return True
    return (kind == "distance" or name in RADII) and _literal_unstated(node, numbers)


def _amount_word(node: ast.expr) -> bool:
    """A vague amount word ('a bit', 'a lot', ...): copied from an example when the words say none."""
    return isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in INTENSITY


def _unstated_value(name: str, word: str | None) -> ast.Constant:
    """What replaces a made-up value: the user's vague word for an amount, the default for a radius."""
    return ast.Constant(word if word and name not in RADII else None)

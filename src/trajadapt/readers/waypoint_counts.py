"""A count of waypoints the words give, and the ``resample`` that makes it.

"Resample the trajectory with 10 more waypoints" came back as ``resample(t, 10)`` (ten in all),
"use 10 more waypoints" as ``resample(t, 10 * len(t))`` (ten times as many). The words give a count

- by a change: "10 more waypoints", "5 extra points", "add 8 waypoints" -> ``len(t) + 10``; "6
  fewer waypoints", "drop 6 points" -> ``len(t) - 6``;
- by a factor: "double the waypoints", "twice as many points" -> ``2 * len(t)``; "halve the number
  of waypoints" -> ``len(t) // 2``;
- in all: "with 60 waypoints", "resample to 25 points", "use 30 waypoints in total" -> ``60``.

A count of a part of the path ("the first 10 waypoints", "every 5 points") gives none. When the
words give exactly one count, the one ``resample`` step of another count takes it, or, with no
``resample`` step, one is added as the last step. Words that only say which way ("use fewer points",
"reduce the number of waypoints", "thin it out", "more waypoints") get half or twice the count, when
no ``resample`` step is there or the one there gives a count the words never say. Code that is not
made of skill calls alone is left alone. A review note says what changed and why.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import after_last_step, call_of, in_place_of, parse_code, skill_program
from trajadapt.readers.words import NUMBER_WORDS, whole_count
from trajadapt.skills import SKILL_NAMES

_COUNT = r"(\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
_POINTS = r"(?:way\s*-?\s*)?points?\b"
_PART = r"(?<!first\s)(?<!last\s)(?<!next\s)(?<!every\s)(?<!each\s)(?<!final\s)(?<!initial\s)"
CHANGE = re.compile(
    rf"\b{_PART}{_COUNT}\s+(more|extra|additional|fewer|less)\s+{_POINTS}"
    rf"|\b(add|insert|remove|drop|delete|cut)\w*\s+{_PART}{_COUNT}\s+(?:\w+\s+)?{_POINTS}",
    re.I,
)
"""A count said as a change: "10 more waypoints", "add 8 points", "drop 6 waypoints"."""
FACTOR = re.compile(
    r"\b(double|twice|triple|thrice|halve|half)\w*\s+(?:as\s+many\s+|the\s+(?:number\s+of\s+|count\s+of\s+)?)?"
    rf"{_POINTS}",
    re.I,
)
"""A count said as a factor: "double the waypoints", "twice as many points", "halve the waypoints"."""
IN_ALL = re.compile(
    rf"\b(?:with|to|into|use|using|have|having|exactly|total\s+of)\s+{_PART}{_COUNT}\s+(?:evenly\s+spaced\s+)?"
    rf"{_POINTS}(?!\s+(?:to|towards?|left|right|up|down|front|back|of\s+the))",
    re.I,
)
"""A count in all: "with 60 waypoints", "resample to 25 points", "use 30 waypoints"."""
LESS = ("fewer", "less", "remove", "drop", "delete", "cut")
UNCOUNTED = re.compile(
    rf"\b(?:(fewer|less|more|extra|additional)\s+(?:\w+\s+)?{_POINTS}"
    rf"|(reduc|decreas|lower|cut|increas|rais)\w*\s+(?:down\s+)?(?:the\s+)?(?:number|count)\s+of\s+{_POINTS}"
    r"|(thin)(?:s|ned|ning)?\s+(?:it\s+|them\s+|the\s+\w+\s+)?out\b|(sparser|denser))",
    re.I,
)
"""A count said by its way alone: "use fewer points", "reduce the number of waypoints", "thin it out"."""


def asked_count(words: str) -> str | None:
    """The count of waypoints the words give, as the code that makes it (see the module), if one.

    >>> asked_count("resample it with 12 more waypoints")
    'len(t) + 12'
    >>> asked_count("twice as many points please")
    '2 * len(t)'
    """
    found = [_change(m) for m in CHANGE.finditer(words)]
    found += [_factor(m.group(1)) for m in FACTOR.finditer(words)]
    found += [str(whole_count(m.group(1))) for m in IN_ALL.finditer(words) if whole_count(m.group(1)) >= 2]
    counts = {count for count in found if count}
    return counts.pop() if len(counts) == 1 else None


def _change(found: re.Match[str]) -> str:
    count = whole_count(found.group(1) or found.group(4))
    way = (found.group(2) or found.group(3)).lower()
    if not count:
        return ""
    return f"len(t) - {count}" if way.startswith(LESS) else f"len(t) + {count}"


def _factor(word: str) -> str:
    return (
        "len(t) // 2"
        if NUMBER_WORDS.get(word.lower(), 2.0) < 1
        else f"{int(NUMBER_WORDS[word.lower()])} * len(t)"
    )


def count_as_asked(code: str, asked: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` resampled to the count of waypoints the words give (see the module)."""
    lines = code.splitlines()
    program = skill_program(lines, SKILL_NAMES, empty=True)
    if program is None:
        return code, []
    words, variable = " ".join(asked), program[1]
    count = asked_count(words)
    written = [i for i, line in enumerate(lines) if call_of(line, ("resample",)) is not None]
    if count is None:
        return _uncounted(lines, words, variable, written)
    step = _resample_step(variable, count)
    if len(written) > 1 or any(_same(lines[i], step) for i in written):
        return code, []
    if written:
        before = lines[written[0]].strip()
        lines[written[0]] = in_place_of(lines[written[0]], step)
        return "\n".join(lines), [f"`{before}` -> `{step}`: the words give that count of waypoints"]
    lines.insert(after_last_step(lines, SKILL_NAMES), step)
    return "\n".join(lines), [f"added `{step}`: the words give that count of waypoints and no step makes it"]


def _resample_step(variable: str, count: str) -> str:
    """The ``resample`` statement of ``count`` (written on ``len(t)``) for the program's variable."""
    return f"{variable} = resample({variable}, {count.replace('len(t)', f'len({variable})')})"


def _uncounted(lines: list[str], words: str, variable: str, written: list[int]) -> tuple[str, list[str]]:
    """The lines with a resample to half or twice the count, for words that only say which way.

    Added when no ``resample`` is written; one written with a made-up count ("resample the
    trajectory with more waypoints" came back as ``resample(t, 20)`` on a path of 100) takes it.
    """
    ways = {_way(found) for found in UNCOUNTED.finditer(words)}
    if len(ways) != 1 or len(written) > 1 or (written and not _made_up_count(lines[written[0]], words)):
        return "\n".join(lines), []
    step = _resample_step(variable, "len(t) // 2" if ways.pop() == "fewer" else "2 * len(t)")
    if written:
        before = lines[written[0]].strip()
        lines[written[0]] = in_place_of(lines[written[0]], step)
        note = f"`{before}` -> `{step}`: the words ask that way of waypoints, and no count"
        return "\n".join(lines), [note]
    lines.insert(after_last_step(lines, SKILL_NAMES), step)
    return "\n".join(lines), [f"added `{step}`: the words ask that way of waypoints and no step makes it"]


def _made_up_count(line: str, words: str) -> bool:
    """Whether the ``resample`` on ``line`` gives a plain count the words never say."""
    call = call_of(line, ("resample",))
    given = call.args[1] if call is not None and len(call.args) > 1 else None
    if not (isinstance(given, ast.Constant) and isinstance(given.value, int | float)):
        return False
    return re.search(rf"(?<![\d.]){given.value:g}(?!\d|\.\d)", words) is None


def _way(found: re.Match[str]) -> str:
    """'fewer' or 'more' for a count said by its way alone."""
    word = next(group for group in found.groups() if group).lower()
    return (
        "fewer"
        if word.startswith(("fewer", "less", "reduc", "decreas", "lower", "cut", "thin", "sparser"))
        else "more"
    )


def _same(line: str, step: str) -> bool:
    """Whether ``line`` is ``step`` up to spaces."""
    return ast.dump(parse_code(line.strip())) == ast.dump(parse_code(step))

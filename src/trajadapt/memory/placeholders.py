"""Scene names out of a remembered answer, and a new scene's names back in.

An approved answer says "slow down near the red mug" and looks up ``detect_objects('red mug')``. It is
kept as "slow down near <object 1>" with ``detect_objects('<object 1>')``, numbered in the order the
instruction names them, so that it carries over to a scene without a red mug: recalled for "slow
down near the kettle", ``<object 1>`` becomes the kettle (the scene's objects in the order the new
instruction names them, then the others).
"""

from __future__ import annotations

import re
from collections.abc import Sequence

PLACEHOLDER = re.compile(r"<object (\d+)>")
LOOKUP = re.compile(r"detect_objects\(\s*['\"]([^'\"]+)['\"]\s*\)")


def placeholder(number: int) -> str:
    """The placeholder for the ``number``-th object (from 1)."""
    return f"<object {number}>"


def _name_pattern(name: str) -> re.Pattern[str]:
    return re.compile(rf"(?<![\w]){re.escape(name)}(?![\w])", re.IGNORECASE)


def mentioned(text: str, names: Sequence[str]) -> list[str]:
    """The names ``text`` mentions, in the order of their first mention (a longer name wins)."""
    spans: list[tuple[int, str]] = []
    taken: list[range] = []
    for name in sorted({n for n in names if n.strip()}, key=len, reverse=True):
        for match in _name_pattern(name).finditer(text):
            if not any(match.start() in span for span in taken):
                spans.append((match.start(), name))
                taken.append(range(match.start(), match.end()))
                break
    return [name for _, name in sorted(spans)]


def abstract(texts: Sequence[str], names: Sequence[str], first: int = 1) -> tuple[list[str], int]:
    """``texts`` with every scene name replaced by its placeholder, and how many placeholders.

    Names are numbered from ``first`` by first mention across the texts in order (instruction, plan,
    code).
    """
    order: list[str] = []
    for text in texts:
        order += [name for name in mentioned(text, names) if name.lower() not in {o.lower() for o in order}]
    abstracted = list(texts)
    for number, name in sorted(enumerate(order, start=first), key=lambda item: -len(item[1])):
        abstracted = [_name_pattern(name).sub(placeholder(number), text) for text in abstracted]
    return abstracted, len(order)


def looked_up(code: str) -> list[str]:
    """The object names the code passes to ``detect_objects`` as literals."""
    return LOOKUP.findall(code)


def fill(texts: Sequence[str], count: int, instruction: str, names: Sequence[str]) -> list[str]:
    """Put a scene's names in place of ``count`` placeholders.

    The objects the new instruction names come first, in its order, then the scene's others; a
    placeholder with no object left stays as it is.
    """
    chosen = mentioned(instruction, names)
    chosen += [name for name in names if name not in chosen]
    filled = list(texts)
    for number in range(1, min(count, len(chosen)) + 1):
        filled = [text.replace(placeholder(number), chosen[number - 1]) for text in filled]
    return filled

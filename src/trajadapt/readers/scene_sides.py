"""A side of an object nobody named, where the words name no object: a side of the scene.

"Stay on the left", "stay on the front part a bit": the words name no object, and a small model
writes ``keep_side(t, 'left', detect_objects('<some object>'))``. When the words name none of the
scene's objects, every ``keep_side`` becomes a ``shift`` to its side with the words' vague word
("a bit"). A review note says so.
"""

from __future__ import annotations

from collections.abc import Iterable

from trajadapt.code_parse import call_of, direction_argument, in_place_of
from trajadapt.readers.words import intensity_word, names_in


def sides_of_the_scene(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with each ``keep_side`` a shift to its side when the words name no object, and notes."""
    words = " ".join(asked)
    if names_in(words, names):
        return code, []
    lines, notes = code.splitlines(), list[str]()
    for index, line in enumerate(lines):
        side = direction_argument(call_of(line, ("keep_side",)))
        if side is None:
            continue
        word = intensity_word(words)
        shifted = f"t = shift(t, {side!r}{f', {word!r}' if word else ''})"
        notes.append(f"`{line.strip()}` -> `{shifted}`: the instruction names no object, so {side} is a "
                     f"side of the scene")  # fmt: skip
        lines[index] = in_place_of(line, shifted)
    return ("\n".join(lines), notes) if notes else (code, [])

"""An object pointed back to with "it" after a word of place: "go slower as you pass by *it*".

"Don't come within 80 cm of the fan, and go slower as you pass by it": the path cannot pass by
itself, so "it" after a word of place ("by", "near", "past", "around", "from", "over", ...) is an
object, the one the words named before it. Where the words before name exactly one scene object,
such an "it" is written as that object ("pass by the fan"); elsewhere "it" is the path or the robot
("move it left", "slow it down") and stays.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from trajadapt.readers.words import longest_names, names_in

PLACED_IT = re.compile(
    r"\b((?:pass(?:es|ing)?\s+)?(?:by|near|past|around|round|beside|alongside|over|above"
    r"|towards?|from|next\s+to|close\s+to|closer\s+to|nearer\s+to|away\s+from|clear\s+of|in\s+front\s+of"
    r"|behind|between\s+(?:the\s+|your\s+)?(?:robot|drone|arm|gripper|end\s+effector|tool|vehicle|path|route)"
    r"\s+and|within\s+(?:(?:about|roughly|around)\s+)?[\d.]+\s*(?:m|cm|mm|metres?|meters?)?\s+of"
    r"|[\d.]+\s*(?:m|cm|mm|metres?|meters?)?\s+away\s+from"
    r"|(?:stay|keep|remain|hold)\w*\s+(?:at\s+least\s+)?[\d.]+\s*(?:m|cm|mm|metres?|meters?)?\s+(?:from|off))\s+)it\b"
    r"(?!\s*(?:is|was|'s)\b)",
    re.I,
)
""""it" after a word of place: "pass by it", "near it", "keep clear of it", or of a distance from it:
"never come within 12 cm of it", "stay 0.3 from it", "at least 40 cm between the drone and it" (not
"by it is": a new statement)."""


def objects_for_it(words: str, names: Sequence[str]) -> str:
    """``words`` with each "it" after a word of place written as the one object named before it."""
    parts, last = [], 0
    for found in PLACED_IT.finditer(words):
        named = longest_names(names_in(words[: found.start()], names))
        if len(named) != 1:
            continue
        parts += [words[last : found.start()], f"{found.group(1)}the {named[0]}"]
        last = found.end()
    return "".join([*parts, words[last:]]) if parts else words

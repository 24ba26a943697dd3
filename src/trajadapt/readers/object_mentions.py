"""An object the words call by another name: the one the answer chose ("the maze" for "labyrinth").

People call a scene object by a word that is not its label: "the maze" for the scene's labyrinth,
"the sheath" for the scabbard, "the oboe" for the hautbois. No word-reading code can match those,
but the model knows what they mean, and picks the object in its answer. Read by name alone, the
words would name no object, and the readers would drop that step as one about an object nobody
named. So where the request holds exactly one such word after a word of place ("closer to the
maze"), and the answer uses exactly one object the words do not name, the readers read the word as
that object's name. Anything else leaves the words as they are.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from trajadapt.code_parse import detected_names, parse_code
from trajadapt.readers.plain_words import NOT_OBJECT_WORDS
from trajadapt.readers.words import names_in, whole_words

MENTION = re.compile(
    r"\b(?:to|from|of|near|nearby|around|round|past|by|over|above|below|under|beneath|beside|behind"
    r"|towards?|through|at|reach|approach|circle|avoid|pass|give|skirt|hug|clear|dodge|orbit|visit|leave)"
    r"(?:e?s|ing|ed)?\s+the\s+([a-z][a-z'-]{2,})\b(?!\s+of\b)",
    re.I,
)
"""A thing said after a word of place or a verb of passing: "closer to the maze", "give the oboe"."""
NOT_THINGS = NOT_OBJECT_WORDS | frozenset(
    "trajectory route proximity vicinity surroundings surrounding rest same whole entire initial original "
    "final closest nearest most scene room way time timesteps beginning destination target target's "
    "ones path's robot's".split()
)
"""Words after a word of place that name a part of the path, a place or a time, never an object."""


def chosen_referents(request: str, code: str, names: Sequence[str]) -> tuple[str, list[str]]:
    """``request`` with a thing no scene object is called written as the one object the answer chose."""
    said = _unnamed_things(request, names)
    if len(said) != 1:
        return request, []
    chosen = _chosen_objects(code) - {n.casefold() for n in names_in(request, names)}
    spelled = [n for n in names if n.casefold() in chosen]
    if len(spelled) != 1:
        return request, []
    word, name = said.pop(), spelled[0]
    read = re.sub(rf"\bthe\s+{re.escape(word)}\b", f"the {name}", request, flags=re.I)
    note = f"read \u201cthe {word}\u201d as {name}, the object the answer chose (no object is called that)"
    return read, [note]


def _unnamed_things(request: str, names: Sequence[str]) -> set[str]:
    """The words after a word of place that are no word of any scene name and no part of the path.

    A hyphened word is a scene name's where its parts are ("the horse-cart" for the horse-cart).
    """
    scene_words = set(whole_words(" ".join(names)).split())
    return {
        found.group(1).lower()
        for found in MENTION.finditer(request)
        if found.group(1).lower() not in NOT_THINGS
        and not set(whole_words(found.group(1)).split()) <= scene_words
    }


def _chosen_objects(code: str) -> set[str]:
    """The scene objects the code detects, case-folded."""
    try:
        tree = parse_code(code)
    except SyntaxError:
        return set()
    return {name.casefold() for name in detected_names(tree)}

"""Other names of the same kind of object: "the oboe" for the scene's "hautbois".

The scenes name their objects by one of the names of an ImageNet class ("hautbois", "Mergus
serrator", "prairie wolf", "dustbin"), and people call the same thing by another ("the oboe", "the
red-breasted merganser", "the coyote", "the trash can"). ``data/object_kinds.txt`` lists each kind's
names (WordNet's synonyms of the class); where the words call one scene object by another name of
its kind, with "the", "this" or "that" before it, that name is written as the scene spells it. A name
that is a word of another scene object, that two of the scene's objects share, or that is an everyday
word of instructions ("the spot", "the head": ``GENERAL_WORDS``, a part of the path) is left as said,
and so is every name where the scene's own name is already in the words.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Sequence
from importlib import resources

from trajadapt.readers.words import PART_OR_END, whole_words

GENERAL_WORDS = frozenset(
    "spot drop head point light site scope scale rule press board mail cell market grand semi sub bar bars "
    "beam bullet coach carriage carrier rig slot switch screen plane pick comfort essence upright tank "
    "remote wireless cliff coast spike ear hopper killer painter ounce tup chute tandem mole groin spiral "
    "helix whorl volute loop".split()
)
"""Names of a kind that are also everyday words of an instruction ("the spot", "the head of the
path", "the drop"): never read as an object's other name."""
KINDS_FILE = "object_kinds.txt"
"""The kinds' names, one kind per line, names separated by ", " (lines starting with "#" are notes)."""


@functools.cache
def kinds() -> tuple[tuple[str, ...], ...]:
    """Each kind's names, as ``whole_words`` spells them (lower case, words split on punctuation)."""
    text = resources.files("trajadapt.readers").joinpath("data", KINDS_FILE).read_text(encoding="utf-8")
    lines = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    return tuple(tuple(whole_words(name).strip() for name in line.split(", ")) for line in lines)


def other_names(name: str) -> set[str]:
    """The other names of ``name``'s kind (of every kind it names), as ``whole_words`` spells them."""
    spelled = whole_words(name).strip()
    others = {other for kind in kinds() if spelled in kind for other in kind}
    return {other for other in others if other not in GENERAL_WORDS and not PART_OR_END.fullmatch(other)} - {
        spelled
    }


def names_by_their_kind(words: str, names: Sequence[str]) -> str:
    """``words`` with each scene object called by another name of its kind written by its scene name."""
    text = whole_words(words)
    said = {name: other_names(name) for name in names if whole_words(name) not in text}
    scene_words = {word for name in names for word in whole_words(name).split()}
    for name, others in said.items():
        for other in sorted(others, key=len, reverse=True):
            shared = any(other in rest for owner, rest in said.items() if owner != name)
            if shared or set(other.split()) & scene_words or f" {other} " not in text:
                continue
            spoken = r"[\s_-]+".join(re.escape(word) for word in other.split())
            called = re.compile(rf"\b((?:the|this|that)\s+){spoken}\b", re.I)
            words, found = called.subn(r"\g<1>" + name.replace("\\", "\\\\"), words)
            if found:
                break
    return words

"""Worked examples chosen for the instruction: a bank of instruction -> plan -> code, ranked by BM25.

The bank (``prompts/examples.jsonl``) is written by us, one example or more per skill and per common
phrase family, in our own words; none is taken from a benchmark's cases. At request time the ``k``
examples nearest to the instruction (Okapi BM25 over word stems, with the scene's object names left
out of the query, so that "closer to the pretzel" finds "closer to the vase") go into the user
message, after the fixed system prefix, whose cached state is still reused.
"""

from __future__ import annotations

import json
import math
import re
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

from trajadapt.llm.answer import answer_json
from trajadapt.model.scene import without_names

WORD = re.compile(r"[a-z]+|\d+(?:\.\d+)?")
OBJECT_NAME = re.compile(r"detect_objects\('([^']*)'\)")
STOP_WORDS = frozenset(
    "the a an to of and by in on at it its is be as for with from your you this that then when while "
    "please path trajectory robot route motion way position "
    # motion verbs and intensity words say nothing about which change is meant
    "go goes going walk walking drive driving move moving fly flying head travel execute perform do make "
    "get bit little lot much very slightly slighlty somewhat really more less".split()
)
K1, B = 1.5, 0.75  # the usual Okapi BM25 constants


@dataclass(frozen=True)
class Example:
    """One worked example: what a user said, the numbered plan, and the code that carries it out."""

    instruction: str
    high_level_plan: str
    code: str
    remembered: str = ""
    """The id of the user's remembered example this is ('' for the shipped bank's)."""

    def render(self) -> str:
        """As the prompt shows examples: the instruction, then the answer's JSON on one line."""
        return f"Instruction: {self.instruction}\n{answer_json(self.high_level_plan, self.code)}"

    @property
    def object_names(self) -> list[str]:
        """The object names the code looks up."""
        return OBJECT_NAME.findall(self.code)


SAME_MEANING = {
    "further": "far", "farther": "far", "furthest": "far", "distant": "far",
    "closer": "close", "closely": "close", "nearer": "close", "near": "close", "nearby": "close",
    "approach": "close", "towards": "close", "toward": "close",
    "faster": "fast", "quicker": "fast", "quickly": "fast", "quick": "fast", "hurry": "fast",
    "rapid": "fast", "slower": "slow", "slowly": "slow", "velocity": "speed",
    "higher": "up", "top": "up", "above": "up", "upward": "up", "upwards": "up", "raise": "up",
    "lower": "down", "bottom": "down", "below": "down", "downward": "down", "downwards": "down",
    "forward": "front", "forwards": "front", "ahead": "front", "backward": "back",
    "backwards": "back", "behind": "back", "rear": "back",
    "halt": "stop", "pause": "wait", "hold": "wait", "revolve": "circle", "orbit": "circle",
    "loop": "circle", "round": "around", "smoothen": "smooth", "timestep": "step",
    "timesteps": "step", "steps": "step", "waypoints": "waypoint", "points": "waypoint",
    "end": "goal", "final": "goal", "finish": "goal", "destination": "goal", "begin": "start",
    "beginning": "start", "initial": "start", "starting": "start", "curvature": "curve", "curved": "curve",
    "curvy": "curve", "proximity": "close", "surrounding": "close", "surroundings": "close",
    "vicinity": "close", "next": "close", "beside": "close", "passing": "pass",
}  # fmt: skip
"""Words read as one: direction, speed and distance words a user may say in several ways."""


def stem(word: str) -> str:
    """A word's meaning class (``SAME_MEANING``), else a light stem ('passing' -> 'pass')."""
    if word in SAME_MEANING:
        return SAME_MEANING[word]
    for suffix, shortest in (("ing", 6), ("ly", 5), ("ed", 5), ("s", 4)):
        if word.endswith(suffix) and len(word) >= shortest and not word.endswith(("ss", "us", "eed")):
            return SAME_MEANING.get(word[: -len(suffix)], word[: -len(suffix)])
    return word


def terms(text: str, leave_out: Iterable[str] = ()) -> list[str]:
    """The stems of ``text`` without stop words, then each pair of neighbouring stems.

    Numbers become '<number>' and the given names are removed first. The pairs ('slow+close') tell
    "slower near" from "closer" and "slower".
    """
    words = WORD.findall(without_names(text, leave_out))
    stems = ["<number>" if word[0].isdigit() else stem(word) for word in words if word not in STOP_WORDS]
    return stems + [f"{first}+{second}" for first, second in zip(stems, stems[1:], strict=False)]


class ExampleBank:
    """Examples and their BM25 index.

    ``meanings`` adds tokens of its own to each instruction's stems, read the same way from the
    examples and from the query (``memory.meaning``: what the words ask, whatever the words).
    """

    def __init__(
        self, examples: Sequence[Example], meanings: Callable[[str], list[str]] | None = None
    ) -> None:
        self.examples = tuple(examples)
        self._meanings = meanings
        self._documents = [Counter(self.terms(e.instruction, e.object_names)) for e in self.examples]
        self._average_length = sum(sum(d.values()) for d in self._documents) / max(len(self._documents), 1)
        frequency: Counter[str] = Counter(term for document in self._documents for term in document)
        count = len(self._documents)
        self._idf = {term: math.log((count - df + 0.5) / (df + 0.5) + 1.0) for term, df in frequency.items()}

    def terms(self, text: str, leave_out: Iterable[str] = ()) -> list[str]:
        """The index terms of ``text``: its stems and pairs (``terms``), then its meaning tokens."""
        return terms(text, leave_out) + (self._meanings(text) if self._meanings else [])

    def ranked(self, text: str, object_names: Iterable[str] = ()) -> list[int]:
        """Every example's index, best for ``text`` first (ties: bank order)."""
        query = self.terms(text, object_names)
        return sorted(range(len(self.examples)), key=lambda i: (-self.score(query, i), i))

    def score(self, query: Sequence[str], index: int) -> float:
        """BM25 score of example ``index`` for the query terms."""
        document = self._documents[index]
        length = sum(document.values())
        total = 0.0
        for term in query:
            tf = document.get(term, 0)
            if tf:
                norm = tf + K1 * (1 - B + B * length / self._average_length)
                total += self._idf[term] * tf * (K1 + 1) / norm
        return total

    def nearest(self, instruction: str, k: int, object_names: Iterable[str] = ()) -> list[Example]:
        """The ``k`` best examples for ``instruction``, best first (ties: bank order)."""
        if k <= 0:
            return []
        return [self.examples[i] for i in self.ranked(instruction, object_names)[:k]]


def read_examples(lines: Iterable[str]) -> list[Example]:
    """Examples from JSON lines with the fields instruction, high_level_plan and code.

    Raises:
        ValueError: a line that is not such an object, with its number.
    """
    examples = []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
            examples.append(Example(record["instruction"], record["high_level_plan"], record["code"]))
        except (ValueError, KeyError, TypeError) as exc:
            raise ValueError(f"example bank line {number}: {exc}") from exc
    return examples


@lru_cache(maxsize=1)
def default_bank() -> ExampleBank:
    """The bank shipped with the package."""
    text = resources.files("trajadapt.prompts").joinpath("examples.jsonl").read_text(encoding="utf-8")
    return ExampleBank(read_examples(text.splitlines()))

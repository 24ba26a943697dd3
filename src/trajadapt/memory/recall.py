"""A request's worked examples, from the user's remembered answers and the shipped bank.

Both banks are ranked together with the same BM25 (``example_bank``), after the remembered ones are
given the new scene's names. A remembered example that is a near match of the instruction (the word
stems both share are at least ``NEAR`` of each side's: the same request in other words, or the same
words in another scene) ranks before everything else: it is the user's own answer to this request.
"""

from __future__ import annotations

from collections.abc import Sequence

from trajadapt.llm.example_bank import Example, ExampleBank, default_bank, terms
from trajadapt.memory.bank import RememberedExample

NEAR = 0.5


def choose_examples(
    instruction: str, k: int, names: Sequence[str], remembered: Sequence[RememberedExample] = ()
) -> list[Example]:
    """The ``k`` examples for ``instruction``, best first: near remembered matches, then by BM25."""
    if k <= 0:
        return []
    if not remembered:
        return default_bank().nearest(instruction, k, names)
    own = [example.as_example(instruction, names) for example in remembered]
    bank = ExampleBank([*own, *default_bank().examples])
    query = terms(instruction, names)
    scores = [bank.score(query, index) for index in range(len(bank.examples))]
    near = {index for index, example in enumerate(own) if _near(query, example, names)}
    ranked = sorted(range(len(scores)), key=lambda i: (i not in near, -scores[i], i))
    return [bank.examples[i] for i in ranked[:k]]


def _near(query: Sequence[str], example: Example, names: Sequence[str]) -> bool:
    words = {term for term in query if "+" not in term}
    theirs = {term for term in terms(example.instruction, [*names, *example.object_names]) if "+" not in term}
    if not words or not theirs:
        return False
    shared = len(words & theirs)
    return min(shared / len(words), shared / len(theirs)) >= NEAR

"""A request's worked examples, from the user's remembered answers and the shipped bank.

Both banks are ranked together with the same BM25 (``example_bank``), after the remembered ones are
given the new scene's names. A remembered example that is a near match of the instruction ranks
before everything else: it is the user's own answer to this request. Near means it asks the same
(``_request``: the same meaning tokens of ``meaning.asked_meanings``, as many named objects, the same
numbers, an amount word as strong), so "get nearer to the husky and climb a little" meets "go
slightly upwards and walk closer to the husky" whatever the verbs, and "keep more distance" never
meets "keep less", nor "much closer" "slightly closer". Where the readers find no meaning in the
instruction, near falls back to words: the stems both share are at least ``NEAR`` of each side's
(the same words in another scene). Measured in docs/benchmarks.md, "Issue #28, session 12".
Where near matches answer differently, the user's latest answer (to these very words first) speaks
for them and the older ones are not shown (``_latest_answers``; "Issues #28 and #24, session 15"),
and the very same words get that answer without asking the model (``answer_to_same_words``).

How the rest are chosen is ``by``:

- ``"words"`` (the default): BM25 over the whole instruction's word stems only.
- ``"clauses"``: the index also holds what the words ask (``meaning.asked_meanings``),
  and an instruction of several clauses (``readers.clause_split.split_clauses``) first gets the best
  example of each clause, then the best for the whole; the chosen are shown in the order of their
  score for the whole instruction. Ranked by the whole alone, the clause with the rarest words takes
  every place ("move the start 0.2 right, and also raise the path slightly" showed no example going up).
  Measured on 2026-11-25 (docs/benchmarks.md, "Issue #24, session 11"): 5 more of 106 blind
  paraphrases passed, 6 fewer of 111 dev cases in their original words (both halves lost), so it
  is not the default.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import lru_cache
from typing import Literal

from trajadapt.code_parse import same_program
from trajadapt.llm.example_bank import Example, ExampleBank, default_bank, terms
from trajadapt.memory.bank import RememberedExample
from trajadapt.memory.meaning import asked_meanings
from trajadapt.memory.placeholders import mentioned
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.words import amount_size, stated_numbers

NEAR = 0.5
Request = tuple[frozenset[str], int, frozenset[float], str]
"""What an instruction asks (``_request``): meaning tokens, named objects, numbers, how much."""
Retrieval = Literal["words", "clauses"]
RETRIEVALS: tuple[Retrieval, ...] = ("words", "clauses")


def choose_examples(
    instruction: str,
    k: int,
    names: Sequence[str],
    remembered: Sequence[RememberedExample] = (),
    by: Retrieval = "words",
) -> list[Example]:
    """The ``k`` examples for ``instruction``, best first: near remembered matches, then ``by``."""
    if k <= 0:
        return []
    own = [example.as_example(instruction, names) for example in remembered]
    bank = shipped_bank(by) if not own else ExampleBank([*own, *default_bank().examples], _meanings(by))
    matches = _near_matches(instruction, own, names)
    near = _latest_answers(instruction, matches, own)
    superseded = matches - near  # own come first in ``bank``, so their indices are the same there
    whole = [index for index in bank.ranked(instruction, names) if index not in superseded]
    chosen = sorted(near, key=whole.index)
    if by == "clauses":
        chosen += _best_per_clause(bank, instruction, names, chosen, superseded)
    chosen += [index for index in whole if index not in chosen]
    picked = chosen[:k]
    return [bank.examples[i] for i in sorted(picked, key=lambda i: (i not in near, whole.index(i)))]


def _best_per_clause(
    bank: ExampleBank, instruction: str, names: Sequence[str], taken: list[int], superseded: set[int]
) -> list[int]:
    """The best example of each clause of a compound instruction that ``taken`` does not hold yet.

    A ``superseded`` example is never the best of a clause.
    """
    parts = split_clauses(instruction, names)
    if len(parts) < 2:
        return []
    best: list[int] = []
    for part in parts:
        first = next(i for i in bank.ranked(part, names) if i not in superseded)
        if first not in taken and first not in best:
            best.append(first)
    return best


@lru_cache(maxsize=len(RETRIEVALS))
def shipped_bank(by: Retrieval) -> ExampleBank:
    """The shipped bank, indexed for ``by`` (built once per process)."""
    return ExampleBank(default_bank().examples, _meanings(by)) if by == "clauses" else default_bank()


def _meanings(by: Retrieval) -> Callable[[str], list[str]] | None:
    """What the index adds to each instruction's stems for ``by``."""
    return asked_meanings if by == "clauses" else None


def _request(text: str, names: Sequence[str]) -> Request:
    """What ``text`` asks, whatever its words: meaning tokens, objects, numbers, how much.

    How much is ``words.amount_size``: "slightly closer", "closer" and "much closer" differ.
    """
    meanings = frozenset(asked_meanings(text))
    return meanings, len(mentioned(text, names)), frozenset(stated_numbers(text)), amount_size(text)


def _near_matches(instruction: str, own: Sequence[Example], names: Sequence[str]) -> set[int]:
    """The indices of ``own`` that ask what ``instruction`` asks, or share its words (none asked)."""
    if not own:
        return set()
    asked = _request(instruction, names)
    if asked[0]:
        return {i for i, e in enumerate(own) if _request(e.instruction, [*names, *e.object_names]) == asked}
    return {i for i, e in enumerate(own) if _shares_words(instruction, e, names)}


def _latest_answers(instruction: str, near: set[int], own: Sequence[Example]) -> set[int]:
    """Of the near matches, the latest and those that answer as it does (``own`` is oldest first).

    Every near match asks what the instruction asks, so where their programs differ the user's
    latest answer is their word on this request now: an answer corrected to ``scale_speed(t, 2.5,
    ...)`` supersedes the 1.6x answers approved before it for the same "a lot faster". The latest
    answer to these very words comes before the latest to other words.
    """
    same_words = {i for i in near if _words(own[i].instruction) == _words(instruction)}
    latest = max(same_words or near, default=None)
    if latest is None:
        return set()
    return {i for i in near if same_program(own[i].code, own[latest].code)}


def _words(text: str) -> str:
    """The words as compared for "the same words": case, spacing and a closing full stop aside."""
    return " ".join(text.lower().split()).rstrip(" .!")


def _shares_words(instruction: str, example: Example, names: Sequence[str]) -> bool:
    """Whether the word stems both share are at least ``NEAR`` of each side's."""
    words = {term for term in terms(instruction, names) if "+" not in term}
    theirs = {term for term in terms(example.instruction, [*names, *example.object_names]) if "+" not in term}
    if not words or not theirs:
        return False
    shared = len(words & theirs)
    return min(shared / len(words), shared / len(theirs)) >= NEAR


def answer_to_same_words(instruction: str, chosen: Sequence[Example]) -> Example | None:
    """The user's remembered answer to these very words among the ``chosen`` examples, if any.

    The user approved that program for exactly this request (names aside), so it is the answer again:
    asking the model would only risk the misreading they corrected.
    """
    return next((e for e in chosen if e.remembered and _words(e.instruction) == _words(instruction)), None)


def asks_all_of(example: Example, instruction: str) -> bool:
    """Whether the example's request asks everything ``instruction`` asks (its meaning tokens).

    A remembered program is only the user's answer to this request when nothing asked here is missing
    from the request it answered: "keep a smaller distance from the chair" does not answer "go slightly
    upwards keeping a smaller distance from the chair".
    """
    return set(asked_meanings(instruction)) <= set(asked_meanings(example.instruction))

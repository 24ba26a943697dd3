"""What an instruction asks, as tokens that stay the same whatever the words: retrieval's second vocabulary.

BM25 over word stems finds an example only through shared words, so a reworded instruction ("keep a
larger distance from the soap") misses the examples of its own request, and a particle or a place
word pulls in another's ("speed up" finds "raise the middle section"). Here each clause is read
with the product's own readers of words (the ones the checks use: a pace asked faster or slower,
the directions the path should move in, closer or further from an object, the parts and positions
of the path it speaks of) and each reading becomes a token such as ``@faster``, ``@up`` or
``@away``. Examples and instructions are read the same way, so two wordings that the readers
understand alike meet on these tokens whatever their verbs. Used by ``recall`` to tell whether a
remembered answer asks what the instruction asks (always), and by ``retrieval=clauses``, which is
opt-in: see docs/benchmarks.md, "Issue #24, session 11" and "Issue #28, session 12".
"""

from __future__ import annotations

from trajadapt.clauses.grammar import said_places
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.words import AWAY, CLOSER, FASTER, SLOWER, asks_pace

MARK = "@"
"""What starts a meaning token (no word stem does)."""


def asked_meanings(text: str) -> list[str]:
    """The meaning tokens of each clause of ``text`` (``split_clauses``), in order: once per clause.

    >>> asked_meanings("slow down near the lamp and go up a bit")
    ['@slower', '@up']
    >>> asked_meanings("keep a larger distance from the soap")
    ['@away']
    """
    tokens: list[str] = []
    for clause in split_clauses(text):
        tokens += _clause_meanings(clause)
    return tokens


def _clause_meanings(clause: str) -> list[str]:
    """The meaning tokens of one clause: its pace, directions, closer/away, parts and positions."""
    lowered = clause.lower()
    found = []
    if asks_pace(clause):
        found.append("faster" if FASTER.search(lowered) else "slower" if SLOWER.search(lowered) else "pace")
    found += sorted(said_directions(clause))
    found += ["closer"] if CLOSER.search(lowered) else []
    found += ["away"] if AWAY.search(lowered) else []
    found += sorted(said_places(clause))
    return [MARK + meaning for meaning in found]

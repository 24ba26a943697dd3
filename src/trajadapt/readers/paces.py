"""How much faster or slower the user's words ask: the calibrated factor of their speed clause."""

from __future__ import annotations

from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.request_words import is_statement
from trajadapt.readers.words import SPEED_WORDS, amount_size
from trajadapt.skills.speed import SPEED_FACTORS


def speed_factor(words: str, faster: bool) -> float:
    """The calibrated factor for the speed clause of ``words``: 'a bit', plain or 'a lot' faster/slower.

    The clause is the first of ``split_clauses`` with a speed word, so an amount word of another
    clause ("go left a lot and walk faster") does not count, and not one that only says how the
    path is now ("it's way too slow near the basket; speed up a lot there").
    """
    paced = [c for c in split_clauses(words) if SPEED_WORDS.search(c)]
    clause = next((c for c in paced if not is_statement(c)), paced[0] if paced else "")
    return SPEED_FACTORS["faster" if faster else "slower"][amount_size(clause)]

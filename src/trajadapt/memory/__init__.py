"""Memory of approved answers: the user's own examples, recalled before the shipped ones.

``MemoryBank`` keeps approved answers (scene names as placeholders) in a file under
``TRAJADAPT_HOME``; ``recall`` chooses a request's worked examples from it and the shipped bank,
by clauses and what they ask (``meaning``) or by words alone; the user's answer to the very same
words is the answer again (``answer_to_same_words``).
"""

from trajadapt.memory.bank import MemoryBank, RememberedExample
from trajadapt.memory.recall import (
    RETRIEVALS,
    Retrieval,
    answer_to_same_words,
    asks_all_of,
    choose_examples,
)

__all__ = [
    "RETRIEVALS",
    "MemoryBank",
    "RememberedExample",
    "Retrieval",
    "answer_to_same_words",
    "asks_all_of",
    "choose_examples",
]

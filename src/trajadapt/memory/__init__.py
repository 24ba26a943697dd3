"""Memory of approved answers: the user's own examples, recalled before the shipped ones.

``MemoryBank`` keeps approved answers (scene names as placeholders) in a file under
``TRAJADAPT_HOME``; ``recall`` chooses a request's worked examples from it and the shipped bank,
by clauses and what they ask (``meaning``) or by words alone.
"""

from trajadapt.memory.bank import MemoryBank, RememberedExample
from trajadapt.memory.recall import RETRIEVALS, Retrieval, asks_all_of, choose_examples

__all__ = ["RETRIEVALS", "MemoryBank", "RememberedExample", "Retrieval", "asks_all_of", "choose_examples"]

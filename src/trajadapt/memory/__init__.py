"""Memory of approved answers: the user's own examples, recalled before the shipped ones.

``MemoryBank`` keeps approved answers (scene names as placeholders) in a file under
``TRAJADAPT_HOME``; ``recall`` chooses a request's worked examples from it and the shipped bank.
"""

from trajadapt.memory.bank import MemoryBank, RememberedExample
from trajadapt.memory.recall import choose_examples

__all__ = ["MemoryBank", "RememberedExample", "choose_examples"]

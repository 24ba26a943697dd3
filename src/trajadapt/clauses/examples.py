"""Worked examples for one clause: the bank's examples cut into (clause, step) pairs.

The shipped bank (``prompts/examples.jsonl``) pairs whole instructions with whole programs. Cut by
the same splitter the user's words go through, an example whose clauses and steps are as many gives
one pair per clause, in order; a one-clause example gives its clause with all its steps; any other
is left out. Retrieval then matches a clause with the clauses that asked the same thing, so an
example's other steps (and its numbers) never reach a clause that did not ask for them.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from functools import lru_cache

from trajadapt.clauses.split import split_clauses
from trajadapt.example_bank import Example, ExampleBank, default_bank


def clause_pairs(examples: Iterable[Example]) -> list[Example]:
    """One example per clause (its steps as the code), from whole examples that cut cleanly."""
    pairs = []
    for example in examples:
        steps = [
            line
            for line in example.code.splitlines()
            if line.startswith("t = ") and "get_trajectory" not in line
        ]
        clauses = split_clauses(example.instruction, example.object_names)
        if len(clauses) == 1:
            pairs.append(Example(clauses[0], "", "\n".join(steps)))
        elif len(clauses) == len(steps):
            pairs += [Example(clause, "", step) for clause, step in zip(clauses, steps, strict=True)]
    return pairs


@lru_cache(maxsize=1)
def clause_bank() -> ExampleBank:
    """The shipped bank, cut into clauses."""
    return ExampleBank(clause_pairs(default_bank().examples))


def render_clause_examples(clause: str, count: int, object_names: Sequence[str] = ()) -> str:
    """The ``count`` clause examples nearest to ``clause``, nearest last, as a prompt section."""
    chosen = clause_bank().nearest(clause, count, object_names)
    if not chosen:
        return ""
    body = "\n\n".join(f"Words: {example.instruction}\n{example.code}" for example in reversed(chosen))
    return f"STEPS FOR SIMILAR WORDS (their objects are not in this scene):\n{body}\n\n"

"""Reading the instruction as clauses: one splitter, each clause's own rules, and a check per clause.

The stage in run order: ``split_clauses`` (the clauses, and which only keep something) ->
``clause_answer_grammar`` (the first answer keeps a step per clause, each naming only what its words
give) -> ``attribute_lines`` (which lines of an answer each clause got) -> ``clause_findings`` (what a
clause's step, run alone, contradicts in its words). The session runs it (``AdaptationSession.draft``).
"""

from trajadapt.clauses.check import clause_findings
from trajadapt.clauses.grammar import attribute_lines, clause_answer_grammar, step_grammar
from trajadapt.readers.clause_split import only_keeps, split_clauses

__all__ = [
    "attribute_lines",
    "clause_answer_grammar",
    "clause_findings",
    "only_keeps",
    "split_clauses",
    "step_grammar",
]

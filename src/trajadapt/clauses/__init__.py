"""Reading the instruction as clauses: one splitter, each clause's own rules, and a check per clause.

The stage in run order: ``split_clauses`` (the clauses, and which only keep something) ->
``clause_answer_grammar`` (the first answer keeps a step per clause, each naming only what its words
give) -> ``attribute_lines`` (which lines of an answer each clause got) -> ``clause_findings`` (what a
clause's step, run alone, contradicts in its words). The session runs it (``AdaptationSession.draft``).
Without clause steps, ``shape_findings`` reads an answer's shape against the clauses that ask for
something (no step at all, a step repeated) and the session asks afresh on a finding.
"""

from trajadapt.clauses.check import clause_findings
from trajadapt.clauses.grammar import attribute_lines, clause_answer_grammar, step_grammar
from trajadapt.clauses.shape import asking_clauses, shape_findings
from trajadapt.readers.clause_split import only_keeps, split_clauses

__all__ = [
    "asking_clauses",
    "attribute_lines",
    "clause_answer_grammar",
    "clause_findings",
    "only_keeps",
    "shape_findings",
    "split_clauses",
    "step_grammar",
]

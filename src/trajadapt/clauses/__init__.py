"""Reading the instruction as clauses: one splitter, and a first answer written one clause at a time.

Run order of the stage: ``split_clauses`` -> per clause ``clause_request`` (its examples, its
grammar) -> the backend -> ``step_lines`` -> ``compose_plan``. ``draft_by_clause`` runs it.
"""

from trajadapt.clauses.draft import ClauseDraft, ClauseRequests, ClauseStep, compose_plan, draft_by_clause
from trajadapt.clauses.split import split_clauses

__all__ = ["ClauseDraft", "ClauseRequests", "ClauseStep", "compose_plan", "draft_by_clause", "split_clauses"]

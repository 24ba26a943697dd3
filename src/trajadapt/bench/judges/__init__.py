"""Expectation checks: does an adapted trajectory do what the instruction asked?

``CHECKS`` holds every check by kind: where the path goes (``judges.path``) and how fast
(``judges.speed``); ``run_check`` runs one expectation on a ``CheckContext``.
"""

from trajadapt.bench.judges import path, speed
from trajadapt.bench.judges.core import CHECKS, CheckContext, Verdict, check, run_check

__all__ = ["CHECKS", "CheckContext", "Verdict", "check", "path", "run_check", "speed"]

"""Parsing generated code from several threads at once.

CPython 3.11 before 3.11.8 can fail ``ast.parse`` called from several threads at the same time
("AST constructor recursion depth mismatch", python/cpython#106905); the review server reads plans
on many threads. Every host-side reader of generated code parses through ``parse_code``.
"""

from __future__ import annotations

import ast
import threading

_PARSE_LOCK = threading.Lock()


def parse_code(source: str) -> ast.Module:
    """``ast.parse(source)``, one thread at a time.

    Raises:
        SyntaxError: the source is not Python.
    """
    with _PARSE_LOCK:
        return ast.parse(source)

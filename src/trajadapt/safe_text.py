"""Text from outside made safe once, at the edge: no lone surrogates, no control bytes, a length cap.

Text reaches trajadapt from case files, the LLM, generated code's exceptions and prints, and the review
page. Any of it may hold a lone surrogate (which UTF-8 cannot encode: SQLite, files and terminals then
raise), terminal control sequences, or megabytes where a line was expected. ``safe_text`` returns a str
that every sink accepts; callers pick the cap that fits the place it goes.
"""

from __future__ import annotations

import re

MESSAGE_CHARS = 4_000
"""Cap for one error message or note (the console, the repair prompt, the log)."""

INSTRUCTION_CHARS = 10_000
"""Cap for an instruction or feedback text."""

ANSWER_CHARS = 200_000
"""Cap for an LLM answer, a plan or code (a 1.5B model's answers are a few thousand characters)."""

REPLACEMENT = "\ufffd"
# C0 controls except tab and newline, DEL, C1 controls, and lone surrogates.
_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\ud800-\udfff]")


def safe_text(value: object, limit: int = MESSAGE_CHARS) -> str:
    r"""Return ``value`` as text that any file, database, terminal or HTTP body accepts.

    Carriage returns become newlines, other control characters and lone surrogates become U+FFFD,
    and text longer than ``limit`` is cut with a note of how much was left out.

    >>> safe_text("ok\ud800\x1b[2J") == "ok\ufffd\ufffd[2J"
    True
    >>> safe_text("x" * 30, limit=10)
    'xxxxxxxxxx… [20 more characters cut]'
    """
    text = value if isinstance(value, str) else str(value)
    cut = len(text) - limit
    if cut > 0:
        text = text[:limit]
    text = _UNSAFE.sub(REPLACEMENT, text.replace("\r\n", "\n").replace("\r", "\n"))
    return f"{text}… [{cut} more characters cut]" if cut > 0 else text


def safe_optional(value: object, limit: int = MESSAGE_CHARS) -> str | None:
    """``safe_text`` for a value that may be None (kept as None)."""
    return None if value is None else safe_text(value, limit)

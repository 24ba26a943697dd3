"""Plan: the LLM's numbered high-level plan and code, read robustly out of its answer text."""

from __future__ import annotations

import ast
import json
import re
from dataclasses import dataclass
from typing import Any

from trajadapt.errors import AnswerParseError
from trajadapt.safe_text import ANSWER_CHARS, MESSAGE_CHARS, safe_text

PLAN_KEYS = ("high_level_plan", "high-level plan", "high level plan", "plan", "hlp")
CODE_KEYS = ("python_code", "python code", "code", "python")
FENCE = re.compile(r"```[ \t]*([A-Za-z0-9_+-]*)[ \t]*\n(.*?)(?:```|\Z)", re.DOTALL)
STEP_START = re.compile(r"^\s*(?:step\s*)?\d+\s*[).:-]\s*", re.IGNORECASE)


@dataclass(frozen=True)
class Plan:
    """A high-level plan (numbered steps), the code that carries it out, and the raw answer."""

    steps: tuple[str, ...]
    code: str
    raw_text: str = ""

    def numbered(self) -> str:
        """The steps as the user reads them: ``1) ...`` one per line."""
        return "\n".join(f"{index}) {step}" for index, step in enumerate(self.steps, start=1))


def answer_json(plan: str, code: str) -> str:
    """A plan and its code as an answer in the form the prompt asks for (``parse_answer`` reads it)."""
    return json.dumps({"high_level_plan": plan, "python_code": code})


def parse_answer(text: str) -> Plan:
    """Read the plan and code out of an LLM answer.

    Accepts a JSON object (also inside a fence or surrounded by prose, with single quotes as in
    the paper's example, or with the code as a string of escaped newlines) and falls back to a
    fenced Python block with the plan as the text before it.

    Raises:
        AnswerParseError: there is no code in the answer.
    """
    record = _find_record(text)
    if record is not None:
        plan_value, code_value = _pick(record, PLAN_KEYS), _pick(record, CODE_KEYS)
        if isinstance(code_value, str) and code_value.strip():
            return _safe_plan(_steps(plan_value), _clean_code(code_value), text)
    fenced = _fenced_python(text)
    if fenced is not None:
        before = text[: text.find(fenced[0])]
        plan_value = _pick(record, PLAN_KEYS) if record else before
        return _safe_plan(_steps(plan_value), _clean_code(fenced[1]), text)
    raise AnswerParseError(safe_text(_no_code_message(text, record)))


def _safe_plan(steps: tuple[str, ...], code: str, text: str) -> Plan:
    """A plan whose texts are safe to show, log and store (JSON escapes can hide lone surrogates)."""
    return Plan(
        tuple(safe_text(step, MESSAGE_CHARS) for step in steps),
        safe_text(code, ANSWER_CHARS),
        safe_text(text, ANSWER_CHARS),
    )


def _no_code_message(text: str, record: dict[str, Any] | None) -> str:
    excerpt = " ".join(text.split())[:160] or "(empty)"
    if record is not None:
        keys = ", ".join(map(repr, record)) or "none"
        return (
            f"the answer is JSON but has no Python code (keys: {keys}); expected the fields "
            f"'high_level_plan' and 'python_code'. Answer began: {excerpt}"
        )
    return (
        "the answer holds neither a JSON object with 'high_level_plan' and 'python_code' nor a "
        f"```python block. Answer began: {excerpt}"
    )


def _find_record(text: str) -> dict[str, Any] | None:
    candidates = [body for language, body in FENCE.findall(text) if language.lower() in ("json", "")]
    candidates.append(text)
    for candidate in candidates:
        for snippet in _brace_spans(candidate):
            record = _load_mapping(snippet)
            if record is not None and (_pick(record, CODE_KEYS) or _pick(record, PLAN_KEYS)):
                return record
    return None


def _brace_spans(text: str) -> list[str]:
    """Substrings from a '{' to the last '}' after it, outermost first."""
    spans = []
    end = text.rfind("}")
    start = text.find("{")
    while start != -1 and start < end:
        spans.append(text[start : end + 1])
        start = text.find("{", start + 1)
        if len(spans) >= 8:
            break
    return spans


def _load_mapping(snippet: str) -> dict[str, Any] | None:
    for loader in (_json_loads, ast.literal_eval):
        try:
            value = loader(snippet)
        except (ValueError, SyntaxError, TypeError, MemoryError, RecursionError):
            continue
        if isinstance(value, dict):
            return value
    return None


def _json_loads(snippet: str) -> Any:
    return json.loads(snippet, strict=False)


def _pick(record: dict[str, Any] | None, keys: tuple[str, ...]) -> Any:
    if not record:
        return None
    normalised = {str(key).strip().lower().replace("_", " "): value for key, value in record.items()}
    for key in keys:
        value = normalised.get(key.replace("_", " "))
        if value is not None:
            return value
    return None


def _steps(value: Any) -> tuple[str, ...]:
    if isinstance(value, list | tuple):
        items = [str(item) for item in value]
    elif isinstance(value, str):
        items = _split_numbered(value)
    else:
        items = []
    steps = [STEP_START.sub("", item).strip() for item in items]
    return tuple(step for step in steps if step)


def _split_numbered(text: str) -> list[str]:
    steps: list[str] = []
    for line in text.replace("\\n", "\n").splitlines():
        if STEP_START.match(line) or not steps:
            steps.append(line)
        elif line.strip():
            steps[-1] += " " + line.strip()
    if len(steps) == 1:  # "1) a 2) b" on one line
        parts = re.split(r"(?:^|\s)(?=\d+\)\s)", steps[0])
        steps = [part for part in parts if part.strip()]
    return steps


def _clean_code(code: str) -> str:
    fenced = _fenced_python(code)
    if fenced is not None:
        code = fenced[1]
    if "\n" not in code and "\\n" in code:
        code = code.replace("\\r\\n", "\n").replace("\\n", "\n").replace("\\t", "    ")
        code = code.replace('\\"', '"').replace("\\'", "'")
    return code.strip("\n") + "\n"


def _fenced_python(text: str) -> tuple[str, str] | None:
    for match in FENCE.finditer(text):
        language, body = match.group(1).lower(), match.group(2)
        if language in ("python", "py", "python3") or (language == "" and _looks_like_code(body)):
            return match.group(0), body
    return None


def _looks_like_code(body: str) -> bool:
    stripped = body.strip()
    return not stripped.startswith("{") and ("=" in stripped or "import " in stripped)

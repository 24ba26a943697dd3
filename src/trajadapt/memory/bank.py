"""The user's bank of approved answers: one JSON-lines file under ``TRAJADAPT_HOME``, append only.

Each line is a record: the first one names the format, then ``add`` (an approved answer, its scene
names replaced by placeholders) and ``remove`` (a forgotten one). Appends are one ``write`` each
under an exclusive ``flock``, so two processes approving at once both land, and a reader under a
shared lock never sees half a line. Nothing in the file is ever executed: an example is text for the
prompt, and the answer the model writes from it still goes through the grammar and the sandbox.
"""

from __future__ import annotations

import fcntl
import json
import os
import socket
import time
import uuid
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from trajadapt.errors import MemoryUnusable
from trajadapt.files.atomic_files import publish_bytes
from trajadapt.llm.example_bank import Example
from trajadapt.memory.placeholders import PLACEHOLDER, abstract, fill, looked_up
from trajadapt.readers.clause_split import split_clauses
from trajadapt.sandbox.guard import check_code

FORMAT = {"trajadapt_memory": 1}
LIMITS = {"instruction": 2_000, "plan": 4_000, "code": 8_000}
MAX_EXAMPLES = 10_000
MAX_FILE_BYTES = 32 * 1024 * 1024
NEXT_STEP = "move the file aside to start an empty bank, or turn memory off with --no-memory"


@dataclass(frozen=True)
class RememberedExample:
    """An approved answer as the bank keeps it: scene names replaced by ``<object k>``."""

    id: str
    instruction: str
    clauses: tuple[str, ...]
    plan: str
    code: str
    objects: int
    created: float
    origin: str

    def as_example(self, instruction: str, names: Sequence[str]) -> Example:
        """This answer for a new request, with the scene's names in place of the placeholders."""
        text, plan, code = fill([self.instruction, self.plan, self.code], self.objects, instruction, names)
        return Example(text, plan, code, remembered=self.id)

    def to_record(self) -> dict[str, Any]:
        """The ``add`` line of this example."""
        return {"op": "add", **asdict(self), "clauses": list(self.clauses)}


class MemoryBank:
    """Approved answers the user's sessions remember, in the file at ``path``.

    A ``read_only`` bank is recalled from but never written (a benchmark's ``--memory``).
    """

    def __init__(self, path: Path, read_only: bool = False) -> None:
        self.path = path
        self.read_only = read_only

    def examples(self) -> list[RememberedExample]:
        """Every remembered example not forgotten, oldest first.

        Raises:
            MemoryUnusable: the file cannot be read or is not a bank.
        """
        if not self.path.exists():
            return []
        with self._locked(fcntl.LOCK_SH, "read") as stream:
            return list(_live(_records(stream.read(), str(self.path))))

    def get(self, example_id: str) -> RememberedExample | None:
        """The example with this id, or None."""
        return next((e for e in self.examples() if e.id == example_id), None)

    def remember(self, instruction: str, plan: str, code: str, names: Sequence[str]) -> RememberedExample:
        """Keep an approved answer (an equal one already kept is returned instead of a copy).

        Raises:
            MemoryUnusable: the file cannot be written, or the bank is full.
            InputError: the answer is not one the bank can hold (too long, code the sandbox refuses).
        """
        (text, plan_text, code_text), count = abstract([instruction, plan, code], names)
        example = _checked({"id": uuid.uuid4().hex[:10], "instruction": text, "plan": plan_text,
                            "code": code_text, "objects": count, "created": time.time(),
                            "origin": socket.gethostname(), "clauses": list(split_clauses(text))},
                           "the approved answer")  # fmt: skip
        return self._append([example])[0]

    def forget(self, example_id: str) -> bool:
        """Forget an example; False when there is none with that id."""
        removal = {"op": "remove", "id": example_id}
        return bool(self._update(lambda live: [removal] if any(e.id == example_id for e in live) else []))

    def export(self, target: Path) -> int:
        """Write the live examples to ``target`` as a bank file of its own; how many."""
        examples = self.examples()
        lines = [json.dumps(FORMAT)] + [json.dumps(e.to_record()) for e in examples]
        publish_bytes(target, ("\n".join(lines) + "\n").encode("utf-8"), replace=False)
        return len(examples)

    def import_file(self, source: Path, names: Sequence[str] = ()) -> list[RememberedExample]:
        """Add the examples of a bank file from elsewhere, with new ids.

        Names of ``names`` (or any name the code looks up that is not a placeholder) become
        placeholders, so examples written in another lab's scene carry over. The whole file is
        checked before anything is added.

        Raises:
            MemoryUnusable: the file is not a bank (or is damaged), with the line that is wrong.
        """
        try:
            text = source.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise MemoryUnusable(f"cannot read {source} ({type(exc).__name__}: {exc})") from exc
        foreign = list(_live(_records(text, str(source))))
        remapped = [_remapped(example, names, str(source)) for example in foreign]
        return self._append(remapped)

    def _append(self, examples: list[RememberedExample]) -> list[RememberedExample]:
        """Add examples not already kept (same instruction and code); the kept ones, as stored."""
        kept: dict[tuple[str, str], RememberedExample] = {}

        def additions(live: list[RememberedExample]) -> list[dict[str, Any]]:
            kept.update({(e.instruction, e.code): e for e in live})
            new = [e for e in examples if (e.instruction, e.code) not in kept]
            if len(kept) + len(new) > MAX_EXAMPLES:
                raise MemoryUnusable(f"the bank {self.path} holds {MAX_EXAMPLES} examples; forget some first")
            return [example.to_record() for example in new]

        self._update(additions)
        return [kept.get((e.instruction, e.code), e) for e in examples]

    def _update(self, records_for: Callable[[list[RememberedExample]], list[dict[str, Any]]]) -> int:
        """Append the records ``records_for`` gives for the live examples; how many.

        The file is read and written under one exclusive lock, so a check and its write are never
        split by another process (two approving the same answer keep it once).
        """
        if self.read_only:
            raise MemoryUnusable(f"the bank {self.path} was opened read-only")
        with self._locked(fcntl.LOCK_EX, "write to", create=True) as stream:
            records = records_for(list(_live(_records(stream.read(), str(self.path)))))
            if not records:
                return 0
            body = "".join(json.dumps(record) + "\n" for record in records)
            if stream.tell() == 0:
                body = json.dumps(FORMAT) + "\n" + body
            if stream.tell() + len(body) > MAX_FILE_BYTES:
                raise MemoryUnusable(f"the bank {self.path} is full ({MAX_FILE_BYTES // 2**20} MB)")
            stream.write(body)
            stream.flush()
            os.fsync(stream.fileno())
        return len(records)

    @contextmanager
    def _locked(self, mode: int, doing: str, create: bool = False) -> Iterator[Any]:
        try:
            if create:
                self.path.parent.mkdir(parents=True, exist_ok=True)
            with self.path.open("a+" if create else "r", encoding="utf-8") as stream:
                fcntl.flock(stream.fileno(), mode)
                stream.seek(0)
                yield stream
        except (OSError, UnicodeDecodeError) as exc:
            raise MemoryUnusable(
                f"cannot {doing} the bank of remembered examples {self.path} ({type(exc).__name__}: "
                f"{exc}); {NEXT_STEP}"
            ) from exc


def _records(text: str, where: str) -> Iterator[dict[str, Any]]:
    lines = text.splitlines()
    if not lines:
        return
    if _json(lines[0], where, 1) != FORMAT:
        raise MemoryUnusable(f"{where} is not a trajadapt bank of examples (its first line is not {FORMAT})")
    for number, line in enumerate(lines[1:], start=2):
        if line.strip():
            yield {**_json(line, where, number), "_line": number}


def _json(line: str, where: str, number: int) -> Any:
    try:
        return json.loads(line)
    except ValueError as exc:
        raise MemoryUnusable(f"{where} line {number} is not JSON ({exc}); {NEXT_STEP}") from exc


def _live(records: Iterable[dict[str, Any]]) -> Iterator[RememberedExample]:
    """The examples added and not removed since, in the order they were added."""
    added: dict[str, RememberedExample] = {}
    for record in records:
        where = f"line {record.pop('_line')}"
        if record.get("op") == "add":
            example = _checked(record, where)
            added[example.id] = example
        elif record.get("op") == "remove" and isinstance(record.get("id"), str):
            added.pop(record["id"], None)
        else:
            raise MemoryUnusable(f"{where} of the bank is neither an add nor a remove record; {NEXT_STEP}")
    yield from added.values()


def _checked(record: dict[str, Any], where: str) -> RememberedExample:
    """A record as an example, after checking every field's type, length and the code's safety."""
    texts = {key: record.get(key) for key in ("id", *LIMITS, "origin")}
    if not all(isinstance(value, str) for value in texts.values()):
        raise MemoryUnusable(f"{where}: an example needs id, instruction, plan, code and origin as text")
    for key, limit in LIMITS.items():
        if not texts[key] or len(str(texts[key])) > limit:
            raise MemoryUnusable(f"{where}: {key} is empty or longer than {limit} characters")
    clauses, objects, created = record.get("clauses"), record.get("objects"), record.get("created")
    if not (isinstance(clauses, list) and all(isinstance(c, str) for c in clauses) and len(clauses) <= 50):
        raise MemoryUnusable(f"{where}: clauses must be a list of texts")
    if type(objects) is not int or not 0 <= objects <= 100 or not isinstance(created, int | float):
        raise MemoryUnusable(f"{where}: objects must be a count and created a time")
    violation = check_code(str(texts["code"]))
    if violation is not None:
        raise MemoryUnusable(f"{where}: its code would be refused by the sandbox ({violation.message})")
    return RememberedExample(str(texts["id"]), str(texts["instruction"]), tuple(clauses), str(texts["plan"]),
                             str(texts["code"]), objects, float(created), str(texts["origin"]))  # fmt: skip


def _remapped(example: RememberedExample, names: Sequence[str], where: str) -> RememberedExample:
    """A foreign example with a new id, its concrete names (given or looked up) as placeholders."""
    concrete = [*names, *(name for name in looked_up(example.code) if not PLACEHOLDER.fullmatch(name))]
    texts = [example.instruction, example.plan, example.code]
    (text, plan, code), extra = abstract(texts, concrete, first=example.objects + 1)
    record = {**example.to_record(), "id": uuid.uuid4().hex[:10], "instruction": text, "plan": plan,
              "code": code, "objects": example.objects + extra,
              "clauses": list(split_clauses(text))}  # fmt: skip
    return _checked(record, f"{where} ({example.id})")

"""The bank of remembered examples: it survives restarts, loses nothing to a race, forgets for good,
refuses damaged or foreign files in words, and imports another machine's bank with names remapped."""

from __future__ import annotations

import json
import multiprocessing
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from trajadapt.errors import MemoryUnusable
from trajadapt.memory import MemoryBank, choose_examples
from trajadapt.memory.placeholders import abstract, fill

CODE = "t = get_trajectory()\nt = move_closer(t, detect_objects('red mug'), 'a bit')\nmodified_trajectory = t"


def remember_one(bank: MemoryBank, words: str = "hug the red mug") -> str:
    return bank.remember(words, "1) Closer to the red mug.", CODE, ["red mug", "table"]).id


def test_an_approved_answer_is_kept_with_placeholders_and_survives_a_restart(tmp_path: Path) -> None:
    example_id = remember_one(MemoryBank(tmp_path / "memory.jsonl"))
    again = MemoryBank(tmp_path / "memory.jsonl").examples()
    assert [e.id for e in again] == [example_id]
    kept = again[0]
    assert kept.instruction == "hug the <object 1>" and "detect_objects('<object 1>')" in kept.code
    assert kept.objects == 1 and kept.clauses == ("hug the <object 1>",)


def test_the_same_answer_twice_is_kept_once(tmp_path: Path) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    assert remember_one(bank) == remember_one(bank)
    assert len(bank.examples()) == 1


def _approve_many(path: str, worker: int) -> None:
    bank = MemoryBank(Path(path))
    for k in range(15):
        bank.remember(
            f"go left by {worker}.{k}",
            "1) Left.",
            f"t = get_trajectory()\nt = shift(t, 'left', {worker}.{k})\nmodified_trajectory = t",
            [],
        )


def test_two_processes_approving_at_once_lose_nothing(tmp_path: Path) -> None:
    path = tmp_path / "memory.jsonl"
    context = multiprocessing.get_context("spawn")
    workers = [context.Process(target=_approve_many, args=(str(path), w)) for w in (1, 2, 3)]
    for worker in workers:
        worker.start()
    for worker in workers:
        worker.join(60)
        assert worker.exitcode == 0
    examples = MemoryBank(path).examples()
    assert len(examples) == 45 and len({e.id for e in examples}) == 45
    assert path.read_text().count('"trajadapt_memory"') == 1


def test_a_forgotten_example_is_never_recalled(tmp_path: Path) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    example_id = remember_one(bank)
    assert choose_examples("hug the kettle", 3, ["kettle"], bank.examples())[0].remembered == example_id
    assert bank.forget(example_id) and not bank.forget(example_id)
    assert bank.examples() == [] and MemoryBank(tmp_path / "memory.jsonl").get(example_id) is None
    assert all(not e.remembered for e in choose_examples("hug the kettle", 3, ["kettle"], bank.examples()))


def test_a_read_only_bank_is_never_written(tmp_path: Path) -> None:
    path = tmp_path / "memory.jsonl"
    remember_one(MemoryBank(path))
    before = path.read_bytes()
    with pytest.raises(MemoryUnusable, match="read-only"):
        remember_one(MemoryBank(path, read_only=True), "a new request about the red mug")
    assert path.read_bytes() == before


@pytest.mark.parametrize(
    ("content", "message"),
    [
        (b"\x00\xff garbage", "cannot read"),
        (b'{"something": "else"}\n', "not a trajadapt bank"),
        (b'{"trajadapt_memory": 1}\n{"op": "add", "id": "x"\n', "line 2 is not JSON"),
        (b'{"trajadapt_memory": 1}\n{"op": "drop", "id": "x"}\n', "neither an add nor a remove"),
        (
            b'{"trajadapt_memory": 1}\n{"op": "add", "id": "x", "instruction": "go", "plan": "1) Go.", '
            b'"code": "import os\\nos.system(\'true\')", "objects": 0, "created": 1, "origin": "h", "clauses": []}\n',
            "would be refused by the sandbox",
        ),
        (
            b'{"trajadapt_memory": 1}\n{"op": "add", "id": "x", "instruction": "go", "plan": "1) Go.", '
            b'"code": "t = 1", "objects": "many", "created": 1, "origin": "h", "clauses": []}\n',
            "objects must be a count",
        ),
    ],
)
def test_a_damaged_or_foreign_bank_is_an_error_in_words(tmp_path: Path, content: bytes, message: str) -> None:
    path = tmp_path / "memory.jsonl"
    path.write_bytes(content)
    with pytest.raises(MemoryUnusable, match=message):
        MemoryBank(path).examples()
    with pytest.raises(MemoryUnusable, match=message):
        MemoryBank(tmp_path / "mine.jsonl").import_file(path)
    assert not (tmp_path / "mine.jsonl").exists()  # nothing added from a bad file


def test_a_bank_that_is_a_folder_says_what_to_do(tmp_path: Path) -> None:
    (tmp_path / "memory.jsonl").mkdir()
    with pytest.raises(MemoryUnusable, match="--no-memory"):
        MemoryBank(tmp_path / "memory.jsonl").examples()


def test_a_bank_from_another_machine_imports_with_new_ids_and_names_remapped(tmp_path: Path) -> None:
    theirs = tmp_path / "theirs.jsonl"
    record = {"op": "add", "id": "abc", "instruction": "hover over the <object 1> then the lamp",
              "plan": "1) Over the <object 1>. 2) Over the lamp.",
              "code": "t = get_trajectory()\nt = pass_through(t, detect_objects('<object 1>'))\n"
                      "t = pass_through(t, detect_objects('lamp'))\nmodified_trajectory = t",
              "objects": 1, "created": 1.0, "origin": "lab-pc", "clauses": []}  # fmt: skip
    theirs.write_text(json.dumps({"trajadapt_memory": 1}) + "\n" + json.dumps(record) + "\n")
    mine = MemoryBank(tmp_path / "memory.jsonl")
    (imported,) = mine.import_file(theirs)
    assert imported.id != "abc" and imported.origin == "lab-pc" and imported.objects == 2
    assert imported.instruction == "hover over the <object 1> then the <object 2>"
    assert "detect_objects('<object 2>')" in imported.code and "lamp" not in imported.code
    example = imported.as_example("hover over the kettle then the sink", ["sink", "kettle"])
    assert "detect_objects('kettle')" in example.code and "detect_objects('sink')" in example.code
    assert example.code.index("kettle") < example.code.index("sink")  # in the order the new words name them


def test_export_then_import_round_trips(tmp_path: Path) -> None:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    remember_one(bank)
    assert bank.export(tmp_path / "out.jsonl") == 1
    other = MemoryBank(tmp_path / "other.jsonl")
    (copy,) = other.import_file(tmp_path / "out.jsonl")
    assert copy.instruction == bank.examples()[0].instruction and copy.code == bank.examples()[0].code


NAMES = st.lists(
    st.sampled_from(["red mug", "mug", "lamp", "Table", "blue box", "box"]),
    min_size=1,
    max_size=4,
    unique=True,
)


@settings(max_examples=80, deadline=None)
@given(NAMES, st.data())
def test_placeholders_round_trip_in_the_same_scene(names: list[str], data: st.DataObject) -> None:
    used = data.draw(st.lists(st.sampled_from(names), min_size=1, max_size=3, unique=True))
    instruction = "go near the " + " and then the ".join(used)
    code = "\n".join(f"t = move_closer(t, detect_objects('{name}'))" for name in used)
    (text, abstract_code), count = abstract([instruction, code], names)
    assert not any(f"'{name}'" in abstract_code for name in names)
    back = fill([text, abstract_code], count, instruction, names)
    assert back == [instruction, code]

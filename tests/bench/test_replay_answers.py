"""`benchmarks/replay_answers.py` gives back the model's own answer when a result keeps it."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

from trajadapt.backends.scripted import ScriptedBackend
from trajadapt.bench.runner import BenchConfig, discover_cases, run_benchmark

REPLAY = Path(__file__).resolve().parents[2] / "benchmarks" / "replay_answers.py"
KEEP = Path(__file__).resolve().parents[2] / "benchmarks" / "keep_answers.py"
LEFT_AND_MORE = json.dumps(
    {
        "high_level_plan": "1) Shift left. 2) Extend.",
        "python_code": "t = get_trajectory()\nt = shift(t, 'left')\nt = extend(t, 0.5)\nmodified_trajectory = t",
    }
)


def _replayed_notes(stored: Path, cases: Path, out: Path) -> list[str]:
    subprocess.run([sys.executable, str(REPLAY), str(stored), str(cases), "--out", str(out)], check=True,
                   capture_output=True)  # fmt: skip
    return json.loads((out / "left.result.json").read_text())["review_notes"]


def test_a_replay_starts_from_the_models_answer_not_from_the_readers_code(
    tmp_path: Path, ovita_dir: Path
) -> None:
    cases = tmp_path / "cases"
    cases.mkdir()
    shutil.copy(ovita_dir / "latte_subset" / "latte_32.json", cases / "left.json")  # "go to the left"
    stored = tmp_path / "stored"
    run_benchmark(
        discover_cases([cases]), ScriptedBackend(answers=[LEFT_AND_MORE]), BenchConfig(out_dir=stored)
    )
    record = json.loads((stored / "left.result.json").read_text())
    assert record["answer"] == LEFT_AND_MORE and "extend" not in record["code"]
    assert any("extend" in note for note in _replayed_notes(stored, cases, tmp_path / "again"))
    del record["answer"]  # a result from before answers were kept: the readers' code is all there is
    (stored / "left.result.json").write_text(json.dumps(record))
    assert not any("extend" in note for note in _replayed_notes(stored, cases, tmp_path / "older"))


def test_a_replay_finds_the_answer_to_words_that_state_a_problem(tmp_path: Path, ovita_dir: Path) -> None:
    """The model is shown the request, not the statement of the problem: the replay looks it up so."""
    case = json.loads((ovita_dir / "latte_subset" / "latte_32.json").read_text())
    case["instruction"] = "It sits too far right. Go to the left."
    cases = tmp_path / "cases"
    cases.mkdir()
    (cases / "left.json").write_text(json.dumps(case))
    stored = tmp_path / "stored"
    run_benchmark(
        discover_cases([cases]), ScriptedBackend(answers=[LEFT_AND_MORE]), BenchConfig(out_dir=stored)
    )
    assert any("extend" in note for note in _replayed_notes(stored, cases, tmp_path / "again"))


def test_kept_answers_replay_as_the_folder_does(tmp_path: Path, ovita_dir: Path) -> None:
    """The small file of kept answers stands in for the bench output folder."""
    cases = tmp_path / "cases"
    cases.mkdir()
    shutil.copy(ovita_dir / "latte_subset" / "latte_32.json", cases / "left.json")
    stored = tmp_path / "stored"
    run_benchmark(
        discover_cases([cases]), ScriptedBackend(answers=[LEFT_AND_MORE]), BenchConfig(out_dir=stored)
    )
    kept = tmp_path / "answers.jsonl"
    subprocess.run([sys.executable, str(KEEP), str(kept), str(stored)], check=True, capture_output=True)
    assert json.loads(kept.read_text())["answer"] == LEFT_AND_MORE
    assert _replayed_notes(kept, cases, tmp_path / "from-file") == _replayed_notes(
        stored, cases, tmp_path / "again"
    )

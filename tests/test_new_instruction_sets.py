"""The sets of new instructions with their own checks (tests/data/new_instructions) are sound.

Each set was written blind: a new instruction for a dev scene and the checks that judge it. These
tests hold the sets to what a judge must be: every check a kind the judges know, the expectations
file the case writer makes loads as the bench loads it, and the unchanged path fails every case
(a check the original already passes judges nothing).
"""

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from trajadapt.bench.expectations import DEFAULT_SMOOTHNESS, load_expectations
from trajadapt.bench.judges import CHECKS, CheckContext, run_check
from trajadapt.model.geometry import PAPER_AXES

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))
from new_instruction_cases import SETS, expectations_toml, read_set, write_new_instruction_cases  # noqa: E402

NAMES = sorted(path.stem for path in SETS.glob("*.json"))


def test_there_is_a_set():
    assert NAMES


@pytest.mark.parametrize("name", NAMES)
def test_every_case_has_an_instruction_and_checks_of_known_kinds(name):
    cases = read_set(name)
    assert cases
    for key, case in cases.items():
        assert case["instruction"].strip(), key
        assert case["checks"], key
        assert {check["kind"] for check in case["checks"]} <= set(CHECKS), key


@pytest.mark.parametrize("name", NAMES)
def test_the_expectations_file_loads_with_the_checks_as_written(name, tmp_path):
    cases = read_set(name)
    path = tmp_path / "expectations.toml"
    path.write_text(expectations_toml(cases), encoding="utf-8")
    loaded = load_expectations(path, name)
    for key, case in cases.items():
        assert list(loaded.cases[key].checks) == [*case["checks"], DEFAULT_SMOOTHNESS]


@pytest.mark.parametrize("name", NAMES)
def test_the_unchanged_path_fails_every_case(name, ovita_dir, tmp_path):
    written = write_new_instruction_cases(ovita_dir, tmp_path, name)
    for key, case in read_set(name).items():
        scene = json.loads((ovita_dir / f"{key}.json").read_text(encoding="utf-8"))
        original = np.asarray(scene["trajectory"], dtype=np.float64)
        objects = {o["name"].casefold(): np.array([o["x"], o["y"], o["z"]]) for o in scene["objects"]}
        context = CheckContext(original, original.copy(), objects, PAPER_AXES)
        verdicts = [run_check(context, dict(check)) for check in case["checks"]]
        assert not all(v.passed for v in verdicts), f"{key}: the unchanged path passes {case['checks']}"
    assert len(written) == len(read_set(name))


def test_a_value_toml_cannot_write_is_refused():
    with pytest.raises(TypeError, match="must be a string, number, boolean or list"):
        expectations_toml(
            {"a/b": {"instruction": "x", "checks": [{"kind": "changed", "bad": {"nested": 1}}]}}
        )

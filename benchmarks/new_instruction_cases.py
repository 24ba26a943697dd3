"""Write dev scenes with new instructions and their own checks, to measure instructions nobody tuned for.

A set (tests/data/new_instructions/NAME.json) holds, per dev case, an instruction written blind for
that scene (by someone who saw only the scene and the check vocabulary, never an instruction written
for it) and the checks that judge it. The copies go to OUT/NAME/<case>.json with the set's checks in
OUT/NAME/expectations.toml, where `trajadapt bench` finds them.

Run: .venv/bin/python benchmarks/new_instruction_cases.py ../shared/data/ovita-dev out/new fresh-a
Then: trajadapt bench out/new/fresh-a --out bench-out/NAME
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any

SETS = Path(__file__).resolve().parent.parent / "tests" / "data" / "new_instructions"


def read_set(name: str, sets: Path = SETS) -> dict[str, dict[str, Any]]:
    """The set's cases: ``{case: {"instruction": ..., "checks": [...]}}``."""
    text = (sets / f"{name}.json").read_text(encoding="utf-8")
    cases: dict[str, dict[str, Any]] = json.loads(text)["cases"]
    return cases


def toml_value(value: Any) -> str:
    """One value as TOML: a string, number, boolean, or a list of them."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(item) for item in value) + "]"
    raise TypeError(f"a check's value must be a string, number, boolean or list, got {value!r}")


def expectations_toml(cases: dict[str, dict[str, Any]]) -> str:
    """The expectations file of a set: one table per case with its checks."""
    lines = ["version = 1"]
    for key, case in cases.items():
        tables = (
            "{" + ", ".join(f"{name} = {toml_value(value)}" for name, value in check.items()) + "}"
            for check in case["checks"]
        )
        lines += [f'["{key}"]', f"checks = [{', '.join(tables)}]"]
    return "\n".join(lines) + "\n"


def write_new_instruction_cases(cases: Path, out: Path, name: str, sets: Path = SETS) -> list[Path]:
    """One copy of each case of set ``name`` under ``out/name``, its instruction replaced, and its checks."""
    new = read_set(name, sets)
    folder = out / name
    written = []
    for key, entry in new.items():
        case = json.loads((cases / f"{key}.json").read_text(encoding="utf-8"))
        case["instruction"] = entry["instruction"]
        target = folder / f"{key}.json"
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(json.dumps(case), encoding="utf-8")
        written.append(target)
    (folder / "expectations.toml").write_text(expectations_toml(new), encoding="utf-8")
    return written


def main() -> None:
    """Write the set's cases and checks and say how many."""
    formatter = argparse.RawDescriptionHelpFormatter
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=formatter)
    parser.add_argument("cases", type=Path, help="the ovita-dev folder (the scenes)")
    parser.add_argument("out", type=Path, help="where the copies go (OUT/NAME/...)")
    parser.add_argument("name", help="the set's name in tests/data/new_instructions (fresh-a)")
    args = parser.parse_args()
    written = write_new_instruction_cases(args.cases, args.out, args.name)
    print(f"wrote {len(written)} case(s) and their checks under {args.out / args.name}")


if __name__ == "__main__":
    main()

"""What the skill library can reach on LaTTe-style cases, without a model: calibrate vague amounts and reach.

For each case of a folder in the latte-dev layout (cases/<kind>/, targets/<kind>/), the instruction
is read with LaTTe's published instruction grammar (see latte-dev's README) into the skill call a
perfect model would write with our prompt's phrase table (``shift(t, 'left')``, ``move_closer(t, x,
'a lot')``, ``scale_speed(t, 0.5, near=x)``). Running that call and scoring it with LaTTe's metric
tells how good the skills' constants are (the amount words, how far an object-relative change
reaches), separately from the model's mistakes. ``--sweep`` tries other constants and prints the
MSE of each, per kind, next to copying the input.

Usage:
    python benchmarks/latte_oracle.py ../shared/data/latte-dev [--sweep]
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import numpy as np

from trajadapt.bench.metrics import latte_scores
from trajadapt.skills import bind_skills
from trajadapt.skills import objects as object_skills
from trajadapt.skills import shape as shape_skills
from trajadapt.skills import speed as speed_skills

SKILLS = bind_skills()
DIRECTIONS = {"left": "left", "right": "right", "front": "front", "back": "back", "top": "up",
              "upper part": "up", "bottom part": "down", "bottom": "down", "down": "down"}  # fmt: skip
SPEED_UP = {None: 1.4, "a bit": 1.25, "a lot": 1.6}  # the prompt's phrase table: "faster near X"
SLOW_DOWN = {None: 0.65, "a bit": 0.75, "a lot": 0.45}
INTENSITY = {"a bit": "a bit", "a little": "a bit", "much": "a lot", "a lot": "a lot", "very": "a lot"}


def intensity(text: str) -> str | None:
    """The amount word of an instruction, as our prompt's phrase table writes it."""
    return next((word for key, word in INTENSITY.items() if re.search(rf"\b{key}\b", text)), None)


def oracle(kind: str, text: str, objects: dict[str, np.ndarray]) -> Callable[[np.ndarray], np.ndarray]:
    """The skill call for a LaTTe instruction, as a function of the trajectory."""
    text = text.lower()
    if kind == "cartesian":
        word = next(
            key for key in sorted(DIRECTIONS, key=len, reverse=True) if re.search(rf"\b{key}\b", text)
        )
        return lambda t: SKILLS["shift"](t, DIRECTIONS[word])
    name = max((n for n in objects if n.lower() in text), key=len)
    point, amount = objects[name], intensity(text)
    if kind == "dist":
        closer = "closer" in text or "smaller" in text
        skill = SKILLS["move_closer" if closer else "move_away"]
        return lambda t: skill(t, point, amount)
    faster = "faster" in text or "increase" in text
    factor = (SPEED_UP if faster else SLOW_DOWN)[amount]
    return lambda t: SKILLS["scale_speed"](t, factor, near=point)


def load(folder: Path) -> list[tuple[str, dict[str, Any], np.ndarray]]:
    """(kind, case, target) for every case with a target."""
    cases = []
    for path in sorted((folder / "cases").glob("*/*.json")):
        target = folder / "targets" / path.parent.name / path.name
        if target.is_file():
            case = json.loads(path.read_text())
            cases.append((path.parent.name, case, np.asarray(json.loads(target.read_text())["output_traj"])))
    return cases


def score(cases: list[tuple[str, dict[str, Any], np.ndarray]]) -> dict[str, dict[str, float]]:
    """Mean MSE and DFD per kind for the oracle calls and for copying the input."""
    rows: dict[str, list[tuple[float, float, float, float]]] = {}
    for kind, case, target in cases:
        original = np.asarray(case["trajectory"], dtype=np.float64)
        objects = {o["name"]: np.array([o["x"], o["y"], o["z"]], dtype=np.float64) for o in case["objects"]}
        adapted = oracle(kind, case["instruction"], objects)(original)
        tool, copy = latte_scores(target, adapted), latte_scores(target, original)
        rows.setdefault(kind, []).append((tool["mse"], copy["mse"], tool["dfd"], copy["dfd"]))
    rows["overall"] = [row for kind_rows in list(rows.values()) for row in kind_rows]
    return {
        kind: {
            name: statistics.fmean(r[i] for r in values)
            for i, name in enumerate(("mse", "copy_mse", "dfd", "copy_dfd"))
        }
        for kind, values in rows.items()
    }


@contextmanager
def constants(module: Any, **values: Any) -> Iterator[None]:
    """Set module constants for the duration of a block."""
    saved = {name: getattr(module, name) for name in values}
    for name, value in values.items():
        setattr(module, name, value)
    try:
        yield
    finally:
        for name, value in saved.items():
            setattr(module, name, value)


def show(label: str, table: dict[str, dict[str, float]]) -> None:
    """One line: MSE/DFD per kind."""
    cells = "  ".join(f"{kind} {v['mse']:.5f}/{v['dfd']:.3f}" for kind, v in table.items())
    print(f"{label:<38} {cells}")


def main() -> int:
    """Score the oracle calls (and, with --sweep, other constants) on a latte-dev folder."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("folder", type=Path)
    parser.add_argument("--sweep", action="store_true", help="try other constants")
    args = parser.parse_args()
    cases = load(args.folder)
    if not cases:
        print(f"no cases with targets under {args.folder}", file=sys.stderr)
        return 2
    today = score(cases)
    print("MSE/DFD per kind (lower is better)")
    show("copy the input", {k: {"mse": v["copy_mse"], "dfd": v["copy_dfd"]} for k, v in today.items()})
    show("oracle calls, today's constants", today)
    if args.sweep:
        for blend in (0.05, 0.1, 0.15, 0.25):
            with constants(shape_skills, BLEND_IN=blend):
                show(f"shift BLEND_IN={blend}", score(cases))
        for influence in (0.5, 0.75, 1.0, 1.5):
            with constants(object_skills, INFLUENCE=influence):
                show(f"objects INFLUENCE={influence}", score(cases))
        for reach in (0.2, 0.4, 0.6, 1.0):
            with constants(speed_skills, NEAR_REACH=reach):
                show(f"speed NEAR_REACH={reach}", score(cases))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Simulation speed per robot, and the README's pictures.

For each robot, one of our own cases (benchmarks/cases/) is resampled to 100 waypoints, adapted by the
skill a correct answer to its instruction calls (no LLM involved: this measures the simulator), and run
in pybullet DIRECT mode. Reports seconds of wall time per simulated second (physics and control only;
rendering is timed apart), the tracking error and the time to render the GIF.

Run: .venv/bin/python benchmarks/sim_speed.py [--images docs/images] [--repeats 3]
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

from trajadapt.model.case import load_case
from trajadapt.model.trajectory import Trajectory
from trajadapt.sim import SimulationOptions, simulate
from trajadapt.skills import bind_skills

CASES = Path(__file__).resolve().parent / "cases"
SKILLS = bind_skills()
Adapt = Callable[[np.ndarray, dict[str, list[float]]], np.ndarray]

RUNS: dict[str, tuple[str, Adapt]] = {
    "arm": ("arm/closer_to_bowl.json", lambda t, o: SKILLS["move_closer"](t, o["yellow bowl"], "a lot")),
    "drone": ("drone/further_from_lamp.json", lambda t, o: SKILLS["move_away"](t, o["lamp"], 1.0)),
    "ground": ("ground/left_20_keep_10_box.json",
               lambda t, o: SKILLS["avoid"](SKILLS["shift"](t, "left", 20), o["box"], 10)),
}  # fmt: skip


def run_robot(robot: str, images: Path | None, repeats: int) -> dict[str, float]:
    """Time one robot's run ``repeats`` times (median); the last run writes the pictures if asked."""
    relative, adapt = RUNS[robot]
    case = load_case(CASES / relative)
    original = np.c_[case.trajectory.positions, case.trajectory.speeds]
    original = SKILLS["resample"](original, 100)
    objects = {o.name: list(o.position) for o in case.scene.objects}
    adapted = Trajectory(adapt(original, objects))
    ratios, report = [], None
    for attempt in range(repeats):
        last = attempt == repeats - 1
        folder = images if (images is not None and last) else None
        options = SimulationOptions(
            image=folder / f"sim-{robot}.png" if folder else None,
            animation=Path(tempfile.gettempdir()) / f"sim-{robot}.gif" if last else None,
        )
        report = simulate(adapted, case.scene, robot, options, original=Trajectory(original))
        ratios.append(report.wall_per_simulated_s)
    assert report is not None
    return {
        "instruction": case.instruction,  # type: ignore[dict-item]
        "wall_per_simulated_s": statistics.median(ratios),
        "simulated_s": report.simulated_s,
        "tracking_mean_cm": report.tracking.mean * 100,
        "tracking_max_cm": report.tracking.max * 100,
        "problems": len(report.problems),
        "gif_render_s": report.animation_s,
    }


def main() -> None:
    """Run every robot and print a table."""
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--images", type=Path, default=None, help="Folder for the README pictures.")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    if args.images:
        args.images.mkdir(parents=True, exist_ok=True)
    print(
        "| robot | instruction | wall s per simulated s | simulated s | tracking mean / max (cm) | problems | GIF render s |"
    )
    print("|---|---|---|---|---|---|---|")
    for robot in RUNS:
        started = time.perf_counter()
        r = run_robot(robot, args.images, args.repeats)
        print(
            f"| {robot} | {r['instruction']} | {r['wall_per_simulated_s']:.3f} | {r['simulated_s']:.1f} | "
            f"{r['tracking_mean_cm']:.2f} / {r['tracking_max_cm']:.2f} | {r['problems']} | {r['gif_render_s']:.1f} |",
            flush=True,
        )
        print(f"<!-- {robot}: {time.perf_counter() - started:.1f} s in all -->", flush=True)


if __name__ == "__main__":
    main()

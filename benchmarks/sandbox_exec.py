"""Time one sandboxed execution of generated code on a 100-point trajectory with a warm worker.

Run: .venv/bin/python benchmarks/sandbox_exec.py [--runs 200] [--isolation auto|bwrap|process]
Prints the median, 10th and 90th percentile in milliseconds, host round trip included.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.runner import Sandbox

CODE = """
import numpy as np
t = get_trajectory()
box = np.array(detect_objects('box'))
d = np.linalg.norm(t[:, :3] - box, axis=1)
w = np.sin(np.linspace(0, np.pi, len(t)))
t[:, 0] += 0.1 * w
t[:, 3] *= 1 - 0.5 * np.exp(-(d / 0.2) ** 2)
modified_trajectory = t
"""


def main() -> None:
    """Measure and print."""
    formatter = argparse.RawDescriptionHelpFormatter
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=formatter)
    parser.add_argument("--runs", type=int, default=200)
    parser.add_argument("--isolation", default="auto", choices=["auto", "bwrap", "process"])
    args = parser.parse_args()
    s = np.linspace(0, 1, 100)
    trajectory = Trajectory(np.c_[s, np.sin(s), np.zeros(100), np.ones(100)])
    scene = Scene((SceneObject("box", 0.5, 0.5, 0.0),))
    with Sandbox(isolation=args.isolation) as sandbox:
        sandbox.run(CODE, trajectory, scene)  # start the worker
        times = []
        for _ in range(args.runs):
            started = time.perf_counter()
            result = sandbox.run(CODE, trajectory, scene)
            times.append((time.perf_counter() - started) * 1000)
            assert result.ok, result.error
        layers = ", ".join(result.layers)
    deciles = statistics.quantiles(times, n=10)
    print(f"sandbox execution, 100 waypoints, {args.runs} runs, layers: {layers}")
    print(f"median {statistics.median(times):.1f} ms, p10 {deciles[0]:.1f} ms, p90 {deciles[-1]:.1f} ms")


if __name__ == "__main__":
    main()

"""trajadapt from Python: build a case from arrays, adapt it with feedback, read the result, export, simulate.

Run it as it is (offline: the answers are replayed by the scripted backend):

    .venv/bin/python examples/python_api.py OUT_DIR

With the embedded model, replace ``get_backend("scripted", ...)`` by ``get_backend("local")``; with
your own server, ``get_backend("openai", {"base_url": "http://127.0.0.1:8080/v1", "model": "qwen"})``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

from trajadapt import AdaptationSession, Case, Sandbox, Scene, SceneObject, Trajectory, get_backend
from trajadapt.files.atomic_files import write_json_atomic
from trajadapt.session import SessionSettings


def answer(plan: str, code: str) -> str:
    """An answer as the LLM writes it (only needed for the offline, scripted run)."""
    return json.dumps({"high_level_plan": plan, "python_code": code})


def main(out_dir: Path) -> None:
    """Adapt a straight path past a box, with one round of feedback, and write what came of it."""
    # 1. A case from arrays: 30 waypoints along +y at height 0.5, speed 1; a box beside the path.
    y = np.linspace(0.0, 3.0, 30)
    trajectory = Trajectory.from_rows(np.column_stack([np.zeros(30), y, np.full(30, 0.5), np.ones(30)]))
    scene = Scene((SceneObject("box", 0.4, 1.5, 0.5),))
    case = Case("python-api", trajectory, scene, "walk closer to the box")

    # 2. A backend: the scripted one replays these two answers (first plan, then the plan after feedback).
    backend = get_backend("scripted")
    backend.enqueue(  # type: ignore[attr-defined]
        answer("1) Bring the path closer to the box.",
               "t = get_trajectory()\nt = move_closer(t, detect_objects('box'))\nmodified_trajectory = t"),
        answer("1) Bring the path closer to the box. 2) Slow down near it.",
               "t = get_trajectory()\nt = move_closer(t, detect_objects('box'))\n"
               "t = scale_speed(t, 0.65, near=detect_objects('box'))\nmodified_trajectory = t"),
    )  # fmt: skip

    # 3. A session: draft, read the plan and its explanation, give feedback, approve.
    with Sandbox() as sandbox:
        session = AdaptationSession(case, backend, sandbox, SessionSettings())
        plan = session.draft()
        print("plan:", plan.numbered())
        print("does:", session.explain().lines)
        plan = session.feedback("and go slower near it")
        print("plan after feedback:", plan.numbered())
        result = session.approve()

    # 4. The result: status, trajectory, what changed (measured), flags, the file.
    assert result.ok and result.trajectory is not None, result.error
    assert result.effect is not None
    for line in result.effect.describe():
        print("effect:", line)
    print("contradictions:", list(result.contradictions) or "none")
    out_dir.mkdir(parents=True, exist_ok=True)
    write_json_atomic(out_dir / "python-api.result.json", result.to_dict())

    # 5. Optional: play it on a simulated ground robot (needs the 'sim' extra: pybullet).
    try:
        from trajadapt.sim.run import SimulationOptions, simulate
    except ImportError:
        print("simulation skipped: pip install 'trajadapt[sim]'")
        return
    options = SimulationOptions(image=out_dir / "python-api-ground.png")
    report = simulate(result.trajectory, scene, "ground", options, original=trajectory)
    print(f"simulated on {report.robot}: {report.simulated_s:.1f} s, {report.waypoints} waypoints")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else Path("python-api-out"))

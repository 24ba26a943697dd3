"""What a simulation run reports: tracking error, timing, problems per waypoint and the files made."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from trajadapt.sim.robots.base import Problem

Array = npt.NDArray[np.float64]


@dataclass(frozen=True)
class Tracking:
    """How closely the robot followed the waypoints, in metres (robot frame).

    ``mean``/``max``: each waypoint's distance to the executed path (did the robot go there);
    ``final``: the robot's last position to the goal; ``timing_mean``: each waypoint's distance to
    where the robot was at the time that waypoint was due (did it keep pace).
    """

    mean: float
    max: float
    final: float
    timing_mean: float

    def to_dict(self) -> dict[str, float]:
        """JSON form, rounded to 0.1 mm."""
        return {k: round(v, 4) for k, v in vars(self).items()}


def measure_tracking(waypoints: Array, times: Array, executed: Array, executed_times: Array) -> Tracking:
    """Compare waypoints (N, 3) due at ``times`` with the executed samples (M, 3) at ``executed_times``."""
    # One waypoint at a time: the executed samples come at 240 Hz, so a full N x M distance matrix of a
    # long run would take gigabytes.
    to_path = np.array([np.linalg.norm(executed - waypoint, axis=1).min() for waypoint in waypoints])
    at_time = np.stack([np.interp(times, executed_times, executed[:, k]) for k in range(3)], axis=1)
    return Tracking(
        mean=float(to_path.mean()),
        max=float(to_path.max()),
        final=float(np.linalg.norm(executed[-1] - waypoints[-1])),
        timing_mean=float(np.linalg.norm(at_time - waypoints, axis=1).mean()),
    )


@dataclass
class SimulationReport:
    """Everything one run found and wrote."""

    robot: str
    robot_description: str
    mapping: str
    waypoints: int
    simulated_s: float
    wall_s: float
    tracking: Tracking
    problems: list[Problem] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    executed: Array = field(default_factory=lambda: np.zeros((0, 3)))
    image: Path | None = None
    animation: Path | None = None
    animation_s: float = 0.0

    @property
    def wall_per_simulated_s(self) -> float:
        """Seconds of wall time per simulated second (render time excluded)."""
        return self.wall_s / self.simulated_s if self.simulated_s else 0.0

    def to_dict(self) -> dict[str, Any]:
        """JSON form (the executed path subsampled to at most 500 points)."""
        step = max(1, -(-len(self.executed) // 500))
        return {
            "robot": self.robot,
            "robot_description": self.robot_description,
            "mapping": self.mapping,
            "waypoints": self.waypoints,
            "simulated_s": round(self.simulated_s, 3),
            "wall_s": round(self.wall_s, 3),
            "wall_per_simulated_s": round(self.wall_per_simulated_s, 4),
            "tracking_m": self.tracking.to_dict(),
            "problems": [p.to_dict() for p in self.problems],
            "notes": self.notes,
            "image": str(self.image) if self.image else None,
            "animation": str(self.animation) if self.animation else None,
            "animation_s": round(self.animation_s, 2),
            "executed": np.round(self.executed[::step], 5).tolist(),
        }

    def summary_lines(self) -> list[str]:
        """Lines for the terminal."""
        t = self.tracking
        lines = [
            f"{self.robot}: {self.robot_description}",
            f"mapping: {self.mapping}",
            f"tracking error: mean {t.mean * 100:.2f} cm, max {t.max * 100:.2f} cm, "
            f"final {t.final * 100:.2f} cm (timing {t.timing_mean * 100:.2f} cm)",
            f"simulated {self.simulated_s:.1f} s in {self.wall_s:.1f} s wall "
            f"({self.wall_per_simulated_s:.2f} s per simulated s)",
        ]
        lines += [f"note: {n}" for n in self.notes]
        lines += [f"problem at waypoint {p.index}: {p.kind}: {p.detail}" for p in self.problems[:20]]
        if len(self.problems) > 20:
            lines.append(f"... and {len(self.problems) - 20} more problems")
        if self.image:
            lines.append(f"image: {self.image}")
        if self.animation:
            lines.append(f"animation: {self.animation} ({self.animation_s:.1f} s to render)")
        return lines

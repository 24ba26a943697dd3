"""What ``trajadapt simulate`` reads: a result file (adapted + original) or a plain case file."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from trajadapt.errors import InputError
from trajadapt.model.case import case_from_dict
from trajadapt.model.scene import Scene, parse_objects
from trajadapt.model.trajectory import Trajectory, read_json_file


@dataclass(frozen=True)
class RunInput:
    """The trajectory to execute, the one it was adapted from (if any) and the scene."""

    trajectory: Trajectory
    original: Trajectory | None
    scene: Scene
    axes: str | None = None  # the convention a result was adapted in (its recorded settings)


def load_run_input(path: Path) -> RunInput:
    """Read a result file (``modified_trajectory``, ``original_trajectory``, ``objects``) or a case file.

    Raises:
        InputError: the file is missing, not JSON, a failed result, or has no trajectory.
    """
    data = read_json_file(path)
    if isinstance(data, dict) and "modified_trajectory" in data:
        if not data["modified_trajectory"]:
            raise InputError(
                f"{path}: this result has no adapted trajectory (status {data.get('status')!r}); "
                "adapt again or simulate the case file instead"
            )
        trajectory = Trajectory.from_rows(data["modified_trajectory"], f"{path}: modified_trajectory")
        original = None
        if data.get("original_trajectory"):
            original = Trajectory.from_rows(data["original_trajectory"], f"{path}: original_trajectory")
        settings = data.get("settings")
        axes = settings.get("axes") if isinstance(settings, dict) else None
        return RunInput(
            trajectory,
            original,
            Scene(objects=parse_objects(data.get("objects"), f"{path}: objects")),
            axes if axes in ("paper", "ovita") else None,
        )
    case = case_from_dict(data, str(path), name=path.stem)
    return RunInput(case.trajectory, None, case.scene)

"""The contract with generated code: the functions it may call and the variable it must set.

This module is imported inside the sandbox child, so it depends on numpy and the standard library
only. The prompt's FUNCTIONS AVAILABLE section is rendered from ``CONTRACT`` so the two never drift.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from trajadapt.model.scene import name_key

RESULT_VARIABLE = "modified_trajectory"


@dataclass(frozen=True)
class ApiFunction:
    """One function the generated code may call, as the prompt describes it."""

    signature: str
    description: str


CONTRACT = (
    ApiFunction(
        "get_trajectory()",
        "returns the original trajectory as a numpy array of shape (N, 4); each row is "
        "(x, y, z, velocity). Each call returns a fresh copy.",
    ),
    ApiFunction(
        "detect_objects(object_name)",
        "returns the [x, y, z] position of the named object (case-insensitive) if it is present, else None.",
    ),
)


@dataclass
class ApiCalls:
    """What the code asked for that was not there, to explain a failure afterwards."""

    known_objects: list[str]
    missing_objects: list[str]

    def hint(self) -> str:
        """A sentence for the error message, or '' when every lookup succeeded."""
        if not self.missing_objects:
            return ""
        missing = ", ".join(repr(name) for name in dict.fromkeys(self.missing_objects))
        known = ", ".join(repr(name) for name in self.known_objects) or "none"
        return (
            f"detect_objects found no object named {missing} (it returned None); "
            f"objects in the scene: {known}"
        )


# Names that mean the trajectory's own ends when no scene object has them ("reach the goal position").
START_NAMES = ("start", "start position", "starting position", "start point", "beginning")
GOAL_NAMES = ("goal", "goal position", "goal point", "end", "end point", "destination", "target")


def build_api(
    trajectory_rows: list[list[float]], objects: dict[str, list[float]]
) -> tuple[dict[str, Callable[..., Any]], ApiCalls]:
    """Return ``get_trajectory`` and ``detect_objects`` bound to one job's data, and their call log."""
    original = np.asarray(trajectory_rows, dtype=np.float64)
    positions = {name_key(name): [float(v) for v in xyz] for name, xyz in objects.items()}
    calls = ApiCalls(known_objects=list(objects), missing_objects=[])

    def get_trajectory() -> np.ndarray:
        return original.copy()

    landmarks = {key: original[0, :3] for key in START_NAMES} | {key: original[-1, :3] for key in GOAL_NAMES}

    def detect_objects(object_name: str) -> list[float] | None:
        key = name_key(object_name)
        found = positions.get(key)
        if found is None and key in landmarks:
            found = [float(v) for v in landmarks[key]]
        if found is None:
            calls.missing_objects.append(str(object_name))
        return list(found) if found is not None else None

    return {"get_trajectory": get_trajectory, "detect_objects": detect_objects}, calls

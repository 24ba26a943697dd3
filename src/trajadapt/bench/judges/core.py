"""The judges' registry and what every check looks at: ``CheckContext``, ``check``, ``run_check``.

Each check is a pure function ``(context, params) -> (passed, detail)`` registered under a kind.
Vague words are judged leniently (any real change in the asked direction counts); numbers are
judged strictly (within a tolerance). Trajectories are (N, 4) arrays; the two may differ in length.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from trajadapt.model.geometry import Array, Axes, extent, progress

REAL_CHANGE = 0.02  # of the original's size: smaller moves do not count as a change
NEAR_FRACTION = 0.25  # the share of waypoints nearest an object that count as "near" it


@dataclass(frozen=True)
class Verdict:
    """The outcome of one check, with the measured numbers in words."""

    kind: str
    passed: bool
    detail: str


@dataclass(frozen=True)
class CheckContext:
    """What a check looks at."""

    original: Array
    adapted: Array
    objects: dict[str, Array]
    axes: Axes

    @property
    def size(self) -> float:
        """The original's largest bounding-box side."""
        return extent(self.original)

    def point(self, params: dict[str, Any]) -> Array:
        """The position named by ``object`` (or a midpoint of ``objects``, or an explicit ``point``)."""
        if "point" in params:
            return np.asarray(params["point"], dtype=np.float64)
        names = params.get("objects") or [params["object"]]
        centre: Array = np.mean([self.objects[str(name).strip().casefold()] for name in names], axis=0)
        return centre


CheckFunction = Callable[[CheckContext, dict[str, Any]], tuple[bool, str]]
CHECKS: dict[str, CheckFunction] = {}


def check(kind: str) -> Callable[[CheckFunction], CheckFunction]:
    """Register a check function under ``kind``."""

    def register(function: CheckFunction) -> CheckFunction:
        CHECKS[kind] = function
        return function

    return register


def run_check(context: CheckContext, spec: dict[str, Any]) -> Verdict:
    """Run one expectation ``{"kind": ..., **params}``; an unknown kind or bad parameter fails loudly.

    Raises:
        KeyError: the kind is not registered.
    """
    kind = spec["kind"]
    passed, detail = CHECKS[kind](context, {k: v for k, v in spec.items() if k != "kind"})
    return Verdict(kind, bool(passed), detail)


def distances_to(points: Array, target: Array) -> Array:
    """Each waypoint's distance to ``target``."""
    return np.asarray(np.linalg.norm(points[:, :3] - target, axis=1))


def near_mean(trajectory: Array, target: Array) -> float:
    """The mean distance of the ``NEAR_FRACTION`` of waypoints nearest ``target``."""
    distances = np.sort(distances_to(trajectory, target))
    return float(distances[: max(2, int(NEAR_FRACTION * len(distances)))].mean())


def at_progress(trajectory: Array, fractions: Array) -> Array:
    """The trajectory interpolated at fractions of its length."""
    s = progress(trajectory)
    return np.stack([np.interp(fractions, s, trajectory[:, k]) for k in range(4)], axis=1)

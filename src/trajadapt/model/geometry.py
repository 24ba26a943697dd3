"""Geometry every part of trajadapt shares: direction words, frames, a path's size, progress, parts.

The skills, the effect report, the benchmark's judges and the constraints all measure with these,
so they agree on what "left", "the size of the path" and "the middle" mean. Pure numpy: it also
loads inside the sandbox child.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float64]

DIRECTION_SYNONYMS = {
    "left": "left", "right": "right", "front": "front", "forward": "front", "forwards": "front",
    "ahead": "front", "back": "back", "backward": "back", "backwards": "back", "behind": "back",
    "rear": "back", "up": "up", "upward": "up", "upwards": "up", "higher": "up", "top": "up",
    "above": "up", "upper": "up", "down": "down", "downward": "down", "downwards": "down",
    "lower": "down", "bottom": "down", "below": "down",
}  # fmt: skip

DIRECTION_VERBS = {
    "rise": "up", "rises": "up", "rising": "up", "rose": "up", "climb": "up", "climbs": "up",
    "climbing": "up", "ascend": "up", "ascends": "up", "ascending": "up", "ascent": "up", "lift": "up",
    "lifts": "up", "lifting": "up", "raise": "up", "raises": "up", "raising": "up", "elevate": "up",
    "elevates": "up", "elevating": "up", "descend": "down", "descends": "down", "descending": "down",
    "descent": "down", "sink": "down", "sinks": "down", "sinking": "down", "dip": "down", "dips": "down",
    "dipping": "down", "drop": "down", "drops": "down", "dropped": "down", "dropping": "down",
    "lowers": "down", "lowered": "down", "lowering": "down",
}  # fmt: skip
"""Verbs that name a direction of motion ("climb a little" is up). Words of the user's only: a skill's
direction argument takes ``DIRECTION_SYNONYMS``, so ``shift(t, 'climb')`` stays an error."""


@dataclass(frozen=True)
class Axes:
    """Unit vectors of the six named directions in the trajectory's frame."""

    left: tuple[float, float, float] = (1.0, 0.0, 0.0)
    front: tuple[float, float, float] = (0.0, 1.0, 0.0)
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)

    @classmethod
    def from_positive_x(cls, positive_x: str) -> Axes:
        """The paper's frame when +X is left, OVITA's when +X is right (front +Y, up +Z in both)."""
        return cls(left=(1.0, 0.0, 0.0) if positive_x == "left" else (-1.0, 0.0, 0.0))

    def vector(self, direction: str) -> Array:
        """The unit vector of a direction word ('left', 'upwards', 'back', ...).

        Raises:
            ValueError: an unknown word, listing the known ones.
        """
        word = DIRECTION_SYNONYMS.get(str(direction).strip().lower())
        if word is None:
            raise ValueError(_direction_advice(direction))
        sign = -1.0 if word in ("right", "back", "down") else 1.0
        base = {"left": self.left, "right": self.left, "front": self.front, "back": self.front}
        return sign * np.asarray(base.get(word, self.up), dtype=np.float64)


PAPER_AXES = Axes()


@dataclass(frozen=True)
class AxisConvention:
    """What the positive direction of each axis means to the user: the one record of an axis convention.

    ``frame`` gives its unit vectors; ``describe`` the lines the prompt states.
    """

    name: str
    positive_x: str
    negative_x: str
    positive_y: str = "front"
    negative_y: str = "back"
    positive_z: str = "up"
    negative_z: str = "down"

    @property
    def frame(self) -> Axes:
        """The unit vectors of the named directions in this convention."""
        return Axes.from_positive_x(self.positive_x)

    def describe(self) -> str:
        """The COORDINATE SYSTEM section's lines."""
        return "\n".join(
            f"The positive {axis} axis is {positive}; the negative {axis} axis is {negative}."
            for axis, positive, negative in (
                ("X", self.positive_x, self.negative_x),
                ("Y", self.positive_y, self.negative_y),
                ("Z", self.positive_z, self.negative_z),
            )
        )


AXIS_CONVENTIONS = {
    "paper": AxisConvention("paper", positive_x="left", negative_x="right"),
    "ovita": AxisConvention("ovita", positive_x="right", negative_x="left"),
}

DIRECTIONS = ("left", "right", "front", "back", "up", "down")
"""The canonical direction words (DIRECTION_SYNONYMS maps every other word onto one of them)."""

OPPOSITE_DIRECTIONS = {
    "left": "right", "right": "left", "front": "back", "back": "front", "up": "down", "down": "up",
}  # fmt: skip
"""Each canonical direction's opposite."""

RELATIVE_WORDS = ("away", "further", "farther", "closer", "towards", "toward", "near", "nearer")


def _direction_advice(direction: Any) -> str:
    """Why a direction word was refused, and which function to use instead."""
    word = str(direction).strip().lower()
    known = ", ".join(sorted(set(DIRECTION_SYNONYMS.values())))
    if word in RELATIVE_WORDS:
        return (
            f"{direction!r} is not a direction but relative to an object: use "
            "move_away(t, detect_objects('name'), amount) or move_closer(t, detect_objects('name'), amount)"
        )
    if word in PART_WORDS or word in ("goal", "start"):
        return (
            f"{direction!r} names a part of the path, not a direction: use shift_goal(t, direction, amount), "
            f"shift_start(t, direction, amount) or shift_part(t, direction, amount, part='{word}'); "
            f"directions are: {known}"
        )
    return f"unknown direction {direction!r}; use one of: {known}"


PART_WORDS = {
    "all": (0.0, 1.0), "whole": (0.0, 1.0), "start": (0.0, 0.3), "beginning": (0.0, 0.3),
    "first half": (0.0, 0.5), "middle": (0.3, 0.7), "center": (0.3, 0.7), "second half": (0.5, 1.0),
    "end": (0.7, 1.0), "goal": (0.7, 1.0), "final": (0.7, 1.0),
}  # fmt: skip


def extent(trajectory: Array) -> float:
    """The largest side of the bounding box of the positions (at least a tiny positive number)."""
    return float(max(np.ptp(trajectory[:, :3], axis=0).max(), 1e-9))


def progress(trajectory: Array) -> Array:
    """Arc-length position of each waypoint along the path, from 0 at the start to 1 at the goal."""
    steps = np.linalg.norm(np.diff(trajectory[:, :3], axis=0), axis=1)
    total = steps.sum()
    if total <= 0:
        return np.linspace(0.0, 1.0, len(trajectory))
    return np.concatenate([[0.0], np.cumsum(steps) / total])

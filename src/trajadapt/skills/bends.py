"""Where a bend through a point passes it, and how far along the path the bend reaches.

``pass_through`` and ``pass_over`` bend the path through a point at one waypoint, fading to nothing
towards the start and the goal; these choose the waypoint (one with room for that fade) and the
bend's spread (wide enough that no step of the path grows into a gap).
"""

from __future__ import annotations

import numpy as np

from trajadapt.model.geometry import Array
from trajadapt.skills.core import nearest_index


def inner_room_to_bend(t: Array, top: Array) -> int | None:
    """Where to pass over ``top``: never at the start or the goal, which stay (``room_to_bend``)."""
    if len(t) < 3:
        return None
    return room_to_bend(t, top, int(np.clip(nearest_index(t, top), 1, len(t) - 2)))


def room_to_bend(t: Array, target: Array, k: int) -> int:
    """The waypoint to pass through the target at: ``k``, or the nearest one with room to bend.

    The bend moves waypoint j by up to |target - t[j]| and fades to nothing at the start and the
    goal; room means enough waypoints between j and each end for that fade to take steps no longer
    than the path's longest on average (the smooth window's steepest step is about 1.5 times that).
    A target near an end and off the path otherwise makes one step many times longer. When no
    waypoint has room on both sides, the one with the most is used.
    """
    longest = float(np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).max())
    if longest <= 0 or k in (0, len(t) - 1):  # at an end the end itself moves: no window to fall
        return k
    need = np.linalg.norm(target - t[:, :3], axis=1) / longest
    index = np.arange(len(t))
    shortfall = np.maximum(need - index, 0.0) + np.maximum(need - (len(t) - 1 - index), 0.0)
    inner = index[1:-1]
    fits = inner[shortfall[1:-1] == 0]
    if fits.size:
        return int(fits[np.argmin(np.abs(fits - k))]) if shortfall[k] > 0 else k
    return int(inner[np.argmin(shortfall[1:-1])])


def bend_sigma(t: Array, offset: Array, width: float) -> float:
    """The bend's spread (in progress): ``width / 2``, or wider when a narrow bend would make gaps.

    A Gaussian bend of spread sigma moving a waypoint by |offset| stretches a step of the path by up
    to about |offset| * step / (sigma * sqrt(e) * length); the spread is widened so that this stays
    below the path's longest step (the longest step at most about doubles).
    """
    length = float(np.linalg.norm(np.diff(t[:, :3], axis=0), axis=1).sum())
    no_gaps = float(np.linalg.norm(offset)) / (float(np.sqrt(np.e)) * max(length, 1e-12))
    return float(max(float(width) / 2.0, no_gaps, 1e-6))

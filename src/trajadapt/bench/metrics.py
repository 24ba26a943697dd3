"""Shape metrics between an original and an adapted path (as LaTTe reports them): Fréchet, DTW, smoothness."""

from __future__ import annotations

import numpy as np

from trajadapt.skills.core import Array


def _pairwise(a: Array, b: Array) -> Array:
    return np.asarray(np.linalg.norm(a[:, None, :3] - b[None, :, :3], axis=2))


def discrete_frechet(a: Array, b: Array) -> float:
    """Discrete Fréchet distance between two polylines (positions only).

    >>> round(discrete_frechet(np.array([[0, 0, 0], [1, 0, 0]]), np.array([[0, 1, 0], [1, 1, 0]])), 6)
    1.0
    """
    distance = _pairwise(a, b)
    table = np.full(distance.shape, np.inf)
    table[0, 0] = distance[0, 0]
    for i in range(distance.shape[0]):
        for j in range(distance.shape[1]):
            if i == 0 and j == 0:
                continue
            previous = min(
                table[i - 1, j] if i else np.inf,
                table[i, j - 1] if j else np.inf,
                table[i - 1, j - 1] if i and j else np.inf,
            )
            table[i, j] = max(previous, distance[i, j])
    return float(table[-1, -1])


def dynamic_time_warping(a: Array, b: Array) -> float:
    """DTW distance (sum of matched point distances along the best alignment), positions only."""
    distance = _pairwise(a, b)
    table = np.full((len(a) + 1, len(b) + 1), np.inf)
    table[0, 0] = 0.0
    for i in range(1, len(a) + 1):
        row_above, row = table[i - 1], table[i]
        for j in range(1, len(b) + 1):
            row[j] = distance[i - 1, j - 1] + min(row_above[j], row[j - 1], row_above[j - 1])
    return float(table[-1, -1])


def roughness(trajectory: Array) -> float:
    """Mean size of the second difference of positions: 0 for a straight evenly spaced line."""
    if len(trajectory) < 3:
        return 0.0
    return float(np.linalg.norm(np.diff(trajectory[:, :3], n=2, axis=0), axis=1).mean())

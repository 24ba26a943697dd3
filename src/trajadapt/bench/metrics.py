"""Shape metrics between an original and an adapted path (as LaTTe reports them): Fréchet, DTW, smoothness."""

from __future__ import annotations

import numpy as np

from trajadapt.model.geometry import Array


def _pairwise(a: Array, b: Array, columns: int = 3) -> Array:
    return np.asarray(np.linalg.norm(a[:, None, :columns] - b[None, :, :columns], axis=2))


def discrete_frechet(a: Array, b: Array, columns: int = 3) -> float:
    """Discrete Fréchet distance between two polylines (positions only, or the first ``columns``).

    >>> round(discrete_frechet(np.array([[0, 0, 0], [1, 0, 0]]), np.array([[0, 1, 0], [1, 1, 0]])), 6)
    1.0
    """
    distance = _pairwise(a, b, columns)
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


def dynamic_time_warping(a: Array, b: Array, columns: int = 3) -> float:
    """DTW distance (sum of matched point distances along the best alignment), positions by default."""
    distance = _pairwise(a, b, columns)
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


def latte_scores(target: Array, prediction: Array) -> dict[str, float]:
    """LaTTe's metrics (``compute_metrics`` in its ``functions.py``) of ``prediction`` against ``target``.

    Waypoints 1.. of both (waypoint 0 is LaTTe's start token), all four columns x, y, z, v in raw
    units: MSE and MAE over every number, DTW as the summed 4-D Euclidean cost, DFD as the 4-D discrete
    Fréchet distance. A prediction with another number of waypoints is resampled to the target's
    (linearly, by index), since LaTTe's model always emits as many as it was given.
    """
    expected = np.asarray(target, dtype=np.float64)
    predicted = resample_rows(np.asarray(prediction, dtype=np.float64), len(expected))
    e, p = expected[1:], predicted[1:]
    return {
        "mse": float(np.mean((e - p) ** 2)),
        "mae": float(np.mean(np.abs(e - p))),
        "dtw": dynamic_time_warping(e, p, columns=4),
        "dfd": discrete_frechet(e, p, columns=4),
    }


def resample_rows(rows: Array, count: int) -> Array:
    """``rows`` linearly interpolated, column by column, to ``count`` rows spread evenly by index."""
    if len(rows) == count:
        return rows
    old = np.linspace(0.0, 1.0, len(rows))
    new = np.linspace(0.0, 1.0, count)
    return np.column_stack([np.interp(new, old, rows[:, column]) for column in range(rows.shape[1])])

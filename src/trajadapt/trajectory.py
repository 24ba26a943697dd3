"""Trajectory: an immutable N x 4 array of waypoints (x, y, z, v) with validation and I/O."""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from trajadapt.errors import InputError

COLUMNS = ("x", "y", "z", "v")
MIN_WAYPOINTS = 2


def validate_waypoints(rows: Any, where: str) -> npt.NDArray[np.float64]:
    """Check that ``rows`` is an N x 4 table of finite numbers with v >= 0 and N >= 2.

    Args:
        rows: a nested sequence or array, one waypoint [x, y, z, v] a row.
        where: names the source in error messages, e.g. ``"case.json: trajectory"``.

    Returns:
        A new float64 array of shape (N, 4).

    Raises:
        InputError: naming ``where``, the offending row and the problem.
    """
    if not isinstance(rows, Sequence | np.ndarray) or isinstance(rows, str | bytes):
        raise InputError(f"{where}: expected a list of [x, y, z, v] waypoints, got {_kind(rows)}")
    if len(rows) < MIN_WAYPOINTS:
        raise InputError(f"{where}: a trajectory needs at least {MIN_WAYPOINTS} waypoints, got {len(rows)}")
    array = np.empty((len(rows), 4), dtype=np.float64)
    for index, row in enumerate(rows):
        array[index] = _validate_row(row, f"{where}[{index}]")
    negative = np.flatnonzero(array[:, 3] < 0)
    if negative.size:
        first = int(negative[0])
        raise InputError(
            f"{where}[{first}]: velocity must be >= 0, got {array[first, 3]:g} "
            f"({negative.size} waypoint(s) with negative velocity)"
        )
    return array


def _validate_row(row: Any, where: str) -> list[float]:
    if isinstance(row, str | bytes) or not isinstance(row, Sequence | np.ndarray):
        raise InputError(f"{where}: expected [x, y, z, v], got {_kind(row)}")
    if len(row) != len(COLUMNS):
        raise InputError(f"{where}: expected 4 numbers [x, y, z, v], got {len(row)}")
    values = []
    for name, value in zip(COLUMNS, row, strict=True):
        if isinstance(value, bool) or not isinstance(value, int | float | np.number):
            raise InputError(f"{where}: {name} must be a number, got {value!r}")
        if not math.isfinite(float(value)):
            raise InputError(f"{where}: {name} must be finite, got {value!r}")
        values.append(float(value))
    return values


def _kind(value: Any) -> str:
    return type(value).__name__ if value is not None else "nothing (null)"


@dataclass(frozen=True, eq=False)
class Trajectory:
    """An immutable sequence of waypoints; ``array`` is a read-only (N, 4) float64 array."""

    array: npt.NDArray[np.float64]

    def __post_init__(self) -> None:
        array = np.array(self.array, dtype=np.float64, copy=True)
        array.setflags(write=False)
        object.__setattr__(self, "array", array)

    @classmethod
    def from_rows(cls, rows: Any, where: str = "trajectory") -> Trajectory:
        """Build a validated trajectory from rows of [x, y, z, v]."""
        return cls(validate_waypoints(rows, where))

    @property
    def positions(self) -> npt.NDArray[np.float64]:
        """The (N, 3) positions, read-only."""
        return self.array[:, :3]

    @property
    def speeds(self) -> npt.NDArray[np.float64]:
        """The (N,) velocities, read-only."""
        return self.array[:, 3]

    def __len__(self) -> int:
        return int(self.array.shape[0])

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Trajectory):
            return NotImplemented
        return self.array.shape == other.array.shape and bool(np.array_equal(self.array, other.array))

    __hash__ = None  # type: ignore[assignment]

    def to_rows(self) -> list[list[float]]:
        """Return the waypoints as plain lists, ready for JSON."""
        return [[float(value) for value in row] for row in self.array]

    def step_lengths(self) -> npt.NDArray[np.float64]:
        """Distances between consecutive waypoints, shape (N - 1,)."""
        steps: npt.NDArray[np.float64] = np.linalg.norm(np.diff(self.positions, axis=0), axis=1)
        return steps

    def path_length(self) -> float:
        """Total length of the polyline through the waypoints."""
        return float(self.step_lengths().sum())


def load_trajectory_file(path: Path) -> Trajectory:
    """Read a trajectory alone from JSON (a list of rows, or {"trajectory": [...]}) or CSV.

    CSV files need a header naming the columns x, y, z, v (in any order; other columns are ignored).

    Raises:
        InputError: the file is missing, unreadable or not a valid trajectory.
    """
    if path.suffix.lower() == ".csv":
        return Trajectory.from_rows(_read_csv_rows(path), f"{path}")
    data = read_json_file(path)
    if isinstance(data, dict):
        if "trajectory" not in data:
            raise InputError(f"{path}: no 'trajectory' field (expected [[x, y, z, v], ...])")
        return Trajectory.from_rows(data["trajectory"], f"{path}: trajectory")
    return Trajectory.from_rows(data, f"{path}")


def _read_csv_rows(path: Path) -> list[list[float]]:
    text = read_text_file(path)
    reader = csv.DictReader(text.splitlines())
    header = [name.strip().lower() for name in reader.fieldnames or []]
    missing = [name for name in COLUMNS if name not in header]
    if missing:
        raise InputError(f"{path}: CSV header must name the columns x, y, z, v; missing {', '.join(missing)}")
    rows = []
    for line_number, record in enumerate(reader, start=2):
        cleaned = {(key or "").strip().lower(): (value or "").strip() for key, value in record.items()}
        try:
            rows.append([float(cleaned[name]) for name in COLUMNS])
        except ValueError as exc:
            raise InputError(f"{path}, line {line_number}: {exc}") from exc
    return rows


def read_text_file(path: Path) -> str:
    """Read a UTF-8 text file, turning OS errors into an InputError that names the file."""
    try:
        return path.read_text(encoding="utf-8")
    except FileNotFoundError as exc:
        raise InputError(f"{path}: file not found") from exc
    except IsADirectoryError as exc:
        raise InputError(f"{path}: is a directory, expected a file") from exc
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"{path}: cannot be read ({exc})") from exc


def read_json_file(path: Path) -> Any:
    """Parse a JSON file, turning every failure into an InputError that names the file."""
    text = read_text_file(path)
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno})") from exc

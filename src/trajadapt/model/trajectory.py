"""Trajectory: an immutable N x 4 array of waypoints (x, y, z, v) with validation and I/O."""

from __future__ import annotations

import csv
import json
import math
import stat
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from trajadapt.errors import InputError, InvalidWaypoints
from trajadapt.safe_text import safe_text

COLUMNS = ("x", "y", "z", "v")
MIN_WAYPOINTS = 2
MAX_WAYPOINTS = 100_000
MAX_MAGNITUDE = 1e9
"""Largest coordinate or speed accepted: beyond it squares and distances lose all precision."""
MAX_FILE_BYTES = 64 * 1024 * 1024
"""Largest case, scene or trajectory file read (100,000 waypoints as JSON take about 8 MB)."""


def validate_waypoints(rows: Any, where: str) -> npt.NDArray[np.float64]:
    """Read ``rows`` (nested sequences, e.g. parsed JSON) as an N x 4 table and check the trajectory rule.

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
    if len(rows) > MAX_WAYPOINTS:
        raise InputError(f"{where}: at most {MAX_WAYPOINTS} waypoints, got {len(rows)}; resample it first")
    array = np.empty((len(rows), 4), dtype=np.float64)
    for index, row in enumerate(rows):
        array[index] = _validate_row(row, f"{where}[{index}]")
    problem = waypoint_problem(array)
    if problem is not None:
        raise InputError(f"{where}: {problem}")
    return array


def waypoint_problem(array: npt.NDArray[np.float64]) -> str | None:
    """What keeps ``array`` from being a trajectory, in words; None when it is one.

    The rule: shape (N, 4) with 2 <= N <= MAX_WAYPOINTS, every value finite and within
    ±MAX_MAGNITUDE, velocity >= 0.
    """
    if array.ndim != 2 or array.shape[1] != 4:
        return f"has shape {array.shape}; it must be (N, 4) with rows (x, y, z, velocity)"
    if array.shape[0] < MIN_WAYPOINTS:
        return f"needs at least {MIN_WAYPOINTS} waypoints, got {array.shape[0]}"
    if array.shape[0] > MAX_WAYPOINTS:
        return f"has {array.shape[0]} waypoints, at most {MAX_WAYPOINTS} are allowed; resample it first"
    for test, words in (
        (~np.isfinite(array), "non-finite value(s) (NaN or inf)"),
        (np.abs(array) > MAX_MAGNITUDE, f"value(s) beyond ±{MAX_MAGNITUDE:.0e} (check the units)"),
    ):
        bad = np.argwhere(test)
        if bad.size:
            row, column = (int(v) for v in bad[0])
            return f"has {len(bad)} {words}, first at row {row}, {COLUMNS[column]} = {array[row, column]:.3g}"
    negative = np.flatnonzero(array[:, 3] < 0)
    if negative.size:
        first = int(negative[0])
        return (
            f"has {negative.size} negative velocity value(s), first at row {first} "
            f"({array[first, 3]:g}); velocity must be >= 0"
        )
    return None


def _validate_row(row: Any, where: str) -> list[float]:
    if isinstance(row, str | bytes) or not isinstance(row, Sequence | np.ndarray):
        raise InputError(f"{where}: expected [x, y, z, v], got {_kind(row)}")
    if len(row) != len(COLUMNS):
        raise InputError(f"{where}: expected 4 numbers [x, y, z, v], got {len(row)}")
    values = []
    for name, value in zip(COLUMNS, row, strict=True):
        if isinstance(value, bool) or not isinstance(value, int | float | np.number):
            raise InputError(f"{where}: {name} must be a number, got {_short(value)}")
        values.append(finite_float(value, f"{where}: {name}"))
    return values


def finite_float(value: Any, where: str) -> float:
    """``value`` as a finite float.

    Raises:
        InputError: the number is NaN, infinite, or too large for a float (an integer of 400 digits).
    """
    try:
        number = float(value)
    except OverflowError:
        raise InputError(f"{where} is too large for a number ({len(str(value))} digits)") from None
    if not math.isfinite(number):
        raise InputError(f"{where} must be finite, got {_short(value)}")
    return number


def _short(value: Any, limit: int = 60) -> str:
    """A value's repr for an error message, cut to ``limit`` characters and made safe."""
    text = repr(value)
    return safe_text(text[:limit] + ("..." if len(text) > limit else ""))


def _kind(value: Any) -> str:
    return type(value).__name__ if value is not None else "nothing (null)"


@dataclass(frozen=True, eq=False)
class Trajectory:
    """An immutable sequence of waypoints; ``array`` is a read-only (N, 4) float64 array.

    Every Trajectory keeps the rule of ``waypoint_problem`` (N x 4, finite, v >= 0, ...): it is
    checked here, once, and nowhere else.
    """

    array: npt.NDArray[np.float64]

    def __post_init__(self) -> None:
        """Copy the array read-only and enforce the trajectory rule (see ``waypoint_problem``).

        Raises:
            InvalidWaypoints: the array breaks the rule, in words.
        """
        array = np.array(self.array, dtype=np.float64, copy=True)
        problem = waypoint_problem(array)
        if problem is not None:
            raise InvalidWaypoints(f"the trajectory {problem}")
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
    reader = csv.DictReader(text.splitlines(), restkey=EXTRA_FIELDS)
    try:
        header = [(name or "").strip().lower() for name in reader.fieldnames or []]
    except csv.Error as exc:  # a field longer than the csv module's limit (131,072 characters)
        raise InputError(f"{path}, line 1: not a CSV header ({exc})") from None
    missing = [name for name in COLUMNS if name not in header]
    if missing:
        raise InputError(f"{path}: CSV header must name the columns x, y, z, v; missing {', '.join(missing)}")
    twice = sorted({name for name in header if name in COLUMNS and header.count(name) > 1})
    if twice:
        raise InputError(
            f"{path}: the CSV header names {', '.join(twice)} more than once; which one is meant?"
        )
    rows = []
    try:
        for record in reader:
            rows.append(_csv_row(record, f"{path}, line {reader.line_num}"))
    except csv.Error as exc:
        raise InputError(f"{path}, line {reader.line_num}: not valid CSV ({exc})") from None
    return rows


EXTRA_FIELDS = "\x00extra"


def _csv_row(record: dict[str, Any], where: str) -> list[float]:
    if record.get(EXTRA_FIELDS):
        raise InputError(f"{where}: more fields than the header names")
    cleaned = {(key or "").strip().lower(): (value or "").strip() for key, value in record.items()}
    values = []
    for name in COLUMNS:
        try:
            values.append(float(cleaned[name]))
        except ValueError:
            raise InputError(f"{where}: {name} must be a number, got {_short(cleaned[name])}") from None
    return values


def read_text_file(path: Path, limit: int = MAX_FILE_BYTES) -> str:
    """Read a UTF-8 text file of at most ``limit`` bytes.

    Only regular files are read (a FIFO would block, a device never end), and the size is checked
    before reading.

    Raises:
        InputError: naming the file: missing, not a regular file, too large, unreadable or not UTF-8.
    """
    try:
        info = path.stat()
    except FileNotFoundError:
        raise InputError(f"{path}: file not found") from None
    except (OSError, ValueError) as exc:
        raise InputError(f"{path}: cannot be read ({exc})") from None
    if stat.S_ISDIR(info.st_mode):
        raise InputError(f"{path}: is a directory, expected a file")
    if not stat.S_ISREG(info.st_mode):
        raise InputError(f"{path}: not a regular file (a device, pipe or socket); give a file")
    if info.st_size > limit:
        raise InputError(f"{path}: {info.st_size / 1e6:.1f} MB is over the {limit / 1e6:.0f} MB limit")
    try:
        with path.open("rb") as handle:
            data = handle.read(limit + 1)
    except OSError as exc:
        raise InputError(f"{path}: cannot be read ({exc})") from None
    if len(data) > limit:
        raise InputError(f"{path}: over the {limit / 1e6:.0f} MB limit")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start})") from None


def read_json_file(path: Path) -> Any:
    """Parse a JSON file, turning every failure into an InputError that names the file."""
    return parse_json_text(read_text_file(path), str(path))


def parse_json_text(text: str, where: str) -> Any:
    """Parse JSON text from outside; malformed, over-long numbers and over-deep input are InputErrors."""
    try:
        return json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{where}: not valid JSON ({exc.msg} at line {exc.lineno})") from None
    except RecursionError:
        raise InputError(f"{where}: JSON nested too deep") from None
    except ValueError as exc:  # an integer of more than 4300 digits
        raise InputError(f"{where}: not valid JSON ({safe_text(str(exc))})") from None

"""Scene: the named objects around a trajectory, plus optional description and constraints text."""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from trajadapt.errors import InputError
from trajadapt.model.trajectory import finite_float
from trajadapt.safe_text import INSTRUCTION_CHARS, safe_text

NAME_CHARS = 200


@dataclass(frozen=True)
class SceneObject:
    """A named object at a position; ``dimensions`` (width, depth, height) when known."""

    name: str
    x: float
    y: float
    z: float
    dimensions: tuple[float, float, float] | None = None

    @property
    def position(self) -> tuple[float, float, float]:
        """The object's (x, y, z)."""
        return (self.x, self.y, self.z)

    def to_dict(self) -> dict[str, Any]:
        """Return the case-file form of this object."""
        data: dict[str, Any] = {"name": self.name, "x": self.x, "y": self.y, "z": self.z}
        if self.dimensions is not None:
            data["dimensions"] = list(self.dimensions)
        return data


@dataclass(frozen=True)
class Scene:
    """The objects of an environment and the free-text description and constraints given with it."""

    objects: tuple[SceneObject, ...] = ()
    description: str = ""
    constraints: str = ""

    def find(self, name: str) -> SceneObject | None:
        """Return the object called ``name`` (case- and surrounding-space-insensitive), or None."""
        key = name_key(name)
        return next((obj for obj in self.objects if name_key(obj.name) == key), None)

    def names(self) -> list[str]:
        """The object names, in file order."""
        return [obj.name for obj in self.objects]


def name_key(name: str) -> str:
    """How object names are compared: case-insensitive, surrounding and repeated spaces ignored."""
    return " ".join(str(name).split()).casefold()


def without_names(text: str, names: Iterable[str]) -> str:
    """``text`` in lower case with each name, as whole words, made a space (longest names first).

    >>> without_names("Move nearer to the Ear", ["ear"])
    'move nearer to the  '
    """
    lowered = text.lower()
    for name in sorted((name for name in names if name.strip()), key=len, reverse=True):
        lowered = re.sub(rf"(?<![a-z0-9]){re.escape(name.lower())}(?![a-z0-9])", " ", lowered)
    return lowered


def parse_objects(raw: Any, where: str) -> tuple[SceneObject, ...]:
    """Validate a list of ``{name, x, y, z[, dimensions]}`` records.

    Raises:
        InputError: naming ``where``, the record and the problem; also for duplicate names
            (compared case-insensitively).
    """
    if raw is None:
        return ()
    if not isinstance(raw, list):
        raise InputError(f"{where}: expected a list of objects, got {type(raw).__name__}")
    objects = tuple(_parse_object(item, f"{where}[{index}]") for index, item in enumerate(raw))
    seen: dict[str, str] = {}
    for obj in objects:
        key = name_key(obj.name)
        if key in seen:
            raise InputError(
                f"{where}: object names must be unique (case-insensitive); "
                f"{seen[key]!r} and {obj.name!r} clash"
            )
        seen[key] = obj.name
    return objects


def _parse_object(item: Any, where: str) -> SceneObject:
    if not isinstance(item, dict):
        raise InputError(f"{where}: expected an object {{name, x, y, z}}, got {type(item).__name__}")
    raw_name = item.get("name")
    if not isinstance(raw_name, str) or not raw_name.strip():
        raise InputError(f"{where}: 'name' must be a non-empty string, got {safe_text(repr(raw_name), 80)}")
    name = safe_text(raw_name.strip(), NAME_CHARS)
    x, y, z = (_finite_number(item.get(axis), f"{where} ({name}): {axis}") for axis in "xyz")
    return SceneObject(name, x, y, z, dimensions=_parse_dimensions(item, where))


def _parse_dimensions(item: dict[str, Any], where: str) -> tuple[float, float, float] | None:
    raw = item.get("dimensions")
    if raw is None:
        return None
    if not isinstance(raw, Sequence) or isinstance(raw, str) or len(raw) != 3:
        raise InputError(
            f"{where}: 'dimensions' must be [width, depth, height], got {safe_text(repr(raw), 80)}"
        )
    width, depth, height = (_finite_number(value, f"{where}: dimensions") for value in raw)
    return (width, depth, height)


def _finite_number(value: Any, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise InputError(f"{where} must be a number, got {safe_text(repr(value), 80)}")
    return finite_float(value, where)


def parse_text_field(raw: Any, where: str, limit: int = INSTRUCTION_CHARS) -> str:
    """Return an optional free-text field as a stripped, safe string ('' when absent), cut to ``limit``.

    Raises:
        InputError: the field is present but not a string.
    """
    if raw is None:
        return ""
    if not isinstance(raw, str):
        raise InputError(f"{where}: expected text, got {type(raw).__name__}")
    return safe_text(raw.strip(), limit)

"""Expectations: per case, the machine-checkable checks written for it, read from a small TOML file.

A file holds ``version`` (bump it when the data or scoring changes, so scores stay comparable) and one
table per case, keyed by the case's path relative to the case folder, without ``.json``::

    version = 1
    ["latte_subset/latte_0"]
    checks = [{kind = "distance", object = "labyrinth", relation = "decreased"}, {kind = "start_kept"}]
    # or: skip = "why this case cannot be judged"
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import Any

from trajadapt.bench.judges import CHECKS
from trajadapt.errors import InputError

EXPECTATIONS_FILENAME = "expectations.toml"
DEFAULT_SMOOTHNESS = {"kind": "smooth", "factor": 3.0}  # added to every judged case unless allow_jumps


@dataclass(frozen=True)
class CaseExpectation:
    """What one case must achieve, or why it is not judged."""

    checks: tuple[dict[str, Any], ...]
    skip: str = ""


@dataclass(frozen=True)
class ExpectationSet:
    """All expectations for one case folder."""

    name: str
    version: int
    cases: dict[str, CaseExpectation]

    def task_id(self, key: str) -> str:
        """A versioned id such as ``ovita-dev/latte_subset/latte_0-v1``."""
        return f"{self.name}/{key}-v{self.version}"


def load_expectations(path: Path, name: str) -> ExpectationSet:
    """Read and validate an expectations file.

    Raises:
        InputError: the file is unreadable, or names an unknown check kind.
    """
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise InputError(f"{path}: cannot be read as TOML ({exc})") from exc
    cases = {}
    for key, entry in data.items():
        if key == "version":
            continue
        checks = tuple(entry.get("checks", ()))
        for spec in checks:
            if spec.get("kind") not in CHECKS:
                known = ", ".join(sorted(CHECKS))
                raise InputError(
                    f"{path}: case {key!r} uses unknown check kind {spec.get('kind')!r}; known: {known}"
                )
        if not checks and not entry.get("skip"):
            raise InputError(f"{path}: case {key!r} has neither checks nor a skip reason")
        if checks and not entry.get("allow_jumps"):
            checks += (DEFAULT_SMOOTHNESS,)
        cases[key] = CaseExpectation(checks, str(entry.get("skip", "")))
    return ExpectationSet(name, int(data.get("version", 1)), cases)


def find_expectations(folder: Path, explicit: Path | None = None) -> ExpectationSet | None:
    """The expectations for a case folder, or None when there are none.

    Looked up in order: ``explicit``, ``folder/expectations.toml``, the packaged file named after the
    folder (``ovita-dev.toml`` for the OVITA cases).
    """
    if explicit is not None:
        return load_expectations(explicit, folder.name)
    beside = folder / EXPECTATIONS_FILENAME
    if beside.is_file():
        return load_expectations(beside, folder.name)
    packaged = resources.files("trajadapt.bench").joinpath("expectations", f"{folder.name}.toml")
    if packaged.is_file():
        return load_expectations(Path(str(packaged)), folder.name)
    return None

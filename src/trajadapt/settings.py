"""Settings: one frozen record, layered defaults < config.toml < TRAJADAPT_* variables < flags."""

from __future__ import annotations

import math
import os
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any

from trajadapt.errors import InputError

HOME_ENV = "TRAJADAPT_HOME"


def default_home() -> Path:
    """``$TRAJADAPT_HOME``, else ``$XDG_DATA_HOME/trajadapt``, else ``~/.local/share/trajadapt``."""
    if os.environ.get(HOME_ENV):
        return Path(os.environ[HOME_ENV]).expanduser()
    data_home = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
    return Path(data_home) / "trajadapt"


@dataclass(frozen=True)
class Settings:
    """Everything configurable, passed explicitly; no global state.

    Attributes:
        home: folder for the log database, the model cache and ``config.toml``.
        backend: the backend name used when none is given.
        backend_options: options for that backend (``[backend_options]`` in config.toml).
        axes: the coordinate convention stated in the prompt: ``paper`` (+X left) or ``ovita``.
        mode: the prompt mode: ``skills`` (the skill library) or ``paper`` (the paper's prompt).
        temperature: sampling temperature; 0 (the default) is deterministic.
        seed: sampling seed, for reproducible answers at a temperature above 0.
        repair_attempts: how often a failing code is sent back to the LLM before giving up.
        log: whether exchanges are logged to SQLite.
        memory: whether approved answers are remembered as examples (``memory_path``) and recalled
            for later requests.
        isolation: the sandbox's outer layer: ``auto``, ``bwrap`` or ``process``.
        waypoints_in_prompt: send every waypoint, not only the trajectory's summary (longer prompts).
        project: project a result that breaks the stated constraints onto them (a review note says how
            far waypoints moved); False sends it back for repair instead.
        grammar: in skills mode, constrain a local model's answer to the scene's answer grammar.
        examples: how many worked examples nearest to the instruction go into the prompt (skills mode).
        leave_out_unasked: leave out skill steps of a topic the instruction never mentions (a speed
            change, an extension past the goal, a pause, a loop, ...; skills mode), and replace a
            distance the instruction never gives by its vague word or the default, with a review note;
            also replace a step that does something other than what its clause asks (a part of the
            path, a speed near an object, a side, closer/away, a stated amount: see the README).
        clause_steps: in skills mode with a grammar, build the first answer's grammar from the
            instruction's clauses: a step per clause, in order, each using only that clause's
            objects, numbers and places (``trajadapt.clauses``).
        clause_check: with ``clause_steps``, run each clause's step alone, and when its measured
            effect contradicts the clause's words, ask once more with what it did; the answer with
            fewer contradictions is kept.
        robot: whose limits every result must keep (``robot_limits``): ``none``, ``arm``, ``drone``
            or ``ground``.
        repair_contradictions: when a result contradicts the instruction's words (effect.py), ask the
            model once more with the contradiction, and keep the new result if it contradicts less.
    """

    home: Path = field(default_factory=default_home)
    backend: str = "local"
    backend_options: Mapping[str, Any] = field(default_factory=dict)
    axes: str = "paper"
    mode: str = "skills"
    temperature: float = 0.0
    seed: int = 0
    repair_attempts: int = 2
    log: bool = True
    memory: bool = True
    isolation: str = "auto"
    waypoints_in_prompt: bool = False
    project: bool = True
    grammar: bool = True
    examples: int = 3
    leave_out_unasked: bool = True
    repair_contradictions: bool = False
    clause_steps: bool = False
    clause_check: bool = True
    robot: str = "none"

    @property
    def log_path(self) -> Path:
        """The SQLite log file."""
        return self.home / "logs.db"

    @property
    def memory_path(self) -> Path:
        """The user's bank of remembered examples."""
        return self.home / "memory.jsonl"

    @property
    def config_path(self) -> Path:
        """The optional TOML configuration file."""
        return self.home / "config.toml"


ENV_FIELDS = {
    "backend": str,
    "axes": str,
    "mode": str,
    "temperature": float,
    "seed": int,
    "repair_attempts": int,
    "log": bool,
    "memory": bool,
    "isolation": str,
    "waypoints_in_prompt": bool,
    "project": bool,
    "grammar": bool,
    "examples": int,
    "leave_out_unasked": bool,
    "repair_contradictions": bool,
    "clause_steps": bool,
    "clause_check": bool,
    "robot": str,
}


def load_settings(overrides: Mapping[str, Any] | None = None) -> Settings:
    """Build settings from defaults, ``config.toml`` in the home folder, the environment, then flags.

    Raises:
        InputError: the config file or an environment variable has a bad value.
    """
    settings = Settings()
    settings = replace(settings, **_from_toml(settings.config_path))
    settings = replace(settings, **_from_environment())
    given = {key: value for key, value in (overrides or {}).items() if value is not None}
    settings = replace(settings, **given)
    _check_choices(settings)
    _check_ranges(settings)
    return settings


RANGES: dict[str, tuple[float, float]] = {
    "temperature": (0.0, 2.0),
    "seed": (0, 2**31 - 1),
    "repair_attempts": (0, 10),
    "examples": (0, 12),
}
"""The values each number may take (the command-line flags have the same bounds)."""

TRUE_WORDS, FALSE_WORDS = ("1", "true", "yes", "on"), ("0", "false", "no", "off")


def _check_ranges(settings: Settings) -> None:
    for name, (low, high) in RANGES.items():
        value = getattr(settings, name)
        if not low <= value <= high:
            raise InputError(
                f"{name} {value!r} is out of range: it takes {low:g} to {high:g} (set by "
                f"TRAJADAPT_{name.upper()}, {settings.config_path} or a command-line flag)"
            )


def typed_value(name: str, value: Any, source: str) -> Any:
    """``value`` as the type setting ``name`` has, or an InputError naming the setting and ``source``.

    Strings (from the environment) are parsed strictly: a boolean is one of 1/true/yes/on or
    0/false/no/off, a number is finite. Values already typed (from TOML) must have the type.
    """
    kind = ENV_FIELDS.get(name, dict if name == "backend_options" else str)
    given = f"{source}={value!r}" if source.startswith("TRAJADAPT_") else f"{source}: {name} = {value!r}"
    problem = f"{given} is not a valid {kind.__name__}"
    if isinstance(value, str) and kind is not str:
        value = _parsed(value.strip(), kind, problem)
    if kind is bool and not isinstance(value, bool):
        raise InputError(f"{problem} (use true or false)")
    if kind is int and (isinstance(value, bool) or not isinstance(value, int)):
        raise InputError(problem)
    if kind is float:
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            raise InputError(f"{problem} (a finite number)")
        value = float(value)
    if kind in (str, dict) and not isinstance(value, kind):
        raise InputError(problem if kind is str else f"{source}: {name} must be a table of backend options")
    return value


def _parsed(raw: str, kind: type, problem: str) -> Any:
    if kind is bool:
        if raw.lower() in TRUE_WORDS + FALSE_WORDS:
            return raw.lower() in TRUE_WORDS
        raise InputError(f"{problem} (use one of {', '.join(TRUE_WORDS + FALSE_WORDS)})")
    try:
        return kind(raw)
    except ValueError as exc:
        raise InputError(problem) from exc


# The names each setting takes; tests check that they match the prompt conventions, modes and isolations.
CHOICES: dict[str, tuple[str, ...]] = {
    "axes": ("ovita", "paper"),
    "mode": ("paper", "skills"),
    "isolation": ("auto", "bwrap", "process"),
    "robot": ("arm", "drone", "ground", "none"),
}


def _check_choices(settings: Settings) -> None:
    for name, allowed in CHOICES.items():
        value = getattr(settings, name)
        if value not in allowed:
            raise InputError(
                f"{name} {value!r} is not one of {', '.join(allowed)} (set by TRAJADAPT_{name.upper()}, "
                f"{settings.config_path} or a command-line flag)"
            )


def _from_toml(path: Path) -> dict[str, Any]:
    if not path.is_file():
        return {}
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:  # TOMLDecodeError and UnicodeDecodeError are ValueErrors
        raise InputError(f"{path}: cannot be read as TOML ({exc})") from exc
    known = {f.name for f in fields(Settings)} - {"home"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise InputError(f"{path}: unknown setting {unknown[0]!r}; known: {', '.join(sorted(known))}")
    return {name: typed_value(name, value, str(path)) for name, value in data.items()}


def _from_environment() -> dict[str, Any]:
    values: dict[str, Any] = {}
    for name in ENV_FIELDS:
        raw = os.environ.get(f"TRAJADAPT_{name.upper()}")
        if raw is not None:
            values[name] = typed_value(name, raw, f"TRAJADAPT_{name.upper()}")
    return values

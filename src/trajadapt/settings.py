"""Settings: one frozen record, layered defaults < config.toml < TRAJADAPT_* variables < flags."""

from __future__ import annotations

import math
import os
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any, Literal, get_args, get_origin, get_type_hints

from trajadapt.errors import InputError

HOME_ENV = "TRAJADAPT_HOME"


def default_home() -> Path:
    """``$TRAJADAPT_HOME``, else ``$XDG_DATA_HOME/trajadapt``, else ``~/.local/share/trajadapt``."""
    if os.environ.get(HOME_ENV):
        return Path(os.environ[HOME_ENV]).expanduser()
    data_home = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
    return Path(data_home) / "trajadapt"


def _bounded(default: float, low: float, high: float) -> Any:
    """A number field and the values it may take (the command-line flags have the same bounds)."""
    return field(default=default, metadata={"range": (low, high)})


@dataclass(frozen=True)
class Settings:
    """Everything configurable, passed explicitly; no global state.

    Each setting is declared here once, with its type: the environment variable
    (``TRAJADAPT_<NAME>``), the names a ``Literal`` allows, the range of a number, strict parsing and
    the session's copy (``SessionSettings.from_settings``) all follow from this declaration.

    Attributes:
        home: folder for the log database, the model cache and ``config.toml``.
        backend: the backend name used when none is given.
        backend_options: options for that backend (``[backend_options]`` in config.toml).
        axes: the coordinate convention stated in the prompt: ``paper`` (+X left) or ``ovita``.
        near_rule: what "near an object" means to a speed change: ``zone`` (the default: the
            whole change where the path passes closest, fading soon beyond) or ``latte`` (LaTTe's
            data generator: a change that falls off with distance from the object, none where the
            path stays far; for scoring LaTTe-style data against its references).
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
        retrieval: how those examples are chosen: ``words`` (by the whole instruction's word
            stems) or ``clauses`` (the best for each clause of the instruction first, ranked by
            word stems and by what the words ask: ``memory.recall``; measured and left opt-in).
        read_against_words: read the answer against the user's words (``trajadapt.readers``, skills
            mode): leave out steps of a topic the words never mention, replace amounts they never
            give, and steps that do something other than what their clause asks, each with a review
            note. The old name ``leave_out_unasked`` is still read.
        clause_steps: in skills mode with a grammar, build the first answer's grammar from the
            instruction's clauses: a step per clause, in order, each using only that clause's
            objects, numbers and places (``trajadapt.clauses``).
        clause_check: with ``clause_steps``, run each clause's step alone, and when its measured
            effect contradicts the clause's words, ask once more with what it did; the answer with
            fewer contradictions is kept.
        shape_check: without ``clause_steps`` (skills mode), when the first answer changes nothing
            the words ask for, repeats a step or has more steps than the clauses can hold (two per
            clause that asks for something; ``clauses.shape``), ask once more with that in words;
            the answer with fewer such findings is kept.
        robot: whose limits every result must keep (``robot_limits``): ``none``, ``arm``, ``drone``
            or ``ground``.
        repair_contradictions: when a result contradicts the words (``checks.contradictions``), ask the
            model once more with the contradiction, and keep the new result if it contradicts less.
    """

    home: Path = field(default_factory=default_home)
    backend: str = "local"
    backend_options: Mapping[str, Any] = field(default_factory=dict)
    axes: Literal["paper", "ovita"] = "paper"
    near_rule: Literal["zone", "latte"] = "zone"
    mode: Literal["skills", "paper"] = "skills"
    temperature: float = _bounded(0.0, 0.0, 2.0)
    seed: int = _bounded(0, 0, 2**31 - 1)
    repair_attempts: int = _bounded(2, 0, 10)
    log: bool = True
    memory: bool = True
    isolation: Literal["auto", "bwrap", "process"] = "auto"
    waypoints_in_prompt: bool = False
    project: bool = True
    grammar: bool = True
    examples: int = _bounded(3, 0, 12)
    retrieval: Literal["words", "clauses"] = "words"
    read_against_words: bool = True
    repair_contradictions: bool = False
    clause_steps: bool = False
    clause_check: bool = True
    shape_check: bool = True
    robot: Literal["none", "arm", "drone", "ground"] = "none"

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


ALIASES = {"leave_out_unasked": "read_against_words"}
"""Old names of settings, still read from config.toml, the environment and overrides."""


def _schema() -> tuple[dict[str, type], dict[str, tuple[str, ...]], dict[str, tuple[float, float]]]:
    """The type of each setting set by name, the names of each Literal, the range of each number."""
    hints = get_type_hints(Settings)
    kinds: dict[str, type] = {}
    choices: dict[str, tuple[str, ...]] = {}
    for name in (f.name for f in fields(Settings) if f.name not in ("home", "backend_options")):
        hint = hints[name]
        if get_origin(hint) is Literal:
            choices[name] = tuple(str(value) for value in get_args(hint))
            hint = str
        kinds[name] = hint
    ranges = {f.name: f.metadata["range"] for f in fields(Settings) if "range" in f.metadata}
    return kinds, choices, ranges


ENV_FIELDS, CHOICES, RANGES = _schema()
"""Derived from ``Settings``: what ``TRAJADAPT_<NAME>`` may set and as which type; the names each
Literal setting takes; the values each number may take."""


def load_settings(overrides: Mapping[str, Any] | None = None) -> Settings:
    """Build settings from defaults, ``config.toml`` in the home folder, the environment, then flags.

    Raises:
        InputError: the config file or an environment variable has a bad value.
    """
    settings = Settings()
    settings = replace(settings, **_from_toml(settings.config_path))
    settings = replace(settings, **_from_environment())
    given = {ALIASES.get(key, key): value for key, value in (overrides or {}).items() if value is not None}
    settings = replace(settings, **given)
    _check_choices(settings)
    _check_ranges(settings)
    return settings


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
    unknown = sorted(set(data) - known - set(ALIASES))
    if unknown:
        raise InputError(f"{path}: unknown setting {unknown[0]!r}; known: {', '.join(sorted(known))}")
    data = {ALIASES.get(name, name): value for name, value in data.items()}
    return {name: typed_value(name, value, str(path)) for name, value in data.items()}


def _from_environment() -> dict[str, Any]:
    values: dict[str, Any] = {}
    for name in [*ALIASES, *ENV_FIELDS]:  # the new name wins over the old
        raw = os.environ.get(f"TRAJADAPT_{name.upper()}")
        if raw is not None:
            setting = ALIASES.get(name, name)
            values[setting] = typed_value(setting, raw, f"TRAJADAPT_{name.upper()}")
    return values

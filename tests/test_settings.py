"""Settings come in layers: defaults < config.toml < TRAJADAPT_* variables < flags."""

from __future__ import annotations

from pathlib import Path

import pytest

from trajadapt.errors import InputError
from trajadapt.settings import load_settings


@pytest.fixture
def home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("TRAJADAPT_HOME", str(tmp_path))
    return tmp_path


def test_defaults_keep_the_summary_prompt(home: Path) -> None:
    settings = load_settings()
    assert settings.home == home and not settings.waypoints_in_prompt and settings.repair_attempts == 2


def test_each_layer_overrides_the_one_before(home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (home / "config.toml").write_text("repair_attempts = 4\nwaypoints_in_prompt = true\nmode = 'paper'\n")
    assert load_settings().repair_attempts == 4 and load_settings().waypoints_in_prompt
    monkeypatch.setenv("TRAJADAPT_REPAIR_ATTEMPTS", "1")
    monkeypatch.setenv("TRAJADAPT_WAYPOINTS_IN_PROMPT", "no")
    from_environment = load_settings()
    assert from_environment.repair_attempts == 1 and not from_environment.waypoints_in_prompt
    flagged = load_settings({"repair_attempts": 0, "waypoints_in_prompt": True, "mode": None})
    assert flagged.repair_attempts == 0 and flagged.waypoints_in_prompt and flagged.mode == "paper"


def test_bad_values_name_their_source(home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("TRAJADAPT_SEED", "seven")
    with pytest.raises(InputError, match="TRAJADAPT_SEED='seven'"):
        load_settings()
    monkeypatch.delenv("TRAJADAPT_SEED")
    (home / "config.toml").write_text("colour = 'red'\n")
    with pytest.raises(InputError, match="unknown setting 'colour'"):
        load_settings()


@pytest.mark.parametrize("name", ["axes", "mode", "isolation", "near_rule"])
def test_an_unknown_choice_in_the_environment_is_a_clear_error(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(f"TRAJADAPT_{name.upper()}", "foo")
    with pytest.raises(InputError, match=f"{name} 'foo' is not one of"):
        load_settings()


def test_the_choices_match_what_the_code_knows() -> None:
    from trajadapt.checks.robot_limits import ROBOT_NAMES
    from trajadapt.model.geometry import AXIS_CONVENTIONS
    from trajadapt.prompts import PROMPT_MODES
    from trajadapt.settings import CHOICES
    from trajadapt.skills.speed import NEAR_RULES

    assert set(CHOICES["axes"]) == set(AXIS_CONVENTIONS)
    assert set(CHOICES["mode"]) == set(PROMPT_MODES)
    assert set(CHOICES["isolation"]) == {"auto", "bwrap", "process"}
    assert set(CHOICES["robot"]) == set(ROBOT_NAMES)
    assert set(CHOICES["near_rule"]) == set(NEAR_RULES)


def test_an_unknown_axes_variable_fails_the_command_in_words(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    from click.testing import CliRunner

    from trajadapt.cli import cli

    monkeypatch.setenv("TRAJADAPT_AXES", "foo")
    result = CliRunner().invoke(cli, ["adapt", str(tmp_path / "absent.json"), "-b", "scripted", "--yes"])
    assert result.exit_code == 1
    assert "axes 'foo' is not one of" in result.output and "Traceback" not in result.output


ENVIRONMENT = {
    "AXES": "ovita",
    "MODE": "paper",
    "TEMPERATURE": "0.5",
    "SEED": "7",
    "REPAIR_ATTEMPTS": "1",
    "WAYPOINTS_IN_PROMPT": "yes",
    "PROJECT": "no",
    "GRAMMAR": "off",
    "EXAMPLES": "5",
    "RETRIEVAL": "clauses",
    "READ_AGAINST_WORDS": "no",
    "REPAIR_CONTRADICTIONS": "yes",
    "CLAUSE_STEPS": "yes",
    "CLAUSE_CHECK": "off",
    "SHAPE_CHECK": "off",
    "ROBOT": "drone",
    "NEAR_RULE": "latte",
}
SEEN = {
    "axes": "ovita",
    "mode": "paper",
    "temperature": 0.5,
    "seed": 7,
    "repair_attempts": 1,
    "waypoints_in_prompt": True,
    "project": False,
    "grammar": False,
    "examples": 5,
    "retrieval": "clauses",
    "read_against_words": False,
    "repair_contradictions": True,
    "clause_steps": True,
    "clause_check": False,
    "shape_check": False,
    "robot": "drone",
    "near_rule": "latte",
}


def test_every_variable_reaches_the_session(home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from trajadapt.session import SessionSettings
    from trajadapt.settings import ENV_FIELDS

    for name, value in ENVIRONMENT.items():
        monkeypatch.setenv(f"TRAJADAPT_{name}", value)
    assert set(ENV_FIELDS) - {"backend", "log", "memory", "isolation"} == set(SEEN)
    described = SessionSettings.from_settings(load_settings()).describe()
    assert {key: described[key] for key in SEEN} == SEEN


def test_bench_sees_the_environment(home: Path, monkeypatch: pytest.MonkeyPatch, ovita_dir: Path) -> None:
    import json

    from click.testing import CliRunner

    from trajadapt.cli import cli

    for name, value in ENVIRONMENT.items():
        monkeypatch.setenv(f"TRAJADAPT_{name}", value)
    answers = home / "answers.json"
    keep = json.dumps(
        {"high_level_plan": "1) Keep.", "python_code": "modified_trajectory = get_trajectory()"}
    )
    answers.write_text(json.dumps([keep]))
    case = ovita_dir / "latte_subset" / "latte_32.json"
    out = home / "out"
    result = CliRunner().invoke(
        cli, ["bench", str(case), "-b", "scripted", "-o", "answers", str(answers), "--out", str(out)]
    )
    assert result.exit_code == 0, result.output
    record = json.loads(next(out.rglob("*.result.json")).read_text())
    assert {key: record["settings"][key] for key in SEEN} == SEEN


@pytest.mark.parametrize("command", ["adapt", "bench", "serve"])
def test_the_near_rule_flag_is_offered_with_its_choices(command: str) -> None:
    from click.testing import CliRunner

    from trajadapt.cli import cli

    result = CliRunner().invoke(cli, [command, "--help"])
    assert result.exit_code == 0 and "--near-rule [zone|latte]" in result.output


def test_bench_records_the_near_rule_a_flag_gives(home: Path, ovita_dir: Path) -> None:
    import json

    from click.testing import CliRunner

    from trajadapt.cli import cli

    answers = home / "answers.json"
    keep = json.dumps(
        {"high_level_plan": "1) Keep.", "python_code": "modified_trajectory = get_trajectory()"}
    )
    answers.write_text(json.dumps([keep]))
    out = home / "out"
    case = ovita_dir / "latte_subset" / "latte_32.json"
    flags = ["-b", "scripted", "-o", "answers", str(answers), "--out", str(out), "--near-rule", "latte"]
    result = CliRunner().invoke(cli, ["bench", str(case), *flags])
    assert result.exit_code == 0, result.output
    assert json.loads(next(out.rglob("*.result.json")).read_text())["settings"]["near_rule"] == "latte"

"""Every setting is read with its type and range; a bad value is an error naming it and where it came from."""

from pathlib import Path

import pytest

from trajadapt.errors import InputError
from trajadapt.settings import load_settings


@pytest.fixture
def home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("TRAJADAPT_HOME", str(tmp_path))
    for name in ("GRAMMAR", "SEED", "TEMPERATURE", "EXAMPLES", "LOG"):
        monkeypatch.delenv(f"TRAJADAPT_{name}", raising=False)
    return tmp_path


@pytest.mark.parametrize(
    ("variable", "value", "said"),
    [
        ("GRAMMAR", "ture", "TRAJADAPT_GRAMMAR"),
        ("SEED", "abc", "TRAJADAPT_SEED"),
        ("TEMPERATURE", "hot", "TRAJADAPT_TEMPERATURE"),
        ("TEMPERATURE", "nan", "TRAJADAPT_TEMPERATURE"),
        ("EXAMPLES", "-5", "examples"),
        ("LOG", "maybe", "TRAJADAPT_LOG"),
    ],
)
def test_a_bad_environment_value_is_refused_by_name(home, monkeypatch, variable, value, said):
    monkeypatch.setenv(f"TRAJADAPT_{variable}", value)
    with pytest.raises(InputError, match=said):
        load_settings()


@pytest.mark.parametrize(
    "line",
    ['seed = "abc"', 'temperature = "hot"', "temperature = nan", "examples = -5", 'log = "maybe"',
     "backend_options = 5", "grammar = 1", "repair_attempts = 1.5"],
)  # fmt: skip
def test_a_bad_config_value_is_refused_by_name(home, line):
    (home / "config.toml").write_text(line + "\n")
    with pytest.raises(InputError, match=line.split(" ")[0]):
        load_settings()


def test_a_config_file_of_binary_bytes_is_an_input_error(home):
    (home / "config.toml").write_bytes(b"\xff\xfe\x00seed = 1")
    with pytest.raises(InputError, match="cannot be read as TOML"):
        load_settings()


def test_good_values_are_read_with_their_types(home, monkeypatch):
    (home / "config.toml").write_text("temperature = 1\nexamples = 4\nbackend_options = {n_ctx = 4096}\n")
    monkeypatch.setenv("TRAJADAPT_GRAMMAR", "Off")
    settings = load_settings()
    assert settings.temperature == 1.0 and isinstance(settings.temperature, float)
    assert (
        settings.examples == 4 and settings.grammar is False and settings.backend_options == {"n_ctx": 4096}
    )


def test_the_schema_is_derived_from_the_one_declaration() -> None:
    from dataclasses import fields

    from trajadapt.session import SessionSettings
    from trajadapt.settings import CHOICES, ENV_FIELDS, RANGES, Settings

    declared = {f.name for f in fields(Settings)} - {"home", "backend_options"}
    assert set(ENV_FIELDS) == declared
    assert CHOICES["robot"] == ("none", "arm", "drone", "ground") and ENV_FIELDS["robot"] is str
    assert RANGES["examples"] == (0, 12) and ENV_FIELDS["temperature"] is float
    described = SessionSettings().describe()
    assert {f.name for f in fields(SessionSettings)} <= set(described)  # describe() omits nothing


@pytest.mark.parametrize("source", ["environment", "config"])
def test_the_old_name_of_the_readers_switch_is_still_read(home, monkeypatch, source):
    monkeypatch.delenv("TRAJADAPT_READ_AGAINST_WORDS", raising=False)
    if source == "environment":
        monkeypatch.setenv("TRAJADAPT_LEAVE_OUT_UNASKED", "false")
    else:
        (home / "config.toml").write_text("leave_out_unasked = false\n")
    settings = load_settings()
    assert settings.read_against_words is False
    from trajadapt.session import SessionSettings

    assert SessionSettings.from_settings(settings).leave_out_unasked is False
    assert load_settings({"leave_out_unasked": True}).read_against_words is True

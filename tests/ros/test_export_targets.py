"""export creates its target whole and exclusively, never over its own input, and maps bad targets to words."""

import json
import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest
from click.testing import CliRunner

from trajadapt.cli import cli
from trajadapt.errors import InputError
from trajadapt.files.atomic_files import publish_bytes

ROWS = [[0.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0], [0.0, 2.0, 0.0, 1.0]]


@pytest.fixture
def result_file(tmp_path: Path) -> Path:
    path = tmp_path / "case.result.json"
    path.write_text(json.dumps({"modified_trajectory": ROWS, "original_trajectory": ROWS, "status": "ok"}))
    return path


def export(*arguments: str):
    return CliRunner().invoke(cli, ["export", *arguments])


@pytest.mark.parametrize("fmt", ["csv", "json"])
def test_an_existing_target_is_refused_unless_forced(result_file, fmt):
    target = result_file.with_name(f"out.{fmt}")
    target.write_text("keep me")
    refused = export(str(result_file), "--format", fmt, "-o", str(target))
    assert refused.exit_code != 0 and "exists already" in refused.output and target.read_text() == "keep me"
    forced = export(str(result_file), "--format", fmt, "-o", str(target), "--force")
    assert forced.exit_code == 0 and target.read_text() != "keep me"


def test_the_result_file_itself_is_never_written_over(result_file):
    before = result_file.read_text()
    outcome = export(str(result_file), "--format", "json", "-o", str(result_file), "--force")
    assert outcome.exit_code != 0 and "RESULT_FILE itself" in outcome.output
    assert result_file.read_text() == before


@pytest.mark.parametrize(
    "target",
    ["missing-folder/out.csv", "/proc/out.csv", "x" * 300 + ".csv"],
)
def test_a_target_that_cannot_be_created_is_an_error_in_words(result_file, target):
    path = target if target.startswith("/") else str(result_file.parent / target)
    outcome = export(str(result_file), "--format", "csv", "-o", path)
    assert outcome.exit_code != 0 and "Traceback" not in outcome.output
    assert "cannot be written" in outcome.output or "does not exist" in outcome.output


def test_a_frame_that_is_not_utf8_is_an_error_in_words(result_file):
    outcome = export(str(result_file), "--format", "json", "--frame", "map\udcff")
    assert outcome.exit_code != 0 and "--frame" in outcome.output


def test_parallel_writers_of_one_new_file_one_wins(tmp_path):
    target = tmp_path / "new.bin"
    wins, losses = [], []

    def write(n: int) -> None:
        try:
            publish_bytes(target, bytes([n]) * 1000)
            wins.append(n)
        except InputError:
            losses.append(n)

    threads = [threading.Thread(target=write, args=(n,)) for n in range(8)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert len(wins) == 1 and len(losses) == 7 and target.read_bytes() == bytes([wins[0]]) * 1000


def test_a_writer_killed_half_way_leaves_nothing_in_the_folder(tmp_path):
    script = (
        "import os, sys, signal\n"
        "from pathlib import Path\n"
        "import trajadapt.files.atomic_files as a\n"
        "real = a._write_all\n"
        "def dying(handle, payload):\n"
        "    os.write(handle, payload[:10])\n"
        "    os.kill(os.getpid(), signal.SIGKILL)\n"
        "a._write_all = dying\n"
        "a.publish_bytes(Path(sys.argv[1]), b'x' * 100000)\n"
    )
    target = tmp_path / "out.mcap"
    done = subprocess.run([sys.executable, "-c", script, str(target)], check=False)
    assert done.returncode == -9
    assert os.listdir(tmp_path) == []

"""The openai backend against a real OpenAI-compatible server: llama-cpp-python's, on the embedded model.

Started once per module on 127.0.0.1 with the same GGUF the local backend uses; at temperature 0 and
with the answer grammar sent in the request (``-o grammar_field grammar``), the served model gives
the same plans as the embedded one. Marked ``local_model``: it needs the model file and llama.cpp.
"""

from __future__ import annotations

import json
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner

from tests.backends.conftest import needs_model
from trajadapt.backends.local import LocalBackend, LocalOptions
from trajadapt.cli import cli

pytestmark = [pytest.mark.local_model, needs_model]
CASES = ("latte_subset/latte_32.json", "latte_subset/latte_10.json")


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@pytest.fixture(scope="module")
def llama_server(real_model: Path, tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    pytest.importorskip("sse_starlette", reason="llama-cpp-python[server] not installed")
    port = _free_port()
    command = [sys.executable, "-m", "llama_cpp.server", "--model", str(real_model), "--model_alias", "qwen",
               "--host", "127.0.0.1", "--port", str(port), "--n_ctx", "4096", "--n_threads", "1",
               "--n_threads_batch", "2"]  # fmt: skip
    log = tmp_path_factory.mktemp("server") / "server.log"
    with log.open("w") as sink:  # a file, not a pipe: llama.cpp's log would fill a pipe and stall the server
        server = subprocess.Popen(command, stdout=sink, stderr=subprocess.STDOUT)
    base_url = f"http://127.0.0.1:{port}/v1"
    try:
        _wait_until_up(server, base_url, log)
        yield base_url
    finally:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()


def _wait_until_up(server: subprocess.Popen[bytes], base_url: str, log: Path) -> None:
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline:
        if server.poll() is not None:
            pytest.fail(f"llama_cpp.server exited: {log.read_text()[-2000:]}")
        try:
            with urllib.request.urlopen(f"{base_url}/models", timeout=2) as response:
                if response.status == 200:
                    return
        except OSError:
            time.sleep(1)
    pytest.fail(f"llama_cpp.server did not answer within 300 s: {log.read_text()[-2000:]}")


def _adapt(case: Path, out: Path, *backend: str) -> dict[str, object]:
    """Adapt ``case`` with no memory: the two runs must see the same prompt (an approval would be recalled)."""
    arguments = [
        "adapt",
        str(case),
        *backend,
        "--yes",
        "--no-log",
        "--no-memory",
        "--repairs",
        "0",
        "--out",
        str(out),
    ]
    result = CliRunner().invoke(cli, arguments)
    assert result.exit_code == 0, result.output
    return json.loads(out.read_text())


def test_adapt_through_the_real_server_gives_the_local_backends_plans(
    llama_server: str, real_model: Path, ovita_dir: Path, tmp_path: Path
) -> None:
    served = [
        "-b",
        "openai",
        "-o",
        "base_url",
        llama_server,
        "-o",
        "model",
        "qwen",
        "-o",
        "grammar_field",
        "grammar",
        "-o",
        "timeout_s",
        "900",
    ]  # fmt: skip  (the first request reads the whole fixed prompt)
    local = ["-b", "local", "--model-path", str(real_model), "-o", "prompt_cache", "false"]
    for name in CASES:
        case = ovita_dir / name
        from_server = _adapt(case, tmp_path / f"served-{case.stem}.json", *served)
        from_local = _adapt(case, tmp_path / f"local-{case.stem}.json", *local)
        assert from_server["status"] == "ok" and from_server["model"] == "qwen"
        assert from_server["code"] == from_local["code"], name


def test_bench_with_two_jobs_through_the_real_server(
    llama_server: str, ovita_dir: Path, tmp_path: Path
) -> None:
    folder = tmp_path / "cases" / "latte_subset"
    folder.mkdir(parents=True)
    for name in CASES:
        (folder / Path(name).name).write_text((ovita_dir / name).read_text())
    arguments = ["bench", str(folder), "-b", "openai", "-o", "base_url", llama_server, "-o", "model", "qwen",
                 "-o", "grammar_field", "grammar", "-o", "timeout_s", "900", "--jobs", "2", "--repairs", "0",
                 "--out", str(tmp_path / "out")]  # fmt: skip
    result = CliRunner().invoke(cli, arguments)
    assert result.exit_code == 0, result.output
    records = [json.loads(p.read_text()) for p in (tmp_path / "out").rglob("*.result.json")]
    assert len(records) == 2 and all(r["status"] == "ok" for r in records)


def test_the_local_backend_is_what_the_server_is_compared_with() -> None:
    assert LocalBackend(LocalOptions(prompt_cache=False)).options.grammar  # the grammar is on in both

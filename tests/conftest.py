"""Shared fixtures: an isolated trajadapt home, the OVITA cases, small trajectories and scenes."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from trajadapt.model.case import Case
from trajadapt.model.scene import Scene, SceneObject
from trajadapt.model.trajectory import Trajectory
from trajadapt.sandbox.runner import Sandbox, SandboxLimits

REPO_ROOT = Path(__file__).resolve().parents[1]
OVITA_DIR = REPO_ROOT.parent / "shared" / "data" / "ovita-dev"


@pytest.fixture(autouse=True)
def isolated_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Point the log database, model cache and config at a temporary folder."""
    home = tmp_path / "trajadapt-home"
    monkeypatch.setenv("TRAJADAPT_HOME", str(home))
    for name in ("TRAJADAPT_BACKEND", "TRAJADAPT_AXES", "TRAJADAPT_LOG", "OPENAI_API_KEY"):
        monkeypatch.delenv(name, raising=False)
    return home


@pytest.fixture
def ovita_dir() -> Path:
    """The released OVITA development cases (read in place)."""
    if not OVITA_DIR.is_dir():
        pytest.skip(f"OVITA cases not found at {OVITA_DIR}")
    return OVITA_DIR


def line_trajectory(n: int = 20) -> Trajectory:
    """A straight line along +y at x = 0, z = 0.5, speed 1."""
    y = np.linspace(0.0, 1.0, n)
    return Trajectory(np.c_[np.zeros(n), y, np.full(n, 0.5), np.ones(n)])


@pytest.fixture
def simple_case() -> Case:
    """A line past a box, with an instruction."""
    scene = Scene((SceneObject("box", 0.2, 0.5, 0.5), SceneObject("Red Mug", -0.3, 0.8, 0.5)))
    return Case("simple", line_trajectory(), scene, "go left")


@pytest.fixture(scope="session")
def sandbox() -> Iterator[Sandbox]:
    """One warm sandbox for the whole test run, with short limits so hostile code ends fast."""
    with Sandbox(SandboxLimits(cpu_s=1.0, wall_s=3.0, memory_mb=256)) as box:
        yield box

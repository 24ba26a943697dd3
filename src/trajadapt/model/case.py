"""Case: one adaptation problem (trajectory, scene, instruction) and the files it is read from."""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from trajadapt.errors import InputError
from trajadapt.model.scene import NAME_CHARS, Scene, parse_objects, parse_text_field
from trajadapt.model.trajectory import Trajectory, load_trajectory_file, read_json_file
from trajadapt.safe_text import INSTRUCTION_CHARS, safe_text

DESCRIPTION_CHARS = 50_000


@dataclass(frozen=True)
class Case:
    """A trajectory to adapt, the scene around it and the user's instruction."""

    name: str
    trajectory: Trajectory
    scene: Scene
    instruction: str = ""
    source: Path | None = None

    def with_instruction(self, instruction: str) -> Case:
        """Return a copy of this case with another instruction."""
        return replace(self, instruction=safe_text(instruction.strip(), INSTRUCTION_CHARS))

    def to_dict(self) -> dict[str, Any]:
        """Return the OVITA case-file form of this case."""
        data: dict[str, Any] = {
            "trajectory": self.trajectory.to_rows(),
            "objects": [obj.to_dict() for obj in self.scene.objects],
            "instruction": self.instruction,
        }
        if self.scene.description:
            data["Env_descp"] = self.scene.description
        if self.scene.constraints:
            data["constraints"] = self.scene.constraints
        return data


def case_from_dict(data: Any, where: str, name: str = "case") -> Case:
    """Validate a case in the OVITA format: trajectory, objects, instruction, Env_descp, constraints.

    Raises:
        InputError: naming ``where``, the field and the problem.
    """
    if not isinstance(data, dict):
        raise InputError(f"{where}: expected a JSON object with a 'trajectory' field")
    if "trajectory" not in data:
        raise InputError(f"{where}: no 'trajectory' field (expected [[x, y, z, v], ...])")
    return Case(
        name=safe_text(name, NAME_CHARS),
        trajectory=Trajectory.from_rows(data["trajectory"], f"{where}: trajectory"),
        scene=scene_from_dict(data, where),
        instruction=parse_text_field(data.get("instruction"), f"{where}: instruction"),
    )


def scene_from_dict(data: dict[str, Any], where: str) -> Scene:
    """Read the scene fields (objects, Env_descp, constraints) of a case or scene file."""
    return Scene(
        objects=parse_objects(data.get("objects"), f"{where}: objects"),
        description=parse_text_field(data.get("Env_descp"), f"{where}: Env_descp", DESCRIPTION_CHARS),
        constraints=parse_text_field(data.get("constraints"), f"{where}: constraints", DESCRIPTION_CHARS),
    )


def load_case(path: Path) -> Case:
    """Read a case file in the OVITA format.

    Raises:
        InputError: the file is missing or not a valid case.
    """
    case = case_from_dict(read_json_file(path), str(path), name=path.stem)
    return replace(case, source=path)


def load_scene(path: Path) -> Scene:
    """Read a scene file: ``{"objects": [...], "Env_descp": ..., "constraints": ...}``."""
    data = read_json_file(path)
    if not isinstance(data, dict):
        raise InputError(f"{path}: expected a JSON object with an 'objects' list")
    return scene_from_dict(data, str(path))


def load_case_from_parts(
    trajectory_path: Path, scene_path: Path | None, instruction: str, trajectory: Trajectory | None = None
) -> Case:
    """Build a case from a trajectory file (JSON or CSV, or ``trajectory`` read from it) and a scene file."""
    scene = load_scene(scene_path) if scene_path is not None else Scene()
    trajectory = trajectory if trajectory is not None else load_trajectory_file(trajectory_path)
    instruction = safe_text(instruction.strip(), INSTRUCTION_CHARS)
    return Case(trajectory_path.stem, trajectory, scene, instruction, trajectory_path)

"""Loading cases, trajectories and scenes: valid files load, each kind of bad file gets one clear error."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from trajadapt.errors import InputError
from trajadapt.model.case import load_case, load_case_from_parts, load_scene
from trajadapt.model.trajectory import Trajectory, load_trajectory_file


def write(path: Path, data: object) -> Path:
    path.write_text(json.dumps(data) if not isinstance(data, str) else data)
    return path


GOOD_CASE = {
    "trajectory": [[0, 0, 0, 1], [1, 0, 0, 1], [2, 0, 0, 0]],
    "objects": [{"name": "box", "x": 1, "y": 1, "z": 0, "dimensions": [0.1, 0.1, 0.1]}],
    "instruction": "go left",
    "Env_descp": "a room",
    "constraints": "x in [-3, 3]",
}


def test_every_ovita_case_loads(ovita_dir: Path) -> None:
    files = sorted(ovita_dir.rglob("*.json"))
    assert len(files) == 116
    for path in files:
        case = load_case(path)
        assert len(case.trajectory) >= 2


def test_case_fields_are_read(tmp_path: Path) -> None:
    case = load_case(write(tmp_path / "c.json", GOOD_CASE))
    assert case.name == "c"
    assert case.instruction == "go left"
    assert case.scene.find("BOX") is not None
    assert case.scene.find("sofa") is None
    assert case.scene.description == "a room" and case.scene.constraints == "x in [-3, 3]"
    assert case.scene.objects[0].dimensions == (0.1, 0.1, 0.1)


@pytest.mark.parametrize(
    ("mutation", "expected"),
    [
        ({"trajectory": [[0, 0, 0], [1, 1, 1]]}, r"trajectory\[0\]: expected 4 numbers"),
        ({"trajectory": [[0, 0, 0, 1]]}, "at least 2 waypoints, got 1"),
        ({"trajectory": []}, "at least 2 waypoints, got 0"),
        ({"trajectory": [[0, 0, 0, 1], [0, "a", 0, 1]]}, r"trajectory\[1\]: y must be a number"),
        ({"trajectory": [[0, 0, 0, 1], [0, 0, 0, -1]]}, "velocity must be >= 0"),
        ({"trajectory": "nope"}, "expected a list of"),
        (
            {"objects": [{"name": "a", "x": 0, "y": 0, "z": 0}, {"name": "A ", "x": 1, "y": 0, "z": 0}]},
            "names must be unique",
        ),
        ({"objects": [{"name": "a", "x": 0, "y": 0}]}, r"objects\[0\] \(a\): z must be a number"),
        ({"objects": [{"x": 0, "y": 0, "z": 0}]}, "'name' must be a non-empty string"),
        ({"instruction": 5}, "instruction: expected text"),
    ],
)
def test_bad_case_fields(tmp_path: Path, mutation: dict[str, object], expected: str) -> None:
    path = write(tmp_path / "bad.json", {**GOOD_CASE, **mutation})
    with pytest.raises(InputError, match=expected) as info:
        load_case(path)
    assert str(path) in str(info.value)


def test_nan_is_refused(tmp_path: Path) -> None:
    path = write(tmp_path / "nan.json", '{"trajectory": [[0, 0, 0, 1], [NaN, 0, 0, 1]]}')
    with pytest.raises(InputError, match=r"trajectory\[1\]: x must be finite"):
        load_case(path)


def test_missing_and_broken_files(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="file not found"):
        load_case(tmp_path / "absent.json")
    with pytest.raises(InputError, match="not valid JSON"):
        load_case(write(tmp_path / "broken.json", "{"))
    with pytest.raises(InputError, match="no 'trajectory' field"):
        load_case(write(tmp_path / "empty.json", {}))


def test_trajectory_csv_and_scene(tmp_path: Path) -> None:
    csv_path = write(tmp_path / "t.csv", "v,x,y,z,label\n1,0,0,0,a\n0.5,1,2,3,b\n")
    trajectory = load_trajectory_file(csv_path)
    assert trajectory.to_rows() == [[0, 0, 0, 1], [1, 2, 3, 0.5]]
    scene_path = write(tmp_path / "s.json", {"objects": GOOD_CASE["objects"]})
    case = load_case_from_parts(csv_path, scene_path, "go up")
    assert case.instruction == "go up" and load_scene(scene_path).names() == ["box"]
    with pytest.raises(InputError, match="missing z"):
        load_trajectory_file(write(tmp_path / "bad.csv", "x,y,v\n1,2,3\n"))
    with pytest.raises(InputError, match="line 3"):
        load_trajectory_file(write(tmp_path / "bad2.csv", "x,y,z,v\n1,2,3,4\n1,2,x,4\n"))


def test_trajectory_is_immutable() -> None:
    rows = [[0.0, 0.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0]]
    trajectory = Trajectory.from_rows(rows)
    with pytest.raises(ValueError):
        trajectory.array[0, 0] = 5
    rows[0][0] = 9
    assert trajectory.array[0, 0] == 0
    source = np.zeros((3, 4))
    copy = Trajectory(source)
    source[0, 0] = 1
    assert copy.array[0, 0] == 0


def test_a_csv_header_field_past_the_csv_limit_is_an_input_error(tmp_path):
    from trajadapt.errors import InputError
    from trajadapt.model.trajectory import load_trajectory_file as load_trajectory

    path = tmp_path / "long.csv"
    path.write_text("x,y,z," + "v" * 140_000 + "\n1,2,3,4\n")
    with pytest.raises(InputError, match="line 1"):
        load_trajectory(path)


def test_a_csv_naming_a_column_twice_is_an_input_error(tmp_path):
    from trajadapt.errors import InputError
    from trajadapt.model.trajectory import load_trajectory_file as load_trajectory

    path = tmp_path / "twice.csv"
    path.write_text("x,y,z,v,x\n1,2,3,4,5\n0,1,2,3,4\n")
    with pytest.raises(InputError, match="more than once"):
        load_trajectory(path)

"""Scene: objects found by name however the user writes it; names are unique."""

from __future__ import annotations

import pytest

from trajadapt.errors import InputError
from trajadapt.model.scene import Scene, SceneObject, name_key, parse_objects


def test_objects_are_found_by_name_in_any_case_and_spacing() -> None:
    scene = Scene((SceneObject("Red  Mug", 1, 2, 3), SceneObject("box", 0, 0, 0)))
    found = scene.find("  red mug ")
    assert found is not None and found.position == (1, 2, 3)
    assert scene.find("lamp") is None and scene.names() == ["Red  Mug", "box"]
    assert name_key("Red  Mug") == name_key("red mug")


def test_names_that_clash_are_refused_in_words() -> None:
    with pytest.raises(InputError, match=r"unique \(case-insensitive\); 'Box' and 'box' clash"):
        parse_objects(
            [{"name": "Box", "x": 0, "y": 0, "z": 0}, {"name": "box ", "x": 1, "y": 0, "z": 0}], "scene"
        )

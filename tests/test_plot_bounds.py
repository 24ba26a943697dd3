"""A plot of a scene with thousands of objects is drawn with bounded work: markers in one call, few labels."""

import numpy as np

from tests.conftest import line_trajectory
from trajadapt.files.plot import MAX_LABELS, labelled, plot_comparison
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.model.scene import Scene, SceneObject


def crowded(count: int) -> Scene:
    rng = np.random.default_rng(0)
    return Scene(tuple(SceneObject(f"o{i}", *rng.uniform(-1, 1, 3)) for i in range(count)))


def test_only_the_objects_nearest_the_path_are_labelled():
    scene = crowded(5000)
    chosen = labelled(scene, line_trajectory())
    assert len(chosen) == MAX_LABELS
    path = line_trajectory().positions
    worst_labelled = max(np.min(np.linalg.norm(path - np.asarray(o.position), axis=1)) for o in chosen)
    unlabelled = [o for o in scene.objects if o not in chosen]
    assert all(
        np.min(np.linalg.norm(path - np.asarray(o.position), axis=1)) >= worst_labelled for o in unlabelled
    )
    assert labelled(crowded(5), line_trajectory()) == list(crowded(5).objects)


def test_a_plot_of_5000_objects_is_drawn(tmp_path):
    out = tmp_path / "plot.png"
    plot_comparison(line_trajectory(), line_trajectory(), crowded(5000), out, AXIS_CONVENTIONS["paper"])
    assert out.stat().st_size > 1000

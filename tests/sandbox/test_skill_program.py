"""The allow-list of skill programs: every shipped example passes, every hostile snippet is refused."""

import json
from importlib import resources

import pytest

from tests.sandbox.hostile_snippets import HOSTILE_SNIPPETS
from trajadapt.errors import CodeRejected
from trajadapt.sandbox.skill_program import check_skill_program


def bank_programs() -> list[str]:
    text = resources.files("trajadapt.prompts").joinpath("examples.jsonl").read_text(encoding="utf-8")
    return [json.loads(line)["code"] for line in text.splitlines() if line.strip()]


@pytest.mark.parametrize("code", bank_programs())
def test_every_shipped_example_is_a_skill_program(code):
    check_skill_program(code)


@pytest.mark.parametrize(("name", "code"), HOSTILE_SNIPPETS, ids=[name for name, _ in HOSTILE_SNIPPETS])
def test_every_hostile_snippet_is_refused(name, code):
    with pytest.raises(CodeRejected):
        check_skill_program(code)


@pytest.mark.parametrize(
    "code",
    [
        "t = get_trajectory()\nt = np.ndarray((1,), dtype=object)\nmodified_trajectory = t",
        "t = get_trajectory()\nt.resize(10, refcheck=False)\nmodified_trajectory = t",
        "t = get_trajectory()\nt = shift(t, 'up', t.tobytes())\nmodified_trajectory = t",
        "t = get_trajectory()\nt = shift(t, **{'direction': 'up'})\nmodified_trajectory = t",
        "t = get_trajectory()\nt = shift(t, 'up')[::-1]\nmodified_trajectory = t",
        "t = get_trajectory()\nt = t[len(t) - 1]\nmodified_trajectory = t",
        "t = get_trajectory()\nt = shift(u, 'up')\nmodified_trajectory = t",
        "t = get_trajectory()\nshift = get_trajectory()\nmodified_trajectory = t",
        "t = get_trajectory()\nt = (lambda: t)()\nmodified_trajectory = t",
        "t = get_trajectory()\nt = [x for x in t]\nmodified_trajectory = t",
        "t = get_trajectory()\nt = shift(t, 'up', 2 ** 100000)\nmodified_trajectory = t",
        "t = get_trajectory()\nt = shift(t, 'up', b'x')\nmodified_trajectory = t",
        "t: int = 1\nmodified_trajectory = t",
        "t = get_trajectory()\nt += 1\nmodified_trajectory = t",
    ],
)
def test_what_the_grammar_would_not_write_is_refused(code):
    with pytest.raises(CodeRejected):
        check_skill_program(code)


def test_what_the_grammar_writes_passes():
    check_skill_program(
        "t = get_trajectory()\n"
        "t = pass_through(t, midpoint(detect_objects('box'), [0.1, -0.2, 0]))\n"
        "t = wait(t, closest_waypoint(t, detect_objects('lamp')), 5)\n"
        "t = resample(t, 2 * len(t))\n"
        "t = scale_speed(t, 0.65, near=t[-1], part=(0.5, 1))\n"
        "modified_trajectory = t"
    )

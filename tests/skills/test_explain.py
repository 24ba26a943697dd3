"""Every skill explains itself with its arguments; other code is left to the model, labelled as such."""

from __future__ import annotations

import ast
import json

import pytest

from trajadapt.llm.answer_grammar import is_statement_skill, skill_parameters
from trajadapt.skills import SKILLS
from trajadapt.skills.explain import TEMPLATES, explain_code

SAMPLE = {  # one argument text per kind
    "point": "detect_objects('teapot')",
    "points": "[detect_objects('teapot'), detect_objects('kettle')]",
    "direction": "'left'",
    "distance": "0.37",
    "fraction": "'a lot'",
    "part": "'end'",
    "waypoint": "'goal'",
    "profile": "'decelerate'",
    "number": "0.37",
    "count": "7",
    "flag": "False",
    "height": "0.37",
    "factor": "0.37",
}
SHOWN = {"point": "teapot", "points": "kettle", "direction": "left", "distance": "0.37", "fraction": "50%",
         "part": "end", "waypoint": "goal", "profile": "decelerate", "number": "0.37", "count": "7", "height": "0.37",
         "factor": "0.37"}  # fmt: skip


@pytest.mark.parametrize("skill", [f for f in SKILLS if is_statement_skill(f)], ids=lambda f: f.__name__)
def test_every_skill_explains_itself_with_its_required_arguments(skill) -> None:  # type: ignore[no-untyped-def]
    assert skill.__name__ in TEMPLATES
    required = [(p, kind) for p, kind in skill_parameters(skill)[1:] if p.default is p.empty]
    call = f"t = {skill.__name__}(t{''.join(', ' + SAMPLE[kind] for _, kind in required)})"
    lines = explain_code(f"t = get_trajectory()\n{call}\nmodified_trajectory = t")
    assert lines is not None and len(lines) == 1 and "{" not in lines[0]
    for _, kind in required:
        if kind in SHOWN:
            assert SHOWN[kind] in lines[0], (call, lines[0])


def test_optional_arguments_and_defaults_are_spelled_out() -> None:
    lines = explain_code(
        "t = get_trajectory()\nt = shift(t, 'up', 'a bit')\nt = move_away(t, detect_objects('lamp'))\n"
        "t = scale_speed(t, 0.65, near=detect_objects('cat'), radius=0.4)\nt = extend(t)\nmodified_trajectory = t"
    )
    assert lines == [
        "moves the path 'a bit' (6% of the path's size) up, keeping the start and blending in over the first 15%",
        "pushes the part of the path nearest the lamp the default amount (12% of the path's size) away from it; "
        "start and goal stay",
        "multiplies the speed by 0.65 within 0.4 of the cat",
        "continues past the goal by 20% of the path's size along the final heading",
    ]


def test_an_object_move_on_a_part_says_which_waypoints_move() -> None:
    lines = explain_code(
        "t = get_trajectory()\nt = move_closer(t, detect_objects('chair'), 'a bit', part=(0, 6))\n"
        "modified_trajectory = t"
    )
    assert lines == ["brings waypoints 0 to 5 'a bit' (20% of the way) towards the chair"]


def test_pass_over_spells_out_its_default_clearance_and_each_object() -> None:
    lines = explain_code(
        "t = get_trajectory()\nt = pass_over(t, [detect_objects('crate'), detect_objects('barrel')])\n"
        "modified_trajectory = t"
    )
    assert lines == ["bends the path so that it passes 10% of the path's size above the crate and the barrel"]


@pytest.mark.parametrize(
    "code",
    [
        "t = get_trajectory()\nt[:, 0] += 0.2\nmodified_trajectory = t",
        "t = get_trajectory()\nt = np.flip(t, 0)\nmodified_trajectory = t",
        "t = get_trajectory()\nfor i in range(3):\n    t = shift(t, 'up')\nmodified_trajectory = t",
        "not python (",
    ],
)
def test_code_that_is_not_only_skill_calls_is_not_explained_here(code: str) -> None:
    assert explain_code(code) is None


def test_the_session_explains_skills_itself_and_asks_the_model_otherwise(simple_case, sandbox) -> None:  # type: ignore[no-untyped-def]
    from trajadapt.backends.scripted import ScriptedBackend
    from trajadapt.session import AdaptationSession

    skills = "t = get_trajectory()\nt = shift(t, 'left', 0.2)\nmodified_trajectory = t"
    numpy = "t = get_trajectory()\nt[:, 0] += 0.2\nmodified_trajectory = t"
    backend = ScriptedBackend(answers=[json.dumps({"high_level_plan": "1) a", "python_code": skills})])
    session = AdaptationSession(simple_case.with_instruction("go left by 0.2"), backend, sandbox)
    session.draft()
    assert session.explain().source == "skills" and len(backend.requests) == 1
    assert session.approve().to_dict()["explanation"]["lines"][0].startswith("moves the path 0.2 left")
    backend = ScriptedBackend(answers=[json.dumps({"high_level_plan": "1) a", "python_code": numpy}),
                                       "1) Adds 0.2 to every x.\n2) Returns it."])  # fmt: skip
    session = AdaptationSession(simple_case, backend, sandbox)
    session.draft()
    explanation = session.explain()
    assert explanation.source == "model" and explanation.lines == (
        "1) Adds 0.2 to every x.",
        "2) Returns it.",
    )
    assert ast.parse(backend.requests[1].messages[0].content.split("CODE:")[1])  # the code is what was sent
    assert session.approve().to_dict()["explanation"] == {"source": "model", "lines": list(explanation.lines)}


def test_a_held_pace_and_a_stop_beside_say_so() -> None:
    lines = explain_code(
        "t = get_trajectory()\nt = scale_speed(t, 0.5, near=detect_objects('lamp'), held=True)\n"
        "t = stop_at(t, detect_objects('sofa'), beside=True)\nmodified_trajectory = t"
    )
    assert lines == [
        "multiplies the speed by 0.5 near the lamp, held over the stretch nearest it, then fading",
        "ends the path beside the sofa: from its waypoint nearest it straight on to beside it, speed 0 there",
    ]


def test_a_stop_within_a_distance_says_the_distance() -> None:
    lines = explain_code(
        "t = get_trajectory()\nt = stop_at(t, detect_objects('sofa'), within=0.3)\nmodified_trajectory = t"
    )
    assert lines == [
        "ends the path within 0.3 of the sofa: from its waypoint nearest it straight on to beside it, speed 0 there"
    ]

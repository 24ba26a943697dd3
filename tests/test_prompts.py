"""The prompt keeps the paper's structure, states the chosen axes, and has a byte-identical prefix."""

from __future__ import annotations

from trajadapt.model.case import Case
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import first_messages, render_functions, system_prompt
from trajadapt.sandbox.api import CONTRACT


def test_sections_in_paper_order(simple_case: Case) -> None:
    system, user = first_messages(simple_case, AXIS_CONVENTIONS["paper"], mode="paper")
    text = system.content
    order = [
        "FUNCTIONS AVAILABLE",
        "COORDINATE SYSTEM",
        "RULES",
        "OUTPUT FORMAT",
        "EXAMPLES OF HIGH-LEVEL PLANS",
    ]
    positions = [text.index(section) for section in order]
    assert positions == sorted(positions)
    assert "ENVIRONMENT DESCRIPTION" in user.content and "INSTRUCTION: go left" in user.content
    assert "modified_trajectory" in text and "Instruction: Go left" in text


def test_skills_prompt_lists_the_library(simple_case: Case) -> None:
    from trajadapt.skills import SKILLS

    text = first_messages(simple_case, AXIS_CONVENTIONS["paper"])[0].content
    positions = [
        text.index(s)
        for s in ("FUNCTIONS AVAILABLE", "COORDINATE SYSTEM", "RULES", "OUTPUT FORMAT", "EXAMPLES")
    ]
    assert positions == sorted(positions)
    for function in SKILLS:
        assert f"- {function.__name__}(" in text
    assert "shift(" not in first_messages(simple_case, AXIS_CONVENTIONS["paper"], mode="paper")[0].content


def test_axes_are_stated_and_the_papers_typo_is_fixed() -> None:
    paper = system_prompt(AXIS_CONVENTIONS["paper"])
    assert "The positive X axis is left; the negative X axis is right." in paper
    assert "The positive Z axis is up; the negative Z axis is down." in paper
    assert "Negative X axis is Down" not in paper
    assert "The positive X axis is right" in system_prompt(AXIS_CONVENTIONS["ovita"])


def test_functions_section_comes_from_the_sandbox_contract() -> None:
    section = render_functions()
    for function in CONTRACT:
        assert function.signature in section


def test_fixed_prefix_is_identical_across_cases(simple_case: Case) -> None:
    other = simple_case.with_instruction("slow down near the box")
    first = first_messages(simple_case, AXIS_CONVENTIONS["paper"])
    second = first_messages(other, AXIS_CONVENTIONS["paper"])
    assert first[0] == second[0]
    assert first[1] != second[1]


def test_environment_lists_objects_description_and_constraints(simple_case: Case) -> None:
    from dataclasses import replace

    scene = replace(simple_case.scene, description="A kitchen.", constraints="Stay below z = 1.")
    user = first_messages(replace(simple_case, scene=scene), AXIS_CONVENTIONS["paper"])[1].content
    assert "- box: [0.2, 0.5, 0.5]" in user and "- Red Mug:" in user
    assert "A kitchen." in user and "Stay below z = 1." in user
    assert "20 waypoints" in user and "start [0, 0, 0.5]" in user


def test_prompt_code_calls_only_what_the_sandbox_defines() -> None:
    import ast
    import json
    import re

    from trajadapt.skills import SKILLS

    text = system_prompt(AXIS_CONVENTIONS["paper"])
    snippets = re.findall(r"-> (t = [^;\n]+)", text)
    snippets += [json.loads(line)["python_code"] for line in text.splitlines() if line.startswith('{"high')]
    assert len(snippets) >= 15
    defined = {f.__name__ for f in SKILLS} | {f.signature.split("(")[0] for f in CONTRACT} | {"len"}
    for snippet in snippets:
        calls = {n.func.id for n in ast.walk(ast.parse(snippet)) if isinstance(n, ast.Call)}
        assert calls <= defined, (snippet, calls - defined)


def test_waypoints_in_prompt_adds_every_row_after_the_fixed_prefix(simple_case: Case) -> None:
    summary = first_messages(simple_case, AXIS_CONVENTIONS["paper"])
    full = first_messages(simple_case, AXIS_CONVENTIONS["paper"], waypoints=True)
    assert full[0] == summary[0]
    rows = [line for line in full[1].content.splitlines() if line.startswith("[")]
    assert len(rows) == len(simple_case.trajectory)
    assert not any(line.startswith("[") for line in summary[1].content.splitlines())
    first = simple_case.trajectory.array[0]
    assert rows[0] == "[" + ", ".join(f"{value:.3g}" for value in first) + "]"

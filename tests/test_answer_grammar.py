"""The answer grammar: generated from the skill library, accepts what the prompt teaches, refuses the rest."""

from __future__ import annotations

import importlib.util
import json
import re

import pytest

from trajadapt.llm.answer_grammar import (
    MAX_PLAN_CHARS,
    answer_grammar,
    is_statement_skill,
    parameter_kind,
    skill_parameters,
)
from trajadapt.llm.gbnf import Grammar, Lit, Ref, Some, alt, seq
from trajadapt.model.geometry import AXIS_CONVENTIONS
from trajadapt.prompts import system_prompt
from trajadapt.skills import SKILLS

SCENE = ("box", "person", "lamp", "chair", "table", "St Bernard")


def answer(code: str, plan: str = "1) Do it.") -> str:
    """The JSON answer the prompt asks for, with ``code`` as its python_code string."""
    return json.dumps({"high_level_plan": plan, "python_code": code})


def wrapped(*steps: str) -> str:
    return answer("\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"]))


def test_every_skill_parameter_has_a_kind_and_every_trajectory_skill_a_rule() -> None:
    rules = answer_grammar(SCENE).rules
    for function in SKILLS:
        kinds = [kind for _, kind in skill_parameters(function)]
        assert kinds, function.__name__
        for kind in kinds[1:]:
            assert kind in rules, (function.__name__, kind)
        if is_statement_skill(function):
            assert f"call-{function.__name__.replace('_', '-')}" in rules
    statement_names = {f.__name__ for f in SKILLS if is_statement_skill(f)}
    assert {"shift", "move_closer", "scale_speed", "wait", "avoid"} <= statement_names
    assert not {"midpoint", "closest_waypoint", "path_size"} & statement_names


def test_an_unannotated_parameter_is_an_error_that_says_what_to_do() -> None:
    with pytest.raises(TypeError, match="ArgKind"):
        parameter_kind(dict)


def test_the_system_prompts_examples_are_in_the_grammar() -> None:
    prompt = system_prompt(AXIS_CONVENTIONS["paper"], "skills")
    examples = prompt.split("EXAMPLES:")[1].splitlines()
    examples = [line for line in examples if line.startswith('{"high_level_plan"')]
    assert len(examples) >= 4
    grammar = answer_grammar(SCENE)
    for example in examples:
        assert grammar.matches(example), example


def test_the_common_phrases_calls_are_in_the_grammar() -> None:
    prompt = system_prompt(AXIS_CONVENTIONS["paper"], "skills")
    section = prompt.split("COMMON PHRASES")[1].split("OUTPUT FORMAT")[0]
    calls = re.findall(r"t = [a-z_]+\(.*?\)(?=;|$|\n)", section, flags=re.MULTILINE)
    assert len(calls) >= 15
    grammar = answer_grammar(("X", "A", "B"))
    for call in calls:
        assert grammar.matches(wrapped(call)), call


@pytest.mark.parametrize(
    "step",
    [
        "t = move_closer(t, detect_objects('cat'))",  # not in this scene
        "t = shift(t, 'left', 'zero point two')",  # a word where a number or amount word belongs
        "t = shift(t, 'closer', 0.2)",  # not a direction
        "t = scale_speed(t, 'slow')",  # a word where a number belongs
        "t = teleport(t)",  # no such skill
        "t = shift(t, 'left', 007)",  # not a Python number
        "box = detect_objects('box')",  # a variable that later code could misspell
        "t = move_away(t, 'box')",  # a name where a position belongs
    ],
)
def test_refused(step: str) -> None:
    assert not answer_grammar(SCENE).matches(wrapped(step))


def test_a_missing_result_variable_or_first_line_is_refused() -> None:
    grammar = answer_grammar(SCENE)
    assert not grammar.matches(answer("t = get_trajectory()\nt = shift(t, 'left', 0.2)"))
    assert not grammar.matches(answer("t = shift(get_trajectory(), 'left', 0.2)\nmodified_trajectory = t"))


@pytest.mark.parametrize(
    "step",
    [
        "t = shift(t, 'left', 0.2)",
        "t = shift(t, 'up', amount='a lot')",
        "t = scale_speed(t, 0.5, near=detect_objects('St Bernard'), radius=0.3)",
        "t = set_speed(t, 0.2, part='end')",
        "t = avoid(t, [detect_objects('box'), detect_objects('lamp')], 0.3)",
        "t = pass_through(t, midpoint(detect_objects('chair'), detect_objects('table')))",
        "t = wait(t, 'goal', 5)",
        "t = stop_at(t, detect_objects('goal'))",
        "t = resample(t, 2 * len(t))",
        "t = shift_part(t, 'down', -0.1, (0.2, 0.6))",
        "t = keep_side(t, 'right', [0.5, -1.25, 0])",
        "t = speed_profile(t, 'trapezoidal', start=0.1)",
        "t = set_height(t, 0.5, keep_goal=False)",
    ],
)
def test_accepted(step: str) -> None:
    assert answer_grammar(SCENE).matches(wrapped(step))


def test_names_that_cannot_be_quoted_are_left_out_and_start_goal_are_always_there() -> None:
    grammar = answer_grammar(("Bob's mug", 'say "hi"', "cup"))
    assert grammar.matches(wrapped("t = reach(t, detect_objects('cup'))"))
    assert grammar.matches(wrapped("t = reach(t, detect_objects('start'))"))
    assert not grammar.matches(wrapped("t = reach(t, detect_objects('Bob'))"))


def test_the_plan_is_free_text_but_one_json_string() -> None:
    grammar = answer_grammar(SCENE)
    code = "t = get_trajectory()\nmodified_trajectory = t"
    assert grammar.matches(answer(code, "1) Keep it. 2) Keep it, really: [0.2] {ok}"))
    assert not grammar.matches(answer(code, 'a "quoted" plan'))  # would need an escape


def test_the_plan_is_bounded_so_a_looping_plan_still_leaves_room_for_the_code() -> None:
    grammar = answer_grammar(SCENE)
    code = "t = get_trajectory()\nmodified_trajectory = t"
    assert grammar.matches(answer(code, "x" * MAX_PLAN_CHARS))
    assert not grammar.matches(answer(code, "x" * (MAX_PLAN_CHARS + 1)))
    assert not grammar.matches(answer(code, ""))


def test_gbnf_rendering_escapes_and_groups() -> None:
    grammar = Grammar({"root": seq('say "', Ref("word"), '"\\n'), "word": Some(alt("a", "b"))})
    text = grammar.to_gbnf()
    assert text.splitlines()[0] == 'root ::= "say \\"" word "\\"\\\\n"'
    assert 'word ::= ("a" | "b")+' in text
    assert grammar.matches('say "abba"\\n') and not grammar.matches('say "abc"\\n')


def test_a_rule_that_is_not_defined_is_caught() -> None:
    with pytest.raises(ValueError, match="undefined rule 'nothing'"):
        Grammar({"root": seq(Lit("x"), Ref("nothing"))}).check()


@pytest.mark.skipif(importlib.util.find_spec("llama_cpp") is None, reason="llama-cpp-python not installed")
def test_llama_cpp_reads_the_generated_grammar() -> None:
    from llama_cpp.llama_grammar import LlamaGrammar

    LlamaGrammar.from_string(answer_grammar(SCENE).to_gbnf(), verbose=False)


def test_a_name_may_be_written_in_lower_case() -> None:
    grammar = answer_grammar(("Siberian husky",))
    assert grammar.matches(wrapped("t = move_closer(t, detect_objects('siberian husky'))"))
    assert grammar.matches(wrapped("t = move_closer(t, detect_objects('Siberian husky'))"))
    assert not grammar.matches(wrapped("t = move_closer(t, detect_objects('SIBERIAN HUSKY'))"))


def test_an_answer_has_at_most_max_steps_skill_calls() -> None:
    from trajadapt.llm.answer_grammar import MAX_STEPS

    grammar = answer_grammar(SCENE)
    step = "t = shift(t, 'left', 0.1)"
    assert grammar.matches(wrapped(*[step] * MAX_STEPS))
    assert not grammar.matches(wrapped(*[step] * (MAX_STEPS + 1)))  # a model repeating a line stops here
    assert "{0,8}" in grammar.to_gbnf()


def test_a_list_of_points_is_bounded() -> None:
    from trajadapt.llm.answer_grammar import MAX_POINTS

    def over(count: int) -> str:
        points = ", ".join(["detect_objects('box')"] * count)
        return wrapped(f"t = pass_over(t, [{points}])")

    grammar = answer_grammar(SCENE)
    assert grammar.matches(over(2)) and grammar.matches(over(MAX_POINTS))
    assert not grammar.matches(over(MAX_POINTS + 1))

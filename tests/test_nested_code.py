"""Absurdly nested generated code is refused by every host-side reader, never a RecursionError."""

import pytest

from trajadapt.code_parse import parse_code
from trajadapt.readers import READERS
from trajadapt.readers.height_asks import relate_heights
from trajadapt.readers.object_asks import replace_object_steps
from trajadapt.readers.part_scope import scope_to_parts
from trajadapt.readers.speed_scope import localize_speed
from trajadapt.readers.stated_amounts import use_stated_amounts
from trajadapt.readers.unasked_directions import replace_unasked_shifts
from trajadapt.readers.unasked_steps import leave_out_unasked
from trajadapt.readers.unstated_amounts import replace_unstated_amounts
from trajadapt.skills.explain import explain_code

NAMES = ["box"]
NESTED = ["x = " + " + ".join(["1"] * 3000), "x = " + "-" * 50000 + "1", "x = " + "[" * 300 + "]" * 300]


@pytest.mark.parametrize("code", NESTED)
def test_nested_code_is_a_syntax_error_for_the_parse(code):
    with pytest.raises(SyntaxError):
        parse_code(code)


@pytest.mark.parametrize("code", NESTED)
def test_every_reader_leaves_nested_code_as_it_is(code):
    program = f"t = get_trajectory()\nt = shift(t, 'up')\n{code}\nmodified_trajectory = t"
    asked = ["go left and slower near the box at a height of 0.1"]
    assert explain_code(program) is None
    for reader in (leave_out_unasked, replace_object_steps, replace_unasked_shifts, localize_speed):
        assert reader(program, asked, NAMES)[0] == program
    for reader in (replace_unstated_amounts, use_stated_amounts, relate_heights, scope_to_parts):
        assert reader(program, asked)[0] == program
    for stage in READERS:  # and every reader of the stage, in case one is added without a line here
        assert stage.read(program, asked, NAMES)[0] == program, stage.name


def test_ordinary_skill_code_still_parses():
    assert parse_code("t = get_trajectory()\nt = shift(t, 'left', 0.2)\nmodified_trajectory = t").body

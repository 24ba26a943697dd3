"""``code_parse.profile_kind`` and ``sole_speed_profile``: the one reading of a speed profile that the
readers share (end-places: a slowing to rest ends the path at rest; unstated-amounts: a slowing's
start; speed-profiles: a profile turned the asked way, or one pace written as a profile; speed-scope:
a profile for a pace placed at an object)."""

from __future__ import annotations

import pytest

from trajadapt.code_parse import call_of, profile_kind, sole_speed_profile


@pytest.mark.parametrize(
    ("line", "kind"),
    [
        ("t = speed_profile(t, 'decelerate', start=0.6)", "decelerate"),
        ("t = speed_profile(t, kind='accelerate')", "accelerate"),
        ("t = speed_profile(t, 'constant', 0.5, 0.7)", "constant"),
        ("t = speed_profile(t, chosen)", None),  # not a constant
        ("t = speed_profile(t)", None),
    ],
)
def test_the_kind_is_read_positionally_or_by_keyword(line: str, kind: str | None) -> None:
    found = profile_kind(call_of(line, ("speed_profile",)))
    assert (found.value if found is not None else None) == kind


def test_no_call_has_no_kind() -> None:
    assert profile_kind(call_of("t = scale_speed(t, 0.5)", ("speed_profile",))) is None


@pytest.mark.parametrize(
    ("steps", "found"),
    [
        (["t = shift(t, 'up')", "t = speed_profile(t, 'decelerate')"], (1, "decelerate")),
        (["t = speed_profile(t, 'accelerate')", "t = scale_speed(t, 0.5)"], None),  # two speed steps
        (["t = scale_speed(t, 0.5)"], None),  # no profile
        (["t = shift(t, 'up')"], None),
    ],
)
def test_the_sole_speed_step_when_it_is_a_profile(steps: list[str], found: tuple[int, str] | None) -> None:
    assert sole_speed_profile(steps) == found

"""``code_parse.profile_kind``: the one reading of a speed profile's kind that three readers share
(end-places: a slowing to rest ends the path at rest; unstated-amounts: a slowing's start; speed-profiles:
a profile turned the asked way)."""

from __future__ import annotations

import pytest

from trajadapt.code_parse import call_of, profile_kind


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

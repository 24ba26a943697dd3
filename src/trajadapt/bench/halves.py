"""The two halves of a case set: one to develop on, one to validate on.

A rule written from a failing case passes that case; whether it is a mechanism shows only on cases
nobody read. Cases are split by their index within their subset, read from the file name's last
number (OVITA numbers its released cases 0, 2, 4, ...; so index = number // 2): even indices are
the development half, odd ones the validation half. Every subset is in both halves.
"""

from __future__ import annotations

import re
from typing import Literal

Half = Literal["development", "validation"]
HALVES: tuple[Half, ...] = ("development", "validation")

_LAST_NUMBER = re.compile(r"(\d+)(?!.*\d)")


def half_of(case_key: str) -> Half:
    """The half a case belongs to, from the last number in its key ('drone/drone_trajectory_6').

    A key with no number belongs to the development half.
    """
    found = _LAST_NUMBER.search(case_key.rsplit("/", 1)[-1])
    index = int(found.group(1)) // 2 if found else 0
    return HALVES[index % 2]

"""A pace the words ask to run down to a stop, or up from rest, written as one uniform scale.

"Head toward the front and ease off until you come to a complete stop" came back as
``scale_speed(t, 0.65)``: slower everywhere, and never stopping. Slowing until a stop is a profile,
``speed_profile(t, 'decelerate', start=0.6)`` (down to 0 at the goal over the last 40%,
``paces.STOP_RAMP_START``); speeding up from rest is ``speed_profile(t, 'accelerate')``. A clause asks
the first when it asks slower and says where the slowing ends ("until you come to a complete
stop", "down to zero", "till the speed reaches 0", "to a standstill"), the second when it asks
faster from a standstill ("from rest", "from zero"), said in the clause or the one before it;
words that name a scene object ("slow down until you stop at the box") give a place, not a
profile, and are left to the other readers; a clause that comes to a stop with no word of slowing
("glide to a halt at the end"; not refused, not a stop on the way) asks the first too. The one speed
step that scales or sets the speed of the whole path (no ``near=``, no ``part=``) becomes the
profile; for a slowing, so does one of the closing part alone (``part='end'``, ``'second half'``),
the profile starting where that part starts. A profile that goes the other way
from the pace the words ask ("reduce the speed evenly as you come to the goal" answered with
'constant' or 'accelerate') is turned to the asked one. And the other way: a slowing or speeding
profile as the one speed step, where the one pace clause names no object, no part or end of the path,
no stop or start from rest and nothing gradual ("run the route roughly 30% slower overall"), runs
the robot down to a stop nobody asked for: it becomes ``scale_speed`` of the clause's factor. A review
note says what changed.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterable

from trajadapt.code_parse import call_of, in_place_of, profile_kind, sole_speed_profile
from trajadapt.model.geometry import PART_WORDS
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.paces import (
    STOP_RAMP_START,
    asked_factor,
    closing_share_start,
    part_said_for_the_pace,
)
from trajadapt.readers.stop_words import AT_REST, COMING_TO_REST
from trajadapt.readers.words import FASTER, NEGATED, PART_OR_END, SLOWER, asks_pace, names_in, part_named

TO_A_STOP = re.compile(
    rf"{COMING_TO_REST.pattern}"
    r"|\b(?:(?:down\s+)?to\s+(?:zero|0(?![.\d]))(?:\s+speed)?"
    r"|(?:speed|velocity|pace)\s+(?:reaches|hits|becomes|is)\s+(?:zero|0(?![.\d])))\b",
    re.I,
)
"""Where a slowing ends: at a stop."""
ON_THE_WAY = re.compile(
    r"\b(?:halfway|midway|middle|for\s+(?:\d+|a\s+few|a\s+couple|some|a\s+while|a\s+moment)"
    r"|then\s+(?:carry|continu|go|mov|resum|head)\w*)",
    re.I,
)
"""A stop on the way, not at the end: a place or a length of the pause, or going on after it."""
FROM_REST = re.compile(r"\bfrom\s+(?:a\s+)?(?:standstill|rest|zero|0|stop|stationary)\b", re.I)
"""Where a speeding up begins: at rest."""
UNIFORM_STEPS = ("scale_speed", "set_speed")
EVEN_PACE = re.compile(
    r"\b(?:constant|steady|uniform|same|unchanging|fixed)\s+(?:\w+\s+)?(?:speed|pace|velocity)", re.I
)
"""Words of an even speed: a 'constant' profile is what they ask."""
CHANGING_PACE = re.compile(
    r"\b(?:gradual\w*|progressive\w*|steadily|increasing\w*|ramp\w*|more\s+and\s+more|decelerat\w*"
    r"|accelerat\w*|as\s+(?:it|you)\s+go(?:es)?|in\s+steps|step\s+by\s+step|stepwise)\b",
    re.I,
)
"""Words of a pace that changes along the path: a profile may be what they ask."""


def asked_profile(words: str, names: Iterable[str]) -> str | None:
    """'decelerate' or 'accelerate' when a clause of ``words`` asks one (see the module), else None."""
    names = list(names)
    asked = set()
    clauses = split_clauses(words, names)
    for before, clause, after in zip(("", *clauses), clauses, (*clauses[1:], ""), strict=False):
        # "start from a standstill and speed up", "slow down gradually and come to a full stop at the
        # end": where the pace starts or ends may be said in the clause next to it
        said = " ".join(c for c in (before, clause, after) if not names_in(c, names))
        if names_in(clause, names):
            continue
        if (SLOWER.search(clause) and TO_A_STOP.search(said)) or _stops_at_the_end(clause):
            asked.add("decelerate")  # "slow down ... to a full stop", "glide to a halt at the end"
        elif FASTER.search(clause) and FROM_REST.search(said):
            asked.add("accelerate")
    return asked.pop() if len(asked) == 1 else None


def _stops_at_the_end(clause: str) -> bool:
    """Whether a clause comes to a stop with no word of slowing ("glide to a halt at the end").

    Not a stop refused ("never come to a halt") or one on the way ("halfway, stop for 5 steps").
    """
    said = TO_A_STOP.search(clause) and not FASTER.search(clause)
    return bool(said) and not NEGATED.search(clause) and not ON_THE_WAY.search(clause)


def profile_paces(code: str, asked: Iterable[str], names: Iterable[str]) -> tuple[str, list[str]]:
    """``code`` with its one whole-path speed step made the asked profile (see the module)."""
    words, names = " ".join(asked), list(names)
    code, notes = _profiles_the_right_way(code, words)
    code, notes = _one_scale_where_no_profile_is_said(code, words, names, notes)
    profile = asked_profile(words, names)
    lines = code.splitlines()
    closing = {i: low for i, line in enumerate(lines) if (low := _closing_part_pace(line)) is not None}
    uniform = [i for i, line in enumerate(lines) if _whole_path_pace(line)]
    uniform += list(closing) if profile == "decelerate" else []
    if profile is None or len(uniform) != 1:
        return code, notes
    index = uniform[0]
    call = call_of(lines[index], UNIFORM_STEPS)
    assert call is not None  # found by _whole_path_pace or _closing_part_pace
    ramp = closing_share_start(words) or closing.get(index, STOP_RAMP_START)
    start = f", start={ramp:g}" if profile == "decelerate" else ""
    target, trajectory = lines[index].split("=")[0].strip(), ast.unparse(call.args[0])
    step = f"{target} = speed_profile({trajectory}, {profile!r}{start})"
    ends = "runs down to a stop" if profile == "decelerate" else "starts from rest"
    note = f"`{lines[index].strip()}` -> `{step}`: the words ask a pace that {ends}, not one scale"
    lines[index] = in_place_of(lines[index], step)
    return "\n".join(lines), [*notes, note]


def _one_scale_where_no_profile_is_said(
    code: str, words: str, names: list[str], notes: list[str]
) -> tuple[str, list[str]]:
    """``code`` with its one slowing or speeding profile as a scale where the words ask none."""
    pacing = [c for c in split_clauses(words, names) if asks_pace(c)]
    lines = code.splitlines()
    profile = sole_speed_profile(lines)
    if len(pacing) != 1 or profile is None or not _asks_one_scale(pacing[0], names):
        return code, notes
    if part_said_for_the_pace(pacing[0], words, names):
        return code, notes
    (clause,), (index, kind) = pacing, profile
    faster = bool(FASTER.search(clause))
    if kind != ("accelerate" if faster else "decelerate"):
        return code, notes
    factor = asked_factor(clause, faster)
    variable = lines[index].split("=")[0].strip()
    step = f"{variable} = scale_speed({variable}, {factor:g})"
    note = f"`{lines[index].strip()}` -> `{step}`: the words ask one pace ({clause.strip()!r}), no profile"
    lines[index] = in_place_of(lines[index], step)
    return "\n".join(lines), [*notes, note]


def _asks_one_scale(clause: str, names: list[str]) -> bool:
    """Whether a pace clause asks only faster or only slower, of the whole path, with nothing changing."""
    if bool(FASTER.search(clause)) == bool(SLOWER.search(clause)) or names_in(clause, names):
        return False
    said = (PART_OR_END, TO_A_STOP, FROM_REST, AT_REST, CHANGING_PACE)
    return part_named(clause) is None and not any(pattern.search(clause) for pattern in said)


def _profiles_the_right_way(code: str, words: str) -> tuple[str, list[str]]:
    """``code`` with a profile that goes the other way from the asked pace turned ('constant' too).

    "As you come to the goal, reduce the speed evenly" came back as ``speed_profile(t, 'constant',
    start=0.7)``, which speeds the end up to the path's top speed. Words that ask only slower make a
    profile 'decelerate', only faster 'accelerate'; words of an even speed ("constant", "steady",
    "uniform speed") keep 'constant', and words of a stop keep 'decelerate' (a slowing to rest at the
    end is no pace of the path: "speed up the opening part and end fully stopped at the crib"). A
    slowing turned so begins where the closing share the words name begins ("over the last third").
    """
    slower, faster = bool(SLOWER.search(words)), bool(FASTER.search(words))
    if slower == faster:
        return code, []
    wanted = "decelerate" if slower else "accelerate"
    lines, notes = code.splitlines(), []
    for index, line in enumerate(lines):
        call = call_of(line, ("speed_profile",))
        kind = profile_kind(call)
        if call is None or kind is None or kind.value in (wanted, "trapezoidal"):
            continue
        if kind.value == "constant" and EVEN_PACE.search(words):
            continue
        if kind.value == "decelerate" and AT_REST.search(words):
            continue  # "speed up the opening part ... end right at the crib, fully stopped there"
        kind.value = wanted
        begins = closing_share_start(words)
        if wanted == "decelerate" and begins is not None and _start_of(call) is None:
            call.keywords.append(ast.keyword("start", ast.Constant(begins)))
        step = f"{line.split('=')[0].strip()} = {ast.unparse(call)}"
        notes.append(f"`{line.strip()}` -> `{step}`: the words ask a {'slower' if slower else 'faster'} pace")
        lines[index] = in_place_of(line, step)
    return "\n".join(lines), notes


def _start_of(call: ast.Call) -> ast.expr | None:
    """Where a profile step was told to begin (its fourth argument or ``start=``), if it was."""
    given = call.args[3:4] + [k.value for k in call.keywords if k.arg == "start"]
    return given[0] if given else None


def _closing_part_pace(line: str) -> float | None:
    """Where a closing part begins (``part='end'``: 0.7), for a speed step of that part alone, else None.

    A slowing to a stop written as a scale of the closing part is the profile from that share.
    """
    call = call_of(line, UNIFORM_STEPS)
    if call is None or len(call.args) > 2 or [k.arg for k in call.keywords] != ["part"]:
        return None
    part = call.keywords[0].value
    bounds = PART_WORDS.get(str(part.value).strip().lower()) if isinstance(part, ast.Constant) else None
    return bounds[0] if bounds is not None and bounds[0] > 0 and bounds[1] == 1.0 else None


def _whole_path_pace(line: str) -> bool:
    """Whether ``line`` scales or sets the speed of the whole path (no place, no part)."""
    call = call_of(line, UNIFORM_STEPS)
    return call is not None and len(call.args) <= 2 and not call.keywords

"""What a measured effect contradicts in the user's words, read clause by clause as the readers read them.

The words are read in the readers' form (``request_words``: negated comparisons said as what they
ask, sentences that only say how the path is now left out) and split by the product's one splitter
(``split_clauses``), so that each flag reads the clause it is about:

- an object a clause asks something of (``object_asks``: closer, further, a pace near it; "avoid" it
  or "steer clear of" it counts as further here): the distance near it (the mean over the share of
  waypoints nearest it, as the speed near it is read) or the speed near it went the other way (read
  only where the path near it stayed: else the waypoints nearest it are others), or, where the
  clause names no part of the path, neither changed at all, or a distance asked did not change;
- a clause that asks a pace of the whole path (no object, no part named): the mean speed went the
  other way;
- a clause that asks the path to move one way (``asked_move``: no place word, no part, no negation,
  no object to come closer to or keep away from): the path moved the other way on average;
- an end the words keep where it is ("keeping the start and end positions the same", "without
  moving the endpoints"): it moved.

An object a clause only names ("pass through the middle of the banana and the glue") asks nothing
that can be checked here, and is not flagged.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

import numpy as np

from trajadapt.checks.effect import NOTICEABLE, Effect, ObjectEffect
from trajadapt.model.geometry import OPPOSITE_DIRECTIONS, Axes
from trajadapt.readers.asked_directions import asked_move
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.end_words import kept_ends
from trajadapt.readers.object_words import ObjectAsk, object_asks
from trajadapt.readers.request_words import request_words
from trajadapt.readers.words import (
    FASTER,
    MINIMUM_DISTANCE,
    PART_OR_END,
    PLACE_WORDS,
    SLOWER,
    asks_distance,
    asks_pace,
    longest_names,
    names_in,
)

AVOIDED = re.compile(r"\b(?:avoid\w*|clear of)\b", re.I)
"""Words that ask a clearance: the flags read them as asking away (the readers leave them to ``avoid``)."""
NOT_ASKED = re.compile(r"\b(?:not|never|no|don't|doesn't|without)\b|n't\b|\bthan\s+(?:\d|\.\d)", re.I)
"""A negation or a limit: "don't slow down", "never faster than 0.3" ask no change of pace (the plain
form leaves them as said)."""
SPEED_NOISE = 1e-3
"""A share of the speed before: a smaller change of a mean speed is no change."""


def contradictions(asked: str | Sequence[str], effect: Effect, axes: Axes | None = None) -> list[str]:
    """What the measured effect contradicts in the user's words (the instruction, then each feedback).

    [] where nothing the words ask can be checked, or nothing is contradicted.
    """
    names = [obj.name for obj in effect.objects]
    said = [asked] if isinstance(asked, str) else list(asked)
    requests = [request_words(text, names) for text in said]
    words = ". ".join(requests)
    clauses = split_clauses(words, names)
    asks = _asks(words, clauses, names)
    noticeable = NOTICEABLE * effect.size
    flags = _whole_path_pace_flags(clauses, names, effect)
    for obj in effect.objects:
        if obj.name in asks:
            flags += _object_flags(asks[obj.name], obj, noticeable)
    return (
        flags
        + _direction_flags(clauses, effect, noticeable, axes or Axes())
        + _kept_end_flags(requests, effect, noticeable)
    )


def _asks(words: str, clauses: Sequence[str], names: list[str]) -> dict[str, ObjectAsk]:
    """What the clauses ask of each object, with a clearance ("avoid the box") as keeping away."""
    asks = object_asks(words, names)
    for clause in clauses:
        named = longest_names(names_in(clause, names))
        if len(named) == 1 and named[0] not in asks and AVOIDED.search(clause):
            asks[named[0]] = ObjectAsk(named[0], "away", clause)
    return asks


def _whole_path_pace_flags(clauses: Sequence[str], names: list[str], effect: Effect) -> list[str]:
    """A pace asked of the whole path that the mean speed does not follow."""
    wanted = {
        "slower" if SLOWER.search(clause) else "faster"
        for clause in clauses
        if asks_pace(clause)
        and bool(SLOWER.search(clause)) != bool(FASTER.search(clause))
        and not names_in(clause, names)
        and not (PART_OR_END.search(clause) or PLACE_WORDS.search(clause) or NOT_ASKED.search(clause))
    }
    if len(wanted) != 1:
        return []
    change = effect.speed_after - effect.speed_before
    if not _against(wanted.pop(), change, SPEED_NOISE * max(effect.speed_before, 1e-9)):
        return []
    way = "rose" if change > 0 else "fell"
    return [
        f"the instruction asks for {'slower' if change > 0 else 'faster'}, but the mean speed {way} "
        f"({effect.speed_before:.3g} -> {effect.speed_after:.3g})"
    ]


def _against(wanted: str, change: float, noise: float) -> bool:
    """Whether a change beyond ``noise`` goes the other way from 'slower'/'faster' (or 'closer'/'away')."""
    return change > noise if wanted in ("slower", "closer") else change < -noise


def _object_flags(ask: ObjectAsk, obj: ObjectEffect, noticeable: float) -> list[str]:
    """What the effect on one object contradicts in what a clause asks of it."""
    if ask.relation == "side" or (ask.relation in ("slower", "faster") and NOT_ASKED.search(ask.clause)):
        return []
    distance = obj.near_after - obj.near_before
    speed = obj.speed_near_after - obj.speed_near_before
    speed_noise = SPEED_NOISE * max(obj.speed_near_before, 1e-9)
    distances = f"({obj.near_before:.3g} -> {obj.near_after:.3g})"
    moved = max(abs(distance), abs(obj.closest_after - obj.closest_before)) > noticeable
    may_hold = bool(MINIMUM_DISTANCE.search(ask.clause) or AVOIDED.search(ask.clause))  # already clear?
    checkable = not PART_OR_END.search(ask.clause) and not may_hold
    if checkable and not moved and abs(speed) <= speed_noise:
        return [f"the instruction names the {obj.name}, but neither the distance to it {distances} "
                "nor the speed near it changed"]  # fmt: skip
    if ask.relation in ("closer", "away"):
        asked, went = ("get closer to", "grew") if ask.relation == "closer" else ("keep away from", "shrank")
        said = f"the instruction asks to {asked} the {obj.name}"
        if _against(ask.relation, distance, noticeable):
            return [f"{said}, but the distance near it {went} {distances}"]
        if checkable and abs(distance) <= noticeable:  # near it, where the distance is asked
            return [f"{said}, but the distance near it did not change {distances}"]
    stayed = abs(distance) <= noticeable  # else the waypoints nearest it are others: speeds do not compare
    if ask.relation in ("slower", "faster") and stayed and _against(ask.relation, speed, speed_noise):
        speeds = f"({obj.speed_near_before:.3g} -> {obj.speed_near_after:.3g})"
        return [f"the instruction asks for {ask.relation} near the {obj.name}, but the speed near it "
                f"{'rose' if speed > 0 else 'fell'} {speeds}"]  # fmt: skip
    return []


def _direction_flags(clauses: Sequence[str], effect: Effect, noticeable: float, axes: Axes) -> list[str]:
    """A direction a clause asks the whole path to move in, while it moved the other way on average."""
    asked = {move for clause in clauses if not asks_distance(clause) and (move := asked_move(clause))}
    flags = []
    for direction in sorted(d for d in asked if OPPOSITE_DIRECTIONS[d] not in asked):
        along = float(np.asarray(effect.mean_shift) @ axes.vector(direction))
        if along < -noticeable:
            went = effect.mean_shift_direction
            flags.append(f"the instruction says {direction}, but the path moved {went} on average")
    return flags


def _kept_end_flags(requests: Sequence[str], effect: Effect, noticeable: float) -> list[str]:
    """An end of the path the words keep where it is ("keep the start and end fixed"), moved.

    A later request that names the end ("now move the goal left") takes the keeping back.
    """
    kept = kept_ends(requests)
    moves = {
        "start": (effect.start_moved, effect.start_direction),
        "goal": (effect.goal_moved, effect.goal_direction),
    }
    return [
        f"the words keep the {end} where it is, but it moved {moves[end][0]:.3g} {moves[end][1]}"
        for end in ("start", "goal")
        if end in kept and moves[end][0] > noticeable
    ]

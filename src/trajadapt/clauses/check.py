"""One clause's step checked against that clause's words, by what it measurably does.

Each clause's lines run alone on the original path (a few milliseconds in the sandbox) and the
effect is measured (``effect.measure_effect``). Read against one clause, the words say one kind of
thing far more often than a whole instruction does, so a contradiction is clear: the effect report's
own flags (slower asked, the speed rose; an object named that neither the distance to nor the speed
near changed; "left" asked, the path went right), and two of kind:

- a clause that asks only for a pace ("take it slower by the lamp") whose step moved the path;
- a clause that asks only where the path goes, towards a direction or an object ("keep 0.2 from
  the marmoset"), whose step changed only the speed.
"""

from __future__ import annotations

import numpy as np

from trajadapt.checks.contradictions import contradictions
from trajadapt.checks.effect import NOTICEABLE, Effect
from trajadapt.model.geometry import Axes
from trajadapt.readers.direction_words import asked_kinds, said_directions
from trajadapt.readers.words import asks_distance, names_in


def clause_findings(clause: str, effect: Effect, axes: Axes) -> list[str]:
    """What the step's measured effect contradicts in the clause's words; [] when nothing."""
    flags = contradictions(clause, effect, axes)
    findings = list(flags)
    kinds = asked_kinds(clause)
    pace, place = "pace" in kinds, "place" in kinds
    moved = effect.largest_displacement > NOTICEABLE * effect.size
    speed_changed = abs(effect.speed_after - effect.speed_before) > 1e-6 * max(effect.speed_before, 1.0)
    if pace and not place and moved:
        findings.append(
            f"the step moved the path (by up to {effect.largest_displacement:.3g}), but these words ask "
            "only for a change of speed"
        )
    concrete = bool(said_directions(clause) or names_in(clause, [obj.name for obj in effect.objects]))
    if place and concrete and not pace and speed_changed and not moved:
        findings.append(
            "the step changed only the speed, but these words ask where the path goes, not how fast"
        )
    return findings + _not_moved_as_said(clause, effect, axes, _of_sign(flags))


def _not_moved_as_said(clause: str, effect: Effect, axes: Axes, moved_the_other_way: bool) -> list[str]:
    """One direction said, no object to go closer to or away from, and nothing moved that way.

    ``moved_the_other_way``: the effect report already flags a move against the words.
    """
    said = said_directions(clause)
    if len(said) != 1 or asks_distance(clause) or moved_the_other_way:
        return []
    (direction,) = said
    noticeable = NOTICEABLE * effect.size
    along = float(np.asarray(effect.mean_shift) @ axes.vector(direction))
    ends = [moved for moved, way in ((effect.start_moved, effect.start_direction),
            (effect.goal_moved, effect.goal_direction)) if direction in way]  # fmt: skip
    if along > noticeable / 2 or any(moved > noticeable for moved in ends):
        return []
    return [f"the words say {direction}, but the step moved the path {along:.3g} {direction} on average"]


def _of_sign(flags: list[str]) -> bool:
    """Whether the effect report's flags (``contradictions``) hold a move the other way."""
    return any("says" in flag for flag in flags)

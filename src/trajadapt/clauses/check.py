"""One clause's step checked against that clause's words, by what it measurably does.

Each clause's lines run alone on the original path (a few milliseconds in the sandbox) and the
effect is measured (``effect.measure_effect``). Read against one clause, the words say one kind of
thing far more often than a whole instruction does, so a contradiction is clear: the effect report's
own flags (slower asked, the speed rose; an object named that neither the distance to nor the speed
near changed; "left" asked, the path went right), and two of kind:

- a clause that asks only for a pace ("take it slower by the lamp") whose step moved the path;
- a clause that asks only where the path goes ("keep 0.2 from the marmoset") whose step changed
  only the speed.
"""

from __future__ import annotations

import re

from trajadapt.effect import NOTICEABLE, Effect, contradictions
from trajadapt.geometry import Axes
from trajadapt.wording import SPEED_WORDS, said_directions

PLACE_WORDS = re.compile(
    r"\b(?:distance|clear|avoid|away|reach|pass|through|between|around|circle|spiral|loop|extend|continu"
    r"|further|farther|closer|nearer|approach|shift|curv|bend|arc|zig|weav|smooth|height|altitude|above"
    r"|below|over|under|rotat|turn|tilt|scale|waypoint|side|towards?|hug|bow|offset)\w*",
    re.I,
)
"""Word stems that ask where the path goes (its place or shape), not how fast."""


def clause_findings(clause: str, effect: Effect, axes: Axes) -> list[str]:
    """What the step's measured effect contradicts in the clause's words; [] when nothing."""
    findings = contradictions(clause, effect, axes)
    pace = bool(SPEED_WORDS.search(clause))
    place = bool(PLACE_WORDS.search(clause) or said_directions(clause))
    moved = effect.largest_displacement > NOTICEABLE * effect.size
    speed_changed = abs(effect.speed_after - effect.speed_before) > 1e-6 * max(effect.speed_before, 1.0)
    if pace and not place and moved:
        findings.append(
            f"the step moved the path (by up to {effect.largest_displacement:.3g}), but these words ask "
            "only for a change of speed"
        )
    if place and not pace and speed_changed and not moved:
        findings.append(
            "the step changed only the speed, but these words ask where the path goes, not how fast"
        )
    return findings

"""Words of coming to rest, one vocabulary for every reader that reads a stop.

The readers of paces (a stop at the end runs the speed down), profiles (a slowing that ends at a
stop), pauses (a stop that ends the path) and unasked steps (a ``stop_at`` the words ask) read a
stop in the same words, so that a new way of saying it ("bring it to rest", "glide to a halt") is
learnt once.
"""

from __future__ import annotations

import re

COMING_TO_REST = re.compile(
    r"\b(?:(?:to|into|until|till)\s+(?:you\s+|it\s+)?(?:comes?\s+to\s+|reach(?:es)?\s+|gets?\s+to\s+)?"
    r"(?:a\s+|an\s+)?(?:(?!the\b)\w+\s+)?(?:stop|standstill|halt)\b"
    r"|(?:com(?:e|es|ing)|came|bring\w*|brought|get\w*|got|settl\w*)\s+(?:\w+\s+){0,3}?to\s+(?:a\s+(?:\w+\s+)?)?rest\b(?!\s+(?:area|stop|room|of)\b)"
    r"|(?:until|till)\s+the\s+\w+\s+(?:comes?\s+to|reach(?:es)?|gets?\s+to)\s+(?:a\s+)?(?:\w+\s+)?(?:stop|standstill|halt)\b"
    r"|until\s+(?:it|you|the\s+\w+)\s+(?:stops|halts)"
    r"|\b(?:end|ends|ending|ended|finish\w*)\s+(?:at|in|with)\s+(?:a\s+)?(?:(?!the\b)\w+\s+)?(?:stop|standstill|halt)\b"
    r"|\b(?:(?:speed|velocity|pace)\s+(?:\w+\s+){0,2}?down|slow\w*(?:\s+\w+){0,2}?|decelerat\w*)\s+to\s+(?:zero|nothing"
    r"|0(?![.\d]))\b)",
    re.I,
)
"""Words that end a motion at rest: "to a stop", "roll to a gradual stop", "glide to a halt", "to a
standstill", "until it stops", "come to rest", "come to a complete rest", "bring it to rest", "ends
at a full stop", "ease the speed down to zero", "slow it to 0" (one vocabulary for every reader that
reads a stop: the readers of paces, profiles, pauses and unasked steps)."""
STOPPING = re.compile(
    rf"{COMING_TO_REST.pattern}|\b(?:stop\w*|halt\w*|standstill|stand\w*\s+still|at\s+rest\b|motionless"
    r"|stationary|terminat\w*)",
    re.I,
)
"""Any word of stopping: the words that end a motion at rest, and "stop", "halt", "stand still"."""
DOWN_TO_REST = re.compile(rf"\bdown\b(?=(?:\s+\w+){{0,2}}?\s+(?:{COMING_TO_REST.pattern}))", re.I)
"""A "down" that runs to a stop ("coast down gradually to a standstill", "wind down to a halt"): a
pace's particle, no direction."""
ENDING_THERE = re.compile(
    rf"{STOPPING.pattern}|\b(?:end\w*|finish\w*|arriv\w*|land\w*|park\w*|destination|goal)\b", re.I
)
"""Words that may end the path at a place: a stop, "end", "finish", "arrive", "land", "park"."""
AT_REST = re.compile(
    rf"{COMING_TO_REST.pattern}|\b(?:stop(?:s|ped|ping)?|halt(?:s|ed|ing)?|standstill|stand\w*\s+still|at\s+rest"
    r"|motionless|stationary|still\s+there)\b|\bnot\s+moving\b(?!\s+(?:the|its|it|either|both)\b)",
    re.I,
)
"""Words that leave the robot at rest where it ends: a word of stopping, "not moving", "still there"."""

COUNT = re.compile(
    r"\b(\d+|[a-z]+)\s+(?:of\s+)?(?:time\s*)?steps?\b"
    r"|\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten|twelve|fifteen|twenty|(?<=a\s)couple"
    r"|(?<=a\s)few)\s+(?:of\s+)?(?:waypoints?|beats?|ticks?)\b",
    re.I,
)
"""A count of timesteps: "10 timesteps", "five time steps", "7 steps", "a few steps", "a couple of steps",
"3 waypoints", "a couple of waypoints" (not "the middle waypoint": a place), "a couple of beats"."""

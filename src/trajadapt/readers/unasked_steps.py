"""Steps nobody asked for: found in skills code and left out before the user reviews the plan.

A small model adds steps the instruction does not ask for: ``t = extend(t, 10.0)`` appended to
"pass much further away from the sandal" moved the path ten times the scene's size, and
``set_speed(t, 0.6)`` was added to "drive a lot closer to the stop watch". Each guarded skill
belongs to a topic; a topic is asked for when the user's words (the instruction and any feedback)
contain one of its word stems. A line ``t = <skill>(t, ...)`` whose topic is not asked for is left
out (it maps the trajectory to a new one, so leaving it out is the identity for that step) and a
review note says so. Skills that change the shape of the path are never left out: almost every
instruction asks for a change of shape in some words, with one exception: in an instruction about
speed, "near the box" says where the speed changes, so a step that moves the path closer to or
away from an object is left out unless the words also ask for a change of distance ("closer",
"away", "avoid", ...). Measured on stored answers in docs/benchmarks.md.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from dataclasses import dataclass

from trajadapt.model.scene import without_names
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.stop_words import COMING_TO_REST, STOPPING
from trajadapt.readers.words import (
    GOES_FURTHER,
    MINIMUM_DISTANCE,
    PAST_THE_GOAL,
    asks_distance,
    asks_pace,
    asks_visit,
)


@dataclass(frozen=True)
class Topic:
    """A kind of change, the skills that make it, and the word stems that ask for it."""

    name: str
    skills: tuple[str, ...]
    stems: tuple[str, ...]
    only_with: str | None = None  # guarded only when this other topic is asked for
    also: Callable[[str], bool] | None = None  # the shared vocabulary's reading of the same topic
    otherwise: re.Pattern[str] | None = None  # the topic's stems said of something else


TOPICS = (
    Topic(
        "a speed change",
        ("scale_speed", "set_speed", "speed_profile"),
        (
            "speed",
            "fast",
            "slow",
            "quick",
            "velocit",
            "pace",
            "hurr",
            "accelerat",
            "decelerat",
            "brak",
            "rush",
            "crawl",
            "rapid",
            "swift",
            "leisure",
            "stop",
            "time",
            "tempo",
            "sprint",
            "dash",
            "gentl",
            "careful",
            "steady",
            "cruis",
            "constant",
            "uniform",
        ),
        also=lambda words: asks_pace(words) or COMING_TO_REST.search(words) is not None,
        # "ease off", "take it easy", "reduce your speed", "glide to a halt": the readers' one vocabulary
    ),  # fmt: skip
    Topic(
        "going on past the goal",
        ("extend", "append_segment"),
        (
            "extend",
            "continu",
            "beyond",
            "past",
            "after",
            "then",
            "carry on",
            "go on",
            "keep going",
            "keep moving",
            "keep travel",
            "onward",
            "longer",
            "straight to",
            "proceed",
            "lengthen",
            "reach",
            "finally",
            "next",
        ),
        also=lambda words: bool(
            PAST_THE_GOAL.search(words) or GOES_FURTHER.search(words)
        ),  # "once at the end"
    ),  # fmt: skip
    Topic(
        "a pause",
        ("wait",),
        (
            "wait",
            "pause",
            "stop",
            "halt",
            "hold",
            "rest",
            "timestep",
            "step",
            "linger",
            "stay for",
            "break",
            "still",
            "freeze",
            "dwell",
            "second",
            "hover",
            "idl",
            "hang",
            "standstill",
        ),
    ),  # fmt: skip
    Topic(
        "stopping early",
        ("stop_at",),
        ("stop", "halt", "end", "finish", "arriv", "terminat", "until"),
        also=lambda words: STOPPING.search(words) is not None,  # "bring it to rest at the lamp"
    ),
    Topic(
        "a loop",
        ("spiral", "circle_around"),
        ("spiral", "circl", "loop", "revolv", "orbit", "around", "round", "turn", "swirl", "helix", "rotat"),
    ),  # fmt: skip
    Topic(
        "a new number of waypoints",
        ("resample",),
        (
            "waypoint",
            "point",
            "sampl",
            "resolution",
            "dens",
            "sparse",
            "fewer",
            "interpolat",
            "smooth",
            "granular",
            "step",
        ),
        otherwise=re.compile(
            r"\bfor\s+(?:about\s+|around\s+)?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten|a\s+few"
            r"|a\s+couple\s+of|several)\s+(?:more\s+)?(?:way)?points?\b"
        ),  # "hover next to it for three waypoints": a pause's length, no number of waypoints
    ),  # fmt: skip
    Topic("noise", ("add_noise",), ("nois", "random", "jitter", "perturb", "stochastic", "shak", "robust")),
    Topic(
        "a change of distance to an object",
        ("move_away", "move_closer", "avoid"),
        (
            "away",
            "closer",
            "nearer",
            "further",
            "farther",
            "distan",
            "approach",
            "avoid",
            "clear",
            "apart",
            "gap",
            "margin",
            "toward",
            "collid",
            "hit",
            "touch",
            "keep",
            "stay",
            "reach",
            "go to",
            "move to",
            "through",
            "far",
        ),
        only_with="a speed change",
        also=lambda words: (
            asks_distance(words)
            or MINIMUM_DISTANCE.search(words) is not None
            or any(asks_visit(c) for c in split_clauses(words))
        ),
        # "a wider berth", "a tighter gap", "swing by the lamp", "don't come within 0.8 of": the
        # readers' one vocabulary
    ),  # fmt: skip
)
STATEMENT = re.compile(r"^\s*([A-Za-z_]\w*)\s*=\s*([A-Za-z_]\w*)\(\s*([A-Za-z_]\w*)\s*[,)]")
MULTIPLIER = re.compile(
    r"\b(?:\d+(?:\.\d+)?|one|two|three|four|five|six|seven|eight|nine|ten|many)\s+times\b", re.I
)
"""A count of times ("by two times", "3 times further"): how much, not the "time" of a speed."""
PERIOD = re.compile(
    r"\b(?:every|each|per|once\s+(?:per|every))\s+(?:block\s+of\s+)?(?:\d+|two|three|four|five|six|seven|eight"
    r"|nine|ten|few)\s+(?:way)?points?\b",
    re.I,
)
"""How often along the path ("every 4 waypoints"): where a change repeats, not a number of waypoints."""


def asks_for(topic: Topic, words: str) -> bool:
    """Whether ``words`` contain a stem of ``topic`` at the start of a word.

    "Two times" is no time, "every 4 waypoints" asks no number of waypoints, and neither does a pause
    "for 3 waypoints" (the topic's ``otherwise``).
    """
    lowered = PERIOD.sub(" ", MULTIPLIER.sub(" ", words.lower()))
    if topic.otherwise is not None:
        lowered = topic.otherwise.sub(" ", lowered)
    if topic.also is not None and topic.also(words):
        return True
    return any(re.search(r"\b" + re.escape(stem), lowered) for stem in topic.stems)


def topic_of(skill: str) -> Topic | None:
    """The guarded topic a skill belongs to, if any."""
    return next((topic for topic in TOPICS if skill in topic.skills), None)


def guarded(topic: Topic, words: str) -> bool:
    """Whether ``topic``'s steps may be left out for these words (its ``only_with`` topic is asked)."""
    if topic.only_with is None:
        return True
    return any(other.name == topic.only_with and asks_for(other, words) for other in TOPICS)


def leave_out_unasked(
    code: str, asked: Iterable[str], object_names: Iterable[str] = ()
) -> tuple[str, list[str]]:
    """``code`` without the steps of a topic no ``asked`` text mentions, and a note per step left out.

    Object names are not read as words ("stop watch" does not ask to stop), and only whole words are
    names (the object "ear" leaves "nearer" as it is). Only lines of the form
    ``t = skill(t, ...)`` (the same variable in and out) are left out.
    """
    words = without_names(" ".join(asked), object_names)
    kept, notes = [], []
    for line in code.splitlines():
        match = STATEMENT.match(line)
        topic = topic_of(match.group(2)) if match and match.group(1) == match.group(3) else None
        if topic is not None and guarded(topic, words) and not asks_for(topic, words):
            notes.append(f"left out `{line.strip()}`: the instruction does not ask for {topic.name}")
            continue
        kept.append(line)
    return "\n".join(kept), notes

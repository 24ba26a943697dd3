"""How the user's words are read without a model: speed words, places, numbers, object names.

Every reader of the answer (``trajadapt.readers``), the clearance's exemptions
(``checks.constraints``) and the effect's flags (``checks.effect``) read instructions with these
helpers, so that one number reading and one vocabulary serve them all; the clauses they read come
from the one splitter, ``readers.clause_split``. The directions the words ask are read in
``readers.direction_words``.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from trajadapt.model.geometry import PART_WORDS
from trajadapt.skills.core import AMOUNT_WORDS, NUMBER

NUMBER_TEXT = r"(?:\d+\.?\d*|\.\d+)"
"""A number as the user writes it ("2", "0.2", ".5"); readers put it in their own phrases."""

PLACE_WORDS = re.compile(
    r"\b(?:near\w*|close|closer|proximity|vicinity|surround\w*|pass\w*|around|within|next to|beside"
    r"|(?<!are\s)(?<!is\s)(?<!once\s)(?<!been\s)past|approach\w*|by the|when|while|as you)\b",
    re.I,
)
"""Words that say where along the path something happens ("near the lamp", "while passing")."""

SPEED_WORDS = re.compile(r"\b(?:fast|slow|quick|speed|velocit|pace|hurr|rapid|swift|brisk|leisure)", re.I)
"""Word stems that make a clause about speed."""

PATH_WORDS = re.compile(
    r"\b(?:distance|clear|avoid|away|reach|pass|through|between|around|circle|spiral|loop|extend|continu"
    r"|further|farther|closer|nearer|approach|shift|curv|bend|arc|zig|weav|smooth|height|altitude|above"
    r"|below|over|under|rotat|turn|tilt|scale|waypoint|side|towards?|hug|bow|offset)\w*",
    re.I,
)
"""Word stems that ask where the path goes (its place or shape), not how fast."""


SENTENCE_END = re.compile(r"[.;!?](?!\d)")
"""Where a sentence ends: a full stop (not a decimal point), a semicolon, "!" or "?"."""

START = re.compile(
    r"\b(?:the\s+(?:start|beginning)\b|start(?:ing)?\s+(?:position|point|waypoint|pose|location)"
    r"|initial\s+(?:position|point|waypoint|pose|location)|beginning)",
    re.I,
)
"""Words that name the path's start ("the start", "the initial position")."""
GOAL = re.compile(
    r"\b(?:the\s+goal\b|goal\s+(?:position|point|pose|location)|end(?:ing)?\s+(?:position|point|pose|location)"
    r"|final\s+(?:(?!few|couple|several|last|two|three|four|five|\d)[a-z-]+\s+)?(?:position|point|waypoint|pose|location)"
    r"|destination)",
    re.I,
)
"""Words that name the path's goal ("the goal", "the end point", "the destination", "the final hover
point"; "the final few points" are the end of the path)."""

PART_OR_END = re.compile(
    r"\b(?:start\w*|begin\w*|goal|end(?![\s-]*effector)\w*|destination|target|finish|first|last|middle|half|halfway"
    r"|cent(?:er|re)|waypoints?|points?|part|section|segment|portion)\b",
    re.I,
)
"""Words that place a request at a part or an end of the path ("the start", "after the goal", "the
first half"), so it does not ask the whole path to move ("the end effector" is the robot's, no end)."""


_AS_IT_IS = r"(?:(?:current|present|existing|old|original|planned|usual|normal|actual)\s+)?"
"""A word that says the goal as it is now ("the current end", "its present goal")."""
PAST_THE_GOAL = re.compile(
    rf"\b(?:(?:after|past|beyond|once|upon)\b(?:\s+[\w']+){{0,3}}?\s+(?:the\s+|its\s+|your\s+)?{_AS_IT_IS}"
    r"(?:goal|end|destination|final)"
    r"|(?:past|beyond)\s+where\s+(?:[\w']+\s+){0,3}?(?:ends|ended|stops|stopped|finishes|finished)"
    r"|(?:when\w*|as soon as|on|first)\s+(?:[\w']+\s+){0,2}?"
    rf"(?:reach\w*|arriv\w*(?:\s+at)?|get\w*\s+to|got\s+to|hit\w*|at)\s+(?:the\s+|its\s+|your\s+)?{_AS_IT_IS}"
    r"(?:goal|end|destination|final)"
    r"|(?:goal|destination)(?:\s+\w+){0,2}?\s+(?:is|has been|was|gets)\s+reached)\b",
    re.I,
)
"""Words that place a request after the path's goal: "after reaching the goal", "past the end", "once
at the destination", "upon arrival at the goal", "when you get to the goal", "once the goal is
reached", "past where the path currently ends", "once you reach the current end"."""
GOES_FURTHER = re.compile(
    r"\b(?:continu\w*|carry\w*\s+on|keep\w*\s+(?:going|moving|flying|driving|rolling|on)|go(?:es|ing)?\s+on"
    r"|push\w*\s+on|press\w*\s+on|proceed\w*|travel\w*\s+on)"
    rf"(?:\s+[\w']+){{0,3}}?\s+(?:another|an\s+extra|a\s+further|{NUMBER_TEXT}\s*(?:[a-z]+\s+)?(?:further|farther|more))\b"
    r"(?!\s+(?:times|loops?|laps?|turns?|circles?|steps?|timesteps?|waypoints?|swings?|cycles?|seconds?)\b)",
    re.I,
)
"""Going on by a further amount ("continue another 0.1 forward", "keep going forward another 0.15",
"carry on 0.2 further left"): in a clause that names no object, the path goes on past its goal."""


PACE_PHRASES = re.compile(
    r"\b(?:slow|slowing|speed|speeding|calm|hurry|ramp|ramping|wind|winding|ease|easing)"
    r"\s+(?:(?:it|things|the robot|the drone|the arm|everything|this|right|way|right\s+way)\s+)?(?:down|up)\b"
    r"|\b(?:slow|slowing|speed|speeding|ramp|ramping)\s+(?:the|your|its|this|that)"
    r"(?:\s+(?!and\b|then\b|to\b|so\b)[a-z]+){1,4}?\s+(?:down|up)\b"
    r"|\b(?:bring|brought|get|got|take|took|turn|dial|knock|drop|crank|push|pull)\w*\s+(?:the\s+|its\s+|your\s+)?"
    r"(?:speed|pace|velocity|tempo)\s+(?:back\s+)?(?:down|up)\b"
    r"|\b(?:throttl|dial)\w*\s+(?:it\s+)?(?:back\s+)?(?:down|up|back)\b",
    re.I,
)
"""Phrasal verbs of pace whose particle is no direction ("slow down", "slow it down", "speed up", "ease up",
"speed the whole run up", "bring the speed down", "dial the pace back up", "throttle back")."""

SPEED_NOUN = r"(?:the\s+|your\s+|its\s+|their\s+|a\s+)?(?:speed|pace|velocity)\b"
"""A speed as the object of a verb ("raise the speed", "lower your pace")."""
_NOT_A_MODIFIER = r"(?:and|or|but|then|so|at|in|on|by|to|of|for|from|with|while|as|near|around|up|down)"
CHANGED_SPEED = (
    rf"(?:the\s+|your\s+|its\s+|their\s+|a\s+)?(?:(?!{_NOT_A_MODIFIER}\b)[a-z']+\s+){{0,2}}"
    r"(?:speed|pace|velocity)\b"
)
"""A speed as the object of a verb of more or less, with up to two words before it ("cut the overall
speed", "lower the robot's travel speed"; not "lower the path at constant speed")."""


_SPEED_VERB = (
    "(?:"
    + "|".join(
        f"(?<={word}\\s)"
        for word in (r"\band", r"\bthen", r"\bto", r"\bplease", r"\bjust", r"\balso", "[,.;:!?]")
    )
    + "|(?<!.))speed"
)
"""'speed' as a verb ("speed through that part", "and then speed past the lamp"): at the start of a
clause or after a joining word, never a noun ("reduce speed through the door", "at constant speed")."""


_SPEED_OF = (
    r"(?:the\s+|your\s+|its\s+|their\s+)?"
    r"(?:(?:current|present|usual|normal|original|old)\s+)?(?:speed|pace)\b"
)
"""A speed after a factor that names its direction: "half your current speed", "twice the pace"."""


_TURNING_THE_PACE = (
    r"(?:(?:ramp|dial|crank|throttl)\w*\s+(?:it|things|everything)\s+|throttl\w*\s+"
    rf"|(?:ramp|dial|crank|throttl|bring|brought|knock|turn)\w*\s+{SPEED_NOUN}\s+)(?:back\s+)?"
)
"""A verb that turns a pace up or down ("ramp the speed down", "dial it back down", "crank the pace
up", "bring the speed down"): with "down" slower, "up" faster ("bring it down" is a height, "take the
ramp down" a place: a speed noun or "it" after the verb)."""
FASTER = re.compile(
    r"\b(?:fast\w*|quick\w*|rapid\w*|swift\w*|hurr\w*|accelerat\w*|brisk\w*|zip\w*|zoom\w*|sprint\w*|rush\w*"
    r"|hustl\w*|speed(?:s|ing)?\s+(?:(?:the|your|its|this|that)\s+(?:[a-z]+\s+){0,2}?)?up\b"
    rf"|{_SPEED_VERB}(?:s|ing|ed)?\s+(?:through|past|along|across|over|by)\b"
    rf"|(?:increas|rais|boost|doubl|higher|greater|more)\w*\s+{CHANGED_SPEED}"
    rf"|pick(?:s|ed|ing)?\s+up\s+{SPEED_NOUN}|(?:twice|double|triple)\s+{_SPEED_OF}"
    rf"|{_TURNING_THE_PACE}up\b)",
    re.I,
)
SLOWER = re.compile(
    r"\b(?:slow\w*|decelerat\w*|leisure\w*|brak\w*|crawl\w*|creep\w*|crept|tiptoe\w*|dawdl\w*|gentl\w*"
    r"|eas(?:e|es|ed|ing)\s+(?:off|up)|tak(?:e|es|ing|en)\s+it\s+eas(?:y|ier)|go(?:es|ing)?\s+(?:easy|easier)"
    rf"|(?:reduc|decreas|lower|cut|drop|halv|lessen|less|smaller)\w*\s+{CHANGED_SPEED}"
    rf"|(?:half|a\s+third\s+of|a\s+quarter\s+of)\s+{_SPEED_OF}"
    rf"|{_TURNING_THE_PACE}down\b|\btaper\w*\s+(?:{SPEED_NOUN}\s+)?off\b"
    r"|\b(?:throttl|dial)\w*\s+(?:it\s+)?(?:back|down)\b(?!\s+up))",
    re.I,
)
"""What asks for more speed, and for less: speed words ("ease off", "take it easy", "crawl", "creep",
"gently", "ramp the speed down", "taper off", "throttle back" are slower; "zip", "zoom", "rush",
"speed through", "crank the pace up" faster), a verb or adjective of more or less before a speed
("reduce your speed", "raise the pace", "at a lower speed"), and a factor that names its direction
("at half your current speed", "at twice the pace")."""

GAP_NOUN = r"(?:the\s+|your\s+|its\s+|their\s+|a\s+)?(?:distance|gap|berth|clearance|margin|separation)\b"
CLOSER = re.compile(
    r"\b(?:closer|nearer|approach\w*|toward[s]?|hug\w*|tight(?:er|ly)?\s+(?:to|by|against|past)"
    r"|in\s+(?:\w+\s+)?tight|right next to|(?:immediate(?:ly)?|just|directly)\s+(?:to\s+|in\s+)?(?:the\s+)?"
    r"(?:left|right|front|back|behind)(?:\s+side)?\s+of"
    r"|(?:smaller|shorter|less(?:er)?|reduced?|tighter|narrower) (?:distance|gap|berth|clearance|margin))\b"
    rf"|\b(?:reduc|decreas|lower|cut|shrink|shrank|shrunk|narrow|lessen|tighten|clos(?:e|es|ed|ing))\w*\s+{GAP_NOUN}",
    re.I,
)
AWAY = re.compile(
    r"\b(?:away|further|farther|clear\s+of"
    r"|(?:greater|larger|bigger|more|increased?|wider|extra|wide|big|large|generous|ample|healthy|decent"
    r"|safe|respectful|comfortable|plenty\s+of|lots\s+of|a\s+lot\s+of)"
    r" (?:distance|berth|space|room|gap|clearance|margin)|wider\s+(?:around|round|past|of|by))\b"
    rf"|\b(?:increas|widen|grow|grew|enlarg|expand|extend|doubl|rais|boost)\w*\s+{GAP_NOUN}",
    re.I,
)
"""What asks to come closer to an object, and to keep further from it ("tighter to", "in tight",
"just right of", "right next to", "steer clear of", "a wider margin", "a wide berth", "plenty of
room", "go wider around", a verb of less or more before a distance: "reduce the gap", "widen your
clearance"; "avoid" asks a clearance, which the readers leave to ``avoid``; only the effect's flags
count it as away)."""


VISIT = re.compile(
    r"\b(?:visit\w*|via|by\s+way\s+of|(?:swing|stop|drop|call)(?:s|ped|ping|ing|ed)?\s+by"
    r"|(?:close|right)\s+(?:to|by|past|beside|alongside)"
    r"|(?:pass|go|goes|going|went|fly|flies|flying|flew|drive\w*|drove|walk\w*|rout\w*|run\w*|ran"
    r"|head\w*|travel\w*|mov\w*|come|comes|coming|came|get|gets|getting|got|sweep\w*|skim\w*|cruis\w*"
    r"|detour\w*|divert\w*|veer\w*|swerv\w*|swing\w*|swung|dip\w*|cut\w*|wander\w*)"
    r"\s+(?:\w+\s+)?(?:by|past|next\s+to|beside|alongside|near(?:by)?|through)"
    r"|(?:pass\w*|go|goes|going|went|fly|flies|flying|flew|drive\w*|drove|rout\w*|come|comes|coming|came|get"
    r"|gets|getting|got|swing\w*|swung|dip\w*|bring\w*|brought)\s+(?:\w+\s+){0,2}?within)\b",
    re.I,
)
"""What asks the path to pass close by an object (not closer than it is: close to it): "pass close to",
"swing by", "fly close past", "route past", "take a detour past", "veer by", "come close to", "go
through", "via", "visit", "pass within 0.3 of", "bring it within 0.2 of" (not "keep within": a place kept)."""
KEEPING = re.compile(r"\b(?:stay\w*|keep\w*|kept|remain\w*|hold\w*|stick\w*)\b", re.I)
"""Verbs of keeping: "stay close to X", "keep close to X" ask the path to keep near it, not to visit it."""
REFUSED = re.compile(r"\b(?:not|never|no|avoid\w*|without|instead\s+of|too)\b|n't\b", re.I)
"""Words that refuse what follows: "avoid passing close to X", "don't go by X", "too close to X"."""
PLACING = re.compile(r"^\W*(?:while|when\w*|as|once|if|until|passing|going|driving|flying|walking)\b", re.I)
"""A lead-in that places another request: "while passing close to X, slow down" visits nothing."""


MINIMUM_DISTANCE = re.compile(
    r"(?:\bat\s+least|(?:\bno|\bnever|\bnot|n't)\s+(?:[a-z']+\s+){0,5}?(?:closer|nearer|less)\s+than"
    r"|(?:\bno|\bnever|\bnot|n't)\s+(?:(?:ever|let\s+(?:it|the\s+\w+))\s+)?"
    r"(?:com|get|go|pass|mov|fly|flie|driv|be)\w*\s+within"
    r"|\b(?:a\s+)?(?:minimum|min\b\.?)\s+(?:of\s+)?"
    rf"(?:(?:clearance|distance|gap|margin|separation)\s+(?:of\s+)?)?"
    r"|\b(?:a|the)\s+(?:clearance|buffer|margin|berth|standoff)\s+of"
    rf"|\bclear\s+of\s+(?:[\w-]+\s+){{1,5}}?by(?=\s+{NUMBER_TEXT}\s+or\s+(?:more|further|farther|greater)\b)"
    r"|\b(?:berth|margin|clearance|gap|room|buffer|space|distance)\W+"
    rf"(?={NUMBER_TEXT}\s+(?:minimum|min\b|at\s+(?:the\s+)?(?:least|minimum)))"
    r"|\bclear\w*\s+(?:[\w-]+\s+){1,4}?by(?=\s+" + NUMBER_TEXT + r")"
    r"|\b(?:keep|stay|remain|hold|leave|allow)\w*"
    r"(?:\s+(?:it|the\s+(?:robot|arm|drone|gripper|end\s+effector|tool|vehicle|path|route)))?"
    rf"(?:\s+(?:a|at))?(?:\s+(?:full|good|solid|clear))?"
    rf"(?=\s+{NUMBER_TEXT}\s+(?:(?:away\s+)?(?:from|off)|clear\s+of|between)\b)"
    r"|\b(?:(?:keep|give|leave|allow|maintain|hold|have)\w*|with)(?:\s+(?:the\s+)?[\w-]+){0,3}?"
    rf"(?=\s+{NUMBER_TEXT}\s+(?:of\s+)?(?:clearance|room|space|berth|buffer|margin|gap|separation|standoff)\b))\s*"
    rf"({NUMBER_TEXT})",
    re.I,
)
"""A clearance the words state as a least distance: "at least 0.2", "no closer than 0.2", "never
closer than 0.2", "don't get nearer than 0.2", "never let it come closer than 0.2" (up to five words
between the negation and the comparison), "never come within 0.2", "a minimum clearance of 0.2", "a
clearance of 0.2", "keep 0.4 from", "stay a full 1 away from", "clear of it by 0.1 or more", "0.15
minimum", "1.5 at least", "keep 0.8 of clearance from", "give the lamp 0.3 of room", "keep the arm 0.25
away from", "clear the spoon by 0.1", "min 0.4 clearance"."""


def whole_words(text: str) -> str:
    """Lower-case words with a space on each side, so that names match whole words only.

    >>> whole_words("the Red-Box!")
    ' the red box '
    """
    return f" {' '.join(re.findall(r'[a-z0-9]+', text.casefold()))} "


def names_in(text: str, names: Iterable[str]) -> list[str]:
    """The names that ``text`` contains as whole words, in the order of ``names``."""
    words = whole_words(text)
    return [name for name in names if name and whole_words(name) in words]


OF_SPEED = re.compile(rf"\b[a-z]+\s+{SPEED_NOUN}", re.I)
"""A word before a speed: "higher speed" and "raise the pace" name no direction."""
OF_DISTANCE = re.compile(rf"\b[a-z]+\s+{GAP_NOUN}", re.I)
"""A word before a distance: "lower the clearance" and "raise the margin" ask closer or further
(``CLOSER``, ``AWAY``), not down or up."""


def longest_names(named: list[str]) -> list[str]:
    """The names not inside another of them ('red box' and 'box' found: 'red box')."""
    return [n for n in named if not any(n != o and n.casefold() in o.casefold() for o in named)]


def asks_pace(words: str) -> bool:
    """Whether the words ask about speed: a speed word, or one that asks for more or less of it."""
    return bool(SPEED_WORDS.search(words) or FASTER.search(words) or SLOWER.search(words))


def asks_visit(clause: str) -> bool:
    """Whether a clause asks to pass close by something (``VISIT``).

    Not where it keeps near it, refuses it ("don't go by", "too close to") or only places another
    request ("while passing close to", "go slower when passing close to the box": a pace's place).
    """
    return (
        bool(VISIT.search(clause))
        and not any(words.search(clause) for words in (KEEPING, REFUSED, PLACING))
        and not asks_pace(clause)
    )


def asks_distance(words: str) -> bool:
    """Whether the words ask to come closer to something or keep further from it."""
    return bool(CLOSER.search(words) or AWAY.search(words))


NUMBER_WORDS = {
    "one": 1.0, "two": 2.0, "three": 3.0, "four": 4.0, "five": 5.0, "six": 6.0, "seven": 7.0,
    "eight": 8.0, "nine": 9.0, "ten": 10.0, "twice": 2.0, "double": 2.0, "thrice": 3.0, "triple": 3.0,
    "half": 0.5, "halve": 0.5, "halved": 0.5, "halving": 0.5, "quarter": 0.25,
    "couple": 2.0, "few": 3.0, "several": 3.0,
}  # fmt: skip
"""Numbers said in words; "a couple", "a few", "several" are counts of 2, 3 and 3."""
UNIT_FACTORS = (1.0, 0.01, 100.0, 0.001, 1000.0)  # the number as given, cm <-> m, mm <-> m
INTENSITY = sorted((word for word in AMOUNT_WORDS if word and word != "default"), key=len, reverse=True)


def stated_numbers(words: str) -> list[float]:
    """Every number in the user's words, also spelled out ('two times', 'twice', 'half')."""
    spelled = [NUMBER_WORDS[w] for w in re.findall(r"[a-z]+", words.lower()) if w in NUMBER_WORDS]
    return [abs(float(n)) for n in NUMBER.findall(words)] + spelled


def whole_count(word: str) -> int:
    """The whole number >= 1 a count is written as (digits or a word: '6', 'six'), or 0.

    >>> whole_count("six"), whole_count("12"), whole_count("half")
    (6, 12, 0)
    """
    word = word.lower()
    value = float(word) if word.isdigit() else NUMBER_WORDS.get(word, 0.0)
    return int(value) if value >= 1 and value == int(value) else 0


PLACE_GROUPS: tuple[tuple[frozenset[str], frozenset[str]], ...] = (
    (frozenset({"start", "beginning", "begin", "starting", "initial", "initially", "origin"}),
     frozenset({"start", "beginning"})),
    (frozenset({"middle", "center", "centre", "halfway", "midway", "mid", "intermediate", "midpoint"}),
     frozenset({"middle", "center"})),
    (frozenset({"end", "goal", "final", "finish", "destination", "last", "ending", "target"}),
     frozenset({"end", "goal", "final"})),
    (frozenset({"whole", "all", "entire", "everywhere", "throughout"}), frozenset({"all", "whole"})),
)  # fmt: skip
"""Words a user says for a place on the path, and the part or position words that name it in code."""


STRONG_COMPARATIVE = re.compile(r"\b(?:way|loads|lots|heaps|tons|miles)\s+(?:more\b|less\b|[a-z]+er\b)", re.I)
"""A comparative made strong by a word that is no amount elsewhere: "way slower", "loads closer"."""


SMALL_AMOUNT = re.compile(
    r"\b(?:a\s+(?:touch|tad|smidge|smidgen|nudge|shade)\b|a\s+hair\b(?!\s+dryer)|marginally|fractionally"
    r"|minimally|subtl\w*)",
    re.I,
)
LARGE_AMOUNT = re.compile(
    r"\b(?:substantially|considerably|greatly|hugely|massively|dramatically|drastically|markedly"
    r"|a\s+(?:good|great)\s+deal|a\s+long\s+way|by\s+a\s+wide\s+margin)\b",
    re.I,
)
"""Amount idioms the skills take no word for: "a touch", "a tad", "marginally", "subtly" say 'slightly';
"considerably", "a good deal", "a long way" say 'a lot'."""


def intensity_word(words: str) -> str | None:
    """The user's vague amount word, if any ('a lot', 'slightly', ...), as a word the skills take.

    "way slower", "considerably", "a good deal" are 'a lot'; "a touch", "a tad", "marginally" are
    'slightly'.
    """
    lowered = words.lower()
    said = next((word for word in INTENSITY if re.search(rf"\b{re.escape(word)}\b", lowered)), None)
    if said:
        return said
    if SMALL_AMOUNT.search(words):
        return "slightly"
    return "a lot" if STRONG_COMPARATIVE.search(words) or LARGE_AMOUNT.search(words) else None


def is_stated(value: float, numbers: list[float]) -> bool:
    """Whether ``value`` is one of the user's numbers (up to a unit conversion)."""
    return any(abs(abs(value) - n * f) <= 1e-6 * max(1.0, n * f) for n in numbers for f in UNIT_FACTORS)


def amount_size(words: str) -> str:
    """How much the amount word of ``words`` asks: 'a bit' (less than plain), '' (plain) or 'a lot'."""
    strength = AMOUNT_WORDS.get(intensity_word(words) or "", AMOUNT_WORDS["default"])
    plain = AMOUNT_WORDS["default"]
    return "a bit" if strength < plain else "a lot" if strength > plain else ""


def part_named(words: str) -> str | None:
    """The one part of the path the words name ('middle', 'start', 'end', 'first half', ...)."""
    text = whole_words(words)
    named = [part for part in PART_WORDS if part not in ("all", "whole") and f" {part} " in text]
    longest = longest_names(named)
    return longest[0] if len(longest) == 1 else None


ALL_ALONG = re.compile(
    r"\b(?:from\s+(?:the\s+)?(?:start|beginning)\s+(?:to|till|until)\s+(?:the\s+)?(?:finish|end|goal)"
    r"|(?:start|beginning)\s+to\s+(?:finish|end)|(?:the\s+)?(?:whole|entire)\s+(?:way|time|run|path|route|trajectory)"
    r"|throughout|all\s+(?:the\s+way|along)|end\s+to\s+end)\b",
    re.I,
)
"""Words that span the whole path ("from start to finish", "the whole way", "throughout"): the ends
they name are no part of it."""
EVEN_PACE = re.compile(
    r"\b(?:constant|steady|uniform|even|fixed|unchanging)\s+(?:\w+\s+)?(?:speed|pace|velocity)\b", re.I
)
"""An even pace the words state ("a steady 0.4", "constant speed"): a clause about the pace, held the
whole way beside a move closer or away in the same clause."""
SPEED_UNIT = re.compile(r"/\s*s\b|\bper\s+sec\w*|\b(?:a|an|each)\s+second\b|\bmps\b", re.I)
"""A unit of speed: the number before it is a speed, not a factor."""
NEGATED = re.compile(r"\b(?:not|never|no|without)\b|n't\b", re.I)
"""A clause said as what not to do ("no slowing down", "never come to a stop", "don't rush")."""

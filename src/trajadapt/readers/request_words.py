"""What the user asks: their words less the sentences that only say how the path is now.

Feedback often states the problem before or after the fix: "It's far too slow near the wolf. Pick up
the pace near it.", "Raise the path by 0.1 - it runs too close to the lamp.", "Why does it stop at
the goal? Keep going.", "You went right past the mug; hold there for 7 timesteps." The statement
asks nothing, and read as a request it asks the opposite of the fix ("too slow" is no "slower"), so
neither the model nor the readers are shown it: both read ``request_words``.

A statement leaves only where nothing is lost: every object and end of the path it names is named
again in the rest, or the rest points back to its one object or end ("near it", "from that one",
"there", "bring it in closer"), and those words are then written out ("near the wolf", "at the
mug"). Anything else keeps the words whole, exactly as said. A word that only opens the feedback
("No, ...", "Close, but ...", "Hmm.") leaves too: read as a clause, it would ask for a step.
Before that, the words are put in plain form (``readers.plain_words``: lists, decimals in words,
short names of objects, what not to do said as what to do).
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from trajadapt.readers.plain_words import plain_words
from trajadapt.readers.words import GOAL, SENTENCE_END, START, names_in

_OPENER = (
    r"(?:(?:right now|currently|at the moment|at present|as it is|now|so|honestly|also|and|but|though|still)"
    r"\s*[,:\-\u2013\u2014]?\s+)*"
)
_PLACE = r"(?:around|near|by|past|at|in|on|within|inside|close to|next to)"
_WHERE = rf"(?:(?:{_PLACE}|when|whenever|while)\b[^,]*?,\s*|{_PLACE}\s+the\s[^,]*?\s)?"
"""Where the statement is about, said first: "near the lamp, it ...", "around the chair it's ..."."""
_SUBJECT = r"(?:it|this|that|there|you|the(?:\s+[\w'-]+){1,5}?)"
_STATE_VERBS = (
    r"(?:(?:just|only|still|always|really|clearly|barely|currently|never|now|also)\s+)?"
    r"(?:is|isn't|are|aren't|was|wasn't|were|weren't|does|doesn't|did|didn't|do not|does not|did not|don't"
    r"|[a-z]+(?<!\bthi)(?<!\bit)s|[a-z]+ed|went|got|came|ran|flew|drove|cut|hit|took|made|had|kept|rose"
    r"|swung|felt|sped|crept|sat|hung|stuck|bent|fell|never)"
)
"""What a subject does in a statement: a verb in the present (ending in s) or past, or a state."""
STATEMENT = re.compile(
    rf"^{_OPENER}(?:{_WHERE}{_SUBJECT}(?:'s|'re|\s+{_STATE_VERBS})\b"
    r"|(?:why|how come)\b|(?:isn't|aren't|doesn't|wasn't|didn't)\s+(?:it|the|you|this|that)\b)",
    re.I,
)
"""A sentence that says how the path is now, or asks why: "it's too fast near the lamp", "the path sits
a bit low", "you went right past the mug", "why does it stop at the goal", "the lamp is way too close"."""
INSTEAD = re.compile(
    r"(?P<opening>(?:^|(?<=[.;:!?])\s*)(?:instead\s+of|rather\s+than)\s+[a-z]+ing\b[^,;:.]*[,;:]\s*)"
    r"|(?<=[\w'\"]),?\s+(?:instead\s+of|rather\s+than)\s+[a-z]+ing\b[^,;:.!?]*?(?=\s+(?:and|then|but)\b|[,;:.!?]|$)",
    re.I,
)
"""Where a piece that says what to do instead of opens or follows the request: "*Instead of stopping
mid-route,* drive on", "route past the fan *instead of hugging the wall*"."""

REQUESTING = re.compile(
    r"\b(?:should|must|needs? to|has to|have to|ought|want|would like|could you|can you|please|let it"
    r"|why (?:don't|not)|how about|what about|new (?:goal|destination|end ?point))\b",
    re.I,
)
"""Words that make a sentence about the path a request ("it should stop at the goal", "why not go left",
"the new goal is the lamp")."""

REASON = re.compile(r"\s+[-\u2013\u2014]+\s+|\s*[\u2013\u2014]\s*|,?\s+\b(?:because|since)\b\s+", re.I)
"""Where a reason follows the fix inside one sentence: a dash, "because", "since"."""


def is_statement(words: str) -> bool:
    """Whether the words only say how the path is now ("it's too slow near the lamp"): no request."""
    return bool(STATEMENT.match(OPENER.sub("", words.strip()))) and not REQUESTING.search(words)


def request_words(instruction: str, names: Sequence[str] = ()) -> str:
    """The instruction in plain words, less the sentences that only say how the path is now.

    The plain words are ``plain_words``'; a sentence leaves only where nothing is lost.

    >>> request_words("It's far too slow near the wolf. Pick up the pace near it.", ["wolf"])
    'Pick up the pace near the wolf.'
    >>> request_words("Go left by 0.2 and slow down near the box", ["box"])
    'Go left by 0.2 and slow down near the box'
    """
    instruction = _instead_left_out(plain_words(instruction, names, is_statement), names)
    said_so = _sentences(instruction)
    sentences = [s for s in (OPENER.sub("", s) for s in said_so) if s]
    opened = sentences != said_so
    stated = [s for s in sentences if is_statement(s)]
    if not sentences or len(stated) == len(sentences) or not (stated or opened):
        return instruction
    missing = {n for s in stated for n in _referents(s, names)} - _said(sentences, stated, names)
    if len(missing) == 1:
        referent = missing.pop()
        sentences = [s if s in stated else _written_out(s, referent, names) for s in sentences]
    said = _said(sentences, stated, names)
    dropped = [s for s in stated if all(n in said for n in _referents(s, names))]
    if not (dropped or opened):
        return instruction
    return ". ".join(s for s in sentences if s not in dropped) + "."


OPENER = re.compile(
    r"^(?:no|nope|nah|not quite|not really|not yet|hmm+|close|almost|nearly|oops|wait|ok|okay|well|sorry"
    r"|actually|yes|yeah|wrong|that's (?:wrong|not right|not it|off|close|better))"
    r"(?:\s*,?\s*but\s+|\s*[,:;!\-\u2013\u2014]+\s*|\s*$)",
    re.I,
)
"""A word that opens feedback and asks nothing: "No, ...", "Not quite: ...", "Close, but ...", "Hmm, ..."."""


def _said(sentences: list[str], stated: list[str], names: Sequence[str]) -> set[str]:
    """The objects and ends the sentences that are not ``stated`` name."""
    return {n for s in sentences if s not in stated for n in _referents(s, names)}


def _sentences(instruction: str) -> list[str]:
    """The sentences, a reason after a dash, "because" or "since" counting as a sentence of its own."""
    return [x.strip() for s in SENTENCE_END.split(instruction) for x in REASON.split(s) if x.strip()]


def _instead_left_out(instruction: str, names: Sequence[str]) -> str:
    """``instruction`` less each "instead of <doing>" piece whose objects and ends the rest names too."""
    read = instruction
    for found in reversed(list(INSTEAD.finditer(instruction))):
        rest = read[: found.start()] + read[found.end() :]
        if set(_referents(found.group(0), names)) <= set(_referents(rest, names)):
            space = " " if found.group("opening") and found.start() else ""
            read = read[: found.start()] + space + read[found.end() :]
    return read.strip() if read != instruction else instruction


def _referents(sentence: str, names: Sequence[str]) -> list[str]:
    """The objects a sentence names, 'start' / 'goal' where it names an end, and the parts it names."""
    ends = [end for end, words in (("start", START), ("goal", GOAL)) if words.search(sentence)]
    parts = [" ".join(found.group(1).lower().split()) for found in PART.finditer(sentence)]
    return [*names_in(sentence, names), *ends, *parts]


PART = re.compile(
    r"\b((?:middle|cent(?:er|re)|first|second|last|final|initial|opening|closing)\s+"
    r"(?:half|third|quarter|part|section|segment|portion|stretch|leg|bit)|middle|halfway)\b",
    re.I,
)
"""A part of the path a statement may name ("the middle section", "the last third")."""


PLACE_PREPOSITIONS = (
    r"to|from|of|near|nearer|around|round|past|over|above|below|under|beneath|beside|by|towards?|through"
    r"|at|into|behind|about|off|onto|on top of|in front of|next to|close to|away from|clear of"
)
BACK_TO_IT = re.compile(
    rf"\b({PLACE_PREPOSITIONS})\s+(?:it|them|that one|this one|that)\b(?!\s*(?:'s|is|was))", re.I
)
"""A place said by pointing back: "near it", "away from that one" (the path is never near itself)."""
THAT_ONE = re.compile(r"\b(?:that|this) one\b", re.I)
THERE = re.compile(r"\bthere\b(?!\s*(?:'s|is|are|was|were)\b)", re.I)
TO_THERE = re.compile(
    r"\b(get|gets|go|goes|come|comes|head|heads|move|moves|return|returns|fly|drive|walk|from|to|towards?"
    r"|past|beyond)\s+there\b",
    re.I,
)
"""Motion to a place, or a place to start from, said with "there": written "to" / "from" the place."""
COMPARATIVE_AT_END = re.compile(r"\b(closer|nearer|tighter|further|farther|away|wider|clear)\s*$", re.I)
TOWARDS = frozenset({"closer", "nearer", "tighter"})


def _written_out(sentence: str, referent: str, names: Sequence[str]) -> str:
    """``sentence`` with the words that point back to ``referent`` written out as its name."""
    the = f"the {referent}"
    sentence = TO_THERE.sub(lambda m: f"{_motion(m.group(1))} {the}", sentence)
    if PART.fullmatch(referent):  # a part of the path: only "there" can point back to it
        return THERE.sub(f"in {the}", sentence)
    sentence = BACK_TO_IT.sub(lambda m: f"{m.group(1)} {the}", sentence)
    sentence = THAT_ONE.sub(the, sentence)
    sentence = THERE.sub(f"at {the}" if referent in ("start", "goal") else f"near {the}", sentence)
    ending = COMPARATIVE_AT_END.search(sentence)
    if ending and not names_in(sentence, names):
        sentence += f" to {the}" if ending.group(1).lower() in TOWARDS else f" from {the}"
    return sentence


def _motion(word: str) -> str:
    """The words before a place that replace "<word> there": "get to", "from", "past"."""
    return word if word.lower() in ("from", "to", "toward", "towards", "past", "beyond") else f"{word} to"

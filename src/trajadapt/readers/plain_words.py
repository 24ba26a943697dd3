"""The user's words in the plain form the model and the readers read: what they say, said one way.

People write a request in many forms that ask the same thing. Six of them hide what is asked from
a small model and from word-reading code alike, so they are written out once, before anything reads
the words:

- steps given as a list ("1) go up 2) slow down", "- go up" on its own line) become sentences, so
  that a list number is never read as an amount;
- a number said in words with a decimal point ("zero point three", "point two") or with a fraction
  ("one and a half", "2 and a quarter"), or a distance said in words ("by three", "within two of"),
  becomes digits;
- an object pointed back to with "it" after a word of place ("go slower as you pass by it":
  ``pointed_objects``) is called by its name;
- an object called by another name of its kind ("the oboe" for "hautbois": ``object_kinds``) or by
  one word of its scene name ("the husky" for "Siberian husky", "the remote"
  for "remote_controller") is called by its full name, where no other object of the scene has that
  word, and one written with its words joined or split otherwise ("dishwasher" for "dish washer",
  "tin-opener" for "tinopener") as the scene spells it;
- a comparison said as what not to do ("don't walk so close to the lamp", "don't keep as much
  distance from the barn", "don't rush near the box", "don't go as slow in the middle", "don't keep
  going") is said as what to do ("walk further from the lamp", "keep less distance from the barn",
  "slow down near the box", "go faster in the middle", "stop"), and so is one said as what to stop
  doing ("stop walking so slowly" -> "walking faster", "stop dawdling" -> "speed up"). A negation of
  a plain pace ("don't slow down") or of a limit ("don't go faster than 2") is left as said: it asks
  no change. "Not anywhere near as fast" (or "nearly", "anything like", "remotely") is "a lot
  slower";
- a part of the path called by another name ("the last leg", "the opening stretch", "the central
  section") is called by the part word every reader knows ("the end", "the start", "the middle").

Where none of these forms occurs the words are returned exactly as said.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from trajadapt.readers.object_kinds import names_by_their_kind
from trajadapt.readers.pointed_objects import objects_for_it
from trajadapt.readers.words import whole_words

LIST_MARK = re.compile(r"(?:^|(?<=\n))[ \t]*(?:\d{1,2}[.)]|[-*\u2022])[ \t]+|(?<=\s)\d{1,2}\)[ \t]+", re.M)
"""A list item's mark: "1)" or "2." or "-" or "*" opening a line, or "2)" inside one."""

_DIGITS = {
    "zero": "0", "nought": "0", "oh": "0", "one": "1", "two": "2", "three": "3", "four": "4",
    "five": "5", "six": "6", "seven": "7", "eight": "8", "nine": "9",
}  # fmt: skip
_DIGIT = "|".join(_DIGITS)
DECIMAL_IN_WORDS = re.compile(rf"\b(?:({_DIGIT})\s+)?point((?:\s+(?:{_DIGIT}))+)\b", re.I)
"""A decimal said in words: "zero point three", "point two five", "one point five"."""
_CARDINALS = {**_DIGITS, "ten": "10", "twenty": "20"}
_CARDINAL = "|".join(_CARDINALS)
AMOUNT_IN_WORDS = re.compile(
    rf"\b(?:by\s+(?=(?:{_CARDINAL})\b(?!\s+(?:times|of)\b))|within\s+)({_CARDINAL})\b"
    rf"|\b({_CARDINAL})(?=\s+(?:units?|metres?|meters?)\b)",
    re.I,
)
"""A whole amount said in words where it is a distance: "by three", "within two of", "two units"."""
FRACTIONS = {"a half": ".5", "a quarter": ".25", "three quarters": ".75"}
_FRACTION = "|".join(fraction.replace(" ", r"[\s-]+") for fraction in FRACTIONS)
AND_A_FRACTION = re.compile(rf"\b({_CARDINAL}|\d+)[\s-]+and[\s-]+({_FRACTION})\b", re.I)
"""A whole and a fraction said in words: "one and a half", "2 and a quarter", "two-and-three-quarters"."""

_STRETCH = (
    r"(?:leg|stretch|bit|section|portion|segment|part|phase|stage|few\s+metres|few\s+meters)"
    r"(?:\s+of\s+(?:the\s+|its\s+|your\s+)?(?:path|route|trajectory|flight|run|motion|movement|way|trip|journey))?"
)
PART_CALLED = tuple(
    (re.compile(rf"\b(?:the\s+|its\s+|your\s+)?(?:{words})\s+{_STRETCH}\b", re.I), part)
    for words, part in (
        (r"last|final|closing|ending|concluding|home|tail", "the end"),
        (r"first|opening|initial|early", "the start"),
        (r"middle|mid|central|centre|center", "the middle"),
    )
)
"""A part of the path called by another name: "the last leg", "the final stretch of the route" (the
end), "the opening part" (the start), "the central section" (the middle)."""

NOT_OBJECT_WORDS = frozenset(
    "goal start end path trajectory route way point points waypoint waypoints middle side top bottom "
    "front back left right speed line half section part corner edge centre center area region position "
    "height level ground floor object obstacle robot drone arm base first last other one red blue green "
    "yellow black white small large big little old new".split()
)
"""Words that name no object by themselves, even where a scene name holds them ("goal post")."""
SHORTEST_NAME_WORD = 3
SHORTEST_JOINED = 6

_NEGATION = r"\b(?:do\s+not|does\s+not|did\s+not|don't|doesn't|didn't|never|not|shouldn't|mustn't|won't)\s+"
_DEGREE = r"(?:(?:quite|nearly|anywhere\s+near|anything\s+like|remotely|all)\s+)?(?:so|as|too|that)\s+"
_RELATION_WORDS = (
    r"(?:so|as|too|that|quite|nearly|anywhere|anything|remotely|close\w*|near\w*|far\w*|further|away"
    r"|fast\w*|quick\w*|rapid\w*|slow\w*|rush\w*|hurr\w*|speed\w*|rac\w*|zoom\w*|distance|stop\w*|than"
    r"|left|right|up|down|forwards?|back\w*|higher|lower|above|below|over|under)"
)
_VERB_WORDS = rf"((?:(?!{_RELATION_WORDS}\b)[a-z']+\s+){{0,4}}?)"
_STOPPING = r"\b(?:stop|quit)\s+(?=[a-z]+ing\b)"
"""A negation by stopping: "stop walking so slowly", "stop dawdling" (never "stop near the lamp")."""
_NO_DEGREE_AFTER = r"(?![^,.;]*?\b(?:so|as|too|that)\s+(?:slow|fast|quick|rapid))"
"""A verb that is itself too fast or too slow ("rush", "dawdle") asks the opposite, but where the
clause says how much later ("don't crawl along nearly as slowly"): that degree is what is negated."""
_ASKS = {
    "further": (r"{degree}(?:close(?:ly)?|near)(?:\s+(?:to|by))?\b", "further from"),
    "less": (
        rf"{_DEGREE}(?:much|big|large|wide|great)\s+(?:an?\s+)?(?P<gap>distance|space|room|clearance|gap|margin|berth)\b",
        "less {gap}",
    ),
    "closer": (r"{degree}far(?:\s+away)?\s+from\b", "closer to"),
    "slower": (rf"{_DEGREE}(?:fast|quick(?:ly)?|rapid(?:ly)?|speedily|hastily)\b", "slower"),
    "slow_down": (r"(?:rush|hurry|race|zoom)\w*\b" + _NO_DEGREE_AFTER, "slow down"),
    "faster": (rf"{_DEGREE}slow(?:ly)?\b", "faster"),
    "speed_up": (r"(?:dawdl|crawl|loiter|plod|amble|drag)\w*\b" + _NO_DEGREE_AFTER, "speed up"),
    "stop": (r"(?:keep\s+(?:going|moving)|carry\s+on)\b", "stop"),
}
"""What a negation may negate, by kind, and what it then asks; ``{degree}`` is "so", "as", "too"
before the word, which a negation by stopping needs and "don't" does not ("don't go near")."""


def _negated(negation: str, degree: str) -> re.Pattern[str]:
    """A negation, at most four words that ask nothing of pace or distance, then a kind of ``_ASKS``."""
    kinds = "|".join(f"(?P<{key}>{pattern.format(degree=degree)})" for key, (pattern, _) in _ASKS.items())
    return re.compile(f"{negation}{_VERB_WORDS}(?:{kinds})", re.I)


NEGATED_ASKS = (_negated(_NEGATION, f"(?:{_DEGREE})?"), _negated(_STOPPING, _DEGREE))
"""Each negated comparison, said with "don't" (and the like) or by stopping, and what it asks
instead ("don't walk so close to" -> "walk further from", "stop dawdling" -> "speed up")."""
FAR_FROM_IT = re.compile(r"\b(?:nearly|anywhere\s+near|anything\s+like|remotely)\s", re.I)
"""A degree that makes the negation strong: "not anywhere near as fast" is "a lot slower"."""
LIMIT = re.compile(r"^\s*than\b", re.I)


def plain_words(words: str, names: Sequence[str], keep: Callable[[str], bool]) -> str:
    """``words`` with lists, decimals in words, short names and negated comparisons written plainly.

    ``keep`` says which sentences to leave as said (those that only state how the path is now, where
    a negation is no request: "it doesn't slow down near the lamp").

    >>> words = "1) go up by point two 2) don't walk so close to the husky"
    >>> plain_words(words, ["Siberian husky"], keep=lambda sentence: False)
    'go up by 0.2. walk further from the Siberian husky.'
    """
    plain = _decimals_in_digits(_list_as_sentences(words))
    plain = _full_names(names_by_their_kind(plain, names), names)
    plain = _parts_by_their_names(objects_for_it(plain, names))
    return _negations_as_asks(plain, keep)


def _parts_by_their_names(words: str) -> str:
    """A part of the path called another way by its name: "the last leg" -> "the end"."""
    for pattern, part in PART_CALLED:
        words = pattern.sub(part, words)
    return words


def _list_as_sentences(words: str) -> str:
    """The items of a list as sentences: "1) a 2) b" -> "a. b."."""
    if not LIST_MARK.search(words):
        return words
    items = [item.strip(" \t\n,;") for item in LIST_MARK.split(words)]
    items = [item for item in items if item]
    if not items:  # marks and nothing else: no list to read
        return words
    return " ".join(item if item[-1] in ".!?:" else f"{item}." for item in items)


def _decimals_in_digits(words: str) -> str:
    """Decimals said in words as digits: "zero point three" -> "0.3"."""

    def digits(found: re.Match[str]) -> str:
        whole = _DIGITS[found.group(1).lower()] if found.group(1) else "0"
        return whole + "." + "".join(_DIGITS[d.lower()] for d in found.group(2).split())

    words = AND_A_FRACTION.sub(_and_a_fraction, DECIMAL_IN_WORDS.sub(digits, words))
    return AMOUNT_IN_WORDS.sub(_amount_in_digits, words)


def _and_a_fraction(found: re.Match[str]) -> str:
    """A whole and a fraction in digits: 'one and a half' -> '1.5'."""
    whole = _CARDINALS.get(found.group(1).lower(), found.group(1))
    return whole + FRACTIONS[" ".join(re.split(r"[\s-]+", found.group(2).lower()))]


def _amount_in_digits(found: re.Match[str]) -> str:
    """A whole amount in digits: 'by three' -> 'by 3', 'two units' -> '2 units'."""
    if found.group(1):
        return found.group(0)[: found.start(1) - found.start()] + _CARDINALS[found.group(1).lower()]
    return _CARDINALS[found.group(2).lower()]


def _full_names(words: str, names: Sequence[str]) -> str:
    """``words`` with "the <word>" written as the one scene name that holds the word.

    Also where the full name is said too ("left of the mixing bowl, and no closer than 0.1 to the bowl").
    """
    words = _names_as_spaced(words, names)
    owners: dict[str, list[str]] = {}
    for name in names:
        for word in set(whole_words(name).split()):
            owners.setdefault(word, []).append(name)
    for name in names:
        parts = whole_words(name).split()
        for index, part in enumerate(parts if len(parts) > 1 else ()):
            if len(part) < SHORTEST_NAME_WORD or part in NOT_OBJECT_WORDS or len(owners[part]) > 1:
                continue
            rest = "".join(rf"(?:[\s_-]+{re.escape(word)}" for word in parts[index + 1 :])
            rest += ")?" * (len(parts) - index - 1)  # "the water spaniel": all of "Irish water spaniel"
            short = re.compile(rf"\b(the\s+){re.escape(part)}{rest}(?:s|es)?\b", re.I)
            words = short.sub(_called(name), words)  # the full name said already stays as said
    return words


def _names_as_spaced(words: str, names: Sequence[str]) -> str:
    """``words`` with a scene name written with its words joined or split otherwise, as the scene spells it.

    "dishwasher" for "dish washer", "dish washer" for "dishwasher": the same letters, spaced or
    hyphenated otherwise (at least ``SHORTEST_JOINED`` letters, so that no short word is read as a name).
    """
    text = whole_words(words)
    for name in names:
        spelled = whole_words(name)
        letters = spelled.replace(" ", "")
        if len(letters) < SHORTEST_JOINED or spelled in text:
            continue
        splits = [rf"{letters[:i]}[\s_-]+{letters[i:]}" for i in range(SHORTEST_NAME_WORD, len(letters) - 2)]
        respaced = re.compile(rf"\b(?:{'|'.join([re.escape(letters), *splits])})\b", re.I)
        words = respaced.sub(name.replace("\\", "\\\\"), words)
    return words


def _called(name: str) -> Callable[[re.Match[str]], str]:
    """The replacement of "the <word>" by "the <name>" (the name said in full stays as said)."""
    full = whole_words(name)
    return lambda found: (
        found.group(0)
        if whole_words(found.group(0)[len(found.group(1)) :]) == full
        else (found.group(1) + name)
    )


def _negations_as_asks(words: str, keep: Callable[[str], bool]) -> str:
    """``words`` with each negated comparison said as what it asks, but in sentences to ``keep``."""

    def said(found: re.Match[str]) -> str:
        if LIMIT.match(words[found.end() :]) or keep(_sentence_at(words, found.start())):
            return found.group(0)
        kind = next(key for key in _ASKS if found.group(key))
        much = "a lot " if FAR_FROM_IT.search(found.group(kind)) else ""
        asked = (found.group(1) or "") + much + _ASKS[kind][1].format(gap=found.group("gap") or "")
        return asked[:1].upper() + asked[1:] if found.group(0)[:1].isupper() else asked

    for negated in NEGATED_ASKS:
        words = negated.sub(said, words)
    return words


def _sentence_at(words: str, index: int) -> str:
    """The sentence of ``words`` that holds ``index``."""
    start = max(words.rfind(mark, 0, index) for mark in ".;!?") + 1
    ends = [e for e in (words.find(mark, index) for mark in ".;!?") if e >= 0]
    return words[start : min(ends) if ends else len(words)].strip()

"""The clauses of an instruction: the units that each get their own step.

One splitter for the whole product: the readers, the clearance's exemptions, the per-clause check,
the meaning tokens and the memory all read these clauses. It breaks at punctuation and at the words
that join two requests (``and``, ``then``, ``but``, ``also``), then joins back what is not a request
of its own:

- a piece that only names things ("between the chair *and the table*", "left *and right*"), or
  only qualifies the one before it ("*, a lot further*", "*, bulging upwards*", "*and keep it smooth*"
  is a request; "*and slowly*" is not);
- a lead-in that sets when or where the next request applies ("*after reaching the goal,* go left",
  "*whenever you pass near the wolf,* walk faster").

A participle that makes a second request breaks too: after a request that is complete (it ends
on a direction, a number or an object: "go slightly upwards *keeping* a smaller distance from the
chair") and, after a comma, where it asks about another kind of thing than the piece before ("visit
the sink, *slowing* down there" asks a pace after a place), names another object or turns a move
another way ("move the start 0.2 right, *lifting* the path slightly"); "arc over the middle,
*bulging* upwards" only says more about the place.

"while" breaks before a piece that is more than a place: "head left *while easing to a halt at the
end*" asks two things, but "hurry *while passing the printer*" asks one (the piece after "while"
only says where). "as" never breaks. A clause may need two steps ("go up by 0.1 at a constant
speed of 0.2"), so a clause is not a step.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from trajadapt.readers.direction_words import TO_AND_FRO, asked_kinds, said_directions
from trajadapt.readers.words import (
    NUMBER_TEXT,
    PLACE_WORDS,
    asks_distance,
    names_in,
    whole_words,
)

BREAKS = re.compile(
    r"(?:[,;:!?]|\.(?!\d))|\b(?:and then|and also|and|then|but|also"
    r"|(?<!\ba )(?<!\blittle )(?<!\bshort )(?<!\bgood )while)\b",
    re.I,
)
"""Where one request may end and the next begin: punctuation (not a decimal point) and joining words
(not inside a swing both ways, ``words.TO_AND_FRO``: "back and forth", "left and right" join no
requests)."""

LEAD_INS = re.compile(
    r"^(?:after|once|when|whenever|if|while|as|before|upon|until|as soon as|at the end|at the start"
    r"|in the end|finally|first|firstly|afterwards|near|around|close to|next to|within|inside)\b",
    re.I,
)
"""Words that open a piece saying when or where the following request applies."""

FILLER = frozenset(
    "a an the of to and or by from with as you it its is are be all way both sides side more much "
    "very bit little lot slightly than too so just then also please s re ve ll m d".split()
)
"""Words that carry no request of their own (with the ends of "it's", "you're", "we've", "it'll")."""

AS_YOU_GO = re.compile(r" as you (?:go|move|travel|pass) ")

DIRECTION_WORDS = frozenset(
    "left right up down upward upwards downward downwards front back forward forwards backward backwards "
    "above below top bottom higher lower further farther closer nearer".split()
)


def split_clauses(instruction: str, names: Sequence[str] = ()) -> tuple[str, ...]:
    """The instruction's clauses in the user's order, each a request of its own.

    >>> split_clauses("go left by 20 and slow down near the box", ["box"])
    ('go left by 20', 'slow down near the box')
    >>> split_clauses("pass between the chair and the table", ["chair", "table"])
    ('pass between the chair and the table',)
    """
    pieces = [
        part for joiner, piece in _pieces(instruction) for part in _at_participles(joiner, piece, names)
    ]
    clauses: list[str] = []
    pending = ""
    for joiner, piece in pieces:
        if pending:
            piece, pending = f"{pending} {piece}", ""
        elif clauses and not _starts_a_request(joiner, piece, clauses[-1], names):
            clauses[-1] = f"{clauses[-1]}{joiner}{piece}"
            continue
        opening = not clauses or joiner.strip() in (".", ";", "!", "?")  # an amount may set the sentence
        if LEAD_INS.match(piece) and _is_only_a_setting(piece, names, opening):
            pending = piece + ","
            continue
        clauses.append(piece)
    if pending:
        clauses.append(pending.rstrip(","))
    return tuple(clauses) or (instruction.strip(),)


def _pieces(instruction: str) -> list[tuple[str, str]]:
    """(what joined it to the piece before, the piece) for each non-empty piece."""
    pieces: list[tuple[str, str]] = []
    position, joiner = 0, ""
    swings = [found.span() for found in TO_AND_FRO.finditer(instruction)]
    for found in BREAKS.finditer(instruction):
        if any(start < found.start() < end for start, end in swings):
            continue
        piece = instruction[position : found.start()].strip()
        if piece:
            pieces.append((joiner, piece))
        elif not pieces and found.group(0).strip(",;!?."):
            continue  # a word that opens the instruction stays with it: "While passing the box, ..."
        joiner = found.group(0) if found.group(0) in ",;:" else f" {found.group(0)} "
        position = found.end()
    rest = instruction[position:].strip()
    if rest:
        pieces.append((joiner, rest))
    return [(j if j.startswith(" ") else f"{j} ", p) for j, p in pieces]


def _at_participles(joiner: str, piece: str, names: Sequence[str]) -> list[tuple[str, str]]:
    """The piece cut before each participle that follows a complete request (joiner ``PARTICIPLE``)."""
    words = piece.split(" ")
    ends = {word for name in names for word in whole_words(name).split()[-1:]}
    cuts = [i for i in range(1, len(words)) if _is_participle(words[i]) and _completes(words[i - 1], ends)]
    parts, start, glue = [], 0, joiner
    for cut in cuts:
        parts.append((glue, " ".join(words[start:cut])))
        start, glue = cut, PARTICIPLE
    parts.append((glue, " ".join(words[start:])))
    return [(glue, part) for glue, part in parts if part.strip()]


NOT_PARTICIPLES = frozenset(
    "during thing nothing something anything everything building ceiling morning evening string "
    "bring swing spring sling fling cling wring sting".split()
)


def _is_participle(word: str) -> bool:
    """An -ing verb form ('keeping', 'going'), not a noun or preposition that ends so ('during')."""
    bare = word.strip(".,;:!?").lower()
    return bare.endswith("ing") and len(bare) >= 5 and bare not in NOT_PARTICIPLES


PARTICIPLE = " "
"""The joiner of a piece cut off before a participle."""


def _completes(word: str, object_ends: set[str]) -> bool:
    """Whether a request can end on this word: a direction, a number, an amount or an object's name."""
    bare = word.strip(".,;:!?").lower()
    return (
        bare in DIRECTION_WORDS
        or bare in object_ends
        or bare.replace(".", "", 1).isdigit()
        or bare in {"slightly", "more", "less", "much", "lot", "bit"}
    )


def _starts_a_request(joiner: str, piece: str, previous: str, names: Sequence[str]) -> bool:
    """Whether a piece is a clause of its own rather than more words of the previous one."""
    if joiner.strip().lower() == "while":
        return not _only_a_place(piece, names)
    if joiner.strip() == ":" and _only_a_topic(previous, names):
        return False  # "start point: move it left", "the lamp: keep well away from it"
    if joiner.strip() not in ("", ",", ":", "and", "but", "also"):
        return True  # a sentence mark, "then"
    if joiner.strip().lower() in ("also", "and") and AUXILIARY_AT_END.search(previous):
        return False  # "the last stretch should *also* run slower": the verb of the piece before
    if joiner.strip() == "and" and _second_of_a_pair(previous, piece, names):
        return False  # "the midpoint between the heron *and the spaniel* ..."
    if joiner.strip() == "and" and RANGE_OPENED.search(previous) and RANGE_CLOSED.match(piece):
        return False  # "keep the height between z = -0.2 *and z = 0.2*"
    if joiner.strip() == "and" and FIRST_END.search(previous) and SECOND_END.match(piece):
        return False  # "leave the start *and end points* where they are"
    participle = _is_participle(piece.split()[0])
    if participle and joiner == PARTICIPLE:
        return bool(_content_words(piece, names)[1:]) or bool(said_directions(piece))
    if participle and joiner.strip() == ",":
        if _only_a_heading(piece, names) and not said_directions(previous):
            return False  # "keep going 0.15 beyond the goal, *heading forward*": the going-on's direction
        return bool(asked_kinds(piece) - asked_kinds(previous)) or _asks_more(piece, previous, names)
    return _asks_something(piece, names)


AUXILIARY_AT_END = re.compile(
    r"(?<!\byou\s)(?<!\bwe\s)(?<!\bi\s)(?<!\bit\s)"
    r"\b(?:should|must|will|shall|can|could|would|may|might|has\s+to|have\s+to|needs?\s+to|ought\s+to)\s*$",
    re.I,
)
"""A piece that ends on an auxiliary has its verb in the next one ("the end should | also run
slower"): no request of its own ("as fast as you can" is one, its verb said before)."""

HEADING_WORDS = frozenset(
    "heading head headed going moving travelling traveling facing pointing pointed aiming aimed toward "
    "towards direction straight ahead onward onwards continuing proceeding carrying on".split()
)
"""Words of a participle that only says which way the motion goes ("heading forward", "going left",
"continuing backward")."""


def _only_a_heading(piece: str, names: Sequence[str]) -> bool:
    """Whether a piece says only a direction of travel: "heading forward", "pointing toward the left"."""
    words = _content_words(piece, names)
    return len(said_directions(piece)) == 1 and all(w in HEADING_WORDS or w in DIRECTION_WORDS for w in words)


_VALUE = rf"(?:(?:z|x|y|height|speed)\s*=\s*|(?:a\s+)?(?:height|speed|altitude)\s+of\s+)?-?(?:{NUMBER_TEXT})"
RANGE_OPENED = re.compile(rf"\bbetween\s+{_VALUE}(?:\s*(?:m|cm|mm|m/s))?$", re.I)
RANGE_CLOSED = re.compile(rf"{_VALUE}\b", re.I)
"""A range of numbers: "between z = -0.2 *and* z = 0.2", "between 0.5 *and* 1.2 m" (one clause)."""
_END_NOUN = r"(?:start|starting|beginning|initial|first|origin|end|ending|goal|final|last|finish|destination)"
FIRST_END = re.compile(
    rf"\b(?:the|its|both)\s+{_END_NOUN}(?:\s+(?:point|position|pose|location|waypoint))?$", re.I
)
SECOND_END = re.compile(
    rf"^(?:the\s+)?{_END_NOUN}\b(?!\s+(?:(?:at|near|by|up|with|on|in|beside|next|there|here|right|over|again"
    r"|above|below|after|around|along|behind|under|inside|outside"
    r"|to|further|farther|higher|lower|more|less|a|an|[a-z]+ing)\b|\d|\.\d))",
    re.I,
)
"""Both ends of the path named together: "the start *and* end points", "the start *and* the goal" (one
clause); not where the second word is a verb ("go to the end and start slowing", "and end at the lamp",
"and finish 0.2 higher")."""
PAIRING = re.compile(r"\b(?:between|of)\s+(?:the\s+)?[\w\s-]+$", re.I)
"""A piece that ends with the first of a pair of objects: "between the heron", "the midpoint of X"."""


THE_ROBOT = re.compile(
    r"\bbetween\s+(?:the\s+|your\s+|its\s+)?(?:robot|drone|arm|gripper|end\s+effector|tool|vehicle|craft"
    r"|quadcopter|rover|path|route|trajectory|yourself|you|it|us)$",
    re.I,
)
"""A pair whose first is the robot itself: "keep a clear metre between the robot *and the fan*"."""


def _second_of_a_pair(previous: str, piece: str, names: Sequence[str]) -> bool:
    """Whether ``previous`` ends "between <object or robot>" and ``piece`` begins with the second object."""
    ending = PAIRING.search(previous)
    if ending is None or not (names_in(ending.group(0), names) or THE_ROBOT.search(previous)):
        return False
    start = whole_words(piece)
    return any(
        start.startswith(spoken) or start.startswith(f" the{spoken}")
        for spoken in (whole_words(name) for name in names if name.strip())
    )


MOVING = frozenset(
    "go going goes move moving moves travel travelling traveling drive driving walk walking fly flying "
    "past in at on through".split()
)
"""Words that only say the robot moves somewhere ("while going past the box"): no request of their own."""


def _asks_more(piece: str, previous: str, names: Sequence[str]) -> bool:
    """Whether a piece names an object the one before does not, or a second direction after one.

    "stay 0.2 from the marmoset, *easing off near the paddle*" and "move the start 0.2 right,
    *lifting the path slightly*" ask something more; "arc over the middle, *bulging upwards*" does not.
    """
    before, said = said_directions(previous), said_directions(piece)
    return bool(set(names_in(piece, names)) - set(names_in(previous, names))) or bool(
        before and said - before
    )


ROBOT_ITSELF = re.compile(
    r"\b(?:the|your|its|our)\s+(?:robot|drone|arm|gripper|end\s+effector|tool|vehicle|craft|quadcopter|rover)\b",
    re.I,
)
"""The robot itself as a piece's subject: "while *the gripper* is near the packet" only says where."""


def _only_a_place(piece: str, names: Sequence[str]) -> bool:
    """Whether a piece only says where along the path ("passing close to the quill", "you are near it")."""
    if asks_distance(piece) or said_directions(piece):
        return False  # "while moving nearer to the bow" asks to come closer
    return not set(_content_words(PLACE_WORDS.sub(" ", ROBOT_ITSELF.sub(" ", piece)), names)) - MOVING


def _content_words(piece: str, names: Sequence[str]) -> list[str]:
    """The words of ``piece`` that are not an object's name or filler."""
    text = AS_YOU_GO.sub(" ", whole_words(piece))
    for name in sorted(names, key=len, reverse=True):
        spoken = whole_words(name)
        if spoken.strip():
            text = text.replace(spoken, " ")
    return [word for word in text.split() if word not in FILLER and not word.replace(".", "").isdigit()]


def _asks_something(piece: str, names: Sequence[str]) -> bool:
    """Whether a piece is a request of its own.

    It has a word beyond names, filler, directions and amounts (``AMOUNT_WORDS``), and does not
    start with a word that qualifies the piece before it (an -ing or -ly word).
    """
    words = _content_words(piece, names)
    if not [w for w in words if w not in DIRECTION_WORDS]:
        return False
    if AN_AMOUNT.search(piece) and not [
        w for w in words if w not in DIRECTION_WORDS | AMOUNT_WORDS | HEADING_WORDS
    ]:
        return False  # "*, at least 15 cm*", "*, roughly half a metre*": the amount of the piece before
    first = piece.split()[0].lower()
    return not (_is_participle(first) or _is_adverb(first))


AMOUNT_WORDS = frozenset(
    "at least most less fewer minimum maximum about around roughly approximately approx some or so no "
    "under over good full half quarter third cm mm m metre metres meter meters centimetre centimetres "
    "centimeter centimeters millimetre millimetres millimeter millimeters degree degrees deg another extra "
    "additional".split()
)
"""Words of a piece that only gives an amount: a number's unit, its bound and its hedge ("at least
15 cm", "roughly half a metre", "about 30 degrees", "another 10 cm or so straight ahead", with a
heading: ``HEADING_WORDS``): the amount of the request before it."""
AN_AMOUNT = re.compile(r"\d|\b(?:half|quarter|third)\b", re.I)
"""A number or a share: what a piece of amount words must have to be an amount ("around the maraca"
is a place)."""


LY_VERBS = frozenset("fly apply supply rely reply multiply comply".split())
"""Verbs that end like an adverb: "and fly more slowly" is a request, "and slowly" is not."""


def _is_adverb(word: str) -> bool:
    """A word that qualifies the piece before it ('slowly', 'smoothly'), not a verb ending so ('fly')."""
    return word.endswith("ly") and word not in LY_VERBS


TOPIC_WORDS = frozenset(
    "first second third last final half halves quarter section segment part portion stretch leg bit "
    "beginning ending start starting opening closing speed pace velocity height altitude".split()
)
"""Words that may name what a request is about when said first as its topic ("start point: ...")."""


def _only_a_topic(piece: str, names: Sequence[str]) -> bool:
    """Whether a piece only names what the next is about: a part, an object, the speed; no request."""
    if said_directions(piece) or re.search(r"\d", piece):
        return False
    return all(word in SETTING_WORDS or word in TOPIC_WORDS for word in _content_words(piece, names))


def _is_only_a_setting(piece: str, names: Sequence[str], opening: bool = False) -> bool:
    """A lead-in that says when or where and asks nothing ('after reaching the goal').

    One that opens a sentence may give an amount ('Within about a metre of the piano, ...'); after a
    request, such a piece is that request's amount ('swing by the piano, within about 30 cm of it').
    """
    words = _content_words(LEAD_INS.sub("", piece), names)
    settings = SETTING_WORDS | NEARNESS | MOVING | (AMOUNT_WORDS if opening else frozenset())
    return all(w.endswith(("ing", "ed")) or w in settings for w in words)


SETTING_WORDS = frozenset(
    "goal start end position destination target point path trajectory arriving arrive arrives arrival "
    "reach reaches reached get gets got hit hits at done finished there middle halfway current present "
    "original usual old existing planned final".split()
)
"""Words a lead-in may have besides its opening word and object names."""

NEARNESS = frozenset(
    "near nearby nearer close closer next proximity vicinity surroundings surrounding within beside "
    "alongside abreast level "
    "around past pass passes by re are is am get gets come comes".split()
)
"""Words of a lead-in that says where the next request applies: "whenever you pass near the wolf,"."""


KEEPING = re.compile(
    r"\b(?:keep\w*|maintain\w*|retain\w*|preserv\w*|same|fixed|unchanged|unaltered|untouched"
    r"|as (?:it|they) (?:is|are)|where (?:it|they) (?:is|are)|in place|do(?:n't| not) (?:move|change))\b",
    re.I,
)


def only_keeps(clause: str, names: Sequence[str] = ()) -> bool:
    """Whether the clause only asks that something stay as it is: it needs no step of its own.

    "keeping the start fixed", "the goal stays where it is". A clause that names an object, a
    direction, a pace or a place ("keep 0.2 from the box", "keep left") asks more than that.
    """
    return (
        bool(KEEPING.search(clause))
        and not asked_kinds(clause)
        and not names_in(clause, names)
        and not re.search(r"\d", clause)
    )

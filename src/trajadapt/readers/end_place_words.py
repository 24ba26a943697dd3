"""Words that place the path's end at an object: "finish at", "end right next to", "stop within 0.1 of".

The vocabulary of the end-places reader (``readers.end_places``): an ending verb ("end", "finish",
"wrap up", "park", "come to rest", ...) followed by a word that puts the end on, above, beside,
within a distance of, or where the path passes nearest an object; "there" after an ending verb;
words that name an object as the end; going onto an object to finish. Lengths are in metres by the
time these are read (``read_against_words`` read "10 cm" as 0.1).
"""

from __future__ import annotations

import re

from trajadapt.readers.stop_words import COMING_TO_REST
from trajadapt.readers.words import NUMBER_TEXT

_NOT_A_NOUN = r"(?<!the\s)(?<!its\s)(?<!your\s)(?<!their\s)(?<!this\s)(?<!that\s)(?<!an\s)"
_ENDING = (
    rf"\b{_NOT_A_NOUN}(?:end(?:s|ed|ing)?|finish(?:es|ed|ing)?|terminat\w*|conclud\w*|arriv\w*"
    r"|land(?:s|ed|ing)?|settl\w*|wrap(?:s|ped|ping)?\s+(?:it\s+|things\s+)?up|wind(?:s|ing)?\s+up|wound\s+up"
    r"|come\s+to\s+rest|comes\s+to\s+rest|finish(?:es|ed|ing)?\s+up|end(?:s|ed|ing)?\s+up"
    r"|set(?:s|ting)?\s+down|touch(?:es|ed|ing)?\s+down|park(?:s|ed|ing)?|pull(?:s|ed|ing)?\s+up"
    rf"|{COMING_TO_REST.pattern})"
    r"(?:\s+(?:with\s+)?(?:the\s+|its\s+|your\s+)?(?:path|route|trajectory|motion|run|flight|drive|journey"
    r"|movement|robot|drone|arm|gripper|end\s+effector|tool|vehicle|it))?"
    r"(?:\s+(?:exactly|right|directly|precisely|just|squarely|somewhere))?\s+"
)
AT_PLACE = re.compile(_ENDING + r"(?:at|on|onto|in|into|upon|over\s+at)\b", re.I)
"""An ending verb with a word that puts the end on the object: "finish at", "land on"."""
NEAREST_PLACE = re.compile(
    r"\b(?:(?:stop|end|finish|halt|terminat)\w*(?:\s+(?:it|(?:the|its|your)\s+\w+))?(?:\s+short)?"
    r"|cut\w*\s+(?:it|(?:the|its|your)\s+\w+)\s+short)\s+"
    r"(?:(?:at|in)\s+the\s+(?:point|spot|place|position)\s+)?where\s+(?:it|the\s+\w+(?:\s+\w+)?)\s+"
    r"(?:gets|comes|passes|is|goes|runs|swings|flies|drives)\s+(?:(?:the|its)\s+)?(?:closest|nearest)\s+to\b",
    re.I,
)
"""An end where the path passes nearest an object: "end the motion where the arm gets closest to",
"stop the path where it comes closest to", "stop at the spot where it passes closest to"."""
THERE_PLACE = re.compile(
    rf"\b{_NOT_A_NOUN}(?:end|finish|terminat|conclud|land|park|settl)\w*(?:\s+(?:it|things))?(?:\s+up)?"
    r"\s+(?:(?:right|exactly|just)\s+)?there\b(?!\s+for\b)",
    re.I,
)
"""An ending verb with "there": "bring it to the mug and end there", "finish right there" (a rest
"there", "come to a stop there", rests where the end already is, or where the path passes)."""
ABOVE_PLACE = re.compile(
    _ENDING + rf"(?:(?:about|roughly|around|approximately|some)\s+)?(?P<amount>{NUMBER_TEXT})?\s*"
    r"(?:(?:directly|right|just|straight|exactly)\s+)?(?:above|over)\b",
    re.I,
)
"""An ending verb with a height over the object: "finish about 0.1 directly above", "end just above"
(lengths are in metres by now: ``read_against_words`` read "10 cm" as 0.1)."""
BESIDE_PLACE = re.compile(
    _ENDING + r"(?:beside|next\s+to|near|nearby|by|close\s+to|alongside|adjacent\s+to|against)\b", re.I
)
"""An ending verb with a word that puts the end beside the object: "wind up next to", "end beside"."""
WITHIN_PLACE = re.compile(
    _ENDING + r"(?:[a-z]+ing\s+)?(?:within|no\s+(?:more|further|farther)\s+than|at\s+most)\s+"
    rf"(?:(?:about|roughly|around|approximately|some)\s+)?(?P<within>{NUMBER_TEXT})\s*(?:m\s+|metres?\s+|meters?\s+)?"
    r"(?:of|from|away\s+from)\b",
    re.I,
)
"""An ending verb with a distance the end stays within: "come to rest within 0.1 of", "set down no
more than 0.2 from", "come to a stop hovering within about 0.4 of" (lengths in metres by now)."""
RIGHT_BESIDE = re.compile(r"\b(?:right|directly|exactly|squarely|just)\b|\bagainst\b", re.I)
"""Words that put the end close beside the object ("end right next to", "finish right by", "park up
against"): the end goes on to beside it. A plain "wrap up beside the sofa", "come to a stop by the
bed" ends where the path passes nearest it (where the new-instruction sets were measured, 7 of 7
judges of "right beside" read the object, 4 of 8 of a plain "beside" the path's nearest point)."""
_END_NOUN = (
    r"(?:new\s+)?(?:end\s*-?\s*point|end|final\s+(?:point|position|spot|location|waypoint|destination|stop)"
    r"|finish(?:ing)?(?:\s+(?:point|line|spot))?|destination|goal|last\s+(?:point|waypoint|stop)"
    r"|landing\s+(?:spot|point|place|site)|stopping\s+(?:point|place)|terminus)"
)
NAMED_AS_END = re.compile(
    rf"\b(?:make|use|treat|have|set|take|let|choose|pick)\s+(?P<named>.+?)\s+(?:as\s+|be\s+|become\s+)?"
    rf"(?:your|the|its|our|a)\s+{_END_NOUN}\b"
    rf"|\b(?:your|the|its)\s+{_END_NOUN}\s+(?:is|should\s+be|will\s+be|must\s+be|becomes|being|=)\s+(?P<then>.+)",
    re.I,
)
"""Words that make an object the end: "make the quill your end point", "the final position should be X"."""
FINISHING = re.compile(r"\b(?:to\s+(?:finish|end)|at\s+the\s+(?:very\s+)?end|in\s+the\s+end|finally)\b", re.I)
ONTO = re.compile(
    r"\b(?<!closer\s)(?<!nearer\s)(?<!close\s)(?<!closest\s)(?<!nearest\s)(?<!next\s)(?<!up\s)"
    r"(?:onto|on\s+to|into|to|at|on)\s+",
    re.I,
)
"""A clause that goes onto an object to finish ("bring the gripper down onto the soap to finish",
"at the end go to the box"): the object is the end."""

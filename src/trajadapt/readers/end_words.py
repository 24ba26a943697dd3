"""Words that keep an end of the path where it is: "keep the start fixed", "with the endpoints pinned".

Read by the kept-ends reader (which puts such an end back) and by the effect's flags (which say
when it moved). The words that name each end are ``words.START`` and ``words.GOAL``.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from trajadapt.readers.words import GOAL, START

_PLACE_NOUN = r"(?:positions?|points?|poses?|waypoints?|spots?|places?|locations?)"
_END = (
    rf"(both\s+end(?=\s+{_PLACE_NOUN}\b)|start\w*|begin\w*|initial|take[\s-]?off|end|ends|ending|endpoints?"
    r"|goal|final|destination|both\s+ends|either\s+end(?:point)?s?"
    r"|landing(?=\s+(?:spot|point|pad|place|site|position|zone))|touch[\s-]?down)"
)
_ENDS = (
    rf"(?:both\s+(?!end\b))?(?:the\s+)?{_END}(?:\s+(?:and|&|or)\s+(?:the\s+)?{_END})?"
    rf"(?:\s+{_PLACE_NOUN})?"
)
_STATE = (
    r"(?:(?:exactly|just|precisely|right|firmly|completely|totally|entirely)\s+)?(?:the\s+)?(?:same|fixed|unchanged|untouched|in\s+place|put|pinned|still|locked"
    r"|where\s+(?:it|they)\s+(?:is|are|was|were)|as\s+(?:(?:it|they)\s+)?(?:is|are|was|were)|alone)"
)
_MODAL = (
    r"(?:(?:should|must|will|shall|can|has\s+to|have\s+to|needs?\s+to|is\s+to|are\s+to|ought\s+to)"
    r"\s+(?:still\s+|also\s+)?)"
)
"""A modal before the keeping verb: "the goal *has to* stay", "the start *needs to* remain"."""
KEPT_ENDS = (
    re.compile(
        rf"(?:^|[,;:.(]\s*|\b(?:and|with|but)\s+){_ENDS}\s+(?:(?:left|kept|held)\s+)?"
        r"(?:unchanged|untouched|fixed|pinned|in\s+place|as\s+(?:is|before))\b",
        re.I,
    ),
    re.compile(rf"\b(?:keep\w*|leav\w*|hold\w*|maintain\w*|preserv\w*)\s+{_ENDS}\s+{_STATE}", re.I),
    re.compile(
        rf"\b(?:(?:do\s+not|don't|never|without)\s+(?:chang|mov|alter|touch)\w*|fix\w*|pin\w*)\s+{_ENDS}\b"
        r"(?!\s+(?:speed|pace|velocity|height|altitude))",
        re.I,
    ),
    re.compile(
        rf"\b(?<!neither\s)(?<!not\s){_ENDS}\s+{_MODAL}?(?:stay\w*|remain\w*|(?:is|are)\s+kept|(?:is|are)|be(?:\s+kept)?(?!\s+(?:put|still)\b))\s+{_STATE}",
        re.I,
    ),
    re.compile(
        rf"\b(?<!neither\s)(?<!not\s){_ENDS}\s+(?:(?:must|should|shall|will|would|can|may|needs?\s+to|has\s+to"
        r"|have\s+to)(?:n't|\s+not|\s+never)\s+(?:be\s+|get\s+)?|(?:is|are)(?:n't|\s+not)\s+(?:to\s+be\s+)?(?=\w+ed\b))"
        r"(?:mov|chang|alter|shift|touch|budg|displac)\w*",
        re.I,
    ),
    re.compile(
        rf"\bwith\s+{_ENDS}\s+(?:(?:left|kept|held|staying|remaining)\s+)?(?:fixed|pinned|unchanged|untouched"
        r"|in\s+place|locked|as\s+(?:they|it)\s+(?:are|is))",
        re.I,
    ),
    re.compile(
        r"\b(?:at|to|on|in|into|for|with|reach\w*|toward\w*|keep\w*|retain\w*|preserv\w*|maintain\w*)\s+"
        rf"(?:the\s+|its\s+|your\s+|their\s+)?(?:same|original|usual|old|planned|intended|existing|normal"
        rf"|regular|unchanged)\s+{_ENDS}",
        re.I,
    ),
    re.compile(
        r"\b(?P<end>finish|end)(?:s|ed|ing)?\s+(?:(?:it|up|off|exactly|just|the\s+same)\s+)*"
        r"as\s+(?:before|(?:it\s+)?(?:did|does|was|used\s+to)\b)",
        re.I,
    ),
    re.compile(
        r"\b(?P<end>finish|end|start|begin)(?:s|ed|ing|ning)?\s+(?:up\s+|off\s+)?(?:at|in|on|from)\s+"
        r"(?:(?:exactly|just|precisely)\s+)?the\s+(?:very\s+)?same\s+(?:spot|place|point|position|location|pose)\b"
        r"(?!\s+(?:as|where|that|which|for)\b)"
        r"|\b(?P<there>finish|end|stop)(?:s|ed|ing)?\s+(?:up\s+)?(?:exactly\s+|just\s+)?where\s+"
        r"(?:it|you|we|they|the\s+(?:path|route|robot|arm|drone|trajectory))\s+(?:(?:normally|usually|currently"
        r"|always|originally)\s+)?(?:ends|finishes|stops|did|does|would|used\s+to)\b",
        re.I,
    ),
)
"""Words that keep an end of the path where it is: "keeping the start and end positions the same",
"don't change the start and end positions", "the endpoints stay fixed", "finish at the original goal",
"head to the same endpoint", "on to the usual end spot", "keeping the same start", "then finish
exactly as before", "finish where you normally would", "leave the start and end points exactly where
they are", "the end point is not moved", "the start pose must not change", "ending at the same
spot", "starting from the same point", "end where it ends now", and
said without a verb: "...; goal unchanged", "start and end fixed"."""


def kept_ends(requests: Sequence[str]) -> set[str]:
    """The ends of the path ('start', 'goal') the words keep where they are ("keep the start and end fixed").

    A later request that names the end ("now move the goal left") takes the keeping back.
    """
    kept: set[str] = set()
    for request in requests:
        kept -= {end for end, named in (("start", START), ("goal", GOAL)) if named.search(request)}
        for pattern in KEPT_ENDS:
            for found in pattern.finditer(request):
                kept |= {end for word in found.groups() if word for end in _ends_of(word)}
    return kept


def _ends_of(word: str) -> tuple[str, ...]:
    """Which ends a word names: ('start',), ('goal',), or both (endpoints, both ends)."""
    word = word.lower()
    if word.startswith(("start", "begin", "initial", "take")):
        return ("start",)
    both = word.startswith(("endpoint", "both", "either")) or word == "ends"
    return ("start", "goal") if both else ("goal",)


def without_kept_ends(words: str) -> str:
    """``words`` less what keeps an end where it is ("move the goal back, *keeping the start unchanged*")."""
    spans = [found.span() for pattern in KEPT_ENDS for found in pattern.finditer(words)]
    return "".join(" " if any(a <= i < b for a, b in spans) else c for i, c in enumerate(words))

"""The request: the user's words less what they only say about the path as it is now."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from trajadapt.readers.plain_words import plain_words
from trajadapt.readers.request_words import OPENER, is_statement, request_words

NAMES = ["lamp", "red mug", "chair", "Person"]
PARAPHRASES = Path(__file__).parent / "data" / "paraphrases"


@pytest.mark.parametrize(
    ("words", "read"),
    [
        # a statement whose object the fix names again
        ("It's too slow near the lamp. Speed up near the lamp.", "Speed up near the lamp."),
        # the fix points back to the object of the statement
        ("The lamp is much too close. Keep further away from it.", "Keep further away from the lamp."),
        ("You rushed past the red mug; take it slower around that one", "take it slower around the red mug."),
        ("It never stops by the chair. Wait there for 4 timesteps.", "Wait near the chair for 4 timesteps."),
        ("It swings way wide of the lamp; bring it in closer", "bring it in closer to the lamp."),
        # the fix first, the reason after a dash or 'because'
        (
            "Lift the path by 0.1 over the chair - it scrapes over the chair",
            "Lift the path by 0.1 over the chair.",
        ),
        ("Move left 0.2 because the path is too far right", "Move left 0.2."),
        ("Near the chair it's far too quick. Ease off a lot there.", "Ease off a lot near the chair."),
        # a part of the path, a place to start from
        ("The last third is too fast. Slow down there.", "Slow down in the last third."),
        ("It halts at the goal; from there, loop around the chair", "from the goal, loop around the chair."),
        # an opener that asks nothing
        ("No, go left by 0.3", "go left by 0.3."),
        ("Close, but keep further from the lamp", "keep further from the lamp."),
        ("Nope - go right. Hmm.", "go right."),
        # a question about the path, an opener
        ("Why does it halt right at the goal? Carry on 0.3 past the goal.", "Carry on 0.3 past the goal."),
        (
            "It's far too quick beside the red mug. Ease off beside the red mug.",
            "Ease off beside the red mug.",
        ),
        ("Currently the route hugs the chair; give the chair more room", "give the chair more room."),
        ("The path dips too low. Raise it by 0.2!", "Raise it by 0.2."),
        ("It cuts too wide of the lamp; bring it in closer.", "bring it in closer to the lamp."),
        (
            "Hmm, it ends at the goal position. Once it gets there, go up by 0.2.",
            "Once it gets to the goal, go up by 0.2.",
        ),
    ],
)
def test_the_statement_leaves_and_pointing_back_is_written_out(words, read):
    assert request_words(words, NAMES) == read


@pytest.mark.parametrize(
    ("words", "read"),
    [  # what the robot does now, said as what to do instead of (session 37)
        ("Instead of stopping and starting again, hold 0.3 the whole way.", "hold 0.3 the whole way."),
        ("Pass left of the lamp rather than swinging wide to the right, then slow down.", "Pass left of the lamp, then slow down."),
        ("Go left. Instead of creeping near the chair, speed up near the chair.", "Go left. speed up near the chair."),
        ("Pass left of the lamp instead of going right and slow down near the lamp.", "Pass left of the lamp and slow down near the lamp."),
    ],
)  # fmt: skip
def test_what_to_do_instead_of_leaves_where_nothing_is_lost(words, read):
    assert request_words(words, NAMES) == read


@pytest.mark.parametrize(
    "words",
    [
        "Instead of stopping at the goal, carry on another 0.2 forward.",  # the goal is said only there
        "go over the box rather than around",  # no doing
        "Go left. Instead of creeping near the box go faster near the box.",  # no comma: the piece's end unsaid
    ],
)
def test_what_to_do_instead_of_stays_where_it_names_what_the_rest_does_not(words):
    assert request_words(words, NAMES) == words


@pytest.mark.parametrize(
    "words",
    [
        "Go left by 0.2 and slow down near the lamp",
        "The end point sits too far left. Move it 0.1 right.",
        "The path should stay low. Go left by 0.1.",
        "It should stop at the goal",  # a request about the path
        "The goal is off. Move it right by 0.1.",  # 'it' is the goal: nothing points back to a place
        "It passes the lamp and the chair too closely. Stay further from it.",  # two objects: 'it' is unclear
        "The path is too low.",  # nothing but the statement
        "Go faster - it's too slow near the lamp",  # the place is said only in the reason
        "Why not go left by 0.3?",  # a suggestion
        "don't go left of the lamp",  # an imperative, not a question
        "Close to the lamp, slow down",  # a place, not an opener
        "Whenever you pass near the lamp, walk faster",  # a condition, not a statement
        "No more than 0.2 from the lamp",
    ],
)
def test_words_are_kept_whole_where_something_would_be_lost(words):
    assert request_words(words, NAMES) == words


@pytest.mark.parametrize(
    "words",
    [
        "you went too fast past the lamp",
        "the red mug is way too close",
        "how come it stops so early",
        "Right now, near the chair, it dips low",
        "nope, it's still too high",
    ],
)
def test_statements(words):
    assert is_statement(words)


@pytest.mark.parametrize(
    "words",
    [
        "you should go faster",
        "go left",
        "keep the start where it is",
        "stay above the lamp",
        "the path must avoid the lamp",
        "approach the chair and hover there",
        "the new goal is the point between the two crates",  # said as a fact, asked as a change
        "the new destination is beside the lamp",
    ],
)
def test_requests(words):
    assert not is_statement(words)


def _reworded_sets() -> list[Path]:
    return sorted(p for p in PARAPHRASES.glob("*.json") if p.stem not in {"probe-n", "probe-o"})


@pytest.mark.parametrize("path", _reworded_sets(), ids=lambda p: p.stem)
def test_requests_that_state_no_problem_are_read_as_said(path):
    """The sets written as requests read as said in plain form, but for sentences that only set the scene.

    Probe L's instructions give reasons ("The damselfly is easily scared; walk much slower around
    the damselfly"): such a sentence leaves whole, and nothing else of the words changes.
    """
    data = json.loads(path.read_text())
    sets = [data["paraphrases"]] if "paraphrases" in data else list(data["sets"].values())
    plain = [plain_words(words, [], is_statement) for reworded in sets for words in reworded.values()]
    changed = [(words, request_words(words, [])) for words in plain]
    changed = [(words, read) for words, read in changed if read != words]
    openers = [(words, read) for words, read in changed if set(_sentences(read)) == _opened(words)]
    for words, read in changed:
        assert set(_sentences(read)) < set(_sentences(words)) or (words, read) in openers
    assert len(changed) - len(openers) == (5 if path.stem == "probe-l" else 0)
    assert len(openers) == (1 if path.stem == "probe-s" else 0)  # "Hmm, can you go higher?"


POINTED_IN_OVITA = {"extended_54": ("hover above it", "hover above the lantern")}
"""The one OVITA instruction with something to rewrite: an "it" after a word of place (pointed_objects)."""


def test_the_original_instructions_are_read_exactly_as_said(ovita_dir):
    """OVITA's own words hold no list, number in words, short name or negated comparison to rewrite."""
    for path in sorted(ovita_dir.rglob("*.json")):
        case = json.loads(path.read_text())
        names = [o["name"] if isinstance(o, dict) else str(o) for o in case.get("objects") or []]
        words = case.get("instruction") or ""
        said, plain = POINTED_IN_OVITA.get(path.stem, ("", ""))
        assert request_words(words, names) == words.replace(said, plain), path.stem


def _opened(words: str) -> set[str]:
    """The sentences of ``words`` less an opener that asks nothing ("Hmm, ...")."""
    return {OPENER.sub("", sentence) for sentence in _sentences(words)}


def _sentences(words: str) -> list[str]:
    return [s.strip() for s in re.split(r"[.;!?](?!\d)", words) if s.strip()]

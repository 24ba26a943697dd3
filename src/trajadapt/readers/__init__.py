"""Reading the answer against the user's words: one stage, its readers in ``READERS`` order.

A small model's skill program often does something its words did not ask: a step nobody asked for,
a made-up amount, a shift in a direction nobody said, a speed change for the whole path that the
words tie to one object. Each reader looks at the program and the user's words (the instruction and
any feedback) and changes the lines that contradict them, with a note that says what and why.
``read_against_words`` runs them all in order; the session, the tests and the replay tool call it.

Readers share the word helpers of ``readers.words``, ``readers.object_words`` and
``readers.clause_amounts`` and the code helpers of ``trajadapt.code_parse``; no reader imports
another. To add one: write a module here with a function ``(code, asked, names) -> (code, notes)``
and put it in ``READERS`` where it must run. One function may run twice: ``relations-left`` runs
asked-relations again after every other reader, for a clause whose step a later reader left out.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from trajadapt.readers.alternating_shifts import alternate_shifts
from trajadapt.readers.asked_directions import add_asked_directions
from trajadapt.readers.asked_paces import add_asked_paces
from trajadapt.readers.asked_pass_overs import add_asked_pass_overs
from trajadapt.readers.asked_pauses import add_asked_pauses
from trajadapt.readers.asked_relations import add_asked_relations
from trajadapt.readers.asked_shapes import add_asked_shapes
from trajadapt.readers.asked_turns import turn_as_asked
from trajadapt.readers.clause_amounts import in_metres
from trajadapt.readers.curve_asks import bend_as_asked
from trajadapt.readers.end_places import end_at_asked_places
from trajadapt.readers.height_asks import relate_heights
from trajadapt.readers.held_paces import hold_stated_paces
from trajadapt.readers.kept_ends import keep_kept_ends
from trajadapt.readers.object_asks import replace_object_steps
from trajadapt.readers.object_mentions import chosen_referents
from trajadapt.readers.pace_directions import turn_paces_as_asked
from trajadapt.readers.paced_places import leave_out_moves_of_paced_places
from trajadapt.readers.part_scope import scope_to_parts
from trajadapt.readers.past_the_goal import add_destination
from trajadapt.readers.repeated_steps import cut_copies, leave_out_repeats
from trajadapt.readers.request_words import request_words
from trajadapt.readers.scaled_distances import scale_distances
from trajadapt.readers.scene_sides import sides_of_the_scene
from trajadapt.readers.speed_profiles import profile_paces
from trajadapt.readers.speed_scope import localize_speed
from trajadapt.readers.stated_amounts import use_stated_amounts
from trajadapt.readers.unasked_directions import replace_unasked_shifts
from trajadapt.readers.unasked_steps import leave_out_unasked
from trajadapt.readers.unnamed_objects import leave_out_unnamed
from trajadapt.readers.unstated_amounts import replace_unstated_amounts
from trajadapt.readers.waypoint_counts import count_as_asked
from trajadapt.readers.whole_way_paces import whole_way_paces

ReadFunction = Callable[[str, Sequence[str], Sequence[str]], tuple[str, list[str]]]


@dataclass(frozen=True)
class Reader:
    """One reader: its name (on its notes), what it reads, and the function that does it."""

    name: str
    reads: str
    read: ReadFunction


@dataclass(frozen=True)
class ReaderNote:
    """A change a reader made, in words, and which reader made it."""

    reader: str
    message: str


READERS: tuple[Reader, ...] = (
    Reader("repeated-steps", "back-to-back copies of a step: a decoding loop",
           lambda code, asked, _: leave_out_repeats(code, asked)),
    Reader("unasked-steps", "steps of a topic the words never mention", leave_out_unasked),
    Reader("unnamed-objects", "steps about an object the words never name", leave_out_unnamed),
    Reader("scaled-distances", "a distance from an object the words multiply", scale_distances),
    Reader("unstated-amounts", "amounts the words never give",
           lambda code, asked, _: replace_unstated_amounts(code, asked)),
    Reader("asked-turns", "a turn's angle and sense as its clause says them",
           lambda code, asked, _: turn_as_asked(code, asked)),
    Reader("asked-directions", "a direction a clause asks and no step makes",
           lambda code, asked, _: add_asked_directions(code, asked)),
    Reader("stated-amounts", "a clause's one direction and amount, used as said",
           lambda code, asked, _: use_stated_amounts(code, asked)),
    Reader("height-asks", "heights said as a limit or a level",
           lambda code, asked, _: relate_heights(code, asked)),
    Reader("object-asks", "what each clause asks of the object it names", replace_object_steps),
    Reader("scene-sides", "a side of an object nobody named, where the words name none", sides_of_the_scene),
    Reader("asked-relations", "a closer/further a clause asks of an object and no step makes",
           add_asked_relations),
    Reader("asked-pass-overs", "objects a clause asks to pass over and no step passes over",
           add_asked_pass_overs),
    Reader("past-the-goal", "a place the words ask to go to once the goal is reached",
           add_destination),
    Reader("asked-pauses", "a pause a clause asks for a count of timesteps (or a while) and no step makes",
           add_asked_pauses),
    Reader("asked-shapes", "a weave or a loop a clause asks and no step makes", add_asked_shapes),
    Reader("unasked-directions", "a shift in a direction nobody said", replace_unasked_shifts),
    Reader("part-scope", "the part of the path a clause moves",
           lambda code, asked, _: scope_to_parts(code, asked)),
    Reader("end-places", "an object the words ask the path to end at, and no step ends there",
           end_at_asked_places),
    Reader("alternating-shifts", "shifts the words ask to alternate in blocks of waypoints",
           lambda code, asked, _: alternate_shifts(code, asked)),
    Reader("curve-asks", "a step that bends the path the other way from the words",
           lambda code, asked, _: bend_as_asked(code, asked)),
    Reader("asked-paces", "a pace a clause asks (slower, faster, a stated speed) and no step makes",
           add_asked_paces),
    Reader("speed-scope", "a speed change the words tie to one object", localize_speed),
    Reader("pace-directions", "a speed step near an object that goes against the pace its clause asks there",
           turn_paces_as_asked),
    Reader("whole-way-paces", "a pace the words hold the whole way, written for one part", whole_way_paces),
    Reader("paced-places", "a move by an object the words only place a pace near",
           leave_out_moves_of_paced_places),
    Reader("speed-profiles", "a pace asked to run down to a stop or up from rest, written as one scale",
           profile_paces),
    Reader("held-paces", "a pace the words state near an object, held over the stretch nearest it",
           hold_stated_paces),
    Reader("waypoint-counts", "a count of waypoints the words give, and the resample that makes it",
           lambda code, asked, _: count_as_asked(code, asked)),
    Reader("kept-ends", "an end of the path the words keep where it is, and steps that move it",
           lambda code, asked, _: keep_kept_ends(code, asked)),
    Reader("relations-left", "a closer/further a clause asks whose step a later reader left out",
           add_asked_relations),
)  # fmt: skip
"""The stage's readers in run order; nothing else lists them."""


def read_against_words(code: str, asked: Sequence[str], names: Sequence[str]) -> tuple[str, list[ReaderNote]]:
    """``code`` after every reader in ``READERS`` order, and each change as a note naming its reader.

    ``asked`` holds the user's words (the instruction, then each feedback); ``names`` the scene's
    object names. A sentence that only says how the path is now ("it's too slow near the lamp")
    is no request, and the readers do not read it (``request_words``); an object called by a name
    no scene object has is read as the one the answer chose (``chosen_referents``). Every reader reads
    a length said with a metric unit in metres, as the scene's numbers are ("at least 20 cm" is 0.2,
    "a metre away" is 1: ``clause_amounts.in_metres``). Back-to-back copies of a step are cut to one
    again after the last reader: a reader's step can repeat the model's ("about 20 cm higher" answered
    with a shift up 0.2 and a height the height reader read as that same shift), and a step a reader
    leaves out can leave two copies back to back.
    """
    requests = [request_words(words, names) for words in asked]
    notes = [
        ReaderNote(
            "request-words",
            f"read as the request: \u201c{request}\u201d"
            " (the words in plain form, less what only says how the path is now)",
        )
        for words, request in zip(asked, requests, strict=True)
        if request != words
    ]
    for index, request in enumerate(requests):
        requests[index], found = chosen_referents(request, code, names)
        notes += [ReaderNote("object-mentions", message) for message in found]
    asked = [in_metres(request) for request in requests]
    for reader in READERS:
        code, found = reader.read(code, asked, names)
        notes += [ReaderNote(reader.name, message) for message in found]
    code, found = cut_copies(
        code, "back to back after the readers (a reader wrote or left out a step between)"
    )
    notes += [ReaderNote(READERS[0].name, message) for message in found]
    return code, notes

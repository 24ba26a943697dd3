import pytest

from trajadapt.readers.clause_split import only_keeps, split_clauses

NAMES = ["box", "chair", "table", "lamp", "red mug"]


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        ("go left by 20 and slow down near the box", ("go left by 20", "slow down near the box")),
        (
            "Slow down near the lamp, then stop when you reach the table.",
            ("Slow down near the lamp", "stop when you reach the table"),
        ),
        (
            "walk faster in the middle and slower near the box",
            ("walk faster in the middle", "slower near the box"),
        ),
        # paraphrases none of the sets has: other joins, other order
        (
            "reduce speed by the lamp; also keep more distance from the chair",
            ("reduce speed by the lamp", "keep more distance from the chair"),
        ),
        ("First hug the table. Then hurry past the box!", ("First hug the table", "hurry past the box")),
        ("shift up by 0.1 but keep the goal where it is", ("shift up by 0.1", "keep the goal where it is")),
    ],
)
def test_each_request_is_a_clause(words, clauses):
    assert split_clauses(words, NAMES) == clauses


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        (
            "Give the box more room, at least 15 cm, and lift the end up by 10 cm",
            ("Give the box more room, at least 15 cm", "lift the end up by 10 cm"),
        ),
        ("Move left, roughly half a metre, then slow down", ("Move left, roughly half a metre", "slow down")),
        ("stay clear of the lamp, 20 cm minimum; hurry", ("stay clear of the lamp, 20 cm minimum", "hurry")),
        ("turn the path, about 30 degrees, and stop at the chair", ("turn the path, about 30 degrees", "stop at the chair")),
    ],
)  # fmt: skip
def test_a_piece_that_only_gives_an_amount_belongs_to_the_request_before(words, clauses):
    assert split_clauses(words, NAMES) == clauses


def test_a_going_on_with_its_amount_and_heading_is_one_clause():
    words = "Carry on past the current end point, another 10 cm or so straight ahead."
    assert split_clauses(words, NAMES) == (
        "Carry on past the current end point, another 10 cm or so straight ahead",
    )
    onwards = "go on 5 cm past where it stops, continuing to the left"  # session 37: a going-on participle
    assert split_clauses(onwards, NAMES) == (onwards,)


@pytest.mark.parametrize(
    "words",
    [  # the robot itself as the subject after "while" only says where (session 37: "while the gripper is near")
        "throttle back while the gripper is near the box",
        "hurry while the drone is beside the lamp",
        "ease off while your arm is close to the chair",
    ],
)
def test_while_the_robot_is_somewhere_is_a_place_of_the_request_before(words):
    assert split_clauses(words, NAMES) == (words,)


def test_while_the_robot_does_something_more_is_a_request_of_its_own():
    words = "head left while the arm eases to a halt at the end"
    assert split_clauses(words, NAMES) == ("head left", "the arm eases to a halt at the end")


def test_a_piece_ending_on_an_auxiliary_has_its_verb_in_the_next():
    words = "keep clear of the box; the last stretch should also run slower"
    assert split_clauses(words, NAMES) == ("keep clear of the box", "the last stretch should also run slower")


def test_alongside_an_object_sets_the_next_request():
    words = "When it gets alongside the box, hold still for five waypoints"
    assert split_clauses(words, NAMES) == (words,)
    within = "Within roughly 30 cm of the lamp, cut the pace by a third"  # session 37: with an amount
    assert split_clauses(within, NAMES) == (within,)
    after = "pass by the lamp, within about 30 cm of it, then keep clear of the box"  # the pass's amount
    assert split_clauses(after, NAMES)[-1] == "keep clear of the box"


def test_a_place_said_with_an_amount_word_is_no_amount():
    """A hedge that is also a word of place ("around") with no number sets the next request."""
    words = "give it at least 0.12 of clearance. Also, around the lamp, slow to roughly half speed."
    assert split_clauses(words, NAMES)[-1] == "around the lamp, slow to roughly half speed"


@pytest.mark.parametrize(
    "words",
    [
        "pass between the chair and the table",
        "keep a clear 1 between the robot and the table",  # the robot and an object (fresh-v)
        "leave 0.3 between your gripper and the chair",
        "Keep a distance of at least 0.2 from the chair and the table",
        "weave left and right as you go",
        "Go up by 0.1 at a constant speed of 0.2",
        "hurry while passing the red mug",
        "stay well clear of the lamp, a lot further",
        "arc over the middle, bulging upwards",
        "move 0.5 to the left and 0.3 up",
        "make the point between the chair and the table your new end",  # a pair, then its request
        # both ends named together (session 31)
        "keep the start and goal where they are",
        "the first and last waypoints must not move",
        "pin the beginning and final positions",
    ],
)
def test_what_only_names_or_qualifies_stays_in_its_clause(words):
    assert split_clauses(words, NAMES) == (words,)


def test_a_lead_in_goes_with_the_request_it_sets():
    assert split_clauses("after reaching the goal, go left by 0.2", NAMES) == (
        "after reaching the goal, go left by 0.2",
    )
    assert split_clauses("once there, circle the lamp twice", NAMES) == ("once there, circle the lamp twice",)
    said = "when you're at the goal position, head to the lamp"  # a contraction's end is filler
    assert split_clauses(said, NAMES) == (said,)


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        # a condition of place before its request, in words none of the sets has
        ("If you get close to the chair, take it easy", ("If you get close to the chair, take it easy",)),
        (
            "While going by the lamp, ease off, and climb 0.1",
            ("While going by the lamp, ease off", "climb 0.1"),
        ),
        (
            "Within 0.2 of the red mug, go easy on the speed; also approach the chair",
            ("Within 0.2 of the red mug, go easy on the speed", "approach the chair"),
        ),
        (
            "The table wobbles. As you come within 0.3 of the table, creep along.",
            ("The table wobbles", "As you come within 0.3 of the table, creep along"),
        ),
    ],
)
def test_a_condition_of_place_goes_with_the_request_after_it(words, clauses):
    assert split_clauses(words, NAMES) == clauses


def test_a_lead_in_that_asks_something_stays_a_request():
    assert split_clauses("when near the box go up, and after that slow down", NAMES) == (
        "when near the box go up",
        "after that slow down",
    )
    assert split_clauses("As fast as you can, head left", NAMES) == ("As fast as you can", "head left")


def test_decimal_points_do_not_break_and_nothing_is_lost():
    words = "Go right by 0.3. Then go down by .2 and slow down near the red mug"
    clauses = split_clauses(words, NAMES)
    assert clauses == ("Go right by 0.3", "go down by .2", "slow down near the red mug")
    assert split_clauses("  ", NAMES) == ("",)


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        (
            "Go slightly upwards keeping a smaller distance from the chair",
            ("Go slightly upwards", "keeping a smaller distance from the chair"),
        ),
        ("head right by 0.2 decelerating near the lamp", ("head right by 0.2", "decelerating near the lamp")),
        (
            "visit the table on the way, slowing down there",
            ("visit the table on the way", "slowing down there"),
        ),
    ],
)
def test_a_participle_that_asks_something_more_is_a_clause(words, clauses):
    assert split_clauses(words, NAMES) == clauses


@pytest.mark.parametrize(
    "words",
    [
        "hurry while going past the box",
        "go left during the second half",
        "continue traversing for 0.2 after reaching goal",
        "arc over the middle, bulging upwards",
        "walk much faster when passing in the proximity of the lamp",
    ],
)
def test_a_participle_that_qualifies_stays(words):
    assert split_clauses(words, NAMES) == (words,)


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        ("head left while easing to a halt at the end", ("head left", "easing to a halt at the end")),
        ("climb a bit while keeping further from the sofa", ("climb a bit", "keeping further from the sofa")),
        ("speed up while drifting right", ("speed up", "drifting right")),
        (
            "circle the lamp while edging closer to the table",
            ("circle the lamp", "edging closer to the table"),
        ),
    ],
)
def test_while_before_another_request_breaks(words, clauses):
    assert split_clauses(words, [*NAMES, "sofa"]) == clauses


@pytest.mark.parametrize(
    "words",
    [
        "speed up while you are next to the lamp",
        "crawl while moving past the red mug",
        "go slower while in the vicinity of the table",
        "hover above the lamp for a while",
    ],
)
def test_while_before_a_place_or_as_a_noun_stays(words):
    assert split_clauses(words, NAMES) == (words,)


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        # after a comma, a participle that names another object or turns a move another way asks more
        (
            "keep 0.3 from the lamp, slowing near the table",
            ("keep 0.3 from the lamp", "slowing near the table"),
        ),
        (
            "push the goal 0.1 left, sinking the path a bit",
            ("push the goal 0.1 left", "sinking the path a bit"),
        ),
        # a verb that only ends in -ing is no participle
        (
            "go up by 0.1 and bring the path nearer the lamp",
            ("go up by 0.1", "bring the path nearer the lamp"),
        ),
    ],
)
def test_a_piece_that_asks_more_than_the_one_before_is_a_clause(words, clauses):
    assert split_clauses(words, NAMES) == clauses


@pytest.mark.parametrize(
    ("clause", "keeps"),
    [
        ("keeping the start fixed", True),
        ("the goal stays where it is", True),
        ("leave the end position unchanged", True),
        ("keep a distance of at least 0.2 from the box", False),
        ("keep left", False),
        ("keep the speed the same", False),
        ("slow down near the lamp", False),
    ],
)
def test_a_clause_that_only_keeps_something(clause, keeps):
    assert only_keeps(clause, NAMES) is keeps


@pytest.mark.parametrize(
    "words",
    [
        "the end point: drop it by 0.1",
        "the red mug: keep well clear of it",
        "speed: ease off near the lamp",
        "second half: swing to the right",
    ],
)
def test_a_topic_said_first_goes_with_the_request_after_its_colon(words):
    assert split_clauses(words, NAMES) == (words,)


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        ("go left: then slow down near the box", ("go left", "slow down near the box")),
        (
            "two things: hug the table, then hurry past the box",
            ("two things", "hug the table", "hurry past the box"),
        ),
    ],
)
def test_a_colon_after_a_request_or_anything_else_still_breaks(words, clauses):
    assert split_clauses(words, NAMES) == clauses


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        ("go to the end and start slowing down", ("go to the end", "start slowing down")),
        ("pass the chair and finish 0.2 higher", ("pass the chair", "finish 0.2 higher")),
        ("reach the goal and end there", ("reach the goal", "end there")),
    ],
)
def test_an_end_word_used_as_a_verb_after_an_end_still_breaks(words, clauses):
    assert split_clauses(words, NAMES) == clauses


@pytest.mark.parametrize(
    ("words", "clauses"),
    [
        (
            "keep above the table, and fly more slowly overall",
            ("keep above the table", "fly more slowly overall"),
        ),
        ("stay left of the lamp and apply a gentler pace", ("stay left of the lamp", "apply a gentler pace")),
        ("go left by 0.2 and slowly", ("go left by 0.2 and slowly",)),
    ],
)
def test_a_verb_that_ends_like_an_adverb_starts_a_request(words, clauses):
    assert split_clauses(words, NAMES) == clauses


@pytest.mark.parametrize(
    "words",
    [
        "lift the path a little, keeping the start and goal as they are",
        "leave the start and end alone",
        "hold the start and finish exactly as before",
    ],
)
def test_both_ends_named_before_a_word_beginning_like_an_article_stay_one_clause(words):
    """'goal *as* they are': the words that make the second end a verb are whole words ('a', 'an')."""
    assert len(split_clauses(words, NAMES)) == 1

"""Readings of request families in wordings no benchmark set has (issue #24: a rule that names a
phrase family must pass paraphrases of it that none of the sets holds).

Each family is read through the whole stage (``read_against_words``), as the session reads an answer:
a stop at the end, a going-on past the goal, an end kept in other words, a detour past an object, a
count of waypoints said only by its way, a part of the path called by another name, a pause of "a
few" steps. The answers given are the kinds a small model writes (a step dropped, a wrong skill).
"""

from __future__ import annotations

import pytest

from trajadapt.readers import read_against_words
from trajadapt.readers.clause_split import split_clauses
from trajadapt.readers.direction_words import said_directions
from trajadapt.readers.height_asks import relate_heights
from trajadapt.readers.height_words import asked_heights
from trajadapt.readers.object_words import ends_at_the_place
from trajadapt.readers.paces import closing_share_start, stated_factor
from trajadapt.readers.stop_words import COMING_TO_REST

NAMES = ["lamp", "crate", "armchair"]


def program(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *steps, "modified_trajectory = t"])


def steps_after(instruction: str, *steps: str) -> list[str]:
    code, _ = read_against_words(program(*steps), [instruction], NAMES)
    return code.splitlines()[1:-1]


@pytest.mark.parametrize(
    "words",
    [
        "then let it drift to a halt at the end",
        "ease it into a gentle stop",
        "bring the robot to rest",
        "keep rolling until it stops",
        "finish by settling to rest",
        "come to a dead standstill by the end",
        "it should come to a quiet rest",
        "bring the arm to a gentle rest",
        "ease the speed down to zero as it lands",  # a speed run down to zero (fresh-r)
        "decelerate to 0 by the goal",
    ],
)
def test_a_stop_is_read_in_many_words(words):
    assert COMING_TO_REST.search(words)


@pytest.mark.parametrize(
    "words",
    [
        "go to the stop sign",
        "apply it to the rest of the path",
        "start from rest",
        "get to a rest area",
        "lower the end to zero height",
        "scale the speed to 0.5",
    ],
)
def test_no_stop_where_the_words_only_name_one(words):
    assert not COMING_TO_REST.search(words)


@pytest.mark.parametrize(
    "instruction",
    [
        "Shift right a little, and let it drift to a halt at the end.",
        "Shift right a little; ease it into a gentle stop at the finish.",
        "Shift right a little and bring the robot to rest at the end.",
    ],
)
def test_a_stop_at_the_end_runs_the_speed_down(instruction):
    assert "t = speed_profile(t, 'decelerate', start=0.6)" in steps_after(
        instruction, "t = shift(t, 'right', 'a little')"
    )


def test_a_down_that_runs_to_a_stop_is_no_direction():
    assert said_directions("wind it down gently to a standstill") == set()
    assert said_directions("go down to the crate") == {"down"}


@pytest.mark.parametrize(
    ("instruction", "kept"),
    [
        ("Bring the robot to rest beside the lamp.", "t = stop_at(t, detect_objects('lamp'))"),
        ("Settle to rest right by the lamp.", "t = stop_at(t, detect_objects('lamp'), beside=True)"),
    ],
)
def test_a_stop_at_an_object_said_as_rest_is_kept(instruction, kept):
    assert kept in steps_after(instruction, "t = stop_at(t, detect_objects('lamp'))")


@pytest.mark.parametrize(
    ("instruction", "added"),
    [
        ("Move nearer the crate, and after the goal continue another 0.4.", "t = extend(t, 0.4)"),
        ("Once the end is reached, carry on toward the right.", "t = extend(t, direction='right')"),
        ("Go on for an extra 0.25 beyond the goal, heading left.", "t = extend(t, 0.25, direction='left')"),
    ],
)
def test_a_going_on_past_the_goal_no_step_makes_is_added(instruction, added):
    assert added in steps_after(instruction, "t = move_closer(t, detect_objects('crate'))")


def test_a_going_on_taken_for_a_shift_goes_on_instead():
    steps = steps_after("Push on 0.3 past the goal, pointing backward.", "t = shift(t, 'back', 0.3)")
    assert steps == ["t = extend(t, 0.3, 'back')"]


def test_a_place_after_the_goal_asks_no_going_on():
    steps = steps_after("After the goal, hover above the lamp for a while.", "t = wait(t, 'goal', 10)")
    assert not any("extend" in step for step in steps)


def test_a_heading_joins_the_going_on_it_directs():
    assert split_clauses("keep rolling 0.2 past the end, facing forward") == (
        "keep rolling 0.2 past the end, facing forward",
    )


@pytest.mark.parametrize(
    "instruction",
    [
        "Arc over the crate and return to the original end point.",
        "Loop over the crate, then head for the usual destination.",
        "Go over the crate while keeping the same goal.",
    ],
)
def test_an_end_kept_in_other_words_leaves_out_a_going_on(instruction):
    steps = steps_after(instruction, "t = pass_over(t, detect_objects('crate'))", "t = extend(t)")
    assert not any("extend" in step for step in steps)
    assert "t = reach(t, detect_objects('goal'))" in steps


def test_a_going_on_asked_beside_a_kept_goal_stays():
    steps = steps_after(
        "Keep the goal fixed and once there continue 0.2 to the left.", "t = extend(t, 0.2, 'left')"
    )
    assert "t = extend(t, 0.2, 'left')" in steps


@pytest.mark.parametrize(
    "instruction",
    ["Make a detour past the armchair.", "Veer by the armchair on the way.", "Divert past the armchair."],
)
def test_a_detour_past_an_object_passes_it(instruction):
    steps = steps_after(instruction, "t = smooth(t)")
    assert "t = pass_through(t, detect_objects('armchair'))" in steps


def test_a_detour_answered_with_an_end_there_passes_by_instead():
    steps = steps_after(
        "Swerve by the armchair, but end at the same goal.", "t = reach(t, detect_objects('armchair'))"
    )
    assert steps[0] == "t = pass_through(t, detect_objects('armchair'))"


@pytest.mark.parametrize(
    "words",
    ["swing by the lamp and halt there", "on reaching the lamp, stop", "pass the lamp and land on it"],
)
def test_an_ending_after_a_visit_ends_at_its_place(words):
    assert ends_at_the_place(words.split(" and ")[0].split(",")[0], words)


def test_an_ending_with_a_place_of_its_own_is_elsewhere():
    assert not ends_at_the_place("swing by the lamp", "swing by the lamp, then stop at the end")


@pytest.mark.parametrize(
    ("instruction", "count"),
    [("Give the path a denser set of points.", "2 * len(t)"), ("Thin the waypoints out.", "len(t) // 2")],
)
def test_a_count_said_by_its_way_replaces_a_made_up_one(instruction, count):
    assert steps_after(instruction, "t = resample(t, 35)") == [f"t = resample(t, {count})"]


def test_a_count_the_words_say_is_kept():
    assert steps_after("Use fewer waypoints, 35 of them.", "t = resample(t, 35)") == ["t = resample(t, 35)"]


@pytest.mark.parametrize(
    ("instruction", "part"),
    [
        ("Move away from the lamp and be slower over the closing stretch.", "end"),
        ("Move away from the lamp and be slower over the opening leg.", "start"),
        ("Move away from the lamp and be slower through the central section.", "middle"),
    ],
)
def test_a_part_called_by_another_name_places_its_pace(instruction, part):
    steps = steps_after(instruction, "t = move_away(t, detect_objects('lamp'))")
    assert f"t = scale_speed(t, 0.65, part='{part}')" in steps


def test_a_pace_of_a_part_crossed_onto_an_object_leaves_it():
    steps = steps_after(
        "Keep further from the crate, and go slower in the final segment.",
        "t = move_away(t, detect_objects('crate'))",
        "t = scale_speed(t, 0.65, near=detect_objects('crate'))",
    )
    assert not any("near=detect_objects('crate')" in step for step in steps)
    assert "t = scale_speed(t, 0.65, part='end')" in steps


@pytest.mark.parametrize(
    ("instruction", "steps"),
    [("Idle at the crate for a few steps.", 3), ("Dwell beside the crate for a couple of time steps.", 2)],
)
def test_a_pause_of_a_few_steps_is_counted(instruction, steps):
    assert f"t = wait(t, detect_objects('crate'), {steps})" in steps_after(
        instruction, "t = pass_through(t, detect_objects('crate'))"
    )


@pytest.mark.parametrize(
    "words",
    ["turn the speed down near the end", "dial the pace back up afterwards", "knock the velocity down a bit"],
)
def test_a_speed_turned_down_or_up_is_no_direction(words):
    assert said_directions(words) == set()


@pytest.mark.parametrize(
    "instruction",
    [
        "Keep well clear of the crate and see that the run finishes with a complete stop.",
        "Stay further from the crate; the trip should end in a dead halt at the goal.",
    ],
)
def test_a_stop_at_the_end_taken_to_another_clauses_object_is_the_ends(instruction):
    steps = steps_after(
        instruction, "t = move_away(t, detect_objects('crate'))", "t = stop_at(t, detect_objects('crate'))"
    )
    assert steps == [
        "t = move_away(t, detect_objects('crate'))",
        "t = speed_profile(t, 'decelerate', start=0.6)",
    ]


@pytest.mark.parametrize(
    "instruction",
    ["Head over to the crate and grind to a halt.", "Pass the crate, then come to a stop right there."],
)
def test_a_stop_said_after_reaching_an_object_stays_there(instruction):
    assert "t = stop_at(t, detect_objects('crate'))" in steps_after(
        instruction, "t = stop_at(t, detect_objects('crate'))"
    )


@pytest.mark.parametrize(
    ("words", "limit"),
    [
        ("don't ever sink below an altitude of 0.4", ("stay_above", 0.4)),
        ("stay under an elevation of 1.2 throughout", ("stay_below", 1.2)),
        ("never climb above the height of 0.9", ("stay_below", 0.9)),
    ],
)
def test_a_limit_word_before_a_named_height_is_a_limit(words, limit):
    assert asked_heights(words) == [limit]


@pytest.mark.parametrize("words", ["sway left and right as you go", "bob up and down along the way"])
def test_a_swing_both_ways_is_no_direction_and_no_break(words):
    assert said_directions(words) == set()
    assert len(split_clauses(words)) == 1


@pytest.mark.parametrize(
    "instruction",
    [
        "Hold a buffer of 0.2 from the crate and speed up a little.",
        "Leave the crate a clearance of 0.2 and go a bit faster.",
    ],
)
def test_a_clearance_said_as_a_noun_is_kept_with_avoid(instruction):
    assert "t = avoid(t, detect_objects('crate'), 0.2)" in steps_after(instruction, "t = scale_speed(t, 1.2)")


@pytest.mark.parametrize(
    "words",
    [
        "speed the whole run up",
        "slow the final approach down near the box",
        "ramp the pace up",
        "slow the last couple of metres down",
    ],
)
def test_a_pace_verb_around_its_object_asks_no_direction(words):
    assert said_directions(words) == set()


@pytest.mark.parametrize(
    ("words", "direction"),
    [("ease the gripper down onto the plate", "down"), ("slow it, and then go up", "up")],
)
def test_a_direction_beside_a_pace_verb_stays(words, direction):
    assert said_directions(words) == {direction}


@pytest.mark.parametrize(
    ("words", "limits"),
    [
        (
            "hold the altitude between 0.4 and 0.9 m throughout",
            ["t = stay_above(t, 0.4)", "t = stay_below(t, 0.9)"],
        ),
        (
            "make sure z stays between z = -0.1 and z = 0.3",
            ["t = stay_above(t, -0.1)", "t = stay_below(t, 0.3)"],
        ),
    ],
)
def test_a_band_of_heights_is_both_limits(words, limits):
    code, _ = relate_heights(program("t = scale_speed(t, 0.65)"), [words])
    assert code.splitlines()[2:-1] == limits


@pytest.mark.parametrize(
    "words",
    [
        "cut the pace by at least 40 percent",
        "drop the speed below 50% near the end",
        "go 3 times above the speed",
    ],
)
def test_a_share_or_a_factor_is_no_height(words):
    assert asked_heights(words) == []


@pytest.mark.parametrize(
    ("words", "faster", "factor"),
    [
        ("cut the speed by at least 40%", False, 0.52),
        ("it should be 10 percent quicker or more", True, 1.12),
        ("no less than twice as fast", True, 2.2),
        ("exactly 40% slower", False, 0.6),  # a plain stated factor stays as said
    ],
)
def test_a_least_change_of_pace_is_met_beyond_it(words, faster, factor):
    assert stated_factor(words, faster) == pytest.approx(factor)


@pytest.mark.parametrize(
    ("words", "faster", "factor"),
    [
        ("crawl past the lamp at roughly a third of the current speed there", False, 1 / 3),
        ("cruise by the crate at two-thirds of the pace", False, 2 / 3),
        ("go at three quarters of your speed near the armchair", False, 0.75),
        ("slow to one fifth of the speed by the lamp", False, 0.2),
    ],
)
def test_a_share_of_the_speed_is_a_stated_factor(words, faster, factor):
    assert stated_factor(words, faster) == pytest.approx(factor, abs=1e-5)


@pytest.mark.parametrize(
    "words",
    [
        "slow down over the last third",  # a part of the path, no count before it
        "slow down a quarter of the way along",  # a place on the path
        "ease off for two thirds of the route",
        # a percentage of the path (session 37): "40 percent of the motion" was read as 0.6
        "taper the velocity off over the final 40 percent of the motion",
        "brake gently across the closing 25% of the route",
        "slow down for 30 per cent of the journey",
        "slow down over the second half",
        "slow down halfway",
    ],
)
def test_a_share_of_the_path_is_no_factor(words):
    assert stated_factor(words, False) is None


@pytest.mark.parametrize(
    ("words", "factor"),
    [
        ("go 40 percent slower over the last third", 0.6),
        ("30% slower across 50% of the path", 0.7),
        ("fly at half the flight speed", 0.5),  # "N% of the motion speed" is a speed, not a share of the path
        ("slow to 50% of your usual run speed", 0.5),
        (
            "crawl at 30% of the current pace over the last third",
            0.3,
        ),  # a percentage of a speed is the factor
        ("drop to 70 percent of its speed near the crate", 0.7),
    ],
)
def test_a_share_of_the_speed_beside_a_share_of_the_path_is_still_read(words, factor):
    assert stated_factor(words, False) == pytest.approx(factor)


@pytest.mark.parametrize(
    ("words", "faster", "factor"),
    [  # a change by a fraction of the speed (session 37: "speed the middle section up by about a quarter")
        ("speed the middle section up by about a quarter", True, 1.25),
        ("cut the speed by roughly a third near the crate", False, 2 / 3),
        ("quicken the pace by one fifth", True, 1.2),
    ],
)
def test_a_change_by_a_fraction_is_a_stated_factor(words, faster, factor):
    assert stated_factor(words, faster) == pytest.approx(factor, abs=1e-5)


@pytest.mark.parametrize(
    ("words", "start"),
    [
        ("decelerate over the final 40 percent of the motion", 0.6),
        ("ramp down over the last 25 per cent", 0.75),
    ],
)
def test_a_closing_share_said_in_percent_is_where_the_ramp_starts(words, start):
    assert closing_share_start(words) == pytest.approx(start)


def test_a_share_of_the_speed_replaces_the_models_guess():
    after = steps_after(
        "crawl past the lamp at roughly a third of the current speed there",
        "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
    )
    assert after == ["t = scale_speed(t, 0.333333, near=detect_objects('lamp'), held=True)"]

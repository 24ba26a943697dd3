from trajadapt.clauses.grammar import (
    allowed_numbers,
    clause_objects,
    said_places,
    stated_numbers,
    step_grammar,
)

NAMES = ["kettle", "lamp", "red mug"]


def test_a_clause_names_only_its_own_objects():
    clauses = ["go faster near the kettle", "slower near the lamp"]
    assert clause_objects(clauses, 0, NAMES) == ("kettle",)
    assert clause_objects(clauses, 1, NAMES) == ("lamp",)


def test_a_shorter_word_for_a_name_and_a_word_pointing_back_find_their_object():
    assert clause_objects(["approach the mug"], 0, NAMES) == ("red mug",)
    assert clause_objects(["reach the lamp", "wait there for 5 steps"], 1, NAMES) == ("lamp",)


def test_a_clause_naming_nothing_may_name_no_object():
    assert clause_objects(["go slower by half", "keep away from the kettle"], 0, NAMES) == ()


def test_numbers_are_the_clauses_own_and_the_phrase_tables():
    assert stated_numbers("go left by .5 and up by 20, not 3rd") == ("0.5", "20")
    numbers = allowed_numbers("go left by 0.3")
    assert "0.3" in numbers and "0.65" in numbers and "0.2" not in numbers


def test_the_grammar_admits_the_clauses_step_and_refuses_the_others():
    grammar = step_grammar(("lamp",), allowed_numbers("slower near the lamp"))
    assert grammar.matches("t = scale_speed(t, 0.65, near=detect_objects('lamp'))")
    assert grammar.matches("t = scale_speed(t, 0.65, near=detect_objects('lamp'))\nt = smooth(t)")
    assert not grammar.matches(
        "t = scale_speed(t, 0.65, near=detect_objects('kettle'))"
    )  # another clause's object
    assert not grammar.matches("t = shift(t, 'left', 0.2)")  # a number nobody said
    assert grammar.matches("t = shift(t, 'left', 'a bit')")
    assert not grammar.matches("t = smooth(t)\nt = smooth(t)\nt = smooth(t)")  # two steps at most
    assert "\n" not in grammar.to_gbnf().split("::=")[1].split("\n")[0].strip('"')


def test_a_clause_naming_no_object_and_no_end_can_point_at_nothing_by_name():
    grammar = step_grammar((), allowed_numbers("go slower by half"), said_places("go slower by half"))
    assert grammar.matches("t = scale_speed(t, 0.5)")
    assert not grammar.matches("t = scale_speed(t, 0.5, near=detect_objects('start'))")
    towards_the_end = "slow down towards the end"
    assert step_grammar((), allowed_numbers(towards_the_end), said_places(towards_the_end)).matches(
        "t = scale_speed(t, 0.5, near=detect_objects('goal'))"
    )
    assert "goal" in said_places("once you reach the destination") and not said_places("go slower by half")


def test_places_are_those_the_words_give():
    fan = step_grammar(
        ("fan",), allowed_numbers("stop near the fan for 10 timesteps"), said_places("stop near the fan")
    )
    assert fan.matches("t = wait(t, detect_objects('fan'), 10)")
    assert not fan.matches("t = wait(t, 'goal', 10)") and not fan.matches(
        "t = wait(t, detect_objects('goal'), 10)"
    )
    halfway = step_grammar((), allowed_numbers("pause halfway"), said_places("pause halfway for 5 steps"))
    assert halfway.matches("t = wait(t, 'middle', 5)") and not halfway.matches("t = wait(t, 'end', 5)")
    half = step_grammar(
        (), allowed_numbers("faster in the second half"), said_places("faster in the second half")
    )
    assert half.matches("t = scale_speed(t, 1.4, part='second half')") and not half.matches(
        "t = scale_speed(t, 1.4, part='end')"
    )


def test_with_nothing_to_point_at_no_skill_needs_a_point_and_nothing_is_near():
    grammar = step_grammar(
        (), allowed_numbers("go faster in the middle"), said_places("go faster in the middle")
    )
    assert grammar.matches("t = scale_speed(t, 1.4, part='middle')")
    assert not grammar.matches("t = scale_speed(t, 1.4, near=t[0])")
    assert not grammar.matches("t = move_closer(t, [0, 0, 0])")
    assert grammar.matches("t = wait(t, 'middle', 5)")


def test_the_whole_answer_grammar_from_the_clause_list():
    import json

    from trajadapt.clauses.grammar import clause_answer_grammar

    names = ("box", "lamp")
    grammar = clause_answer_grammar(
        ("go left by 0.2", "slow down near the lamp", "keep the start fixed"), names
    )

    def answer(*lines, plan="1) a 2) b"):
        code = "\n".join(["t = get_trajectory()", *lines, "modified_trajectory = t"])
        return json.dumps({"high_level_plan": plan, "python_code": code})

    assert grammar.matches(
        answer("t = shift(t, 'left', 0.2)", "t = scale_speed(t, 0.65, near=detect_objects('lamp'))")
    )
    assert not grammar.matches(
        answer("t = shift(t, 'left', 0.2)", "t = scale_speed(t, 0.65, near=detect_objects('box'))")
    )
    assert not grammar.matches(answer("t = shift(t, 'left', 0.2)"))  # a clause dropped
    asked = ("t = shift(t, 'left', 0.2)", "t = scale_speed(t, 0.65, near=detect_objects('lamp'))")
    assert not grammar.matches(answer(*asked, plan="1) go left. " * 60))  # a looping plan: bounded
    assert not grammar.matches(
        answer("t = scale_speed(t, 0.65, near=detect_objects('lamp'))", "t = shift(t, 'left', 0.2)")
    )


def test_an_answers_lines_are_attributed_to_their_clauses():
    from trajadapt.clauses.grammar import attribute_lines

    clauses = ("go up by 0.1 at a speed of 0.2", "slow down near the lamp", "keep the start fixed")
    lines = [
        "t = shift(t, 'up', 0.1)",
        "t = set_speed(t, 0.2)",
        "t = scale_speed(t, 0.65, near=detect_objects('lamp'))",
    ]
    assert attribute_lines(lines, clauses, NAMES) == [
        ("go up by 0.1 at a speed of 0.2", tuple(lines[:2])),
        ("slow down near the lamp", (lines[2],)),
    ]
    assert attribute_lines(lines[:1], clauses, NAMES) is None

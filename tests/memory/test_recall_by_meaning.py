"""The user's own answer is recalled for the same request in other words, and never for its opposite.

A remembered example is near (shown first) when it asks what the instruction asks: the same meaning
tokens, as many objects, the same numbers, an amount word as strong. The wordings below are in none
of the paraphrase sets.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from trajadapt.memory import MemoryBank, choose_examples

NAMES = ["husky", "bench"]


def _code(*steps: str) -> str:
    return "\n".join(["t = get_trajectory()", *(f"t = {step}" for step in steps), "modified_trajectory = t"])


def _remember(bank: MemoryBank, words: str, *steps: str) -> str:
    return bank.remember(words, "1) As approved.", _code(*steps), NAMES).id


@pytest.fixture
def bank(tmp_path: Path) -> MemoryBank:
    bank = MemoryBank(tmp_path / "memory.jsonl")
    _remember(bank, "walk closer to the husky", "move_closer(t, detect_objects('husky'))")
    _remember(bank, "go slightly upwards", "shift(t, 'up', 'slightly')")
    _remember(
        bank, "go up and keep away from the husky", "move_away(t, detect_objects('husky'))", "shift(t, 'up')"
    )
    _remember(bank, "slow down near the bench", "scale_speed(t, 0.65, near=detect_objects('bench'))")
    return bank


def _first(bank: MemoryBank, words: str) -> str:
    return choose_examples(words, 3, NAMES, bank.examples())[0].instruction


@pytest.mark.parametrize(
    "words",
    [
        "Climb a bit while drawing nearer to the husky",
        "Ascend slightly, approaching the husky",
        "Lift the path a little and move toward the husky",
    ],
)
def test_a_reworded_request_recalls_the_users_answer_first(bank: MemoryBank, words: str) -> None:
    _remember(bank, "Go slightly upwards and walk closer to the husky",
              "move_closer(t, detect_objects('husky'))", "shift(t, 'up', 0.1)")  # fmt: skip
    assert _first(bank, words) == "Go slightly upwards and walk closer to the husky"


def test_the_same_words_asking_the_opposite_are_not_near(bank: MemoryBank) -> None:
    _remember(bank, "Keep a smaller distance from the husky", "move_closer(t, detect_objects('husky'))")
    _remember(bank, "Stay further away from the husky", "move_away(t, detect_objects('husky'))")
    assert _first(bank, "Keep a greater distance from the husky") == "Stay further away from the husky"


def test_a_stronger_request_is_not_near_a_weaker_one(bank: MemoryBank) -> None:
    _remember(bank, "Walk slightly closer to the husky", "move_closer(t, detect_objects('husky'), 'a bit')")
    _remember(bank, "Get a lot closer to the husky", "move_closer(t, detect_objects('husky'), 'a lot')")
    assert _first(bank, "Move much nearer to the husky") == "Get a lot closer to the husky"


def test_a_pace_asked_with_a_verb_recalls_the_pace_answer(bank: MemoryBank) -> None:
    _remember(bank, "Lower the speed everywhere", "scale_speed(t, 0.65)")
    _remember(bank, "Raise the speed everywhere", "scale_speed(t, 1.5)")
    assert _first(bank, "Boost your pace along the whole route") == "Raise the speed everywhere"
    assert _first(bank, "Cut the pace along the whole route") == "Lower the speed everywhere"


def test_without_a_meaning_the_words_decide(bank: MemoryBank) -> None:
    _remember(bank, "Make the path zigzag", "zigzag(t, 0.1)")
    assert _first(bank, "Make the trajectory zigzag") == "Make the path zigzag"
    assert all(e.remembered == "" for e in choose_examples("Draw a spiral", 3, NAMES, bank.examples())[:1])


def test_the_users_latest_answer_to_a_request_supersedes_the_ones_before_it(bank: MemoryBank) -> None:
    _remember(bank, "go much faster close to the bench", "scale_speed(t, 1.6, near=detect_objects('bench'))")
    _remember(bank, "walk a lot quicker by the husky", "scale_speed(t, 1.6, near=detect_objects('husky'))")
    _remember(bank, "move a lot faster beside the husky", "scale_speed(t, 2.5, near=detect_objects('husky'))")
    chosen = choose_examples("speed up a lot when passing the husky", 3, NAMES, bank.examples())
    assert "2.5" in chosen[0].code
    assert not any("1.6" in example.code for example in chosen)


def test_near_answers_that_agree_are_all_kept(bank: MemoryBank) -> None:
    _remember(bank, "Lower the speed everywhere", "scale_speed(t, 0.65)")
    _remember(bank, "Reduce your speed everywhere", "scale_speed(t, 0.65)")
    chosen = choose_examples("Cut the pace along the whole route", 3, NAMES, bank.examples())
    assert {e.instruction for e in chosen[:2]} == {
        "Lower the speed everywhere",
        "Reduce your speed everywhere",
    }


def test_the_answer_to_the_very_same_words_comes_before_a_later_one_to_other_words(bank: MemoryBank) -> None:
    _remember(bank, "stay much nearer to the husky", "move_closer(t, detect_objects('husky'), 'a lot')")
    _remember(bank, "get a lot closer to the husky", "move_closer(t, detect_objects('husky'), 0.3)")
    assert _first(bank, "Stay much nearer to the husky") == "stay much nearer to the husky"
    assert _first(bank, "walk a lot nearer to the husky") == "get a lot closer to the husky"

"""Mentions the text takes back (``resolve/_retractions``): corrections, alternatives,
choices left open and negations ask for no field of their own, and --explain says why."""

from __future__ import annotations

import pytest

from agrirecipe import generate


def crops(prompt: str) -> list[str]:
    return [f.crop for f in generate(prompt, resolver="hybrid").recipe.fields]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        # a correction before the field that replaces the one before it
        ("cherry tomatoes? no, I mean cherry trees", ["Cherry"]),
        # a correction ending the field it takes back
        ("a carrot patch jk, just an onion field", ["Onion"]),
        # alternatives: one field, of the first named
        ("a field of wheat or maize", ["Wheat"]),
        # negations
        ("no apples, just pears", ["Pear"]),
    ],
)
def test_a_mention_taken_back_is_no_field(prompt: str, expected: list[str]) -> None:
    assert crops(prompt) == expected


def test_a_choice_left_open_names_the_kind_of_the_fields_before() -> None:
    fields = generate("2 plots, any cereal you like", resolver="hybrid").recipe.fields
    assert [f.category for f in fields] == ["Cereals", "Cereals"]


def test_explain_lists_what_was_taken_back() -> None:
    scene = generate(
        "some fruit fields pls, whatever fruit u like", resolver="hybrid", explain=True
    )
    assert scene.explanation is not None
    taken_back = [
        step.subject
        for step in scene.explanation.steps
        if step.detail.startswith("left to the reader's choice")
    ]
    assert taken_back == ["whatever fruit you like"]  # ("u" read as "you")

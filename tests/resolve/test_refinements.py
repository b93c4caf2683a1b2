"""The members a plural mention lists (resolve/_refinements.py), through generate()."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate


def crops(prompt: str) -> list[str | None]:
    return [f.variety or f.crop for f in generate(prompt, resolver="hybrid").recipe.fields]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        ("Two orchards: one of Gala, one of Fuji", ["Gala", "Fuji"]),
        ("three fields: wheat, maize and potatoes", ["Winter Wheat", "Dent", "Bintje"]),
        ("two vineyards, chardonnay west of riesling", ["Chardonnay", "Riesling"]),
        ("five fields: 2 of maize and 3 of wheat", ["Dent"] * 2 + ["Winter Wheat"] * 3),
    ],
)
def test_a_plural_mention_is_the_members_it_lists(prompt: str, expected: list[str]) -> None:
    assert crops(prompt) == expected


def test_the_members_details_stay_their_own() -> None:
    fields = generate(
        "two apple blocks: Granny Smith, fruit ripe, and Fuji, still flowering",
        resolver="hybrid",
    ).recipe.fields
    assert [(f.variety, f.stage) for f in fields] == [
        ("Granny Smith", "Maturation"),
        ("Fuji", "Reproductive"),
    ]


def test_more_members_than_announced_is_an_error() -> None:
    with pytest.raises(PromptError, match="announces 2 field"):
        generate("two fields: sweetcorn, durum wheat and romaine lettuce", resolver="hybrid")

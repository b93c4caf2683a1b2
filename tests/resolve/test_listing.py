"""Whether a clause lists one more member or names one again (resolve/_listing.py),
through generate()."""

from __future__ import annotations

import pytest

from agrirecipe import generate


def varieties(prompt: str) -> list[str]:
    return [f.variety for f in generate(prompt, resolver="hybrid").recipe.fields]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        # a crop listed again while the count has room: one more member
        ("three plots: wheat, potatoes, wheat", ["Winter Wheat", "Bintje", "Winter Wheat"]),
        # a crop named again and placed: the member named again
        ("two fields: carrots and onions, carrots north of the onions", ["Nantes", "Sturon"]),
        # one more field of another variety after a plural of one variety
        (
            "Two Chantenay carrot plots and one Danvers plot",
            ["Chantenay", "Chantenay", "Danvers"],
        ),
    ],
)
def test_listed_or_named_again(prompt: str, expected: list[str]) -> None:
    assert varieties(prompt) == expected


def test_one_of_a_crop_after_a_plural_is_one_more_field() -> None:
    fields = generate("three fields of sweet peppers and one of chillies", resolver="hybrid")
    assert [f.crop for f in fields.recipe.fields] == ["Pepper"] * 4

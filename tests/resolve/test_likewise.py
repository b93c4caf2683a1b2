"""A field said to look "too" as the one before it (resolve/_likewise.py)."""

from __future__ import annotations

import pytest

from agrirecipe import generate


@pytest.mark.parametrize("said", ["too", "as well", "also"])
def test_the_field_after_takes_the_look_before_it(said: str) -> None:
    potatoes, carrots = generate(f"potatoes with blight, the carrots {said}").recipe.fields
    assert (potatoes.health, carrots.health) == ("Ill", "Ill")


def test_without_the_word_the_field_keeps_its_default() -> None:
    _, carrots = generate("potatoes with blight, the carrots").recipe.fields
    assert carrots.health == "Healthy"


def test_only_from_the_field_right_before() -> None:
    apples, pears, plums = (
        f.stage for f in generate("apples in blossom, pears ripe, and cherries too").recipe.fields
    )
    assert (apples, pears, plums) == ("Reproductive", "Maturation", "Maturation")

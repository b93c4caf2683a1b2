"""Text of blind set g38 (issue 8), first fixes: a juice plant is scenery, plants "planted at
zero spacing" are refused, and "the ears fully out" is a cereal's flowering stage."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate


def test_a_juice_plant_is_scenery() -> None:
    (hamlin,) = generate(
        "Hamlin orange trees in Florida in December, fruit just coloured up and ready for the "
        "juice plant, a trailer of bins on the sandy track."
    ).recipe.fields
    assert (hamlin.variety, hamlin.stage) == ("Hamlin", "Maturation")


def test_plants_set_at_zero_spacing_are_refused() -> None:
    with pytest.raises(PromptError, match="positive"):
        generate("Vineyard with the vines planted at zero spacing, next to a wheat field.")


def test_ears_fully_out() -> None:
    fields = generate(
        "The Winter Wheat field is north of the durum, both with a 6 m headland left for the "
        "sprayer to turn on, and the ears fully out on both in late May."
    ).recipe.fields
    assert [(f.variety, f.stage) for f in fields] == [
        ("Winter Wheat", "Reproductive"),
        ("Durum", "Reproductive"),
    ]

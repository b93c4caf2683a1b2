"""Field labels and list marks written plainly (resolve/_labels.py)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._labels import drop_list_numbers


@pytest.mark.parametrize(
    ("said", "plain"),
    [
        ("(1) wheat; (2) maize", "wheat; maize"),
        ("three plots: (a) wheat, (b) maize", "three plots: wheat, maize"),
        # marks in full brackets inside a sentence end the item before them
        (
            "plots are (a) Albion strawberries, ripe (b) Elsanta, flowering",
            "plots are: Albion strawberries, ripe; Elsanta, flowering",
        ),
        # out of order: not a list's marks
        ("wheat (b) and maize (a)", "wheat (b) and maize (a)"),
    ],
)
def test_list_marks_are_dropped(said: str, plain: str) -> None:
    assert drop_list_numbers(said) == plain

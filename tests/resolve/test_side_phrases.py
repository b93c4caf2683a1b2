"""Sides said in other words, rewritten before the prompt is read (``_side_phrases``)."""

from __future__ import annotations

import pytest

from agrirecipe.resolve._side_phrases import place_sides


@pytest.mark.parametrize(
    ("text", "written"),
    [
        (
            "riesling in the middle with pinot noir on one side & cabernet on the other",
            "riesling between pinot noir and cabernet",
        ),
        ("cabbage up top & lettuce under it", "cabbage up top & lettuce below it"),
        ("cabbage in the north, lettuce beneath them", "cabbage in the north, lettuce below them"),
        ("directly below it, so south of the maize, cabbages", "south of the maize, cabbages"),
    ],
)
def test_a_side_said_in_other_words_is_written_as_the_reader_places_it(
    text: str, written: str
) -> None:
    assert place_sides(text) == written


def test_under_with_no_map_of_the_farm_is_left_alone() -> None:
    text = "a Gala orchard with sheep grazing under them"
    assert place_sides(text) == text

"""Text of blind set g22 (issue 8): a "please" before a count of the beds just named,
yards written "yds", and the count of a list said after "so"."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_please_before_the_count_of_the_beds() -> None:
    (strawberries,) = recipe("strawbery beds pls, 8 of them w/ 2 rows per bed").fields
    assert (strawberries.agronomy.rows_per_bed, strawberries.row_count) == (2, 16)


def test_yards_written_yds() -> None:
    (tomatoes,) = recipe("6 rows of roma tomatoes, rows 1.5 m apart n 40 yds long").fields
    assert tomatoes.row_length_m == pytest.approx(36.576, rel=0.01)


def test_the_count_of_a_list_after_so() -> None:
    crops = [f.crop for f in recipe("corn and wheat and carrots so 3 fields").fields]
    assert crops == ["Maize", "Wheat", "Carrot"]

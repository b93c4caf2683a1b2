"""Text of blind set g22 (issue 8): a "please" before a count of the beds just named,
yards written "yds", the count of a list said after "so", sizes in words of tens, years,
and a plot said after its crop with where it is."""

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


def test_a_size_in_words_of_tens() -> None:
    (onions,) = recipe("Only one field on the home farm, twenty-five acres of Sturon onions").fields
    assert onions.geometry.area_m2 == pytest.approx(25 * 4046.8564224, rel=0.01)
    # ("the back forty" is a field's name, not forty fields)
    assert len(recipe("The back forty is popping corn this year").fields) == 1


def test_a_year_is_no_count() -> None:
    fields = recipe(
        "Carrot plan for 2027: Nantes in the north field, Chantenay in the south"
    ).fields
    assert [f.variety for f in fields] == ["Nantes", "Chantenay"]


def test_a_plot_said_after_its_crop_with_where_it_is() -> None:
    (cherries,) = recipe("Kordia cherries, one block up on the hill, the trees in blossom.").fields
    assert cherries.crop == "Cherry"

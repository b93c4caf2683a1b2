"""Text of blind set g22 (issue 8): a "please" before a count of the beds just named,
yards written "yds", the count of a list said after "so", sizes in words of tens, years,
a plot said after its crop with where it is, inches before a placement, hyperspectral
cameras, and open-field plots."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


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


def test_engineering_words_of_g22(named_relations: Callable[[str], NamedRelations]) -> None:
    # "12 rows at 30 in" before a placement: inches, not 30 fields
    _cabbage, corn = recipe(
        "a cabbage plot, 20 rows at 30 in, and a corn block of 12 rows at 30 in just west of "
        "the cabbage"
    ).fields
    assert (corn.row_count, corn.agronomy.row_spacing_m) == (12, 0.762)
    # a hyperspectral camera is scenery
    assert len(recipe("two 20 x 20 m lettuce plots for hyperspectral camera tests").fields) == 2
    # "open-field plots" are plots grown outdoors, not another field
    relations = named_relations(
        "Roma and San Marzano tomatoes in two open-field plots, the Roma south of the San Marzano"
    )
    assert relations == {("south_of", "Roma", ("San Marzano",))}

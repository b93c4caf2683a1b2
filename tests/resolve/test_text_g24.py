"""Text of blind set g24 (issue 8): a side said past words that describe the field, "a
quarter of an acre", a plot named first as where a field stands, counts written "x6" and
"1 jalapeno 1 padron", "in 1 of em", a kind in brackets, "are east", a crop named again
after a heading of no crop, and "three adjacent test strips"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_side_said_past_what_describes_the_field(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Our farm in Western Australia, in July: Washington Navel oranges, ripe and being "
        "picked, on the north side; Valencia Late still hanging green on the south side."
    )
    assert ("north_of", "Navel", ("Valencia",)) in relations
    # (nothing said of the apples in between: the side places the pears)
    assert named_relations("apples, and to the north, pears") == {("north_of", "Pear", ("Apple",))}


def test_a_quarter_of_an_acre() -> None:
    (vines,) = recipe("Behind the house we've a small vineyard, maybe a quarter of an acre").fields
    assert vines.geometry.area_m2 == pytest.approx(4046.8564224 / 4, rel=0.01)


def test_the_plot_where_a_field_stands() -> None:
    (pears,) = recipe(
        "In the field beyond the stone wall there's an old Comice pear orchard, bare branches "
        "covered in hoarfrost."
    ).fields
    assert pears.variety == "Doyenne du Comice"


def test_counts_written_the_casual_way() -> None:
    (strawberries,) = recipe("strawbery beds x6, 2 rows/bed, beds on 1.5m centres").fields
    assert (strawberries.bed_count, strawberries.agronomy.rows_per_bed) == (6, 2)
    peppers = recipe("need 2 pepers fields pls, 1 jalapeno 1 padron, they shud be flowering")
    assert [f.variety for f in peppers.fields] == ["Jalapeno", "Padron"]
    assert len(recipe("2 wheat fields w/ a combine in 1 of em, august").fields) == 2
    # ("1 either side": one field on each side, not a member named "either")
    assert len(recipe("2 grain fields, 1 either side of the spuds").fields) == 3


def test_a_kind_in_brackets_and_are_east(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    tomatoes, _apples = recipe("roma (plum) tomatos + a granny orchard, summer").fields
    assert tomatoes.variety == "Roma"
    assert named_relations("durondeau pears and bing cherries, the cherries r east") == {
        ("east_of", "Bing", ("Durondeau",))
    }


def test_a_crop_named_again_after_a_heading_of_no_crop() -> None:
    onions, _carrots = recipe(
        "Field robotics course layout: a 50 x 20 m onion plot south of a 50 x 20 m carrot "
        "plot. Onion rows 30 cm apart; carrots on 75 cm ridges."
    ).fields
    assert onions.agronomy.row_spacing_m == 0.3


def test_three_adjacent_test_strips(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Three adjacent test strips for the soil-sensor rover: sweetcorn with 8 rows at 76 cm, "
        "spring wheat drilled in 15 cm rows, and Agria potatoes, 6 rows at 90 cm. The wheat "
        "strip is in the middle, between the corn and the potatoes."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Maize", "Wheat", "Potato"]
    assert ("between", "Spring Wheat", ("Sweet Corn", "Agria")) in named_relations(prompt)


def test_words_of_g24_photos() -> None:
    wheat, _potatoes = recipe(
        "Took this in May: Winter Wheat coming into ear next to a field of Agria potatoes"
    ).fields
    assert wheat.stage == "Reproductive"
    # "stone fruit trees": the trees of the stone fruit named first (cherries), not any
    (stone,) = recipe("stone fruit trees along the north edge of the farm").fields
    assert stone.crop == "Cherry"


def test_the_rows_spacing_first_in_a_bracket_of_spacings() -> None:
    _bing, lapins = recipe(
        "two cherry blocks in full bloom: Bing (rows 5 m apart, trees 3 m) and Sweetheart "
        "Lapins (rows 4.5 m, trees 2.5 m). Lapins block east of Bing."
    ).fields
    assert (lapins.agronomy.row_spacing_m, lapins.agronomy.in_row_spacing_m) == (4.5, 2.5)

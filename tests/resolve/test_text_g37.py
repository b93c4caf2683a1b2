"""Text of blind set g37 (issue 8): members told apart by their side and a size said
plainly ("the left one about a hectare"), patches of a field, a ladder against "the
nearest tree", "two old cherry trees", the vines of a vineyard named by its plot, a count
of beds before their width ("four 1.5 m beds"), "18 rows x 90 m at 2.2 m", a dash that is
no minus sign, measures going on past a bracket, "in both blocks", "top bit", "To the
south, a Navel block" opening a sentence, a walk past scenery, "Northwest: orchard.",
"out west" and a strip walked along."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_members_told_apart_by_their_side_and_size(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Photo shows two tomato fields side by side, the left one about a hectare and the right "
        "one half a hectare, both with the fruit turning red."
    )
    left, right = recipe(prompt).fields
    for field, area in ((left, 10_000.0), (right, 5_000.0)):
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(area, rel=0.01)
    assert ("west_of", "Tomato", ("Tomato",)) in named_relations(prompt)


def test_parts_and_single_plants_of_a_field_named() -> None:
    (wheat,) = recipe(
        "Patches of the wheat have yellow rust, orange pustules in stripes along the leaves."
    ).fields
    assert wheat.health == "Ill"
    (pears,) = recipe(
        "The pear trees in the photo have fire blight: blackened blossoms. Blue sky and a "
        "ladder against the nearest tree."
    ).fields
    assert pears.crop == "Pear"
    tomatoes, cherries = recipe(
        "Photo of the back plot: cherry tomatoes climbing the fence on one side and two old "
        "cherry trees on the other."
    ).fields
    assert (tomatoes.crop, cherries.crop) == ("Tomato", "Cherry")
    assert cherries.nominal_plant_count == 2


def test_the_vines_of_a_vineyard_named_by_its_plot() -> None:
    vines, cherries = recipe(
        "Vineyard and cherry orchard side by side near Curicó, Chile. Photo from early "
        "December: the cherries are ripe and red, the vines are in flower."
    ).fields
    assert (vines.crop, vines.stage) == ("Grape", "Reproductive")
    assert (cherries.crop, cherries.stage) == ("Cherry", "Maturation")


def test_beds_counted_before_their_width_and_rows_with_their_length() -> None:
    tomatoes, peppers = recipe(
        "Test bed for a picking robot: staked tomatoes in 8 rows, 1.5 m row spacing, 50 cm "
        "in-row; peppers on four 1.5 m beds with twin rows and 45 cm between plants. Put the "
        "tomatoes west of the peppers."
    ).fields
    assert (peppers.agronomy.row_spacing_m, peppers.agronomy.rows_per_bed) == (1.5, 2)
    assert tomatoes.agronomy.row_spacing_m == 1.5
    assert "beds" in peppers.stated
    pinot, chardonnay = recipe(
        "Two vineyard blocks for canopy LiDAR: a Pinot Nero block of 18 rows x 90 m at 2.2 m, "
        "and west of it a Chardonnay block of 22 rows x 90 m at 2.2 m."
    ).fields
    assert pinot.agronomy.row_spacing_m == chardonnay.agronomy.row_spacing_m == 2.2


def test_measures_after_a_dash_and_past_a_bracket_are_every_fields() -> None:
    fields = recipe(
        "Three pepper plots for the gripper benchmark - California Wonder, Cayenne and "
        "Pimientos de Padrón - 6 beds each, 1.5 m beds with twin rows, plants 45 cm apart."
    ).fields
    assert {(f.agronomy.row_spacing_m, f.agronomy.rows_per_bed) for f in fields} == {(1.5, 2)}
    bibb, cos = recipe(
        "Bibb lettuce north of Cos lettuce; each gets 10 beds 1.2 m wide (centre to centre) "
        "with 3 rows per bed and heads every 30 cm."
    ).fields
    assert bibb.agronomy.rows_per_bed == cos.agronomy.rows_per_bed == 3
    assert bibb.agronomy.in_row_spacing_m == cos.agronomy.in_row_spacing_m == 0.3


def test_rows_said_of_both_blocks_after_them() -> None:
    gala, pears = recipe(
        "Two blocks for the LiDAR canopy dataset. Block A: Gala apples, 12 rows at 3.5 m, trees "
        "1 m apart in the row. Block B, directly east of A: Conference pears, 10 rows at 3.5 m "
        "with 1.2 m in-row spacing. Rows run E-W in both blocks."
    ).fields
    assert gala.geometry.rotation_deg == pears.geometry.rotation_deg == pytest.approx(-90.0)


def test_places_said_in_other_words(named_relations: Callable[[str], NamedRelations]) -> None:
    assert len(recipe("top bit stone fruit, middle roots, bottom grain lol").fields) == 3
    assert ("south_of", "Navel", ("Valencia",)) in named_relations(
        "Citrus blocks for the planner. Valencia Late: 7.2 m between rows, 14 rows. To the "
        "south, a Washington Navel block with 10 rows."
    )
    assert {("north_of", "Orange", ("Maize",)), ("north_of", "Maize", ("Potato",))} <= (
        named_relations(
            "Mum's farm, going from north to south: an orchard by the road, then a maize field, "
            "then potatoes down by the stream."
        )
    )
    fields = recipe(
        "Four zones on the farm. Northwest: orchard. Northeast: vineyard. Southwest: spuds. "
        "Southeast: corn."
    ).fields
    assert [f.crop for f in fields][1:] == ["Grape", "Potato", "Maize"]
    assert named_relations("Out west there's the wheat, out east the potatoes.") == {
        ("west_of", "Wheat", ("Potato",))
    }


def test_a_strip_walked_along_is_no_field() -> None:
    fields = recipe(
        "Overcast day on the farm, a couple of workers walking the strip between a wheat field "
        "and a potato field."
    ).fields
    assert [f.crop for f in fields] == ["Wheat", "Potato"]


def test_a_plot_of_a_category_titling_the_plots_listed_after_it() -> None:
    fields = recipe(
        "Veg block for the drone. Three plots in a line, north to south: cabbages (rows 75 cm "
        "apart, 45 cm between heads), then onions (30 cm rows, 10 cm in row), then carrots on "
        "75 cm ridges. Every plot is 20 m x 50 m."
    ).fields
    assert [f.crop for f in fields] == ["Cabbage", "Onion", "Carrot"]
    # (a plot of the category is still a field when the list names another category)
    fields = recipe("A veg garden. Three plots: cabbages, onions and apples.").fields
    assert len(fields) == 4

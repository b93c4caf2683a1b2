"""Engineering requests of blind set g6 (issue 8): "×", inches after a row count, a
row direction in compass words, "N rows of <crop> at <spacing>", "12 beds of A and 12
of B", a crop heading a count of plots, measures after a full list, fewer rows than
beds, and "respectively" after the measure."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "rows", "length"),
    [
        ("Cherry orchard, 25 rows × 200 m, 4.5 m row spacing, 2.5 m between trees", 25, 200),
        ("Spätburgunder block, 40 rows × 90 m, row spacing 2 m, vines 0.9 m apart", 40, 90),
    ],
)
def test_a_times_sign_joins_rows_and_their_length(prompt: str, rows: int, length: int) -> None:
    (field,) = recipe(prompt).fields
    assert field.row_count == rows
    assert field.row_length_m == pytest.approx(length)


def test_inches_after_a_row_count_and_a_second_block_also_so() -> None:
    scene = recipe(
        "Pollen isolation sim: a sweetcorn block of 30 rows at 30 in, and a popping corn "
        "block, also 30 rows at 30 in, to the west of it."
    )
    assert [f.variety for f in scene.fields] == ["Sweet Corn", "Popcorn"]
    assert [f.row_count for f in scene.fields] == [30, 30]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.762, 0.762]


@pytest.mark.parametrize(
    ("prompt", "bearing"),
    [
        ("Cabernet Sauvignon vineyard, 30 rows, 2.5 m row spacing, row direction NE-SW", 45),
        ("spuds on 90 cm ridges, 30 ridges, rows 80 m long east-west", 90),
    ],
)
def test_row_directions_in_compass_words(prompt: str, bearing: float) -> None:
    assert recipe(prompt).fields[0].row_bearing_deg == pytest.approx(bearing)


def test_rows_of_a_crop_at_a_spacing_and_inch_spacings() -> None:
    scene = recipe(
        "field tomatos for a picking-robot test: 10 rows on 5 ft centers, plants 18 inches "
        "apart in the row, rows 150 ft long. plus 6 rows of peppers at 3 ft, east of the "
        "tomatoes"
    )
    tomato, pepper = scene.fields
    assert (pepper.row_count, pepper.agronomy.row_spacing_m) == (6, 0.9144)
    assert tomato.agronomy.in_row_spacing_m == pytest.approx(0.4572)
    potatoes = recipe("Russet potatoes: 48 rows on 36 in spacing, seed pieces 12 in apart")
    assert potatoes.fields[0].agronomy.row_spacing_m == pytest.approx(0.9144)
    assert potatoes.fields[0].agronomy.in_row_spacing_m == pytest.approx(0.3048)


def test_a_count_said_again_with_of_is_of_the_same_beds() -> None:
    scene = recipe(
        "Onion beds: 12 beds of Sturon and 12 of Red Baron, all on 1.8 m centres with 6 rows "
        "per bed. Put the Red Baron north of the Sturon."
    )
    assert [f.variety for f in scene.fields] == ["Sturon", "Red Baron"]
    assert [f.bed_count for f in scene.fields] == [12, 12]


def test_a_crop_heading_a_count_of_plots_is_no_field() -> None:
    scene = recipe(
        "Lettuce trial for the thinning robot, three plots from north to south: Cos, "
        "crisphead, Lollo Rosso. Every plot is 5 beds of 1.2 m with 4 rows per bed."
    )
    assert [f.variety for f in scene.fields] == ["Romaine", "Iceberg", "Lollo Rosso"]
    assert [f.bed_count for f in scene.fields] == [5, 5, 5]


def test_measures_after_a_full_list_go_to_every_member() -> None:
    scene = recipe(
        "Two strawberry plots of 10 beds each, Elsanta and Albion, beds 1.3 m centre to centre "
        "with 2 rows per bed; Albion directly east of the Elsanta."
    )
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [1.3, 1.3]
    pears = recipe(
        "two pear blocks, rows 3.5 m apart: Doyenné du Comice, 16 rows, and Durondeau, 12 rows"
    )
    assert [f.row_count for f in pears.fields] == [16, 12]


def test_fewer_rows_than_beds_are_rows_on_each_bed() -> None:
    scene = generate(
        "Centenary strawberries on 14 beds at 1.52 m centres, 2 rows each, plants 25 cm apart",
        resolver="hybrid",
    )
    (field,) = scene.recipe.fields
    assert (field.bed_count, field.agronomy.rows_per_bed) == (14, 2)
    assert any("2 rows on each bed" in w for w in scene.recipe.warnings)


def test_respectively_after_the_measure() -> None:
    scene = recipe(
        "Two 50 x 200 m plots for a combine-header sim: winter wheat east of dent corn, rows "
        "15 cm and 76 cm respectively."
    )
    assert [f.crop for f in scene.fields] == ["Wheat", "Maize"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.15, 0.76]


def test_square_grids_and_densities_per_square_metre() -> None:
    (banana,) = recipe("a banana patch planted on a 3 x 3 m square grid, 15 rows").fields
    assert (banana.agronomy.row_spacing_m, banana.row_count) == (3.0, 15)
    onion = recipe("an onion bed of 1.5 x 25 m at 40 per square metre").fields[0]
    assert onion.plants_per_ha == pytest.approx(400_000, rel=0.01)

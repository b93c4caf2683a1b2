"""Engineering text of blind set g7 (issue 8): planting grids said like sizes ("Cripps
Pink 3.4 x 1.0 m, 18 rows", "Savoy cabbage, 60 x 40 cm")."""

from __future__ import annotations

import itertools

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "grids"),
    [
        (
            "Savoy cabbage, 60 x 40 cm, 30 rows of 50 m, heads ready for cutting, November.",
            [(0.6, 0.4)],
        ),
        (
            "Cripps Pink and Bing blocks for a thermal-camera survey: Cripps Pink 3.4 x 1.0 m, "
            "18 rows; Bing 4.6 x 2.4 m, 10 rows; Bing on the south side.",
            [(3.4, 1.0), (4.6, 2.4)],
        ),
        (
            "Next to a Granny Smith block (3.5 m x 1 m, 20 rows) put a Cabernet vineyard.",
            [(3.5, 1.0), None],
        ),
    ],
)
def test_a_size_that_fits_the_crops_spacing_is_its_planting_grid(
    prompt: str, grids: list[tuple[float, float] | None]
) -> None:
    scene = recipe(prompt)
    assert len(scene.fields) == len(grids)
    for field, grid in zip(scene.fields, grids, strict=True):
        if grid is None:
            continue
        assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == grid
        assert {"row_spacing", "in_row_spacing"} <= set(field.stated)
        assert "size" not in field.stated
        assert min(field.geometry.size_m) > grid[0] * 5


def test_a_grid_beside_a_shared_size_is_not_a_second_size() -> None:
    scene = recipe(
        "two veg plots in a north-south line, each 15 x 30 m: beef tomatoes at the north "
        "end (1.5 m x 0.5 m), January King cabbage at the south end (0.75 x 0.45 m)."
    )
    assert [f.geometry.size_m for f in scene.fields] == [(15.0, 30.0), (15.0, 30.0)]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [1.5, 0.75]


@pytest.mark.parametrize("prompt", ["a 5 x 10 m lettuce plot", "a 10 x 12 m carrot plot"])
def test_a_small_plot_that_is_no_spacing_of_its_crop_stays_its_size(prompt: str) -> None:
    (field,) = recipe(prompt).fields
    assert "size" in field.stated
    assert "row_spacing" not in field.stated


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "carrot plot for a weed-detection dataset — 20 ridges at 75 cm centres, 2 rows per "
            "ridge, one carrot every 2 cm, ridge length 50 m, 5 m headland",
            {"row_length_m": 50.0, "in_row_spacing_m": 0.02, "headland_m": 5.0},
        ),
        (
            "popping corn for a tassel-detection model — 20 rows of 90 m on 76 cm, 6 plants per "
            "metre of row",
            {"row_spacing_m": 0.76, "row_length_m": 90.0},
        ),
        (
            "Ladyfinger bananas, 1,111 plants per hectare (3 x 3 m), 250 plants, young plants.",
            {"row_spacing_m": 3.0, "in_row_spacing_m": 3.0},
        ),
    ],
)
def test_row_measures_said_the_engineers_way(prompt: str, expected: dict[str, float]) -> None:
    (field,) = recipe(prompt).fields
    stated = {
        "row_length_m": field.row_length_m,
        "row_spacing_m": field.agronomy.row_spacing_m,
        "in_row_spacing_m": field.agronomy.in_row_spacing_m,
        "headland_m": field.geometry.headland_m,
    }
    for key, value in expected.items():
        assert stated[key] == pytest.approx(value, rel=0.01), key


def test_counted_beds_and_single_rows_of_a_crop_are_its_geometry() -> None:
    lettuce, cabbage = recipe(
        "For a weeding-robot trial put lettuce and cabbage side by side: 8 lettuce beds, 1.2 m "
        "wide centre to centre, 3 rows per bed; 10 single cabbage rows 60 cm apart. Everything "
        "40 m long."
    ).fields
    assert (lettuce.crop, lettuce.agronomy.row_spacing_m, lettuce.agronomy.rows_per_bed) == (
        "Lettuce",
        1.2,
        3,
    )
    assert (cabbage.crop, cabbage.agronomy.row_spacing_m) == ("Cabbage", 0.6)
    assert {"beds", "bed_width"} <= set(lettuce.stated)
    assert "rows" in cabbage.stated


def test_measures_in_the_plots_a_list_is_grown_in_are_each_plots() -> None:
    scene = recipe(
        "Blight camera variety trial: Fontane, Agria and Bintje in three 9-row strips (75 cm "
        "rows, 33 cm in-row, 40 m long), Fontane in the middle between the other two. Late "
        "blight is showing on the Bintje only."
    )
    assert [(f.variety, f.row_count, f.health) for f in scene.fields] == [
        ("Fontane", 9, "Healthy"),
        ("Agria", 9, "Healthy"),
        ("Bintje", 9, "Ill"),
    ]


def test_rows_on_each_ridge_stay_with_their_member() -> None:
    carrots, onions = recipe(
        "Hoeing-robot plots: 12 ridges of Nantes carrots (75 cm ridges, 2 rows on each) and 12 "
        "beds of Sturon onions (1.5 m beds, 4 rows per bed). Ridges and beds all 80 m long; "
        "onions on the west side of the carrots."
    ).fields
    assert (carrots.agronomy.row_spacing_m, carrots.agronomy.rows_per_bed) == (0.75, 2)
    assert (onions.agronomy.row_spacing_m, onions.agronomy.rows_per_bed) == (1.5, 4)
    assert [f.row_length_m for f in (carrots, onions)] == [pytest.approx(80.0)] * 2


def test_a_sentence_opening_with_rows_after_two_fields_is_said_of_both() -> None:
    scene = recipe(
        "Two onion plots for a bulb-sizing camera: Red Baron, 25 rows at 30 cm, bulbs every 8 "
        "cm; Walla Walla, 20 rows at 35 cm, bulbs every 10 cm. Rows 30 m, Walla Walla south of "
        "Red Baron, both mature."
    )
    assert [f.row_length_m for f in scene.fields] == [pytest.approx(30.0)] * 2
    assert [f.row_count for f in scene.fields] == [25, 20]


@pytest.mark.parametrize(
    "prompt",
    [
        "Mildew detection test: two vineyard blocks of 0.5 ha each, 4,000 vines/ha on 2.5 m "
        "rows. The north block has downy mildew, the south block is clean.",
        "two vineyard blocks of 0.5 ha each, 4,000 vines/ha on 2.5 m rows. One to the north "
        "has downy mildew, the other to the south is clean.",
    ],
)
def test_two_members_told_apart_by_their_side(prompt: str) -> None:
    scene = recipe(prompt)
    north, south = scene.fields
    assert (north.health, south.health) == ("Ill", "Healthy")
    assert [f.geometry.area_m2 for f in scene.fields] == [pytest.approx(5000.0)] * 2
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [pytest.approx(1.0)] * 2
    assert ("north_of", north.id, (south.id,)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }


def test_a_plot_named_by_its_side_and_a_crop_is_still_that_crop() -> None:
    east, west = recipe("the east plot is Bintje, the west plot Fontane").fields
    assert (east.variety, west.variety) == ("Bintje", "Fontane")


def test_a_field_named_again_as_the_object_of_a_relation_is_that_field() -> None:
    scene = recipe(
        "For the headland-turning test: maize with 12 m headlands and 0.75 m rows, and potatoes "
        "with 9 m headlands and 0.9 m rows; maize north of potatoes, each 2 ha."
    )
    maize, potatoes = scene.fields
    assert (maize.geometry.headland_m, potatoes.geometry.headland_m) == (12.0, 9.0)
    assert [f.geometry.area_m2 for f in scene.fields] == [pytest.approx(20000.0)] * 2
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("north_of", maize.id, (potatoes.id,))
    ]


def test_plots_in_a_row_from_west_to_east_are_an_order_not_a_row_direction() -> None:
    scene = recipe(
        "GNSS guidance test: four 20 m x 20 m plots in a row from west to east – potatos, "
        "cabbage, onions, carrots."
    )
    ids = [f.id for f in scene.fields]
    found = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert {("west_of", a, (b,)) for a, b in itertools.pairwise(ids)} <= found
    assert all("row_direction" not in f.stated for f in scene.fields)


def test_rows_of_the_same_length_copy_the_row_length_before() -> None:
    gala, pears = recipe(
        "Gala, 3.5 m x 1.0 m, 20 rows of 100 m. Conference pears, 3.75 m between rows and "
        "1.25 m between trees, 16 rows of the same length."
    ).fields
    assert gala.row_length_m == pytest.approx(100.0)
    assert pears.row_length_m == pytest.approx(100.0)
    assert "row_length" in pears.stated


def test_a_measure_said_in_both_blocks_in_its_own_clause_is_both_blocks() -> None:
    scene = recipe("Gala and Conference pears. Rows run east-west in both blocks.")
    assert [f.geometry.rotation_deg for f in scene.fields] == [-90.0, -90.0]


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "Canopy LiDAR dataset with three orchard blocks; the pear block is between the apple "
            "block and the cherrys. Apples 3.5 x 1 m, pears 3.5 x 1.25 m, cherrys 4.5 x 2.5 m, "
            "10 rows in each block.",
            ["Pear", "Apple", "Cherry"],
        ),
        ("two fields. The wheat is ripe, the maize is young.", ["Wheat", "Maize"]),
    ],
)
def test_a_definite_crop_after_a_count_of_plots_is_one_of_them(
    prompt: str, crops: list[str]
) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_two_members_told_apart_by_number_are_one_and_the_other() -> None:
    scene = recipe(
        "Two maize plots for the stand-count algorithm: plot 1 at 70,000 plants/ha, plot 2 at "
        "100,000 plants/ha. Plot 2 directly south of plot 1. Seedlings only."
    )
    first, second = scene.fields
    assert (first.plants_per_ha, second.plants_per_ha) == (
        pytest.approx(70000, rel=0.01),
        pytest.approx(100000, rel=0.01),
    )
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("south_of", second.id, (first.id,))
    ]


@pytest.mark.parametrize(
    "prompt", ["maize, 8 rows x 76 cm x 30 m", "8 rows x 76 cm x 30 m of maize"]
)
def test_rows_by_spacing_by_length(prompt: str) -> None:
    (field,) = recipe(prompt).fields
    assert (field.row_count, field.agronomy.row_spacing_m) == (8, 0.76)
    assert field.row_length_m == pytest.approx(30.0)


@pytest.mark.parametrize(
    ("prompt", "row", "plant"),
    [
        ("Riesling block, 1.8 m inter-row, 1.1 m intra-row, 25 rows, 5 m headland.", 1.8, 1.1),
        ("maize, row pitch 0.8 m, plant pitch 0.16 m, 48 rows, row length 250 m", 0.8, 0.16),
    ],
)
def test_spacings_in_engineers_words(prompt: str, row: float, plant: float) -> None:
    (field,) = recipe(prompt).fields
    assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == (row, plant)


def test_beds_with_rows_each_texted() -> None:
    (field,) = recipe("centenary strawbs, 6 beds w/ 2 rows each, rows 50m long").fields
    assert (field.variety, field.bed_count, field.agronomy.rows_per_bed) == (
        "Malling Centenary",
        6,
        2,
    )

"""Engineering requests of blind set g5 (issue 8): crop rows counted with the crop in
between ("12 maize rows"), spacing said "each way" or as a bare grid, counts of plants,
densities in millions, bearings, grass headlands, minus signs, closing measures shared
by parallel plots, purposes that name a crop, and scenes of scenery only."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "rows"),
    [("12 maize rows at 75 cm", 12), ("twenty Roma rows, 1.5 m apart", 20)],
)
def test_a_crop_between_the_number_and_rows_is_one_field(prompt: str, rows: int) -> None:
    (field,) = recipe(prompt).fields
    assert field.row_count == rows


def test_counted_crop_ridges_are_beds_not_fields() -> None:
    scene = recipe(
        "Weeding robot trial: 40 carrot ridges at 75 cm with two rows per ridge, next to an "
        "onion plot drilled at 30 cm between rows and 10 cm in-row."
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Onion"]
    assert scene.fields[0].bed_count == 40
    assert scene.fields[0].agronomy.rows_per_bed == 2


def test_two_strawberry_beds_without_a_measure_are_still_two_plots() -> None:
    assert len(recipe("two strawberry beds next to a lettuce bed").fields) == 3


@pytest.mark.parametrize(
    ("prompt", "spacing"),
    [
        ("Ladyfinger bananas, plants 3 m apart each way", (3.0, 3.0)),
        ("Durondeau and Bartlett pears, 3.5 m x 1 m, rows north-south", (3.5, 1.0)),
        ("Dwarf Cavendish at 2 m x 2 m", (2.0, 2.0)),
    ],
)
def test_planting_grids(prompt: str, spacing: tuple[float, float]) -> None:
    for field in recipe(prompt).fields:
        assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == spacing


def test_a_count_of_them_counts_plants_not_fields() -> None:
    (field,) = recipe(
        "Pear trees, 1,000 of them at 3.5 x 1.2 m, fire blight present. Disease-detection "
        "drone flights."
    ).fields
    assert field.crop == "Pear" and field.health == "Ill"
    assert field.agronomy.in_row_spacing_m == 1.2
    assert "plant_count" in field.stated


def test_density_in_millions_bearing_and_grass_headland() -> None:
    carrots = recipe("Imperator carrots sown at 2 million plants/ha on 1.5 m beds with 4 rows")
    assert carrots.fields[0].plants_per_ha == pytest.approx(2_000_000, rel=0.01)
    maize = recipe("Maize at 80,000 plants per hectare on 75 cm rows bearing 60 degrees")
    assert maize.fields[0].row_bearing_deg == pytest.approx(60)
    bintje = recipe("Bintje in full flower, ridges on 75 cm, a 6 m grass headland")
    assert bintje.fields[0].geometry.headland_m == 6


@pytest.mark.parametrize(
    "prompt",
    [
        "Potato plot for the robot with a row spacing of -75 cm and 30 cm in-row.",
        "Strawberry beds for the picker: 10 beds at -1.5 m bed spacing, 2 rows per bed.",
        "Conference pears in rows 4 m apart but with the trees at zero spacing in the row",
    ],
)
def test_negative_and_zero_spacings_are_refused(prompt: str) -> None:
    with pytest.raises(PromptError, match="positive number"):
        recipe(prompt)


def test_measures_after_parallel_plots_go_to_both() -> None:
    scene = recipe(
        "Pollination drone: 10 rows of beef tomatoes north of 10 rows of cherry tomatoes, "
        "1.6 m between rows, 50 cm in-row."
    )
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [1.6, 1.6]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [0.5, 0.5]


def test_a_sentence_of_measures_after_a_description_goes_to_every_field() -> None:
    scene = recipe(
        "8 rows of Royal Gala and, directly south of them, 8 rows of Granny Smith. Tall "
        "spindle, 3.5 m between rows, trees 1 m apart, rows 120 m long on a bearing of 15°."
    )
    for field in scene.fields:
        assert field.agronomy.row_spacing_m == 3.5
        assert field.row_length_m == pytest.approx(120)
        assert field.row_bearing_deg == pytest.approx(15)


def test_measures_per_block_go_to_every_block() -> None:
    scene = recipe("Lapins north of Regina, 8 rows per block, 5 m between rows, 3 m between trees.")
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [5.0, 5.0]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [3.0, 3.0]


def test_a_crop_named_in_a_purpose_is_not_a_field() -> None:
    scene = recipe(
        "Dwarf Cavendish at 2 m x 2 m next to Lady Finger at 3 m x 3 m, 1 ha each, for a "
        "banana canopy-segmentation dataset."
    )
    assert [f.variety for f in scene.fields] == ["Cavendish", "Lady Finger"]


def test_a_scene_of_scenery_only_is_refused() -> None:
    with pytest.raises(PromptError, match="only scenery"):
        recipe(
            "Set up a drone survey scene over the equipment yard: two tractors, a sprayer, "
            "the machine shed and an overcast sky."
        )
    assert len(recipe("a farm scene").fields) == 3


def test_either_side_of_it_places_the_field_between() -> None:
    scene = recipe(
        "Between the two tracks sits the Cabernet, and either side of it we've planted "
        "Chardonnay to the west and Pinot Nero to the east."
    )
    cabernet, chardonnay, pinot = (f.id for f in scene.fields)
    assert len(scene.fields) == 3
    assert ("between", cabernet, (chardonnay, pinot)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }


def test_measures_in_brackets_after_plots_are_theirs_only() -> None:
    scene = recipe(
        "Camera rig test: two lettuce plots (10 rows each, 35 cm row spacing) with a cabbage "
        "plot between them planted in 75 cm rows."
    )
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.35, 0.35, 0.75]
    assert [f.row_count for f in scene.fields][:2] == [10, 10]
    assert "rows" not in scene.fields[2].stated


def test_a_plot_word_heading_a_count_of_plots_is_no_field() -> None:
    scene = recipe(
        "Pruning-robot vineyard, two blocks: Chardonnay, 40 rows at 2.2 m, east of Cabernet, "
        "36 rows at 2.5 m. Vines 1 m apart in both."
    )
    assert [f.variety for f in scene.fields] == ["Chardonnay", "Cabernet Sauvignon"]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [1.0, 1.0]


def test_a_spread_list_with_respectively_goes_to_the_fields_in_order() -> None:
    scene = recipe(
        "Three plots for the soil-moisture probes - spuds, carrots and onions - each 12 rows, "
        "at 75, 50 and 30 cm row spacing respectively."
    )
    assert [f.crop for f in scene.fields] == ["Potato", "Carrot", "Onion"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.75, 0.5, 0.3]
    assert [f.row_count for f in scene.fields] == [12, 12, 12]


def test_row_length_then_spacing_in_one_phrase() -> None:
    field = recipe("tomato plants in 100 m rows 1.2 m apart, 40 cm in the row").fields[0]
    assert field.row_length_m == pytest.approx(100)
    assert field.agronomy.row_spacing_m == 1.2


def test_a_measure_said_with_each_by_the_last_of_a_list_is_everyones() -> None:
    scene = recipe(
        "The Hamlin block takes the east half, Washington Navel the west half: 150 trees each "
        "at 7 m x 4 m, rows running north-south."
    )
    assert [(f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in scene.fields] == [
        (7.0, 4.0),
        (7.0, 4.0),
    ]
    assert ("east_of", scene.fields[0].id, (scene.fields[1].id,)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }


def test_a_count_of_plants_in_rows_of_a_stated_length_fills_whole_rows() -> None:
    scene = generate(
        "1,000 tomato plants in 100 m rows 1.5 m apart, 50 cm in the row", resolver="hybrid"
    )
    (field,) = scene.recipe.fields
    assert field.row_length_m == pytest.approx(100)
    assert field.row_count == 5  # 201 positions a row: 5 rows hold the 1,000 ...
    assert field.nominal_plant_count == 1000  # ... the last one short
    assert any("do not fill 100 m rows evenly" in w for w in scene.recipe.warnings)


@pytest.mark.parametrize(
    ("prompt", "rows", "size"),
    [
        ("10 rows of maize 76 cm apart in a 20 x 50 m plot", 10, (20.0, 50.0)),
        (
            "Put a strawberry plot (8 beds, 1.5 m centres, 2 rows per bed) between two wheat "
            "plots drilled at 12.5 cm; all three are 20 x 50 m.",
            16,
            (20.0, 50.0),
        ),
    ],
)
def test_rows_that_fill_less_than_a_stated_plot_are_a_planted_block(
    prompt: str, rows: int, size: tuple[float, float]
) -> None:
    from agrirecipe.layout import field_parameters, place_field

    recipe_ = recipe(prompt)
    field = recipe_.fields[0]
    assert field.geometry.size_m == size
    assert field.row_count == rows
    assert field.geometry.planted_m is not None
    assert field.geometry.planted_m[0] < size[0] - 2 * field.geometry.headland_m
    # the layout kernel (plants.csv, Blender, USD, Unreal) plants exactly that block
    params = field_parameters(recipe_)[0]
    plants = place_field(dict(params, missing_rate=0.0))
    assert len(plants) == field.nominal_plant_count
    xs = sorted({round(p[0], 3) for p in place_field(dict(params, missing_rate=0.0, jitter_m=0.0))})
    assert len(xs) == rows


def test_a_plot_that_the_rows_fill_has_no_planted_block() -> None:
    field = recipe("10 rows of maize 76 cm apart").fields[0]
    assert field.geometry.planted_m is None
    assert field.row_count == 10


def test_a_size_that_fits_the_crops_spacing_is_its_planting_grid() -> None:
    prompt = "Stone fruit along the north edge, citrus along the south; both blocks 4 m x 2 m"
    for text in (prompt, prompt.replace("4 m x 2 m", "planted at 4 m x 2 m")):
        scene = recipe(text)
        assert [(f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in scene.fields] == [
            (4.0, 2.0),
            (4.0, 2.0),
        ]
        assert all(f.geometry.size_m[0] > 4.0 for f in scene.fields)


def test_a_field_too_small_for_its_crop_and_no_grid_of_it_is_refused_with_the_way_to_say_it() -> (
    None
):
    with pytest.raises(PromptError, match="too small for one") as error:
        recipe("a 1 m x 1 m Valencia orange orchard")
    assert "planted at 1 m x 1 m" in (error.value.hint or "")

"""Engineering text of blind set g8 (issue 8): measures said once after two blocks of one
crop, "12 of them", "4 beds of 3 rows", "single row per bed", "1.5 m beds with 3 rows per
bed", a bare "apart" after spaced rows, values listed before a measure, plots "laid out
west to east", a crop heading a colon, diseases named as a dataset's subject, and
"different densities"."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import FieldSpec, SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def spacing(field: FieldSpec) -> tuple[float | None, float | None]:
    return field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m


@pytest.mark.parametrize(
    "prompt",
    [
        "Citrus test site for a fruit-detection camera: a Navel block next to a blood orange "
        "block, 6 m between rows, 3 m between trees, fruit ripe, January.",
        "Two vineyard blocks for a trellis-wire dataset: Chardonnay on the east side and "
        "Cabernet on the west, 6 m between rows, 3 m between vines, rows NW-SE.",
    ],
)
def test_measures_after_two_blocks_of_one_crop_are_both_blocks(prompt: str) -> None:
    scene = recipe(prompt)
    assert [spacing(f) for f in scene.fields] == [(6.0, 3.0), (6.0, 3.0)]


def test_measures_after_two_counted_rows_of_varieties_and_a_placement() -> None:
    scene = recipe(
        "tomato variety trial: 6 rows of Roma and 6 rows of San Marzano, 1.5 m row spacing, "
        "40 cm in-row, 80 m rows, Roma on the north side. Fruit ripening, mid-August."
    )
    assert [spacing(f) for f in scene.fields] == [(1.5, 0.4), (1.5, 0.4)]
    assert [f.stage for f in scene.fields] == ["Maturation", "Maturation"]


def test_measures_of_one_member_stay_with_it() -> None:
    scene = recipe(
        "two sweet cherry blocks: Kordia, 10 rows at 4.6 m with 2.4 m in-row; Regina "
        "directly south, 8 rows at 5 m with 2 m in-row."
    )
    assert [spacing(f) for f in scene.fields] == [(4.6, 2.4), (5.0, 2.0)]


def test_different_crops_do_not_share_measures_said_after_the_last() -> None:
    scene = recipe("a wheat field next to a maize field, 76 cm rows")
    wheat, maize = scene.fields
    assert maize.agronomy.row_spacing_m == pytest.approx(0.76)
    assert wheat.agronomy.row_spacing_m != pytest.approx(0.76)


@pytest.mark.parametrize(
    ("prompt", "rows"),
    [
        ("sweetcorn plot. 30-inch rows, 12 of them, 200 ft long.", 12),
        ("maize, 75 cm rows, twelve of them.", 12),
    ],
)
def test_rows_counted_after_their_spacing(prompt: str, rows: int) -> None:
    (field,) = recipe(prompt).fields
    assert field.row_count == rows


def test_one_of_them_is_no_row_count() -> None:
    scene = recipe("2 maize fields 75cm rows, 1 of them 5 ha the other 3 ha")
    assert sorted(round(f.geometry.area_m2) for f in scene.fields) == [30000, 50000]


def test_beds_of_rows_and_bed_words() -> None:
    scene = recipe(
        "Three lettuce types: Cos, Lollo Rosso and Butterhead, each 4 beds of 3 rows, beds on "
        "1.2 m centres, rows 25 m long."
    )
    for field in scene.fields:
        assert (field.bed_count, field.agronomy.rows_per_bed) == (4, 3)
        assert field.agronomy.row_spacing_m == pytest.approx(1.2)  # bed centres


def test_single_row_per_bed_and_plants_apart_before_the_next_plot() -> None:
    tomatoes, peppers = recipe(
        "Two plots: tomatoes on 1.5 m beds, single row per bed, plants 50 cm apart, and right "
        "next to them peppers in twin rows on 1.4 m beds with 45 cm in-row spacing."
    ).fields
    assert (tomatoes.agronomy.rows_per_bed, tomatoes.agronomy.in_row_spacing_m) == (1, 0.5)
    assert (peppers.agronomy.rows_per_bed, peppers.agronomy.in_row_spacing_m) == (2, 0.45)


def test_same_beds_with_rows_per_bed_is_no_new_plot() -> None:
    scene = recipe(
        "a strawberry plot: 12 raised beds on 1.5 m centres, two rows per bed. Plus a lettuce "
        "plot next to it on the same 1.5 m beds with 3 rows per bed. A polytunnel over the "
        "strawberries is fine."
    )
    assert [(f.crop, f.agronomy.rows_per_bed) for f in scene.fields] == [
        ("Strawberry", 2),
        ("Lettuce", 3),
    ]


def test_a_bare_apart_after_spaced_rows_is_the_plants() -> None:
    (field,) = recipe("carrots in 45 cm rows, 4 cm apart").fields
    assert spacing(field) == (0.45, 0.04)


def test_a_list_value_that_is_not_respective_is_not_checked_as_a_count() -> None:
    scene = recipe(
        "cabbage at 0.75 m x 0.45 m, 0.3 ha, west of a ditch, and carrots on 0.75 m ridges "
        "with 2 rows per ridge, 0.3 ha, east of it."
    )
    assert [f.agronomy.rows_per_bed for f in scene.fields][-1] == 2


def test_values_listed_with_commas_before_a_measure_go_in_order() -> None:
    scene = recipe(
        "Three maize plots at different densities: 60,000, 80,000 and 100,000 plants/ha, all "
        "76 cm rows, placed north to south in that order."
    )
    assert [round(f.plants_per_ha, -2) for f in scene.fields] == [60000, 80000, 100000]
    assert len({f.variety for f in scene.fields}) == 1  # a density trial of one variety


def test_a_range_is_no_list() -> None:
    (field,) = recipe("maize at between 70,000 and 80,000 plants/ha").fields
    assert field.crop == "Maize"


def test_plots_laid_out_west_to_east_is_their_order() -> None:
    scene = recipe(
        "three plots laid out west to east: potatoes (ridges 90 cm), maize (rows 75 cm), "
        "wheat (rows 15 cm). Each plot 50 x 50 m."
    )
    assert [(r.kind, r.subject, r.objects) for r in scene.relations][:2] == [
        ("west_of", scene.fields[0].id, (scene.fields[1].id,)),
        ("west_of", scene.fields[1].id, (scene.fields[2].id,)),
    ]
    assert all(f.geometry.rotation_deg == 0 for f in scene.fields)


def test_a_crop_heading_a_colon_and_a_counted_list() -> None:
    scene = recipe(
        "Rain-cover test for cherries: two blocks, Kordia and Regina, 16 rows each. The "
        "Regina block sits north of the Kordia block."
    )
    assert [f.variety for f in scene.fields] == ["Kordia", "Regina"]


def test_a_disease_a_dataset_is_about_is_no_health() -> None:
    fontane, russet = recipe(
        "Two potato plots for a late-blight spectral dataset: Fontane, infected with late "
        "blight, and Russet, healthy. Each 36 rows at 90 cm; the Russet plot is to the east."
    ).fields
    assert (fontane.health, russet.health) == ("Ill", "Healthy")


def test_compass_members_said_with_in() -> None:
    west, east = recipe(
        "two cabbage plots side by side. in the west plot the leaves are riddled with "
        "caterpillar holes, the east plot is clean."
    ).fields
    assert (west.health, east.health) == ("Ill", "Healthy")


def test_impossible_listed_counts_are_still_refused() -> None:
    with pytest.raises(PromptError, match="whole number"):
        generate("apples and pears, 10.5 and 12 rows respectively")

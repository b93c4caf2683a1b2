"""Engineering requests of blind set g4 (issue 8): plot words used as a machine's kind,
"single rows", a plot placed against "it", a second plot of a weakly named variety,
seed spacing, and a number that is part of a name."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_plot_word_before_a_machine_is_not_a_field() -> None:
    scene = recipe(
        "Row-crop robot test, two adjacent plots: Danvers carrots in single rows 50 cm apart, "
        "40 rows; crisphead lettuce with 40 cm rows and 35 cm in-row, 40 rows."
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Lettuce"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.5, 0.4]


def test_single_rows_are_a_planting_form_not_one_row() -> None:
    scene = recipe("single-row tomatoes, 16 rows 1.6 m apart")
    assert scene.fields[0].agronomy.row_spacing_m == 1.6
    assert scene.fields[0].agronomy.rows_per_bed == 1
    assert recipe("a single row of lettuce").fields[0].geometry.size_m[0] < 1


def test_measures_after_north_of_it_belong_to_the_plot_placed() -> None:
    scene = recipe(
        "chilli plot, 30 rows, 0.9 m row spacing, 0.4 m between plants, rows N-S; Padron "
        "plot north of it, 20 rows, also 0.9 m rows"
    )
    assert [f.variety for f in scene.fields][1] == "Padron"
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("north_of", scene.fields[1].id, (scene.fields[0].id,))
    ]


def test_a_second_plot_of_a_weak_variety_name_is_that_crop() -> None:
    scene = recipe(
        "strawberry beds: 10 beds, 1.2 m bed centres, 3 rows per bed. second plot of Sonata "
        "to the south, 6 beds"
    )
    assert [(f.crop, f.variety) for f in scene.fields][1] == ("Strawberry", "Sonata")


def test_seed_spacing_is_the_in_row_spacing() -> None:
    field = recipe("Russet potatoes, 36-inch rows, 12-inch seed spacing, 48 rows").fields[0]
    assert field.agronomy.in_row_spacing_m == 0.3048


def test_a_number_after_a_capitalised_name_is_not_a_count() -> None:
    scene = recipe("Two sweet cherry blocks on Gisela 6, Kordia and Regina.")
    assert [f.variety for f in scene.fields] == ["Kordia", "Regina"]


def geometry(prompt: str) -> list[tuple[float, int, float]]:
    return [
        (f.agronomy.row_spacing_m, f.agronomy.rows_per_bed, f.agronomy.in_row_spacing_m)
        for f in recipe(prompt).fields
    ]


def test_rows_then_each_length_after_a_comma() -> None:
    field = recipe("Granny Smith block, 12 tree rows, each 80 m, 3.5 m between rows").fields[0]
    assert field.geometry.size_m[1] == pytest.approx(80 + 2 * field.geometry.headland_m)


@pytest.mark.parametrize(
    "prompt",
    [
        "a Fuji block (10 rows, 3.4 m rows, 1 m in-row, 60 m)",
        "Fuji apples: 3.4 m rows, 1 m in-row, 10 rows, 60 m, 4 m headland",
    ],
)
def test_a_bare_length_among_row_measures_is_the_row_length(prompt: str) -> None:
    field = recipe(prompt).fields[0]
    assert field.geometry.size_m[1] == pytest.approx(60 + 2 * field.geometry.headland_m)


def test_twin_rows_on_beds_of_a_width() -> None:
    assert geometry("a sweet pepper plot grown as twin rows on 1.5 m beds, 45 cm in-row") == [
        (1.5, 2, 0.45)
    ]


def test_bed_centres_in_inches() -> None:
    assert geometry("Capsicum plot: 18 beds, 60 in bed centres, 2 rows per bed")[0][:2] == (
        1.524,
        2,
    )


def test_a_listed_member_named_again_is_that_member() -> None:
    scene = recipe(
        "HLB detection plots: a Valencia block with citrus greening and a healthy Hamlin "
        "block, rows 6 m apart, Valencia east of Hamlin."
    )
    assert [f.variety for f in scene.fields] == ["Valencia", "Hamlin"]
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("east_of", scene.fields[0].id, (scene.fields[1].id,))
    ]


def test_a_crop_heading_the_list_of_its_fields_is_not_another_field() -> None:
    scene = recipe(
        "Citrus test site in Chile, July: a blood orange block next to a Valencia Late block"
    )
    assert [f.variety for f in scene.fields] == ["Moro", "Valencia"]
    assert len(recipe("Apples: Gala and Fuji").fields) == 2


def test_the_two_plots_point_back_at_the_listed_members() -> None:
    scene = recipe(
        "Banana variety plots: Big Mike and Lady Finger, 200 plants each, the two plots adjacent."
    )
    assert [f.variety for f in scene.fields] == ["Gros Michel", "Lady Finger"]
    assert [r.kind for r in scene.relations] == ["next_to"]


def test_beds_of_a_width_with_rows_each() -> None:
    assert geometry("peppers on 1.5 m beds with two rows each (12 beds)")[0][:2] == (1.5, 2)


def test_a_stage_word_naming_a_machine_s_job_is_not_the_crop_s_stage() -> None:
    scene = recipe("Harvesting-arm test: peppers on 1.5 m beds, young plants")
    assert scene.fields[0].stage == "Vegetative"
    assert recipe("Harvesting-arm test: peppers").fields[0].stage != "Maturation"


@pytest.mark.parametrize(
    ("prompt", "rotation"),
    [
        ("Wheat field drilled NE-SW, 1.5 ha", -45.0),
        ("potatoes, 40 rows @ 75cm, 150m rows, E-W.", -90.0),
    ],
)
def test_row_directions_said_after_drilling_or_alone(prompt: str, rotation: float) -> None:
    assert recipe(prompt).fields[0].geometry.rotation_deg == rotation


@pytest.mark.parametrize(
    "prompt",
    [
        "Romaine, Iceberg and Lollo Rosso lettuce, each a 15 m x 40 m plot, 35 cm rows",
        "from west to east: carrots, onions, lettuce. Each plot 15 m wide and 40 m long, rows "
        "running north-south",
    ],
)
def test_a_plot_of_each_gives_its_size_to_every_field(prompt: str) -> None:
    scene = recipe(prompt)
    assert len(scene.fields) == 3
    assert {f.geometry.size_m for f in scene.fields} == {(15.0, 40.0)}


def test_same_bed_width_as_the_plot_before() -> None:
    scene = recipe(
        "strawberry beds: 10 beds, 1.2 m bed centres, 3 rows per bed. second plot of Sonata "
        "to the south, 6 beds, same bed width"
    )
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [1.2, 1.2]


def test_rows_in_the_same_direction_as_the_field_before() -> None:
    scene = recipe(
        "wheat, 0.5 ha, 12.5 cm drill rows, rows E-W; right next to it 0.5 ha of maize at "
        "75 cm, rows in the same direction"
    )
    assert [f.geometry.rotation_deg for f in scene.fields] == [-90.0, -90.0]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.125, 0.75]

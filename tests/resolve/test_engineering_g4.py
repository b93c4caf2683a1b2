"""Engineering requests of blind set g4 (issue 8): plot words used as a machine's kind,
"single rows", a plot placed against "it", a second plot of a weakly named variety,
seed spacing, and a number that is part of a name."""

from __future__ import annotations

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

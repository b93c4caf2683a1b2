"""Text of blind set g13 (issue 8): row measures said as pairs and alleys, "single rows",
a crop named again with a plot of its own or after "the", a trailing direction after a
bracket, the order of a list "in that order", and a closing row direction said of fields
of one crop."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str | None, str, tuple[str | None, ...]]]:
    name = {f.id: f.variety or f.crop for f in scene.fields}
    return {(name[r.subject], r.kind, tuple(name[o] for o in r.objects)) for r in scene.relations}


def test_single_rows_are_how_a_crop_is_planted_not_a_count() -> None:
    scene = recipe(
        "Chantenay carrots and Red Baron onions next to each other, both in 20 m rows: carrots "
        "on 75 cm ridges with two rows per ridge, onions in single rows 30 cm apart with 10 "
        "plants per metre."
    )
    assert [f.variety for f in scene.fields] == ["Chantenay", "Red Baron"]
    onions = scene.fields[1]
    assert onions.agronomy.row_spacing_m == pytest.approx(0.3)
    assert onions.agronomy.in_row_spacing_m == pytest.approx(0.1)


@pytest.mark.parametrize(
    "prompt",
    [
        "Two plots for a tropical robotics demo: bananas on a 3 m square grid and chillies in "
        "1 m rows with plants every 40 cm, chilli plot west of the bananas.",
        "Two plots for an inter-row hoe: bananas on a 3 m square grid, and chillies in 1 m "
        "rows; chilli plot directly west of the bananas.",
    ],
)
def test_a_listed_crop_named_again_with_a_plot_and_placed_is_that_member(prompt: str) -> None:
    scene = recipe(prompt)
    assert [f.crop for f in scene.fields] == ["Banana", "Pepper"]
    assert {r.kind for r in scene.relations} == {"west_of"}


def test_a_second_definite_mention_of_a_clause_points_back() -> None:
    scene = recipe(
        "Occlusion test: a maize block (20 rows, 75 cm) immediately south of a tomato block "
        "(10 rows, 1.5 m), so the tall corn casts shadow on the tomatoes."
    )
    assert [f.crop for f in scene.fields] == ["Maize", "Tomato"]


def test_a_trailing_direction_after_a_bracket_places_the_field_before_it() -> None:
    scene = recipe(
        "a Cabernet Sauvignon vineyard (2.7 m rows, 1.2 m vines) to the south and a Fuji "
        "apple block (3.6 m rows, 1.0 m trees) to the north, both 0.4 ha."
    )
    assert relations(scene) == {("Cabernet Sauvignon", "south_of", ("Fuji",))}
    vines, apples = scene.fields
    assert (vines.agronomy.row_spacing_m, vines.agronomy.in_row_spacing_m) == (2.7, 1.2)
    assert (apples.agronomy.row_spacing_m, apples.agronomy.in_row_spacing_m) == (3.6, 1.0)


@pytest.mark.parametrize(
    ("prompt", "rows", "in_row"),
    [
        ("a Jonagold apple block (rows 3.2 m, trees 0.9 m)", 3.2, 0.9),
        ("a Riesling vineyard (2.5 m rows, 1.1 m vines)", 2.5, 1.1),
        ("a sweet cherry orchard: 4.5 m alleys, 2.5 m tree spacing", 4.5, 2.5),
    ],
)
def test_row_measures_said_as_a_pair_or_as_alleys(prompt: str, rows: float, in_row: float) -> None:
    (field,) = recipe(prompt).fields
    assert field.agronomy.row_spacing_m == pytest.approx(rows)
    assert field.agronomy.in_row_spacing_m == pytest.approx(in_row)


def test_alleys_between_double_rows_are_not_the_row_spacing() -> None:
    (banana,) = recipe(
        "a Grande Naine banana plantation: double rows 1 m apart with 3.75 m alleys between "
        "the pairs, 2.25 m between plants in a row"
    ).fields
    assert banana.agronomy.rows_per_bed == 2
    assert banana.agronomy.row_spacing_m == pytest.approx(4.75)


def test_laid_out_in_that_order_is_the_lists_order_not_the_rows() -> None:
    scene = recipe(
        "Red Express, January King and Golden Acre, each 10 rows x 50 m at 0.75 m x 0.4 m, "
        "laid out west to east in that order."
    )
    assert {
        ("Red Express", "west_of", ("January King",)),
        ("January King", "west_of", ("Golden Acre",)),
    } <= relations(scene)
    assert all("row_direction" not in f.stated for f in scene.fields)


def test_a_closing_row_direction_after_fields_of_one_crop_are_placed() -> None:
    scene = recipe(
        "Walla Walla and Stuttgarter Riesen onion plots, 0.3 m rows, 40 rows each, Stuttgarter "
        "plot east of the Walla Walla one, rows NE-SW"
    )
    assert [f.geometry.rotation_deg for f in scene.fields] == [-45.0, -45.0]
    # fields of different crops: the nearest one only
    apples, wheat = recipe("Gala west of wheat, rows NE-SW").fields
    assert "row_direction" not in apples.stated and "row_direction" in wheat.stated

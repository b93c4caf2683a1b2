"""Text of blind set g11 (issue 8): thousands inside a compass label, the whole number of
a field's trees, scenery that is no crop ("a roadside stand"), plant parts that are no
misspelt stage ("fire blight on some shoots"), trade names ("cab sav"), fields placed by
a building, and the way a slope faces."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    crop = {f.id: f.crop for f in scene.fields}
    return {(crop[r.subject], r.kind, tuple(crop[o] for o in r.objects)) for r in scene.relations}


def test_thousands_inside_a_leading_compass_label() -> None:
    scene = recipe(
        "North field: Spring Wheat drilled in 12.5 cm rows. South field: Popcorn at 80,000 "
        "plants/ha."
    )
    wheat, maize = scene.fields
    assert (wheat.variety, maize.variety) == ("Spring Wheat", "Popcorn")
    assert maize.agronomy.row_spacing_m * maize.agronomy.in_row_spacing_m == pytest.approx(
        1 / 8, rel=0.01
    )
    assert relations(scene) == {("Wheat", "north_of", ("Maize",))}


def test_all_of_our_trees_is_the_number_of_plants() -> None:
    (field,) = recipe(
        "All 180 of our Regina trees are in this picture, a wet week in July, fruit rotting on "
        "the branches"
    ).fields
    assert field.variety == "Regina"
    assert "plant_count" in field.stated


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        (
            "swetcorn ready for picking, cobs fat with dry brown silks, and a roadside stand with "
            "a hand-painted sign in the corner of the shot",
            "Maize",
        ),
        ("bartlett pears, ripe, aug, w/ fire blight on some shoots", "Pear"),
        ("cab sav vineyard in argentina, harvest in march", "Grape"),
    ],
)
def test_words_that_are_no_crop_and_no_stage(prompt: str, crop: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.crop == crop


def test_some_shoots_is_no_misspelt_side_shoots() -> None:
    (field,) = recipe("bartlett pears, ripe, aug, w/ fire blight on some shoots").fields
    assert (field.stage, field.health) == ("Maturation", "Ill")


def test_cab_sav_is_cabernet_sauvignon() -> None:
    (field,) = recipe("cab sav vineyard in argentina, harvest in march").fields
    assert field.variety == "Cabernet Sauvignon"


def test_a_field_placed_by_a_building_and_one_placed_by_that_field() -> None:
    scene = recipe(
        "There's a lettuce field east of the big barn, and east of that again a field of maize, "
        "with the duck pond tucked in a corner."
    )
    assert relations(scene) == {("Maize", "east_of", ("Lettuce",))}


def test_a_south_facing_slope_places_nothing() -> None:
    scene = recipe(
        "Shot across the valley on a misty morning: a vineyard on the south-facing slope, a "
        "vegetable field below it, and a wheat field right at the bottom by the river."
    )
    assert [f.crop for f in scene.fields][::2] == ["Grape", "Wheat"]
    assert scene.fields[1].category == "Vegetables"
    assert ("Grape", "south_of", (scene.fields[1].crop,)) not in relations(scene)

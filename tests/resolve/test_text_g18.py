"""Text of blind set g18 (issue 8): clothes, butterflies and the grass under trees are
scenery, ripening said by the fruit reddening or the haulm yellowing off, leaves of a
plant counted, fields told apart as near and beyond, fields said to touch and placed, a
measure after a bracket, and rows on each ridge."""

from __future__ import annotations

import pytest

from agrirecipe import UnknownCropError, generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "The Grande Naine plants have big green bunches hanging down, the leaves covered in "
            "dark streaks. Workers in rubber boots, a cableway for carrying the bunches.",
            ["Banana"],
        ),
        (
            "grany smith trees in full bloom in this one, taken in april, petals all over the "
            "grass and the mower parked by the shed",
            ["Apple"],
        ),
        (
            "Red Express cabbages next to a field of Golden Acre, both freshly transplanted, "
            "cabbage white butterflies over everything.",
            ["Cabbage", "Cabbage"],
        ),
        (
            "Two fields in this one: maize just through the ground at the front, little "
            "two-leaf plants in lines, and a wheat field behind that's still green.",
            ["Maize", "Wheat"],
        ),
        (
            "Snapshot over the gate: cabbages in the near field with yellow V-shaped lesions "
            "eating in from the leaf edges, and carrots in the field beyond looking fine. A "
            "muck spreader sits in the yard.",
            ["Cabbage", "Carrot"],
        ),
    ],
)
def test_no_phantom_field_and_no_unknown_crop(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_a_grass_field_is_still_refused() -> None:
    with pytest.raises(UnknownCropError, match="grass"):
        recipe("a grass field next to wheat")


def test_ripening_said_by_the_fruit_or_the_haulm() -> None:
    fields = recipe("Fuji to the east, Gala in the middle, all with the apples reddening.").fields
    assert {f.stage for f in fields} == {"Maturation"}
    (russets,) = recipe(
        "Our Russet Burbank field in September: the haulm is yellowing off naturally, no "
        "blight anywhere, and the crop is ready for lifting next week."
    ).fields
    assert (russets.stage, russets.health) == ("Maturation", "Healthy")


def test_near_and_beyond_tell_two_fields_apart() -> None:
    cabbage, carrot = recipe(
        "cabbages in the near field with yellow V-shaped lesions, and carrots in the field "
        "beyond looking fine"
    ).fields
    assert (cabbage.health, carrot.health) == ("Ill", "Healthy")


def test_fields_said_to_touch_and_placed_keep_both() -> None:
    scene = recipe(
        "Two wheat fields next to each other: dinkel on the left and durum on the right."
    )
    spelt, durum = scene.fields
    kinds = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert ("west_of", spelt.id, (durum.id,)) in kinds
    assert any(kind == "next_to" for kind, _, _ in kinds)


def test_measures_after_a_bracket_and_rows_on_each_ridge() -> None:
    dent, flint = recipe("dent corn (field corn) 76cm rows & flint corn east of it").fields
    assert (dent.agronomy.row_spacing_m, flint.agronomy.row_spacing_m) == (0.76, 0.75)
    (carrots,) = recipe("Danvers carrots on 30-inch ridges, 2 rows each, 20 ridges").fields
    assert carrots.agronomy.rows_per_bed == 2
    assert carrots.row_count == 40

"""Text of blind set g18 (issue 8): clothes, butterflies and the grass under trees are
scenery, ripening said by the fruit reddening or the haulm yellowing off, leaves of a
plant counted, fields told apart as near and beyond, fields said to touch and placed, a
measure after a bracket, and rows on each ridge."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, UnknownCropError, generate
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


def test_a_gap_before_the_list_of_plots_is_no_row_spacing() -> None:
    onions, carrots = recipe(
        "Two plots for the weeding-robot benchmark, 10 m apart: the western one onions, rows "
        "0.30 m apart with a bulb every 10 cm, 40 rows of 25 m; the eastern one carrots on 75 cm "
        "ridges, two rows per ridge, 12 ridges."
    ).fields
    assert (onions.agronomy.row_spacing_m, carrots.agronomy.rows_per_bed) == (0.3, 2)


def test_the_other_two_and_both_blocks_are_the_members() -> None:
    fields = recipe(
        "Three 20 x 60 m potato plots in a line, north to south: Bintje, then Agria, then "
        "Fontane. Only the Agria in the middle has late blight; the other two are clean."
    ).fields
    assert [f.health for f in fields] == ["Healthy", "Ill", "Healthy"]
    fields = recipe(
        "Two apple blocks: Jonagored at 3.5 m rows and 1 m in-row, and Pink Lady west of it at "
        "3.2 m rows. Rows NW-SE in both blocks. Harvest-ready, late September."
    ).fields
    assert [f.stage for f in fields] == ["Maturation", "Maturation"]
    assert {f.geometry.rotation_deg % 180 for f in fields} == {45.0}


def test_a_weak_variety_name_alone_with_its_field_said() -> None:
    (russet,) = recipe(
        "The big pivot circle is Russet, 50 ha, tops dying back and ready for lifting in September."
    ).fields
    assert (russet.crop, russet.stage) == ("Potato", "Maturation")
    # (a stray name with nothing said of a field is still no crop)
    with pytest.raises(PromptError, match="no crop or field"):
        recipe("Flint walls around the yard")

"""Text of blind set g18 (issue 8): clothes, butterflies and the grass under trees are
scenery, ripening said by the fruit reddening or the haulm yellowing off, leaves of a
plant counted, fields told apart as near and beyond, fields said to touch and placed, a
measure after a bracket, and rows on each ridge."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, UnknownCropError, generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


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


@pytest.mark.parametrize(
    "prompt",
    [
        "Strawberry beds on 1.4 m centres with 80 cm bed tops, 2 rows a bed, 10 beds",
        "Lettuce in 10 beds on 1.4 m centres, beds 20 cm high, 4 rows per bed, 50 cm paths",
        "10 beds of lettuce on 1.4 m centres, 4 rows per bed, sown 2 cm deep",
    ],
)
def test_measures_no_recipe_holds_are_not_used(prompt: str) -> None:
    # a bed's top, its height, the paths between beds and the sowing depth are no bed
    # width and no row spacing (they were read as a second bed width and refused, or
    # taken as the beds' width)
    result = generate(prompt, resolver="hybrid", explain=True)
    (field,) = result.recipe.fields
    assert (field.bed_count, field.agronomy.row_spacing_m) == (10, 1.4)
    assert "not used" in str(result.explanation)


def test_sowing_depth_and_tramlines_are_no_row_spacing() -> None:
    (wheat,) = recipe("wheat drilled 3 cm deep, 12.5 cm rows, tramlines every 24 m").fields
    assert wheat.agronomy.row_spacing_m == 0.125
    (carrots,) = recipe("carrots sown 2 cm deep in 45 cm rows").fields
    assert carrots.agronomy.row_spacing_m == 0.45


def test_a_count_after_the_plot_noun() -> None:
    low, high = recipe(
        "Corn plot pair for our stand-count drone, side by side: one at 30,000 plants per acre "
        "and one at 36,000 per acre, both on 30-inch rows, 24 rows each, 500 ft long."
    ).fields
    assert [round(f.plants_per_ha) for f in (low, high)] == [74132, 88958]
    assert low.row_count == high.row_count == 24
    assert [
        f.variety for f in recipe("we need a lettuce strip trio: Iceberg, Lollo and Cos").fields
    ] == [
        "Iceberg",
        "Lollo Rosso",
        "Romaine",
    ]


def test_a_total_size_before_the_sizes_that_make_it_up() -> None:
    wheat, maize = recipe(
        "We farm 4 acres: 2.5 acres of wheat and 1.5 of corn, with a hedge between them."
    ).fields
    assert (wheat.crop, maize.crop) == ("Wheat", "Maize")
    assert wheat.geometry.area_m2 == pytest.approx(2.5 * 4046.8564224, rel=0.01)
    assert maize.geometry.area_m2 == pytest.approx(1.5 * 4046.8564224, rel=0.01)
    # (a size that is not their sum is still a second size of the first field)
    with pytest.raises(PromptError, match="two sizes"):
        recipe("We farm 9 acres: 2.5 acres of wheat and 1.5 of corn")


def test_rows_on_each_ridge_are_not_every_fields(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Danvers carrots on 30-inch ridges, 2 rows each, 20 ridges, beside a strip of Red "
        "Baron onions in 12-inch rows, 30 rows. For the weeding robot, June."
    )
    carrots, onions = recipe(prompt).fields
    assert (carrots.bed_count, carrots.agronomy.rows_per_bed) == (20, 2)
    assert (onions.row_count, onions.agronomy.rows_per_bed) == (30, 1)
    assert named_relations(prompt) == {("next_to", "Danvers", ("Red Baron",))}


@pytest.mark.parametrize(
    "prompt",
    [
        "Two plots in my photo, side by side with a ditch between: onions whose leaves are pale "
        "with greyish-violet fuzz, and carrots that look perfectly healthy.",
        "Two plots side by side, a farm track running between them: onions and carrots",
    ],
)
def test_a_ditch_between_plots_said_side_by_side_keeps_them_side_by_side(
    prompt: str, named_relations: Callable[[str], NamedRelations]
) -> None:
    assert [f.crop for f in recipe(prompt).fields] == ["Onion", "Carrot"]
    assert named_relations(prompt) == {("next_to", "Carrot", ("Onion",))}


def test_a_hedge_between_two_fields_is_scenery_not_a_between() -> None:
    result = generate("onions and carrots with a hedge between them", resolver="hybrid")
    assert [f.crop for f in result.recipe.fields] == ["Onion", "Carrot"]
    assert not any("between" in w for w in result.recipe.warnings)

"""Text of blind set g45 (issue 8): each miss of its blind run, fixed as the general
mechanism (a crop named alone, then its plots counted; totals over vague plurals; look
cues; comparison headings; measures said "each" of rows; miles and fractions; sides of a
photo; a field placed against a field named again; ...)."""

from __future__ import annotations

import itertools

import pytest

from agrirecipe import SceneRecipe, generate


def _crops(recipe: SceneRecipe) -> list[str | None]:
    return [f.crop for f in recipe.fields]


def test_a_crop_named_alone_then_its_plots_counted() -> None:
    recipe = generate("lettuce!! lots of it. 2 fields, like 50 by 20 m each. thx").recipe
    assert _crops(recipe) == ["Lettuce", "Lettuce"]
    assert all(f.geometry.size_m == (50.0, 20.0) for f in recipe.fields)
    assert _crops(generate("carrots. three plots of them").recipe) == ["Carrot"] * 3


def test_a_field_counted_one_is_no_crop_for_plots_counted_after_it() -> None:
    assert len(generate("a wheat field and 2 fields").recipe.fields) == 3


@pytest.mark.parametrize(
    "prompt",
    [
        "sum fruit trees & some veggies idk, like 4 or 5 fields total",
        "some fruit trees and some vegetables, 4 fields in all",
    ],
)
def test_a_total_counts_vague_plurals_together(prompt: str) -> None:
    fields = generate(prompt).recipe.fields
    assert len(fields) == 4
    assert {f.category for f in fields} == {"Fruits", "Vegetables"}


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        ("cabage field w/ v-shaped yellow bits on the leaf edges ugh", "Cabbage"),
        (
            "Stuttgarter Riesen onions with pale, elongated patches on the leaves and a "
            "greyish-violet down on them in the mornings.",
            "Onion",
        ),
    ],
)
def test_signs_of_disease_said_in_own_words(prompt: str, crop: str) -> None:
    field = generate(prompt).recipe.fields[0]
    assert (field.crop, field.health) == (crop, "Ill")


def test_a_weak_name_opening_a_list_of_one_crop() -> None:
    recipe = generate("albion, sonata & centenary strawberys pls, 1 field each").recipe
    assert [f.variety for f in recipe.fields] == ["Albion", "Sonata", "Malling Centenary"]


def test_a_comparison_heading_is_no_field() -> None:
    recipe = generate(
        "Bell pepper vs jalapeño comparison for the harvest gripper: two plots of 8 beds each "
        "on 1.5 m centres, twin rows per bed, 45 cm in-row. California Wonder on the west "
        "plot, Jalapeños on the east one."
    ).recipe
    wonder, jalapeno = recipe.fields
    assert (wonder.variety, jalapeno.variety) == ("California Wonder", "Jalapeno")
    assert wonder.row_count == jalapeno.row_count == 16
    assert ("east_of", jalapeno.id, (wonder.id,)) in {
        (r.kind, r.subject, r.objects) for r in recipe.relations
    }


def test_rows_each_so_long_are_one_fields_rows() -> None:
    potatoes, corn = generate(
        "Potatoes for a soil-moisture probe network: 36-inch rows, seed pieces every 12 in, "
        "40 rows, each 500 ft long. Put a 1-acre sweetcorn block on the east side of the "
        "potatoes."
    ).recipe.fields
    assert potatoes.row_count == 40
    assert corn.row_count != 40
    width, length = corn.geometry.size_m
    assert width * length == pytest.approx(4046.8564, rel=0.001)


def test_rows_of_a_length_each_after_two_fields_are_each_fields() -> None:
    recipe = generate(
        "a cherry orchard and a pear orchard side by side, 8 rows of 60 m each; row spacing "
        "4.5 m in the cherries and 3.5 m in the pears."
    ).recipe
    assert [f.row_count for f in recipe.fields] == [8, 8]


@pytest.mark.parametrize(
    ("said", "metres"),
    [("a quarter mile long (1,320 ft)", 402.336), ("half a mile long", 804.672)],
)
def test_rows_a_fraction_of_a_mile_long(said: str, metres: float) -> None:
    field = generate(f"corn, 30 inch rows, 24 rows {said}").recipe.fields[0]
    assert field.row_count == 24
    assert field.geometry.size_m[1] == pytest.approx(metres + 2 * field.geometry.headland_m)


def test_two_rows_a_bed() -> None:
    recipe = generate(
        "jalapenos, flowering, on 60-inch beds with two rows a bed and 18 in between "
        "plants, 20 beds - dataset for flower detection"
    ).recipe
    (field,) = recipe.fields
    assert field.row_count == 40
    assert field.agronomy.rows_per_bed == 2
    assert field.agronomy.row_spacing_m == pytest.approx(1.524)
    assert field.agronomy.in_row_spacing_m == pytest.approx(0.4572)


def test_a_crops_beds_counted_in_brackets() -> None:
    strawberries, potatoes = generate(
        "strawberry beds (10 of them, 1.5 m centres) east of a 14-row potato plot at 75 cm, "
        "with a 20 m grass track between them for the robot to turn on"
    ).recipe.fields
    assert strawberries.row_count == 10 * strawberries.agronomy.rows_per_bed
    assert potatoes.row_count == 14


def test_varieties_named_before_a_colon_and_again_after_it_head_the_list() -> None:
    recipe = generate(
        "Gros Michel and Cavendish plots for a Fusarium wilt survey: 600 Gros Michel plants "
        "showing wilt, and 600 healthy Cavendish plants west of them, both 3 m x 2.5 m."
    ).recipe
    assert [(f.variety, f.health) for f in recipe.fields] == [
        ("Gros Michel", "Ill"),
        ("Cavendish", "Healthy"),
    ]


def test_a_headland_which_is_so_wide() -> None:
    field = generate(
        "grapevines, 9 ft rows, 6 ft vine spacing, 1,100 vines, rows due east-west. Weather "
        "station and spray rig parked in the headland, which is 8 m wide."
    ).recipe.fields[0]
    assert field.geometry.headland_m == 8.0


def test_a_farm_of_a_crop_then_one_plot_is_that_crops_plot() -> None:
    recipe = generate(
        "It's a citrus farm really: one big grove on the hillside behind the village."
    ).recipe
    assert _crops(recipe) == ["Orange"]


def test_some_plots_after_a_farms_colon_are_more_than_one() -> None:
    recipe = generate("a mixed farm please: some veg fields, an orchard and a wheat field").recipe
    assert [f.category for f in recipe.fields].count("Vegetables") == 2


def test_bands_named_between_the_top_and_the_bottom_lie_in_the_order_named() -> None:
    recipe = generate(
        "The farm runs downhill to the south in four bands - vines at the top, then stone "
        "fruit, then roots, and grain in the bottom band."
    ).recipe
    order = [f.id for f in recipe.fields]
    north = {(r.subject, r.objects[0]) for r in recipe.relations if r.kind == "north_of"}
    assert set(itertools.pairwise(order)) <= north


def test_setting_bunches_is_flowering() -> None:
    recipe = generate(
        "Banana farm in Queensland (southern hemisphere). Cavendish block north of the shed, "
        "Lady Finger block west of the Cavendish, both setting bunches in February."
    ).recipe
    assert {(f.stage, f.season) for f in recipe.fields} == {("Reproductive", "Summer")}


def test_a_look_reached_by_a_month_is_the_scenes_month() -> None:
    recipe = generate(
        "Winter Wheat on the heavy clay field and Durum on the lighter field east of it, both "
        "in ear by mid-June."
    ).recipe
    assert {(f.stage, f.season) for f in recipe.fields} == {("Reproductive", "Summer")}


def test_the_one_by_the_wood_is_one_of_the_fields_counted() -> None:
    recipe = generate(
        "Two potato fields - the one by the wood has blight, the one by the road is clean."
    ).recipe
    assert [f.health for f in recipe.fields] == ["Ill", "Healthy"]


def test_fruit_starting_to_blush_is_ripening() -> None:
    recipe = generate(
        "our Conference pears on the left and, right next to them, a block of Cripps Pink "
        "with the fruit just starting to blush."
    ).recipe
    assert recipe.fields[1].variety == "Pink Lady"
    assert recipe.fields[1].stage == "Maturation"


def test_the_sides_of_a_photo_and_fields_said_to_touch() -> None:
    recipe = generate(
        "On the left of the picture is a field of cabbage starting to bolt, tall flower "
        "stalks sticking up, and on the right some staked tomatoes with the fruit turning "
        "red. The two fields touch at the fence."
    ).recipe
    cabbage, tomatoes = recipe.fields
    relations = {(r.kind, frozenset((r.subject, *r.objects))) for r in recipe.relations}
    assert ("west_of", frozenset((cabbage.id, tomatoes.id))) in relations
    assert ("next_to", frozenset((cabbage.id, tomatoes.id))) in relations
    assert ("west_of", cabbage.id, (tomatoes.id,)) in {
        (r.kind, r.subject, r.objects) for r in recipe.relations
    }


def test_a_field_named_again_after_a_side_is_not_placed_by_it() -> None:
    recipe = generate(
        "From the bridge: strawberries to the south of the river path and cherries to the "
        "north, the cherry trees netted against birds, cyclists on the path."
    ).recipe
    strawberries, cherries = recipe.fields
    # (either way round: the cherries north of the strawberries across the path)
    assert {(r.kind, r.subject, r.objects) for r in recipe.relations} & {
        ("north_of", cherries.id, (strawberries.id,)),
        ("south_of", strawberries.id, (cherries.id,)),
    }

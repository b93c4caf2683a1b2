"""Text of blind set g34 (issue 8): a rough count after the plots ("veg plots?? like 4 or
5"), a crop spelt by ear ("lettus"), fields "sharing a border", "top half corn bottom half
wheat", a bare "Southern boundary:", "beyond them, to the south", numbered members of a
counted plural ("strip 2 south of strip 1"), a field's own trees after "next to it", a
day of the month ("the 2nd of May"), "vines dead and brown" of potatoes, a bare word for
the fruit after a dash, "the first field" among fields named in order, and scenery placed
by a field named before."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "count", "category"),
    [
        ("can i get some veg plots?? like 4 or 5, need it b4 monday thx", 4, "Vegetables"),
        ("a few fruit fields idk 2 or 3", 2, "Fruits"),
    ],
)
def test_a_rough_count_after_the_plots(prompt: str, count: int, category: str) -> None:
    fields = recipe(prompt).fields
    assert len(fields) == count
    assert {f.category for f in fields} == {category}


def test_a_crop_spelt_by_ear() -> None:
    (lettuce,) = recipe("cn u make a lettus field thx").fields
    assert lettuce.crop == "Lettuce"
    # (a word of its own that sounds like no crop is not read as one: "canes")
    (vines,) = recipe("Picture of the young vines, tiny shoots tied to bamboo canes").fields
    assert vines.crop == "Grape"


def test_fields_sharing_a_border(named_relations: Callable[[str], NamedRelations]) -> None:
    fields = recipe("orchard + vineyard sharing a border pls, thats it").fields
    assert {f.category for f in fields} == {"Fruits"}
    assert [r.kind for r in recipe("orchard + vineyard sharing a border").relations] == ["next_to"]
    assert named_relations("the vineyard shares a border with the carrot field") == {
        ("next_to", "Grape", ("Carrot",))
    }


def test_sides_said_without_a_mark_and_bare_boundaries(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    corn, wheat = recipe("top half corn bottom half wheat, simple as that lol").fields
    assert (corn.crop, wheat.crop) == ("Maize", "Wheat")
    assert named_relations("top half corn bottom half wheat, simple as that lol") == {
        ("north_of", "Maize", ("Wheat",))
    }
    prompt = (
        "Along the northern boundary: Bing cherries. Middle: Danvers carrots. Southern "
        "boundary: popcorn."
    )
    assert {
        ("north_of", "Bing", ("Danvers",)),
        ("north_of", "Danvers", ("Popcorn",)),
    } <= named_relations(prompt)


def test_beyond_them_to_a_side_is_that_side() -> None:
    result = recipe(
        "Cherry trees along the lane, and beyond them, to the south, two fields of potatoes."
    )
    cherries, *potatoes = result.fields
    assert cherries.crop == "Cherry" and [p.crop for p in potatoes] == ["Potato", "Potato"]
    assert {(r.kind, r.subject, r.objects) for r in result.relations} == {
        ("south_of", p.id, (cherries.id,)) for p in potatoes
    }


def test_numbered_members_of_a_counted_plural() -> None:
    result = recipe(
        "Three wheat strips, 10 x 50 m each, drilled at 12.5 cm row spacing with the rows "
        "running east-west. Strip 2 sits directly south of strip 1 and strip 3 south of strip 2."
    )
    one, two, three = result.fields
    assert {f.crop for f in result.fields} == {"Wheat"}
    kinds = {(r.kind, r.subject, r.objects) for r in result.relations}
    assert {("south_of", two.id, (one.id,)), ("south_of", three.id, (two.id,))} <= kinds
    groves = recipe(
        "Two citrus groves for a canopy LiDAR run, 7 m x 4 m spacing (row x tree), 100 trees "
        "each, separated by a 10 m track; grove 2 south of grove 1."
    )
    first, second = groves.fields
    assert first.crop == second.crop == "Orange"
    assert ("south_of", second.id, (first.id,)) in {
        (r.kind, r.subject, r.objects) for r in groves.relations
    }


def test_a_fields_own_trees_said_after_next_to_it() -> None:
    vines, cherries = recipe(
        "Drone spraying test over a 1.5 ha block of vines (rows 2.5 m apart, vines 1.6 m "
        "apart, 2,500 vines/ha, rows E-W) and a 1 ha cherry orchard next to it with trees at "
        "5 x 3 m (row x tree)."
    ).fields
    assert (vines.crop, cherries.crop) == ("Grape", "Cherry")
    assert cherries.agronomy.row_spacing_m == 5.0
    assert cherries.agronomy.in_row_spacing_m == 3.0


def test_a_day_of_the_month_counts_no_fields() -> None:
    (strawberries,) = recipe(
        "Malling Centenary under the tunnel on the 2nd of May: rows of white flowers with "
        "yellow centres and only a few small green berries, rain drumming on the plastic."
    ).fields
    assert (strawberries.variety, strawberries.season) == ("Malling Centenary", "Spring")


def test_potato_vines_dead_and_brown() -> None:
    (potatoes,) = recipe(
        "A Russet potato field in Idaho, vines dead and brown, a harvester digging the first "
        "rows under a huge sky."
    ).fields
    assert (potatoes.variety, potatoes.stage) == ("Russet Burbank", "Maturation")


def test_a_bare_word_for_the_fruit_after_a_dash() -> None:
    (tomatoes,) = recipe(
        "Look at these Beefsteak tomatoes - massive ribbed fruit, but the lower leaves are "
        "brown with dark water-soaked blotches and white mould underneath. Humid, grey August "
        "day."
    ).fields
    assert (tomatoes.variety, tomatoes.health) == ("Beefsteak", "Ill")


def test_the_first_field_among_fields_named_in_order() -> None:
    result = recipe(
        "In the photo, left to right: Bintje, Agria and Fontane potatoes, all three in flower, "
        "with the sprayer boom folded up by the first field and an electricity pole in the "
        "hedge."
    )
    assert [f.variety for f in result.fields] == ["Bintje", "Agria", "Fontane"]
    assert "next_to" not in {r.kind for r in result.relations}
    wheat, maize, potatoes = recipe("wheat, maize and potatoes; the second field is ill").fields
    assert (wheat.health, maize.health, potatoes.health) == ("Healthy", "Ill", "Healthy")


def test_scenery_placed_by_a_field_named_before() -> None:
    result = recipe("Bintje and Agria potatoes, with a tractor parked by the Bintje")
    assert len(result.fields) == 2
    assert result.relations == ()


def test_a_backyard_swing_set_is_scenery_and_rusty_no_disease() -> None:
    (corn,) = recipe(
        "Photo of my backyard corn patch, roughly 50 ft by 80 ft, stalks taller than me with "
        "tassels waving, a rusty swing set off to the side."
    ).fields
    assert (corn.crop, corn.stage, corn.health) == ("Maize", "Reproductive", "Healthy")
    assert corn.geometry.size_m == pytest.approx((15.24, 24.384), rel=0.01)


def test_a_plot_of_a_category_heading_fields_of_its_crops() -> None:
    result = recipe(
        "A photo of the veg field: capsicum on one side and chillies on the other, with a hose "
        "reel and the compost heap in between."
    )
    assert [f.crop for f in result.fields] == ["Pepper", "Pepper"]
    assert "between" not in {r.kind for r in result.relations}


def test_each_members_side_said_before_it() -> None:
    result = recipe(
        "I'm standing between two fields in this photo: to the north, potatoes with mottled, "
        "curling leaves; to the south, wheat that was just drilled and is barely showing."
    )
    potatoes, wheat = result.fields
    assert (potatoes.crop, potatoes.health, wheat.crop, wheat.stage) == (
        "Potato",
        "Ill",
        "Wheat",
        "Vegetative",
    )
    assert ("north_of", potatoes.id, (wheat.id,)) in {
        (r.kind, r.subject, r.objects) for r in result.relations
    }


def test_one_of_the_plots_counted_before_another_field() -> None:
    first, second, maize = recipe(
        "Blight-detection drone test: two potato plots with a maize plot between them, all rows "
        "75 cm apart. One of the potato plots has late blight."
    ).fields
    assert (first.crop, second.crop, maize.crop) == ("Potato", "Potato", "Maize")
    assert sorted((first.health, second.health)) == ["Healthy", "Ill"]
    assert maize.health == "Healthy"


def test_fields_on_either_side_of_the_one_they_are_with() -> None:
    result = recipe(
        "Wheat field with a maize plot to its east and a potato plot to its west, every plot "
        "0.25 ha, for calibrating our row-detection drone."
    )
    wheat, maize, potatoes = result.fields
    kinds = {(r.kind, r.subject, r.objects) for r in result.relations}
    assert {("east_of", maize.id, (wheat.id,)), ("west_of", potatoes.id, (wheat.id,))} <= kinds
    assert [f.geometry.area_m2 for f in result.fields] == pytest.approx([2500] * 3, rel=0.01)


def test_one_plot_of_another_variety_after_a_counted_plural() -> None:
    result = recipe(
        "Two Chantenay carrot plots and one Danvers plot, all 20 x 30 m on beds 1.5 m "
        "centre-to-centre, with the Danvers plot in between the Chantenay ones."
    )
    assert [f.variety for f in result.fields] == ["Chantenay", "Chantenay", "Danvers"]
    one, two, danvers = result.fields
    assert [(r.kind, r.subject, r.objects) for r in result.relations] == [
        ("between", danvers.id, (one.id, two.id))
    ]


def test_all_and_everywhere_said_of_one_fields_plants() -> None:
    elsanta, albion = recipe(
        "Our two strawberry fields in one shot: Elsanta with ripe red berries everywhere, and "
        "Albion still all flowers and no fruit."
    ).fields
    assert (elsanta.stage, albion.stage) == ("Maturation", "Reproductive")


def test_each_a_block_of_rows_after_fields_counted() -> None:
    fields = recipe(
        "three different kinds of fruit tree for our orchard robot, each a block of 8 rows "
        "with 4 m between the rows"
    ).fields
    assert len(fields) == 3
    assert len({f.crop for f in fields}) == 3
    assert {f.row_count for f in fields} == {8}
    assert {f.agronomy.row_spacing_m for f in fields} == {4.0}


def test_an_in_row_spacing_said_in_a_spec_sheet() -> None:
    (corn,) = recipe(
        "spec -> crop: sweetcorn | rows: 16 | row spacing: 0.76 m | in-row: 0.20 m | row "
        "length: 80 m | bearing: 0 deg | headland: 6 m | use: LiDAR ground truth"
    ).fields
    assert (corn.variety, corn.row_count) == ("Sweet Corn", 16)
    assert (corn.agronomy.row_spacing_m, corn.agronomy.in_row_spacing_m) == (0.76, 0.2)
    assert corn.row_length_m == pytest.approx(80)


def test_one_of_two_plots_named_by_its_side() -> None:
    result = recipe(
        "Two banana plots 15 m apart on an east-west line, both 3 x 3 m spacing. The western "
        "plot has black Sigatoka streaks on the leaves."
    )
    western, eastern = result.fields
    assert (western.health, eastern.health) == ("Ill", "Healthy")
    assert [(r.kind, r.subject, r.objects) for r in result.relations] == [
        ("west_of", western.id, (eastern.id,))
    ]
    # (both named by their sides: each its own)
    west, east = recipe(
        "Two banana plots. The western plot has Sigatoka, the eastern plot is healthy."
    ).fields
    assert (west.health, east.health) == ("Ill", "Healthy")


def test_a_bracket_of_measures_after_the_last_field_is_its_own() -> None:
    result = recipe(
        "Jonagored block (rows 3.2 m apart, trees 0.8 m) between two Fuji blocks (rows 3.5 m, "
        "trees 1 m); rows NE-SW throughout."
    )
    jonagold, *fuji = result.fields
    assert (jonagold.variety, [f.variety for f in fuji]) == ("Jonagold", ["Fuji", "Fuji"])
    assert (jonagold.agronomy.row_spacing_m, jonagold.agronomy.in_row_spacing_m) == (3.2, 0.8)
    assert {(f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in fuji} == {(3.5, 1.0)}
    assert {f.row_bearing_deg for f in result.fields} == {45.0}


def test_members_counted_in_a_count_are_on_no_side_of_each_other() -> None:
    result = recipe(
        "Four plots in a 2 x 2 grid, all 15 x 15 m with rows 30 cm apart: two lettuce plots on "
        "the north side, two onion plots on the south side."
    )
    crops = {f.id: f.crop for f in result.fields}
    assert sorted(crops.values()) == ["Lettuce", "Lettuce", "Onion", "Onion"]
    for relation in result.relations:
        assert crops[relation.subject] != crops[relation.objects[0]]
    assert ("north_of", "Lettuce", "Onion") in {
        (r.kind, crops[r.subject], crops[r.objects[0]]) for r in result.relations
    }


def test_a_plot_labelled_middle_between_one_side_and_the_other() -> None:
    result = recipe(
        "Orchard layout, three blocks, rows at 30 degrees from north in all of them. Middle "
        "block: Kordia cherries, rows 4.6 m apart, trees 2.4 m. On one side Gala apples, 3.4 m "
        "rows, trees at 1 m; on the other side Comice pears, 3.5 m rows, trees at 1 m."
    )
    cherries, apples, pears = result.fields
    assert (cherries.variety, apples.variety, pears.crop) == ("Kordia", "Gala", "Pear")
    assert [(r.kind, r.subject, r.objects) for r in result.relations] == [
        ("between", cherries.id, (apples.id, pears.id))
    ]
    assert cherries.agronomy.row_spacing_m == 4.6
    assert {f.row_bearing_deg for f in result.fields} == {30.0}

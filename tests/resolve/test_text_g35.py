"""Text of blind set g35 (issue 8): a "with" after a field's placement ("cabbages in the
middle with caterpillar holes"), bean poles as scenery, banana mats and a bearing said
without a unit ("rows bearing 060"), members numbered in words ("plot one ... plot two"),
"South of the grove a banana block", "with the vines to the north", "to the left of the
roots", "The blocks go west to east in that order", the far end of a field sandwiched
between two others, "cherries furthest south", "Upper block (north):", "each a different
veg", "allotment-style", a spacing grid after a colon ("Both on Gisela 6: 5 m x 2.8 m")
and "the same row spacing, tree spacing and row length"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_with_after_a_fields_placement_is_that_fields() -> None:
    strawberries, cabbages, tomatoes = recipe(
        "This pic: strawberries in the front with ripe red berries, cabbages in the middle "
        "with caterpillar holes chewed all through the leaves, and a tomato field at the back."
    ).fields
    assert (strawberries.crop, cabbages.crop, tomatoes.crop) == ("Strawberry", "Cabbage", "Tomato")
    assert (strawberries.health, cabbages.health, tomatoes.health) == ("Healthy", "Ill", "Healthy")
    assert strawberries.stage == "Maturation"


def test_bean_poles_are_scenery() -> None:
    fields = recipe(
        "Photo of the allotment-style plots: tomatoes, peppers, onions and a couple of rows of "
        "carrots, each in its own little plot, a shed with a water butt and bean poles leaning "
        "on it."
    ).fields
    assert [f.crop for f in fields] == ["Tomato", "Pepper", "Onion", "Carrot"]


def test_banana_mats_and_a_bearing_without_a_unit() -> None:
    (stand,) = recipe(
        "Ladyfinger banana stand, 3 m between rows and 2.5 m between mats, 10 rows of 40 m."
    ).fields
    assert (stand.agronomy.row_spacing_m, stand.agronomy.in_row_spacing_m) == (3.0, 2.5)
    (block,) = recipe("Dwarf Cavendish, 0.25 ha, rows bearing 060.").fields
    assert block.geometry.rotation_deg == pytest.approx(-60.0)
    assert "row_direction" in block.stated


def test_members_numbered_in_words(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Two maize plots: plot one 16 rows at 0.75 m and 9 plants per metre, plot two 16 rows "
        "at 0.5 m and 6 plants per metre, plot two to the west of plot one."
    )
    one, two = recipe(prompt).fields
    assert (one.crop, two.crop) == ("Maize", "Maize")
    assert (one.agronomy.row_spacing_m, two.agronomy.row_spacing_m) == (0.75, 0.5)
    assert [(r.kind, r.subject, r.objects) for r in recipe(prompt).relations] == [
        ("west_of", two.id, (one.id,))
    ]


def test_a_crop_after_a_plot_named_again(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "An orange grove, 10 rows. South of the grove a banana block of 100 plants."
    assert [f.crop for f in recipe(prompt).fields] == ["Orange", "Banana"]
    assert named_relations(prompt) == {("south_of", "Banana", ("Orange",))}


def test_the_plants_of_a_field_named_again_to_place_it(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations(
        "The estate is a vineyard and an orange grove, with the vines to the north."
    ) == {("north_of", "Grape", ("Orange",))}


def test_to_the_left_and_right_of_a_field(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations("Top: grain. Bottom: roots. And to the left of the roots, salad.") == {
        ("north_of", "Wheat", ("Potato",)),
        ("west_of", "Lettuce", ("Potato",)),
    }
    assert named_relations("Wheat, and to the right of the wheat, lettuce.") == {
        ("east_of", "Lettuce", ("Wheat",))
    }


def test_the_blocks_go_in_the_order_named(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Block 1 Fuji, healthy. Block 2 Golden Delicious, scab. Block 3 Durondeau pears, fire "
        "blight. The blocks go west to east in that order."
    )
    assert {
        ("west_of", "Fuji", ("Golden Delicious",)),
        ("west_of", "Golden Delicious", ("Durondeau",)),
    } <= relations


def test_the_far_end_of_a_field_sandwiched_between_two(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Cos lettuce (14 rows, 35 cm) sandwiched between a Red Baron onion strip (20 rows, "
        "30 cm) and an Agria potato strip (10 rows, 75 cm); onions on the north side."
    )
    assert ("north_of", "Romaine", ("Agria",)) in relations
    # the two ends placed: the middle one lies between them on that side too
    relations = named_relations(
        "Cos lettuce between an onion strip and a potato strip; potatoes on the west side."
    )
    assert {("west_of", "Potato", ("Romaine",)), ("west_of", "Romaine", ("Onion",))} <= relations


def test_furthest_to_a_side_and_a_side_in_brackets_after_a_label(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Three tree blocks: apples in the northern block, pears in the middle one, cherries "
        "furthest south."
    )
    assert ("between", "Pear", ("Apple", "Cherry")) in relations
    prompt = (
        "Two vineyard blocks. Upper block (north): Riesling, 20 rows, 2.2 m between rows, vines "
        "1 m apart. Lower block directly south of it: Pinot Noir, 25 rows at 2.5 m x 1.2 m."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Riesling", "Pinot Noir"]
    assert ("north_of", "Riesling", ("Pinot Noir",)) in named_relations(prompt)


def test_each_a_different_category_word_and_a_plot_word_of_a_likeness() -> None:
    fields = recipe(
        "The allotment-style corner of the farm: six little plots, each a different veg."
    ).fields
    assert len(fields) == 6
    assert {f.category for f in fields} == {"Vegetables"}
    assert len({f.crop for f in fields}) == 6


def test_a_spacing_grid_after_a_colon() -> None:
    lapins, regina = recipe(
        "Sweetheart Lapins block north of a Regina block. Both on Gisela 6: 5 m x 2.8 m. Lapins "
        "has 14 rows, Regina 10 rows, all rows 70 m."
    ).fields
    for field in (lapins, regina):
        assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == (5.0, 2.8)


def test_the_same_of_several_measures() -> None:
    conference, comice = recipe(
        "Conference pears planted 3.5 m x 1 m (rows x trees), 18 rows of 100 m; south of them a "
        "Doyenné du Comice block with exactly the same row spacing, tree spacing and row length "
        "but only 12 rows."
    ).fields
    assert (comice.agronomy.row_spacing_m, comice.agronomy.in_row_spacing_m) == (3.5, 1.0)
    assert {"rows", "row_length"} <= set(comice.stated)
    for field in (conference, comice):
        # (rows 100 m long: the field's length less a headland at each end)
        length = field.geometry.size_m[1] - 2 * field.geometry.headland_m
        assert length == pytest.approx(100.0, abs=1e-6)
    imperator, danvers = recipe(
        "Imperator carrots, 2 beds of 1.5 m with 4 rows per bed, north of Danvers carrots on "
        "2 beds of the same width and row count."
    ).fields
    assert danvers.agronomy.rows_per_bed == imperator.agronomy.rows_per_bed == 4


def test_a_count_of_trees_filling_an_area() -> None:
    gala, agria = recipe(
        "Royal Gala orchard, 1 ha, 3.4 m rows, 2,900 trees. East of it a 0.6 ha Agria potato "
        "field, rows 75 cm apart."
    ).fields
    width, length = gala.geometry.size_m
    assert width * length == pytest.approx(10_000.0, rel=1e-6)
    assert gala.agronomy.row_spacing_m == 3.4
    assert gala.geometry.plant_count == 2900
    assert gala.nominal_plant_count == 2900
    assert agria.agronomy.row_spacing_m == 0.75


def test_a_drill_spacing_and_a_fields_own_size_before_other_sizes() -> None:
    wheat, spelt, corn = recipe(
        "Spring Wheat 1 ha at 12.5 cm drill spacing south of a 1 ha Spelt plot at 15 cm, with a "
        "10 m wide block of Sweet Corn (rows 75 cm) between them."
    ).fields
    assert (wheat.variety, spelt.variety, corn.variety) == ("Spring Wheat", "Spelt", "Sweet Corn")
    for field in (wheat, spelt):
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(10_000.0, rel=1e-6)
    spacings = (wheat.agronomy.row_spacing_m, spelt.agronomy.row_spacing_m)
    assert spacings == (0.125, 0.15)
    assert corn.agronomy.row_spacing_m == 0.75

"""Text of blind set g33 (issue 8): a count after a list of a kind and a crop, labels said
bare after "between", an order said along scenery, crops put in labelled fields, a bed
count said again without its noun, a field "in between" the two placed before it, a count
of them in words, looks of a stage ("still cropping", "tassels gone brown", "ears just
emerging", "berries the size of peas"), adjacent plots opening a sentence, "200 m runs",
"3.7 m rows x 1.2 m", a sensor rig, labels defined with "=", a measure after a bare list,
"each block 50 m square"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_count_after_a_list_of_a_kind_and_a_crop_counts_the_list() -> None:
    # "cereals n potatoes, 2 fields": the two listed, not two potato fields
    cereal, potatoes = recipe("cereals n potatoes, 2 fields, both ready to harvest, oct").fields
    assert (cereal.category, potatoes.crop) == ("Cereals", "Potato")
    assert cereal.stage == potatoes.stage == "Maturation"
    assert cereal.season == potatoes.season == "Fall"


def test_labels_said_bare_after_between(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Plot 1 is Elsanta strawberries, ripe. Plot 2 is Savoy cabbage with black rot. Plot 3 "
        "is Nantes carrots, only at the two-leaf stage. Plot 2 lies between 1 and 3."
    )
    assert named_relations(prompt) == {("between", "Savoy", ("Elsanta", "Nantes"))}


def test_an_order_said_along_scenery(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "North to south along the lane: Kordia cherries, Doyenne du Comice pears, then Granny "
        "Smith apples. All three are in flower, mid-April."
    )
    assert {
        ("north_of", "Kordia", ("Doyenne du Comice",)),
        ("north_of", "Doyenne du Comice", ("Granny Smith",)),
    } <= named_relations(prompt)


def test_crops_put_in_labelled_fields(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Vegetable farm plan: Iceberg lettuce in field A, Red Express cabbage in field B next "
        "to it, Chantenay carrots in field C, which is north of field B."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Iceberg", "Red Express", "Chantenay"]
    assert named_relations(prompt) == {
        ("next_to", "Red Express", ("Iceberg",)),
        ("north_of", "Chantenay", ("Red Express",)),
    }
    # (said with "and", and with the crops alone)
    assert named_relations("apples in block 1 and pears in block 2, block 2 east of block 1") == {
        ("east_of", "Pear", ("Apple",))
    }


def test_a_bed_count_said_again_without_its_noun() -> None:
    albion, sonata = recipe(
        "Two strawberry fields: Albion on 12 raised beds and Sonata on 8, beds 1.5 m centre to "
        "centre with 2 rows each. The Sonata field is east of the Albion one."
    ).fields
    assert (albion.bed_count, sonata.bed_count) == (12, 8)
    assert sonata.agronomy.rows_per_bed == 2 and sonata.agronomy.row_spacing_m == 1.5


@pytest.mark.parametrize(
    ("prompt", "between"),
    [
        (
            "We've got veg on the east side of the farm, grapes on the west side and a bit of "
            "wheat in between.",
            ("between", "Wheat", ("Pepper", "Grape")),
        ),
        (
            "Farm sketch: strawberries up north, tomatoes in the south, and a small potato patch "
            "in between them.",
            ("between", "Potato", ("Strawberry", "Tomato")),
        ),
    ],
)
def test_a_field_in_between_the_two_placed_before_it(
    prompt: str,
    between: tuple[str, str, tuple[str, ...]],
    named_relations: Callable[[str], NamedRelations],
) -> None:
    kind, subject, objects = between
    assert any(
        k == kind and s == subject and set(o) == set(objects) for k, s, o in named_relations(prompt)
    )


def test_a_count_of_them_said_in_words() -> None:
    assert len(recipe("carrot fields, three of them").fields) == 3
    # (two said as alternatives: the first)
    assert len(recipe("small fruit fields, five or six of them").fields) == 5


@pytest.mark.parametrize(
    ("prompt", "stage"),
    [
        (
            "Albion strawberries still cropping in this photo from late September, red berries "
            "under the leaves but grey mould on quite a few of them.",
            "Maturation",
        ),
        (
            "Field corn taller than the tractor, the tassels gone brown and the ears hanging "
            "down with dented kernels. Shot in late September.",
            "Maturation",
        ),
        ("Winter wheat in May with the ears just emerging", "Reproductive"),
        (
            "Chardonnay in June: flowering is over and the bunches are hard and green, berries "
            "the size of peas. The sprayer is coming down the next row.",
            "Reproductive",
        ),
    ],
)
def test_looks_of_a_stage(prompt: str, stage: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.stage == stage


def test_adjacent_plots_said_opening_a_sentence(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two adjacent plots of carrots, Imperator and Danvers, feathery tops about ankle high. "
        "Somebody left a hoe leaning on the fence."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Imperator", "Danvers"]
    relations = named_relations(prompt)
    assert relations in (
        {("next_to", "Danvers", ("Imperator",))},
        {("next_to", "Imperator", ("Danvers",))},
    )


def test_measures_said_as_runs_and_rows_by_trees() -> None:
    (wheat,) = recipe(
        "Generate Winter Wheat for a phenotyping rover, drilled at 12.5 cm row spacing, 48 rows, "
        "200 m runs east-west, crop at heading in late May."
    ).fields
    assert (wheat.row_count, wheat.row_bearing_deg) == (48, 90.0)
    assert wheat.row_length_m == pytest.approx(200, rel=0.01)
    (hamlin,) = recipe(
        "Hamlin orange trees, 3.7 m rows x 1.2 m super-high-density spacing, 22 rows at a bearing "
        "of 15 degrees, flowering in March."
    ).fields
    assert (hamlin.agronomy.row_spacing_m, hamlin.agronomy.in_row_spacing_m) == (3.7, 1.2)
    # (not "2.4 m rows x 1.5 m between vines, 20 rows 120 m long": read as before)
    (riesling,) = recipe(
        "Riesling vineyard in New Zealand at harvest in April, 2.4 m rows x 1.5 m between vines, "
        "20 rows 120 m long, north-south, for a LiDAR canopy dataset."
    ).fields
    assert (riesling.row_count, riesling.agronomy.in_row_spacing_m) == (20, 1.5)


def test_a_rig_and_a_test_field_are_no_fields() -> None:
    vines, strawberries = recipe(
        "Sensor rig field: a vineyard (rows 2.8 m, vines 1.5 m apart) south of a strawberry "
        "field on 1.5 m beds with 2 rows per bed."
    ).fields
    assert (vines.crop, strawberries.crop) == ("Grape", "Strawberry")


def test_labels_defined_with_an_equals_sign(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "plot 1 = sweet peppers, plot 2 = tomatoes, plot 2 directly east of plot 1; both 1.2 m "
        "rows, 50 cm in-row, 15 rows"
    )
    peppers, tomatoes = recipe(prompt).fields
    assert (peppers.crop, tomatoes.crop) == ("Pepper", "Tomato")
    assert peppers.row_count == tomatoes.row_count == 15
    assert named_relations(prompt) == {("east_of", "Tomato", ("Pepper",))}


def test_a_measure_after_a_bare_list_is_each_members() -> None:
    apples, pears = recipe(
        "Golden Delicious apples and Durondeau pears on trellis, rows 3.2 m apart, 400 trees in "
        "each block, pears on the west side."
    ).fields
    assert apples.agronomy.row_spacing_m == pears.agronomy.row_spacing_m == 3.2
    assert apples.nominal_plant_count == pears.nominal_plant_count == 400


def test_a_block_said_square() -> None:
    sweet, dent = recipe(
        "Block A: sweetcorn, 0.75 m rows. Block B: dent corn, also 0.75 m rows. Block A is north "
        "of block B, each block 50 m square."
    ).fields
    assert sweet.geometry.size_m == dent.geometry.size_m == (50.0, 50.0)
    # (a square grid is a spacing, not a size)
    (bananas,) = recipe("bananas on a 3 m square grid, half a hectare").fields
    assert bananas.geometry.area_m2 == pytest.approx(5000, rel=0.01)


def test_a_crop_listed_again_fills_the_count(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Test layout, 3 blocks: maize (80,000 plants/ha) | cabbage (rows 0.75 m, plants 0.45 m "
        "apart) | maize again (80,000 plants/ha), with the cabbage block between the two maize "
        "blocks."
    )
    fields = recipe(prompt).fields
    assert [f.crop for f in fields] == ["Maize", "Cabbage", "Maize"]
    assert fields[0].plants_per_ha == pytest.approx(80000, rel=0.01)
    assert fields[2].plants_per_ha == pytest.approx(80000, rel=0.01)
    relations = recipe(prompt).relations
    assert [(r.kind, r.subject, r.objects) for r in relations] == [
        ("between", fields[1].id, (fields[0].id, fields[2].id))
    ]
    # "three plots: wheat, potatoes, wheat": three, the third wheat again (no random crop)
    assert [f.crop for f in recipe("three plots: wheat, potatoes, wheat").fields] == [
        "Wheat",
        "Potato",
        "Wheat",
    ]
    # a crop named again and placed is the member named again
    carrots, onions = recipe("two fields: carrots and onions, carrots north of the onions").fields
    assert (carrots.crop, onions.crop) == ("Carrot", "Onion")


def test_a_vague_number_of_fields_said_again_as_a_count() -> None:
    fields = recipe(
        "Our farm is a patchwork of small fruit fields, five or six of them, each one a "
        "different fruit."
    ).fields
    assert len(fields) == 5
    assert len({f.crop for f in fields}) == 5
    assert {f.category for f in fields} == {"Fruits"}
    assert len(recipe("some vegetable fields, three of them, all young").fields) == 3
    # ("some fields, two of them diseased": a share of them, not their count)
    assert [f.health for f in recipe("four wheat fields, two of them diseased").fields] == [
        "Ill",
        "Ill",
        "Healthy",
        "Healthy",
    ]


def test_different_crops_counted_after_is_and_after_a_category_heading() -> None:
    for prompt in (
        "The vegetable side of the farm is three different crops in long strips.",
        "Vegetables: three different crops in long strips.",
    ):
        fields = recipe(prompt).fields
        assert len(fields) == 3, prompt
        assert {f.category for f in fields} == {"Vegetables"}, prompt
        assert len({f.crop for f in fields}) == 3, prompt
    fruit, vegetables = (
        [f.category for f in recipe("Fruit: two plots. Vegetables: three plots").fields][:2],
        [f.category for f in recipe("Fruit: two plots. Vegetables: three plots").fields][2:],
    )
    assert fruit == ["Fruits", "Fruits"]
    assert vegetables == ["Vegetables"] * 3

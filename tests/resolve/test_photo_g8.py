"""Photo and casual text of blind set g8 (issue 8): words that look like crops but are
colours, loads or skins ("an orange Kubota", "a grain trailer", "russeted fruit"), vague
quantities of a named crop's plants or fruit ("lots of fruit", "a few peppers have
spots"), the members of "two cherry blocks" named by variety, scenery placed against the
fields, and a crop's name said as a title before its field."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def crops(scene: SceneRecipe) -> list[tuple[str, str]]:
    return [(f.crop, f.variety) for f in scene.fields]


@pytest.mark.parametrize(
    "prompt",
    [
        "A lettuce field, an orange tractor at the end.",
        "A lettuce field, orange crates stacked by the gate.",
        "Lettuce bolting, irrigation pipes across the beds, an orange Kubota at the end.",
        "Three lettuce beds and a grain trailer on the road.",
        "A lettuce field, the potato harvester parked at the gate.",
    ],
)
def test_a_crop_word_that_colours_or_loads_a_machine_is_no_field(prompt: str) -> None:
    scene = recipe(prompt)
    assert {f.crop for f in scene.fields} == {"Lettuce"}


def test_an_orange_grove_is_still_oranges() -> None:
    scene = recipe("an orange grove next to a wheat field, orange tractor by the barn")
    assert sorted(f.crop for f in scene.fields) == ["Orange", "Wheat"]


def test_the_skin_of_the_fruit_is_no_variety() -> None:
    scene = recipe(
        "Behind the farmhouse in October there's Durondeau with russeted brownish fruit "
        "ready to pick, and Comice next to it, fat greenish pears also ready."
    )
    assert crops(scene) == [("Pear", "Durondeau"), ("Pear", "Doyenne du Comice")]
    assert [f.stage for f in scene.fields] == ["Maturation", "Maturation"]
    (relation,) = scene.relations
    assert relation.kind == "next_to"


@pytest.mark.parametrize(
    ("prompt", "health"),
    [
        (
            "Jalapeños in the polytunnel, lots of fruit with some already turning red, but "
            "the leaves have dark spots and a few peppers have raised scabby spots.",
            "Ill",
        ),
        ("A Kordia cherry block, a lot of fruit rotting on the branch.", "Ill"),
        ("Bing cherries, loads of fruit, dark red and ripe.", "Healthy"),
    ],
)
def test_a_vague_quantity_of_a_named_crops_fruit_is_no_count_of_fields(
    prompt: str, health: str
) -> None:
    (field,) = recipe(prompt).fields
    assert field.health == health


def test_a_few_plants_of_one_named_crop_describe_that_field_only() -> None:
    scene = recipe("a carrot field and a wheat field, a few carrots have blight")
    assert [(f.crop, f.health) for f in scene.fields] == [
        ("Carrot", "Ill"),
        ("Wheat", "Healthy"),
    ]


def test_a_few_vegetable_plots_are_still_plots() -> None:
    scene = recipe("A cherry orchard with a few vegetable plots scattered around it.")
    assert len(scene.fields) >= 3


def test_members_of_a_counted_crop_named_by_variety() -> None:
    scene = recipe(
        "June photo of two cherry blocks next to each other: the Bing trees are hanging "
        "with dark, almost black ripe cherries, while in the Kordia block a lot of fruit "
        "is rotting on the branch with grey-tan fuzzy tufts. Rain covers rolled up above "
        "both."
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Bing", "Healthy"),
        ("Kordia", "Ill"),
    ]
    assert [r.kind for r in scene.relations] == ["next_to"]  # the covers are "above both"


def test_a_crop_with_fruit_after_with_and_an_adjective() -> None:
    scene = recipe(
        "a bed of Pimientos de Padrón full of small green peppers ready for picking, beside "
        "a row of San Marzano tomatoes with long fruit still green. Chickens wandering "
        "between them."
    )
    assert crops(scene) == [("Pepper", "Padron"), ("Tomato", "San Marzano")]
    assert [r.kind for r in scene.relations] == ["next_to"]


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("onoins!!! just 1 big field of onions!!", 1),
        ("Wheat. A 2 ha wheat field next to a barn.", 1),
        ("Potatoes! two fields of potatoes", 2),
        ("Wheat. Maize. A maize field", 2),
    ],
)
def test_a_crops_name_as_a_title_before_its_field(prompt: str, count: int) -> None:
    assert len(recipe(prompt).fields) == count


def test_fields_in_a_line_with_a_load_named_after() -> None:
    scene = recipe(
        "three fields in a line, corn, then potatoes, then wheat, so the potatoes sit "
        "between the other two. Everything still green, a grain trailer on the road."
    )
    assert [f.crop for f in scene.fields] == ["Maize", "Potato", "Wheat"]


@pytest.mark.parametrize(
    ("prompt", "stage", "health"),
    [
        (
            "Wheat, early June. The ears are out but the flag leaves are covered in bright "
            "yellow-orange stripes of rust pustules.",
            "Reproductive",
            "Ill",
        ),
        (
            "a plantation of Grande Naine bananas, each plant with a big purple flower bud "
            "hanging below the young green bunch.",
            "Reproductive",
            "Healthy",
        ),
        (
            "Onion field at the end of August, tops all flopped over and yellowing, they're "
            "ready to lift.",
            "Maturation",
            "Healthy",
        ),
        ("onions with yellowing leaves and rot", None, "Ill"),
        ("young wheat plants", "Vegetative", "Healthy"),
    ],
)
def test_what_the_plants_look_like(prompt: str, stage: str | None, health: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.health == health
    if stage is not None:
        assert field.stage == stage


def test_a_banana_bell_is_flowering() -> None:
    _, ladyfinger = recipe(
        "a block of Dwarf Cavendish with the bunches bagged in blue plastic, and next to it "
        "Ladyfinger bananas, taller, with the purple bell still hanging."
    ).fields
    assert ladyfinger.stage == "Reproductive"


@pytest.mark.parametrize(
    "prompt",
    [
        "Top half of the farm is cereals, all healthy; the bottom half is root veg with some "
        "rot in places.",
        "cereals at the top, root veg at the bottom",
    ],
)
def test_halves_of_a_farm_with_a_category_each(prompt: str) -> None:
    top, bottom = recipe(prompt).fields
    assert top.crop in ("Wheat", "Maize")
    assert bottom.crop in ("Carrot", "Potato", "Onion")


def test_the_plot_set_apart_by_a_word_is_the_one_described() -> None:
    scene = recipe(
        "Valencia Late oranges in the lower grove and Moro in the upper grove; the upper "
        "grove has blotchy mottled leaves and small lopsided fruit."
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Valencia", "Healthy"),
        ("Moro", "Ill"),
    ]
    scene = recipe(
        "apples in the old orchard and pears in the new orchard; the new orchard has scab"
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Apple", "Healthy"), ("Pear", "Ill")]


def test_another_hectare_is_one_hectare() -> None:
    scene = recipe("Imperator carrots on 1 ha and Danvers carrots on another hectare")
    assert [round(f.geometry.area_m2) for f in scene.fields] == [10000, 10000]


def test_a_city_that_is_also_a_variety() -> None:
    oranges, _ = recipe(
        "Here in Valencia we have a Navel orange grove right next to our Padron peppers"
    ).fields
    assert oranges.variety == "Navel"


@pytest.mark.parametrize(
    "prompt",
    [
        "2 cereal fields n 2 fruit ones, the fruit ones touching each other",
        "2 cereal fields and 2 fruit fields, the fruit fields next to each other",
    ],
)
def test_the_plural_named_again_is_what_lies_side_by_side(prompt: str) -> None:
    scene = recipe(prompt)
    fruit = {f.id for f in scene.fields if f.crop not in ("Wheat", "Maize")}
    (relation,) = scene.relations
    assert {relation.subject, *relation.objects} == fruit


def test_lettered_plots_placed_by_their_letters() -> None:
    scene = recipe(
        "Plots for the farm map. A: Agria potatoes, 2 ha. B: Red Baron onions, 1 ha. C: "
        "Chantenay carrots, 1 ha. D: Golden Acre cabbage, 0.5 ha. A is north of B, C is east "
        "of B, and D sits between A and C."
    )
    a, b, c, d = (f.id for f in scene.fields)
    assert [f.variety for f in scene.fields] == ["Agria", "Red Baron", "Chantenay", "Golden Acre"]
    assert {(r.kind, r.subject, r.objects) for r in scene.relations} == {
        ("north_of", a, (b,)),
        ("east_of", c, (b,)),
        ("between", d, (a, c)),
    }


def test_counted_blocks_placed_by_a_fronted_direction_each() -> None:
    scene = recipe(
        "Two blocks either side of the packing shed. To the north, Jonagored apples: 320 "
        "trees in rows 3.5 m apart. To the south, 280 Conference pear trees."
    )
    apples, pears = scene.fields
    assert (apples.variety, pears.variety) == ("Jonagold", "Conference")
    assert ("north_of", apples.id, (pears.id,)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }

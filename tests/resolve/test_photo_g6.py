"""Photo, casual and farm text of blind set g6 (issue 8): colours named after crops, an
article that is another thing's, "the near one / the far one", "ready for" what is not a
harvest, a sowing month beside the scene's, many plants named by their crop, crops on
terraces, and scenery and cue words."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_crop_joined_to_a_colour_is_a_colour() -> None:
    (field,) = recipe(
        "Jonagored trees in October, the fruit covered in brown corky scab spots and the "
        "leaves with olive-green velvety patches."
    ).fields
    assert (field.crop, field.health) == ("Apple", "Ill")
    scene = recipe(
        "Two wheat fields split by a grass track: the near one is striped yellow-orange with "
        "rust pustules, the far one is clean and green."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Wheat", "Ill"), ("Wheat", "Healthy")]


@pytest.mark.parametrize(
    "prompt",
    [
        "Potatoes in full flower, I count 40 rows running east-west, 75 cm apart. There's an "
        "old wind pump in the corner of the field.",
        "Onions that have only just emerged, thin green loops poking through the soil, so from "
        "a distance the field looks almost bare.",
    ],
)
def test_an_article_of_another_thing_does_not_count_the_field(prompt: str) -> None:
    assert len(recipe(prompt).fields) == 1


def test_ready_for_what_is_not_a_harvest_is_no_stage() -> None:
    (field,) = recipe(
        "Plum tomatoes just transplanted into plastic mulch, wire hoops ready for the fleece, "
        "picture taken in May."
    ).fields
    assert field.stage == "Vegetative"
    assert recipe("cherries ready for the harvest").fields[0].stage == "Maturation"


def test_a_sowing_month_beside_the_scenes_month_is_not_its_season() -> None:
    (field,) = recipe(
        "Winter wheat drilled last October; it's May now and the crop is heading."
    ).fields
    assert (field.season, field.stage) == ("Spring", "Reproductive")


def test_many_plants_named_by_their_crop_are_a_count_of_plants() -> None:
    scene = recipe("200 Fuji trees in the top block and 150 Pink Lady in the bottom block.")
    assert [f.variety for f in scene.fields] == ["Fuji", "Pink Lady"]
    assert [f.nominal_plant_count for f in scene.fields] == [200, 150]


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("Spätburgunder vines on steep slate terraces above the river, October", 1),
        ("tomatoes (san marzanno) & jalapeños in 2 separate fields, both flowering", 2),
        ("apples in two orchards", 2),
    ],
)
def test_the_plots_crops_grow_in(prompt: str, count: int) -> None:
    assert len(recipe(prompt).fields) == count


def test_a_weak_variety_opening_a_plots_clause_is_its_crop() -> None:
    scene = recipe(
        "This is the strawberry farm: Centenary on tabletops to the west, Sonata in the open "
        "ground east of them, both covered in ripe red berries."
    )
    assert [f.variety for f in scene.fields] == ["Malling Centenary", "Sonata"]


@pytest.mark.parametrize(
    ("prompt", "health"),
    [
        (
            "Vines with loads of leaves with yellow oily spots on top and white fuzz underneath",
            "Ill",
        ),
        ("Cabbages riddled with caterpillar holes", "Ill"),
        ("Cabbage field where the outer leaves have yellow V-shaped patches", "Ill"),
        ("Corn in 30-inch rows, leaves curled and grey-looking in the drought", "Ill"),
    ],
)
def test_more_signs_of_illness(prompt: str, health: str) -> None:
    assert recipe(prompt).fields[0].health == health


def test_a_heading_before_a_counted_list_and_distinct_vegetables() -> None:
    scene = recipe(
        "This one's from my allotment: three different veg patches, a shed with a water butt "
        "behind them and my neighbour waving over the fence."
    )
    assert len(scene.fields) == 3
    assert {f.category for f in scene.fields} == {"Vegetables"}
    plots = recipe("Five plots along the lane, each with a different vegetable.")
    assert len(plots.fields) == 5
    assert {f.category for f in plots.fields} == {"Vegetables"}
    assert len({f.crop for f in plots.fields}) == 5


def test_a_bed_with_a_size_is_not_a_bed_width() -> None:
    scene = recipe(
        "Carrot bed 1.5 m x 25 m at 150 plants per square metre, and an onion bed of the same "
        "1.5 x 25 m size at 40 per square metre beside it"
    )
    assert [f.geometry.size_m for f in scene.fields] == [(1.5, 25.0), (1.5, 25.0)]


def test_hands_of_the_bananas_named_are_theirs() -> None:
    (field,) = recipe(
        "a plantation of Dwarf Cavendish with big purple flower buds hanging down and the first "
        "hands of bananas just forming."
    ).fields
    assert (field.variety, field.stage) == ("Cavendish", "Reproductive")


def test_a_winter_orchard_with_bare_branches_is_of_a_deciduous_fruit() -> None:
    scene = recipe(
        "On one side of the lane there's an orchard, bare branches all white with hoarfrost, "
        "and on the other a vineyard pruned right back and dormant."
    )
    assert scene.fields[0].crop in ("Apple", "Pear", "Cherry")
    assert scene.fields[0].season == "Winter"


@pytest.mark.parametrize(
    "prompt",
    [
        "Savoy and January King in two neighbouring blocks, frost on the crinkly leaves",
        "Savoy and January King in adjacent plots",
    ],
)
def test_a_list_in_neighbouring_plots_lies_side_by_side(prompt: str) -> None:
    scene = recipe(prompt)
    savoy, king = scene.fields
    assert [f.variety for f in scene.fields] == ["Savoy", "January King"]
    assert {(r.kind, frozenset((r.subject, *r.objects))) for r in scene.relations} == {
        ("next_to", frozenset((savoy.id, king.id)))
    }

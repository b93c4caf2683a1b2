"""Text of blind set g10 (issue 8): scenery named like crops ("a cherry picker", "shade
trees", "golden evening light"), a colour before a plot that cannot hold that crop
("the orange roots"), damage and ripening cues, "in leaf" as no stage, and neighbours
said over scenery ("on the other side of the hedge", "the next block over")."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "A cherry picker is parked by the packhouse, and behind it the pear orchard and a "
            "small vineyard on the slope.",
            ["Pear", "Grape"],
        ),
        (
            "Golden evening light over the orchard, Fuji on the near side and Cripps Pink behind.",
            ["Apple", "Apple"],
        ),
        (
            "Cayenne chillies going red next to beef tomatoes. Shade trees and a hose reel at "
            "the edge of the picture.",
            ["Pepper", "Tomato"],
        ),
        (
            "Danvers carrots being lifted in October, the orange roots are heaped in the trailer.",
            ["Carrot"],
        ),
        (
            "Cherry tomatoes staked on black plastic, lots of yellow flowers and the first tiny "
            "fruits setting.",
            ["Tomato"],
        ),
    ],
)
def test_scenery_and_colours_that_look_like_crops(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


@pytest.mark.parametrize(
    ("prompt", "stage", "health"),
    [
        (
            "Granny Smith rows loaded with apples, but a lot of the fruit has brown corky "
            "patches and the leaves are covered in olive-green velvety spots.",
            None,
            "Ill",
        ),
        ("California Wonder peppers turning from green to red on the plants", "Maturation", None),
        ("Cherry tomatoes with the first tiny fruits setting", "Reproductive", None),
    ],
)
def test_cues(prompt: str, stage: str | None, health: str | None) -> None:
    (field,) = recipe(prompt).fields
    if stage is not None:
        assert field.stage == stage
    if health is not None:
        assert field.health == health


def test_in_leaf_with_fruitlets_is_no_conflict() -> None:
    pears, cherries = recipe(
        "Comice pears next to Lapins cherries in June: the cherries are full of dark red "
        "fruit, the Comice still in leaf with small fruitlets."
    ).fields
    assert (pears.stage, cherries.stage) == ("Reproductive", "Maturation")


@pytest.mark.parametrize(
    "prompt",
    [
        "A sprayer working the maize, and on the other side of the hedge a field of wheat.",
        "Jalapeños hanging dark green on the bushes, and the next block over is Roma.",
    ],
)
def test_neighbours_said_over_scenery(prompt: str) -> None:
    scene = recipe(prompt)
    (relation,) = scene.relations
    assert relation.kind == "next_to"


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        (
            "Tropical orchard twin: a banana block (2 x 2 m, 400 plants) south of an orange grove "
            "(7 m rows, 4 m in-row, 150 trees).",
            2,
        ),
        (
            "Citrus twin: a Washington Navel block west of a Valencia Late block, both at 3.7 m x "
            "1.2 m, 500 trees each.",
            2,
        ),
        (
            "Crop-row detection dataset, two cereal plots of 50 x 50 m: maize in 75 cm rows, and "
            "wheat in 15 cm rows, with the wheat to the west.",
            2,
        ),
    ],
)
def test_a_digital_twin_and_a_crop_row_are_no_count_and_no_plot(prompt: str, count: int) -> None:
    assert len(recipe(prompt).fields) == count


def test_twin_rows_are_still_two_rows_per_bed() -> None:
    (field,) = recipe("peppers in twin rows on 1.4 m beds").fields
    assert field.agronomy.rows_per_bed == 2


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "The only field we still have is behind the milking parlour: 3 acres of Riesling, the "
            "grapes ripe and perfectly healthy, and it's late September now.",
            ["Grape"],
        ),
        ("pls 2 fields: one w grain one w salad", ["Wheat", "Lettuce"]),
    ],
)
def test_farm_words_and_texting_forms(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields][:1] == crops[:1]
    assert len(recipe(prompt).fields) == len(crops)


def test_a_decimal_after_a_leading_compass_label() -> None:
    maize, wheat = recipe(
        "North field: dent corn on 30-inch rows. South field: Winter Wheat drilled in 12.5 cm rows."
    ).fields
    assert (maize.agronomy.row_spacing_m, wheat.agronomy.row_spacing_m) == (0.762, 0.125)


def test_a_sowing_month_with_sowed() -> None:
    (field,) = recipe(
        "The back field is Chantenay carrots. We sowed them in May and now, in early June, "
        "they're at the two-leaf stage."
    ).fields
    assert (field.stage, field.season) == ("Vegetative", "Summer")


@pytest.mark.parametrize(
    "prompt",
    [
        "From the top of the farm down: vines, then stone fruit, then salad, then spuds.",
        "Grain along the northern boundary, greens along the southern one, and the farmhouse "
        "in between.",
    ],
)
def test_a_farm_from_the_top_down(prompt: str) -> None:
    scene = recipe(prompt)
    ids = [f.id for f in scene.fields]
    assert ("north_of", ids[0], (ids[1],)) in {
        (r.kind, r.subject, r.objects) for r in scene.relations
    }


def test_what_a_comparison_is_between_is_no_field() -> None:
    scene = recipe(
        "Pear-vs-apple LiDAR comparison. Golden Delicious block between a Comice block and a "
        "Durondeau block, all three at 3.5 x 1.0 m, 1 ha each, rows E-W."
    )
    assert [f.variety for f in scene.fields] == [
        "Golden Delicious",
        "Doyenne du Comice",
        "Durondeau",
    ]
    assert all(f.row_bearing_deg == pytest.approx(90.0) for f in scene.fields)


def test_beds_on_inch_centres() -> None:
    (field,) = recipe(
        "Jalapeño beds for the robot: 6 beds on 60 in centres, 2 rows per bed, 18 in between "
        "plants, rows 150 ft."
    ).fields
    assert (field.bed_count, field.agronomy.row_spacing_m) == (6, 1.524)


def test_a_plot_said_after_its_crop_with_of() -> None:
    fields = recipe(
        "we only grow onions now, one field of about 6 acres down the lane past the church"
    ).fields
    assert [f.crop for f in fields] == ["Onion"]
    width, length = fields[0].geometry.size_m
    assert width * length == pytest.approx(6 * 4046.8564, rel=0.01)


@pytest.mark.parametrize(
    "prompt",
    [
        "Plot A is 200 ft by 300 ft of Roma tomatoes. Plot B is the same size, Beefsteak.",
        "Romaine 20 x 30 m. The same size, Iceberg.",
    ],
)
def test_the_same_size_in_a_sentence_before_the_field(prompt: str) -> None:
    fields = recipe(prompt).fields
    assert len(fields) == 2
    assert fields[1].geometry.size_m == fields[0].geometry.size_m


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "Blight has hit every field this summer - the potatoes, the tomatoes and the "
            "carrots too.",
            ["Potato", "Tomato", "Carrot"],
        ),
        ("Blight in every field: potatoes and tomatoes", ["Potato", "Tomato"]),
        ("every field has aphids: apples, pears", ["Apple", "Pear"]),
    ],
)
def test_every_field_says_its_words_of_all_the_fields(prompt: str, crops: list[str]) -> None:
    fields = recipe(prompt).fields
    assert [f.crop for f in fields] == crops
    assert [f.health for f in fields] == ["Ill"] * len(crops)


def test_each_plot_gets_a_headland() -> None:
    fields = recipe(
        "two lettuce plots for the harvester robot, crisphead and Cos, 30 rows each, 0.35 m "
        "row spacing, 0.30 m in row, rows 50 m. the Cos plot goes west of the crisphead plot, "
        "and each plot gets a 4 m headland."
    ).fields
    assert [f.variety for f in fields] == ["Iceberg", "Romaine"]
    assert [f.geometry.headland_m for f in fields] == [4.0, 4.0]


def test_each_growing_a_different_vegetable() -> None:
    fields = recipe(
        "The market-garden side of the farm is four fields, each growing a different vegetable."
    ).fields
    assert len(fields) == 4
    assert len({f.crop for f in fields}) == 4
    assert all(f.category == "Vegetables" for f in fields)


@pytest.mark.parametrize(
    "prompt",
    [
        "the vegetable garden south of the vineyard",
        "a vineyard, a vegetable garden",
        "Could you lay out my farm? There's the vineyard on the hill, the vegetable garden "
        "south of it, and a cornfield east of the vegetables.",
    ],
)
def test_a_vegetable_garden_is_a_field_of_vegetables(prompt: str) -> None:
    fields = recipe(prompt).fields
    assert [f.category for f in fields if f.crop != "Grape" and f.crop != "Maize"] == ["Vegetables"]
    assert "Grape" in [f.crop for f in fields]


def test_bare_spacings_after_each_crop_and_an_uncounted_heading() -> None:
    scene = recipe(
        "sensor test strips: a capsicum strip between a tomato strip and a maize strip. every "
        "strip is 6 rows of 50 m; tomato rows 1.5 m apart, capsicum 0.9 m, maize 0.75 m"
    )
    fields = {f.crop: f for f in scene.fields}
    assert sorted(fields) == ["Maize", "Pepper", "Tomato"]
    assert fields["Pepper"].agronomy.row_spacing_m == 0.9
    assert fields["Tomato"].agronomy.row_spacing_m == 1.5
    assert fields["Maize"].agronomy.row_spacing_m == 0.75
    relation = scene.relations[0]
    assert relation.kind == "between"
    assert relation.subject == fields["Pepper"].id


@pytest.mark.parametrize(
    "prompt",
    [
        "kinda want durondeau pears n granny apples, apples north pears south, spring blossom "
        "everywhere",
        "durondeau pears and granny apples, apples to the north and pears to the south",
    ],
)
def test_crops_placed_again_after_they_are_named(prompt: str) -> None:
    scene = recipe(prompt)
    by_id = {f.id: f.crop for f in scene.fields}
    assert sorted(by_id.values()) == ["Apple", "Pear"]
    assert [(by_id[r.subject], r.kind, [by_id[o] for o in r.objects]) for r in scene.relations] == [
        ("Apple", "north_of", ["Pear"])
    ]


def test_compass_words_of_one_phrase_stay_together() -> None:
    scene = recipe("from west 2 east: sturon onions then chantenay carrots then agria spuds")
    by_id = {f.id: f.crop for f in scene.fields}
    said = [(by_id[r.subject], r.kind, by_id[r.objects[0]]) for r in scene.relations]
    assert ("Onion", "west_of", "Carrot") in said
    assert ("Carrot", "west_of", "Potato") in said


def test_the_upper_and_the_lower_orchard() -> None:
    scene = recipe("Williams pears in the lower orchard, Golden apples in the upper one.")
    by_id = {f.id: f.crop for f in scene.fields}
    assert [(by_id[r.subject], r.kind, [by_id[o] for o in r.objects]) for r in scene.relations] == [
        ("Apple", "north_of", ["Pear"])
    ]


def test_a_second_plural_heading_starts_its_own_list() -> None:
    fields = recipe("Lower terraces: Chardonnay. Upper terraces: Riesling.").fields
    assert [f.variety for f in fields] == ["Chardonnay", "Riesling"]


def test_structures_next_to_each_other_hold_the_list_after_them() -> None:
    scene = recipe(
        "Picking-robot trial in two polytunnels next to each other: tunnel 1 is Elsanta, "
        "tunnel 2 is Centenary. In each one 5 raised beds on 1.5 m centres."
    )
    assert [f.variety for f in scene.fields] == ["Elsanta", "Malling Centenary"]
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("next_to", scene.fields[0].id, (scene.fields[1].id,))
    ]


@pytest.mark.parametrize(
    ("prompt", "varieties"),
    [
        ("the Conference block with the Royal Gala next to it", ["Conference", "Gala"]),
        ("a Sonata bed and a Gala block", ["Sonata", "Gala"]),
    ],
)
def test_a_capitalised_variety_before_its_plot(prompt: str, varieties: list[str]) -> None:
    assert [f.variety for f in recipe(prompt).fields] == varieties


def test_ridges_counted_after_them_and_a_seeding_robot() -> None:
    fields = recipe(
        "seeding robot field test. carrot ridges, 40 of them at 75 cm, 2 rows per ridge, 150 m "
        "rows running east-west. south of the carrots a lettuce block, 35 cm rows, 30 cm in-row."
    ).fields
    carrots = fields[0]
    assert carrots._grid()[0] == 40  # beds across the field, as the plant kernel lays them
    assert carrots.agronomy.row_spacing_m == 0.75  # bed centres, with 2 rows on each
    assert carrots.agronomy.rows_per_bed == 2
    assert "stage" not in carrots.stated


def test_a_spacing_after_two_crops_is_both_fields() -> None:
    fields = recipe(
        "Orchard robot sim with three blocks from north to south: cherries, apples, pears. "
        "Cherries at 4.6 x 2.4 m; apples and pears at 3.5 x 1 m. 8 rows per block."
    ).fields
    spacing = {f.crop: (f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in fields}
    assert spacing == {"Cherry": (4.6, 2.4), "Apple": (3.5, 1.0), "Pear": (3.5, 1.0)}


def test_counted_plots_listed_by_a_placement() -> None:
    scene = recipe(
        "Could you make two 0.25 ha plots for the drone, carrots north of onions? Carrots at "
        "150 plants per m², onions at 0.30 m x 0.10 m."
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Onion"]
    for field in scene.fields:
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(2500, rel=0.01)
    assert scene.relations[0].kind == "north_of"


def test_a_list_separated_by_bars() -> None:
    scene = recipe(
        "Onion strip trial for the drone, west to east: Sturon | Stuttgarter Riesen | Walla "
        "Walla. Each strip 6 rows at 30 cm, 10 cm in-row, 40 m long."
    )
    assert [f.variety for f in scene.fields] == ["Sturon", "Stuttgarter", "Walla Walla"]
    ids = [f.id for f in scene.fields]
    said = [(r.kind, r.subject, r.objects) for r in scene.relations]
    assert ("west_of", ids[0], (ids[1],)) in said
    assert ("west_of", ids[1], (ids[2],)) in said


def test_two_crops_heading_the_list_after_a_colon() -> None:
    scene = recipe(
        "Carrot variety strips plus a lettuce strip for our weeding robot, north to south: "
        "Imperator, then Danvers, then Bibb lettuce, each 10 ridges on 75 cm centres with 50 m "
        "rows."
    )
    assert [f.variety for f in scene.fields] == ["Imperator", "Danvers", "Butterhead"]
    ids = [f.id for f in scene.fields]
    said = [(r.kind, r.subject, r.objects) for r in scene.relations]
    assert ("north_of", ids[0], (ids[1],)) in said
    assert ("north_of", ids[1], (ids[2],)) in said


def test_depth_words_beside_a_compass_zone() -> None:
    scene = recipe(
        "Drone shot looking north: wheat at the top of the frame, then a strip of maize, then "
        "potatoes closest to the camera at the bottom."
    )
    ids = {f.crop: f.id for f in scene.fields}
    said = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert ("north_of", ids["Wheat"], (ids["Maize"],)) in said
    assert ("north_of", ids["Maize"], (ids["Potato"],)) in said


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("Iceberg heads hearted up, next to a few beds of Cos that have started bolting", 2),
        ("Aerial photo of a patchwork of small wheat fields with hedges between them", 4),
    ],
)
def test_vague_amounts_of_beds_and_of_fields(prompt: str, count: int) -> None:
    assert len(recipe(prompt).fields) == count


def test_a_cue_keeps_its_fields_stage_against_words_said_of_the_other() -> None:
    fields = recipe(
        "Cayenne chillies going red and beef tomatoes the size of fists but still green"
    ).fields
    assert [(f.crop, f.stage) for f in fields] == [
        ("Pepper", "Maturation"),
        ("Tomato", "Reproductive"),
    ]


def test_a_vague_number_of_beds_is_as_many_as_the_list_after_it() -> None:
    fields = recipe(
        "A patchwork of veg beds behind the house, I can make out onions, carrots and lettuce, "
        "all still young."
    ).fields
    assert [f.crop for f in fields] == ["Onion", "Carrot", "Lettuce"]

"""Text of blind set g11 (issue 8): thousands inside a compass label, the whole number of
a field's trees, scenery that is no crop ("a roadside stand"), plant parts that are no
misspelt stage ("fire blight on some shoots"), trade names ("cab sav"), fields placed by
a building, and the way a slope faces."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    crop = {f.id: f.crop for f in scene.fields}
    return {(crop[r.subject], r.kind, tuple(crop[o] for o in r.objects)) for r in scene.relations}


def test_thousands_inside_a_leading_compass_label() -> None:
    scene = recipe(
        "North field: Spring Wheat drilled in 12.5 cm rows. South field: Popcorn at 80,000 "
        "plants/ha."
    )
    wheat, maize = scene.fields
    assert (wheat.variety, maize.variety) == ("Spring Wheat", "Popcorn")
    assert maize.agronomy.row_spacing_m * maize.agronomy.in_row_spacing_m == pytest.approx(
        1 / 8, rel=0.01
    )
    assert relations(scene) == {("Wheat", "north_of", ("Maize",))}


def test_all_of_our_trees_is_the_number_of_plants() -> None:
    (field,) = recipe(
        "All 180 of our Regina trees are in this picture, a wet week in July, fruit rotting on "
        "the branches"
    ).fields
    assert field.variety == "Regina"
    assert "plant_count" in field.stated


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        (
            "swetcorn ready for picking, cobs fat with dry brown silks, and a roadside stand with "
            "a hand-painted sign in the corner of the shot",
            "Maize",
        ),
        ("bartlett pears, ripe, aug, w/ fire blight on some shoots", "Pear"),
        ("cab sav vineyard in argentina, harvest in march", "Grape"),
    ],
)
def test_words_that_are_no_crop_and_no_stage(prompt: str, crop: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.crop == crop


def test_some_shoots_is_no_misspelt_side_shoots() -> None:
    (field,) = recipe("bartlett pears, ripe, aug, w/ fire blight on some shoots").fields
    assert (field.stage, field.health) == ("Maturation", "Ill")


def test_cab_sav_is_cabernet_sauvignon() -> None:
    (field,) = recipe("cab sav vineyard in argentina, harvest in march").fields
    assert field.variety == "Cabernet Sauvignon"


def test_a_field_placed_by_a_building_and_one_placed_by_that_field() -> None:
    scene = recipe(
        "There's a lettuce field east of the big barn, and east of that again a field of maize, "
        "with the duck pond tucked in a corner."
    )
    assert relations(scene) == {("Maize", "east_of", ("Lettuce",))}


def test_a_south_facing_slope_places_nothing() -> None:
    scene = recipe(
        "Shot across the valley on a misty morning: a vineyard on the south-facing slope, a "
        "vegetable field below it, and a wheat field right at the bottom by the river."
    )
    assert [f.crop for f in scene.fields][::2] == ["Grape", "Wheat"]
    assert scene.fields[1].category == "Vegetables"
    assert ("Grape", "south_of", (scene.fields[1].crop,)) not in relations(scene)


def test_sides_joined_by_by_are_one_size() -> None:
    scene = recipe(
        "Three camera test strips, all 10 m wide by 80 m long, laid out from west to east: "
        "Savoy cabbage, Red Baron onions, Romaine lettuce."
    )
    assert [f.geometry.size_m for f in scene.fields] == [(10.0, 80.0)] * 3
    assert ("Cabbage", "west_of", ("Onion",)) in relations(scene)
    assert all(r.kind != "next_to" for r in scene.relations)


def test_a_field_placed_east_of_both_fields_split_by_a_hedge() -> None:
    scene = recipe(
        "two wheat fields split by a hawthorn hedge, and a maize field to the east of both"
    )
    assert [f.crop for f in scene.fields] == ["Wheat", "Wheat", "Maize"]
    # (the hedge is scenery; the two fields it splits touch it, side by side)
    wheat = {f.id for f in scene.fields[:2]}
    assert {(r.kind, frozenset((r.subject, *r.objects)) == wheat) for r in scene.relations} == {
        ("east_of", False),
        ("next_to", True),
    }


def test_a_block_between_two_groves_named_before() -> None:
    scene = recipe(
        "Hamlin oranges on the west, Valencia Late on the east, and between the two groves a "
        "block of Grande Naine bananas."
    )
    assert [f.crop for f in scene.fields] == ["Orange", "Orange", "Banana"]
    banana = scene.fields[2].id
    between = [r for r in scene.relations if r.kind == "between"]
    assert [r.subject for r in between] == [banana]


def test_quarters_named_bare_and_a_grid_of_plots() -> None:
    scene = recipe(
        "Four 0.25 ha plots in a 2x2 grid for the drone: strawberries NW, lettuce NE, cabbage "
        "SW, onions SE."
    )
    assert [f.crop for f in scene.fields] == ["Strawberry", "Lettuce", "Cabbage", "Onion"]
    assert relations(scene) == {
        ("Strawberry", "north_of", ("Cabbage",)),
        ("Lettuce", "north_of", ("Onion",)),
        ("Strawberry", "west_of", ("Lettuce",)),
        ("Cabbage", "west_of", ("Onion",)),
    }


def test_quarters_as_leading_labels() -> None:
    scene = recipe(
        "Think of the farm as four squares. North-west: Bing cherries. North-east: Williams "
        "pears. South-west: Butterhead lettuce. South-east: Flint corn."
    )
    assert ("Cherry", "west_of", ("Pear",)) in relations(scene)
    assert ("Cherry", "north_of", ("Lettuce",)) in relations(scene)


def test_a_square_grid_that_matches_the_density_is_the_planting_grid() -> None:
    (field,) = recipe(
        "banana plants for a drone LAI survey: 3 m by 3 m, 1,111 plants per hectare, 5 ha, "
        "rows north-south"
    ).fields
    assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == (3.0, 3.0)
    width, length = field.geometry.size_m
    assert width * length == pytest.approx(50_000, rel=0.01)


def test_this_one_is_the_photo_not_a_count() -> None:
    scene = recipe(
        "Two strawberry fields in this one, Sonata on the south side with red fruit ready to "
        "pick and Albion to the north still flowering."
    )
    assert [(f.variety, f.stage) for f in scene.fields] == [
        ("Sonata", "Maturation"),
        ("Albion", "Reproductive"),
    ]
    # (the Sonata south of the Albion, said from each side)
    assert relations(scene) <= {
        ("Strawberry", "south_of", ("Strawberry",)),
        ("Strawberry", "north_of", ("Strawberry",)),
    }
    sonata, albion = (f.id for f in scene.fields)
    assert any(
        (r.kind, r.subject, r.objects)
        in {("south_of", sonata, (albion,)), ("north_of", albion, (sonata,))}
        for r in scene.relations
    )


def test_flowers_all_over_one_member_stay_with_it() -> None:
    fields = recipe(
        "Two fields in this one: spuds, lush and green with white flowers all over the ridges, "
        "and a wheat field gone completely straw-coloured with the heads drooping."
    ).fields
    assert [(f.crop, f.stage) for f in fields] == [
        ("Potato", "Reproductive"),
        ("Wheat", "Maturation"),
    ]


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "Spätburgunder bunches hanging dark purple, pickers with buckets working down the "
            "row and a tractor with a grape hopper waiting.",
            ["Grape"],
        ),
        (
            "Winter wheat, just a couple of leaves per plant poking through the frosty clods, "
            "rooks all over it and the tramlines from the drill clearly visible.",
            ["Wheat"],
        ),
        (
            "Washington Navels, fruit hanging ripe and orange, packed crates and a forklift on "
            "the track, and snow on the mountains far off.",
            ["Orange"],
        ),
        ("ripe wheat and orange trees", ["Wheat", "Orange"]),
    ],
)
def test_loads_leaves_and_colours_are_no_fields(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_the_two_plots_counted_together_before() -> None:
    scene = recipe(
        "two tomato plots and one pepper plot, each 15 x 40 m. Tomatoes on 1.5 m rows, peppers "
        "on 1.4 m beds, and the pepper plot sits between the two tomato plots."
    )
    assert [f.crop for f in scene.fields] == ["Tomato", "Tomato", "Pepper"]
    tomato_1, tomato_2, pepper = (f.id for f in scene.fields)
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("between", pepper, (tomato_1, tomato_2))
    ]


def test_a_count_said_again_before_the_varieties_are_placed() -> None:
    scene = recipe(
        "centenary & albion strawberries, 2 fields, albion south of centenary, polytunnels "
        "everywhere"
    )
    assert [f.variety for f in scene.fields] == ["Malling Centenary", "Albion"]
    centenary, albion = (f.id for f in scene.fields)
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("south_of", albion, (centenary,))
    ]


@pytest.mark.parametrize(
    ("prompt", "varieties"),
    [
        (
            "plot list for the home farm - plot 1 Bintje potatoes on 75 cm ridges, plot 2 Nantes "
            "carrots, plot 3 Sturon onions.",
            ["Bintje", "Nantes", "Sturon"],
        ),
        (
            "Tunnel one has Roma tomatoes, all fine; tunnel two has California Wonder peppers "
            "with bacterial spot; tunnel three is Jalapeño seedlings.",
            ["Roma", "California Wonder", "Jalapeno"],
        ),
    ],
)
def test_plots_and_tunnels_labelled_by_number(prompt: str, varieties: list[str]) -> None:
    assert [f.variety for f in recipe(prompt).fields] == varieties


@pytest.mark.parametrize(
    ("prompt", "health"),
    [
        (
            "Dwarf Cavendish up front with heavy green bunches, and the Ladyfinger block next to "
            "them has yellowing, mottled leaves and some plants wilting.",
            ["Healthy", "Ill"],
        ),
        (
            "Beefsteak tomatoes staked up in the foreground with big fruit still green, and "
            "behind them a bed of Padrón peppers whose leaves are spotted dark and whose fruit "
            "has raised scabby spots.",
            ["Healthy", "Ill"],
        ),
        (
            "Bibb and Lollo lettuce just planted out side by side, tiny plants in black plastic, "
            "fleece hoops waiting to go over them on a gusty spring day.",
            ["Healthy", "Healthy"],
        ),
    ],
)
def test_damage_stays_with_the_field_it_is_said_of(prompt: str, health: list[str]) -> None:
    assert [f.health for f in recipe(prompt).fields] == health


@pytest.mark.parametrize(
    ("prompt", "stages"),
    [
        (
            "Flint corn, waist high and green, no tassels yet, rows 75 cm apart",
            ["Vegetative"],
        ),
        (
            "Spelt on one side of the hedge, straw-coloured with the heads bowed, and Walla "
            "Walla onions on the other, lifted and drying in windrows.",
            ["Maturation", "Maturation"],
        ),
    ],
)
def test_stages_seen_before_tassels_and_after_lifting(prompt: str, stages: list[str]) -> None:
    assert [f.stage for f in recipe(prompt).fields] == stages


@pytest.mark.parametrize(
    "prompt",
    [
        "Spelt on one side of the hedge, straw-coloured with the heads bowed, and Walla Walla "
        "onions on the other, lifted and drying in windrows.",
        "This is the corner where the Imperator carrots meet the Danvers: the Imperator look "
        "healthy, the Danvers have dark spots with yellow rings on the leaves.",
    ],
)
def test_two_fields_that_meet(prompt: str) -> None:
    scene = recipe(prompt)
    assert len(scene.fields) == 2
    assert [r.kind for r in scene.relations] == ["next_to"]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "Block 1: Cabernet, 32 rows, 2.7 m spacing. Block 2, south of block 1: Riesling, 20 "
            "rows, 2.7 m spacing.",
            ("Grape", "south_of", ("Grape",)),
        ),
        (
            "Plot A: Bintje potatoes, 16 rows at 75 cm, rows 60 m. Plot B sits directly east of "
            "A: Nantes carrots on 8 ridges (75 cm ridge centres, 2 rows per ridge).",
            ("Carrot", "east_of", ("Potato",)),
        ),
    ],
)
def test_a_label_placed_against_another_label(
    prompt: str, expected: tuple[str, str, tuple[str, ...]]
) -> None:
    scene = recipe(prompt)
    assert len(scene.fields) == 2
    assert relations(scene) == {expected}
    # the field defined second is the one placed
    assert scene.relations[0].subject == scene.fields[1].id


def test_versus_lists_two_fields_and_ridged_at_is_the_bed_width() -> None:
    scene = recipe(
        "weeding robot A/B test -> carrots vs onions, 100 m rows, both ridged at 75 cm, carrots "
        "on the north side of the onions please"
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Onion"]
    assert all(f.agronomy.row_spacing_m == 0.75 for f in scene.fields)
    assert relations(scene) == {("Carrot", "north_of", ("Onion",))}


def test_squares_counted_with_their_size() -> None:
    scene = recipe(
        "We need three 20 x 20 m calibration squares for the multispectral camera, stacked "
        "north to south: potatoes at the north end, then carrots, then onions at the south end."
    )
    assert [f.crop for f in scene.fields] == ["Potato", "Carrot", "Onion"]
    assert [f.geometry.size_m for f in scene.fields] == [(20.0, 20.0)] * 3
    assert ("Potato", "north_of", ("Carrot",)) in relations(scene)
    assert ("Carrot", "north_of", ("Onion",)) in relations(scene)


def test_same_size_right_after_a_dropped_label() -> None:
    scene = recipe(
        "Field A is 200 m by 150 m of dent corn in 30-inch rows. Field B, same size, is spelt, "
        "and it's west of A."
    )
    assert [f.geometry.size_m for f in scene.fields] == [(200.0, 150.0), (200.0, 150.0)]
    assert relations(scene) == {("Wheat", "west_of", ("Maize",))}


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "It's April; the Winter Wheat east of the farmhouse is well up, and west of the "
            "house the Russet potatoes have just been planted.",
            {("Wheat", "east_of", ("Potato",))},
        ),
        (
            "Half the farm is fruit and half is veg, split down the middle by the old railway "
            "line, with the fruit on the east side.",
            None,
        ),
        (
            "strawberies in the polytunnels, tomatos right next to them in the glasshouse, and a "
            "potato field out the back",
            {("Tomato", "next_to", ("Strawberry",))},
        ),
    ],
)
def test_fields_placed_by_a_landmark_a_half_and_a_pronoun(
    prompt: str, expected: set[tuple[str, str, tuple[str, ...]]] | None
) -> None:
    scene = recipe(prompt)
    if expected is not None:
        assert expected <= relations(scene)
    else:
        fruit, veg = scene.fields
        assert (fruit.category, veg.category) == ("Fruits", "Vegetables")
        assert ("east_of", fruit.id, (veg.id,)) in {
            (r.kind, r.subject, r.objects) for r in scene.relations
        }


def test_a_row_heading_east_from_the_field_before_then() -> None:
    scene = recipe(
        "From the farm gate: Gala trees first, then heading east the Durondeau pears, then "
        "further east the Regina cherries, all of them in blossom."
    )
    said = relations(scene)
    assert ("Apple", "west_of", ("Pear",)) in said
    assert ("Cherry", "east_of", ("Pear",)) in said


def test_a_size_before_a_plus_and_a_week_ago() -> None:
    onions, spuds = recipe("wala wala onions, mature, sept, 1 ha + 1 ha of spuds nxt door").fields
    for field in (onions, spuds):
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(10_000, rel=0.01)
    fields = recipe("padron peppers 🌶 & red express cabbage, both planted last wk so v tiny").fields
    assert [f.stage for f in fields] == ["Vegetative", "Vegetative"]


def test_rows_of_each_field_both_so_long() -> None:
    fields = recipe(
        "Weed-mapping drone scene with Stuttgarter Riesen onions, 20 rows at 30 cm, and Danvers "
        "carrots, 20 rows at 45 cm, carrots north of the onions, both 40 m long."
    ).fields
    assert all("row_length" in f.stated for f in fields)
    assert [f.agronomy.row_spacing_m for f in fields] == [0.3, 0.45]


def test_the_article_of_a_farm_counts_no_field() -> None:
    fields = recipe(
        "A mixed farm with some vegetable plots and a couple of cereal fields round the yard, a "
        "few cows by the gate."
    ).fields
    assert [f.category for f in fields].count("Vegetables") == 2
    assert [f.category for f in fields].count("Cereals") == 2

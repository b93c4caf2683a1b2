"""Text of blind set g27 (issue 8): crops listed with no mark between them, a count said
again with "so", a plot's size said in the heading of a list that names the fields
again, "one either side of", "beside the first", "each one further north", "split
between", a field between two on a diagonal, one tree of a field, looks of grain heads
and banana flowers, two fields placed in the parts of a view, "100 yd rows on 36-inch
spacing", "(looking north)", "in three plots of 10 x 25 m", "rows 40 cm, 30 cm and 75 cm
apart respectively", a title of what a test compares and a fruit's rusty-brown skin."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "omg need 3 diff fruit orchards for a demo lol: apple pear cherry",
            ["Apple", "Pear", "Cherry"],
        ),
        (
            "4 lil veg plots: carrots onions lettuce & cabbage",
            ["Carrot", "Onion", "Lettuce", "Cabbage"],
        ),
    ],
)
def test_crops_listed_with_no_mark_between_them(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_a_count_said_again_with_so(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = "lettuce in the middle & a cabbage field on either side of it (so 2 cabbage fields)"
    assert [f.crop for f in recipe(prompt).fields] == ["Lettuce", "Cabbage", "Cabbage"]
    assert named_relations(prompt) == {("between", "Lettuce", ("Cabbage", "Cabbage"))}
    # (without a side word, the crop named before takes the count)
    assert [f.crop for f in recipe("a wheat field, so 2 wheat fields").fields] == ["Wheat"] * 2


def test_sizes_in_a_heading_of_fields_named_again(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "potato field 2ha, onion field 1ha, carrot field 1ha, in a line n to s: potatoes then "
        "onions then carrots"
    )
    fields = recipe(prompt).fields
    assert [(f.crop, round(f.geometry.size_m[0] * f.geometry.size_m[1])) for f in fields] == [
        ("Potato", 20000),
        ("Onion", 10000),
        ("Carrot", 10000),
    ]
    relations = named_relations(prompt)
    assert ("north_of", "Potato", ("Onion",)) in relations
    assert ("north_of", "Onion", ("Carrot",)) in relations


@pytest.mark.parametrize(
    "prompt",
    [
        "Two Chantenay carrot fields, one either side of the Lollo lettuce plot.",
        "Two carrot fields, one on each side of the lettuce plot.",
        "Two carrot fields either side of the lettuce plot.",
    ],
)
def test_two_fields_one_either_side(
    prompt: str, named_relations: Callable[[str], NamedRelations]
) -> None:
    assert sorted(f.crop for f in recipe(prompt).fields) == ["Carrot", "Carrot", "Lettuce"]
    ((kind, subject, objects),) = named_relations(prompt)
    assert (kind, objects[0] == objects[1]) == ("between", True)
    assert subject in ("Lettuce", "Lollo Rosso") and objects[0] in ("Carrot", "Chantenay")


def test_beside_the_first(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Everything on our farm is grain: one field of wheat, one of maize, and a second wheat "
        "field beside the first."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Wheat", "Maize", "Wheat"]
    assert named_relations(prompt) == {("next_to", "Wheat", ("Wheat",))}
    scene = recipe(prompt)
    (relation,) = scene.relations
    assert (relation.subject, relation.objects) == (scene.fields[2].id, (scene.fields[0].id,))


def test_each_one_further_north(named_relations: Callable[[str], NamedRelations]) -> None:
    relations = named_relations(
        "From the road in: first the Hamlin orange grove, then a strip of Navel oranges, then "
        "the Moro, each one further north."
    )
    assert ("south_of", "Hamlin", ("Navel",)) in relations
    assert ("south_of", "Navel", ("Moro",)) in relations


def test_a_plot_split_between_two_crops(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Our vineyard is split between Chardonnay on the east side and Cabernet on the west "
        "side, and everything is being harvested in September."
    )
    fields = recipe(prompt).fields
    assert [(f.variety, f.stage, f.season) for f in fields] == [
        ("Chardonnay", "Maturation", "Fall"),
        ("Cabernet Sauvignon", "Maturation", "Fall"),
    ]
    assert named_relations(prompt) == {("east_of", "Chardonnay", ("Cabernet Sauvignon",))}


def test_a_field_between_two_corners() -> None:
    scene = generate(
        "farm layout: orchard in the NE corner, vegetables in the SW corner, and a cereal "
        "field between them",
        resolver="hybrid",
    )
    orchard, vegetables, cereal = scene.recipe.fields
    assert (cereal.category, vegetables.category) == ("Cereals", "Vegetables")
    assert any(r.kind == "between" and r.subject == cereal.id for r in scene.recipe.relations)
    boxes = {f.id: (f.geometry.origin_m, f.geometry.size_m) for f in scene.recipe.fields}
    (ox, oy), _ = boxes[orchard.id]
    (cx, cy), (cw, ch) = boxes[cereal.id]
    (vx, vy), (vw, vh) = boxes[vegetables.id]
    assert vx + vw <= cx and cx + cw <= ox
    assert vy + vh <= cy and cy + ch <= oy


def test_one_tree_of_the_field_is_no_field() -> None:
    fields = recipe(
        "Commice pears hanging big and yellow-green, ready to pick, mid September. The "
        "ladder's up against the third tree and there's a bin trailer in the alley."
    ).fields
    assert [(f.crop, f.stage) for f in fields] == [("Pear", "Maturation")]


def test_looks_of_grain_heads_and_banana_flowers() -> None:
    grain, pears = recipe(
        "A grain field with the heads full and drooping, next to a pear orchard, with a red "
        "combine waiting in the gateway and swallows low over the hedge."
    ).fields
    assert (grain.category, grain.stage, "stage" in grain.stated) == ("Cereals", "Maturation", True)
    assert pears.crop == "Pear"
    (bananas,) = recipe(
        "Our Grande Naine block on Tenerife. Every plant has a heavy bunch with the purple "
        "flower still hanging under it, and the leaves are glossy with no streaks at all."
    ).fields
    assert (bananas.variety, bananas.stage, bananas.health) == (
        "Grand Nain",
        "Reproductive",
        "Healthy",
    )


def test_two_fields_placed_in_the_parts_of_a_view(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two fields either side of the farm track. On the left is our Bintje; on the right "
        "the Nantes carrots."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Bintje", "Nantes"]
    # (either side of the track, the two fields are next to each other across it)
    assert named_relations(prompt) == {
        ("west_of", "Bintje", ("Nantes",)),
        ("next_to", "Nantes", ("Bintje",)),
    }


def test_rows_in_yards_on_a_spacing_in_inches() -> None:
    maize, potatoes = recipe(
        "corn plot with 100 yd rows on 36-inch spacing, 32 rows, 10 yd headland, and a potato "
        "patch 30 yd x 40 yd south of it, for a row-detection camera"
    ).fields
    assert maize.row_length_m == pytest.approx(91.44)
    assert (maize.row_count, maize.agronomy.row_spacing_m) == (32, pytest.approx(0.9144))
    assert maize.geometry.headland_m == pytest.approx(9.144)
    assert potatoes.geometry.size_m == pytest.approx((27.432, 36.576), abs=0.01)


def test_left_and_right_looking_north(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Two lettuce plots side by side for a robotic harvester, crisphead on the left and "
        "Boston on the right (looking north): beds 1.2 m, 3 rows per bed, 28 cm between heads, "
        "10 beds each, rows N-S."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Iceberg", "Butterhead"]
    assert ("west_of", "Iceberg", ("Butterhead",)) in named_relations(prompt)


def test_a_list_in_plots_of_a_size() -> None:
    fields = recipe(
        "Salad trial for the harvest camera: Cos, iceberg and Lollo Rosso in three plots of "
        "10 x 25 m, the iceberg plot in the middle between the other two. Beds 1.5 m centre to "
        "centre, 4 rows per bed, 30 cm between heads, heads ready to cut."
    ).fields
    assert [(f.variety, f.geometry.size_m) for f in fields] == [
        ("Romaine", (10.0, 25.0)),
        ("Iceberg", (10.0, 25.0)),
        ("Lollo Rosso", (10.0, 25.0)),
    ]


def test_values_each_with_its_unit_given_respectively() -> None:
    fields = recipe(
        "Red-crop scene for colour camera calibration: Lollo Rosso, Red Baron onions and Red "
        "Express cabbage, three 4 m x 30 m plots from south to north in that order, rows 40 "
        "cm, 30 cm and 75 cm apart respectively."
    ).fields
    assert [(f.crop, f.agronomy.row_spacing_m) for f in fields] == [
        ("Lettuce", 0.4),
        ("Onion", 0.3),
        ("Cabbage", 0.75),
    ]


def test_a_title_of_what_a_test_compares_and_a_rusty_brown_skin() -> None:
    fields = recipe(
        "Bed-geometry comparison, two strawberry plots for the picker robot: plot 1 on 1.5 m "
        "beds with two rows, plot 2 on 1.0 m beds with one row, plot 2 directly north of plot "
        "1, 10 beds each."
    ).fields
    assert [(f.crop, f.bed_count, f.agronomy.rows_per_bed) for f in fields] == [
        ("Strawberry", 10, 2),
        ("Strawberry", 10, 1),
    ]
    (pears,) = recipe("Durondeau trees with rusty-brown fruit ready to pick").fields
    assert (pears.stage, pears.health) == ("Maturation", "Healthy")


def test_a_pronoun_placement_looks_no_further_than_its_sentence(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "From the drone at 30 m you can count 24 rows of maize, about 75 cm apart and running "
        "east to west, and a drilled wheat field beyond the farm track to the north of it. "
        "There's a tractor with a hoe working in the maize."
    )
    assert named_relations(prompt) == {("north_of", "Wheat", ("Maize",))}
    # ("in between" said right after a field: between the fields named either side of it)
    assert named_relations(
        "Looking across the valley you can see three fields: cabbages nearest to me, a strip "
        "of onions in between, and a field of sweetcorn up the hill. There are sprinkler pipes "
        "lying in the cabbages."
    ) == {("between", "Onion", ("Cabbage", "Sweet Corn"))}


def test_a_fence_named_by_its_wood_is_scenery() -> None:
    (cabbages,) = recipe(
        "Young cabbage transplants riddled with little holes where the flea beetles have chewed "
        "them. Overcast, a roll of fleece lying at the edge and a chestnut paling fence."
    ).fields
    assert (cabbages.crop, cabbages.stage, cabbages.health) == ("Cabbage", "Vegetative", "Ill")


def test_a_look_after_a_list_whose_member_is_placed_again() -> None:
    fields = recipe(
        "Cabbage variety block for the head-size camera: Savoy, Red Express and January King, "
        "each 10 rows at 75 cm, 45 cm in-row, 50 m long, with Red Express between the other "
        "two. Heads formed and ready for harvest."
    ).fields
    assert [(f.variety, f.stage) for f in fields] == [
        ("Savoy", "Maturation"),
        ("Red Express", "Maturation"),
        ("January King", "Maturation"),
    ]
    # (a field named again in its own sentence keeps the look said after it)
    wheat, maize = recipe("Wheat and maize. The maize is ripe. Tall and green.").fields
    assert ("stage" in wheat.stated, maize.stage) == (False, "Maturation")


def test_a_bare_pair_of_measures_after_a_named_pair() -> None:
    cherries, apples = recipe(
        "Sweetheart Lapins cherries west of a Royal Gala block; cherries 4.5 m between rows "
        "and 2.5 m between trees, apples 3.3 m and 0.9 m; 0.8 ha each."
    ).fields
    assert (cherries.agronomy.row_spacing_m, cherries.agronomy.in_row_spacing_m) == (4.5, 2.5)
    assert (apples.agronomy.row_spacing_m, apples.agronomy.in_row_spacing_m) == (3.3, 0.9)


@pytest.mark.parametrize("noun", ["block", "one"])
def test_members_told_apart_by_their_sides(
    noun: str, named_relations: Callable[[str], NamedRelations]
) -> None:
    prompt = (
        f"Two vineyard blocks for a robot sim, 20 rows each: the western {noun} at 2.75 m "
        f"between rows, the eastern {noun} at 3 m, vines 1.5 m apart throughout."
    )
    fields = recipe(prompt).fields
    assert [(f.crop, f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in fields] == [
        ("Grape", 2.75, 1.5),
        ("Grape", 3.0, 1.5),
    ]
    scene = recipe(prompt)
    west, east = (f.id for f in scene.fields)
    assert ("west_of", west, (east,)) in {(r.kind, r.subject, r.objects) for r in scene.relations}

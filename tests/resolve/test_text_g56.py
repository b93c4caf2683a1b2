"""Text of blind set g56 (issue 8): its misses fixed as general mechanisms (a spacing in
"in" inches; a member named again to place it; a colour hanging on the trees; a plot
placed, then planted; visual cues; "winter cereals"; "2 ha each" before another field;
"one each of"; "400 m long and 250 m wide"; a list whose members carry their measures in
brackets, then a direction)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


@pytest.mark.parametrize(
    "prompt",
    [
        "cabages at 24 in x 18 in (row x plant), 10 rows of 30 ft; onions in 12-inch rows "
        "south of them",
        "cabbages at 24 x 18 in, 10 rows of 30 ft; onions in 12-inch rows south of them",
    ],
)
def test_a_spacing_in_inches_written_in_is_no_count_of_fields(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert [f.crop for f in recipe.fields] == ["Cabbage", "Onion"]
    cabbage = recipe.fields[0].agronomy
    assert (cabbage.row_spacing_m, cabbage.in_row_spacing_m) == pytest.approx((0.6096, 0.4572))


def test_in_followed_by_a_place_is_still_a_preposition() -> None:
    recipe = generate("cabbages 24 x 18 in the north field").recipe
    assert len(recipe.fields) == 1
    assert recipe.fields[0].agronomy.row_spacing_m != pytest.approx(0.6096)


@pytest.mark.parametrize(
    "prompt",
    [
        "Two orchards of 300 trees each, apple and cherry, rows 4 m apart in both; cherries "
        "north of the apples.",
        "Two grain plots for UAV multispectral work, wheat at 12.5 cm rows and maize at 75 cm "
        "rows, 0.25 ha each, maize east of the wheat.",
    ],
)
def test_a_listed_member_named_again_to_place_it_ends_the_list(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert len(recipe.fields) == 2
    assert len({f.crop for f in recipe.fields}) == 2
    assert len(recipe.relations) == 1


def test_a_colour_hanging_on_the_trees_is_no_crop() -> None:
    recipe = generate(
        "We're a small farm, really just one block of Navel oranges beside the packing shed: "
        "fruit ripe and orange on the trees, mid-winter, healthy."
    ).recipe
    assert [(f.variety, f.stage) for f in recipe.fields] == [("Navel", "Maturation")]


def test_a_plot_placed_on_a_side_of_the_farm_then_planted_is_one_field() -> None:
    recipe = generate(
        "The orchard on the south side of the farm has apple trees in full blossom, and it's "
        "December."
    ).recipe
    assert [(f.crop, f.stage, f.season) for f in recipe.fields] == [
        ("Apple", "Reproductive", "Winter")
    ]
    assert any("not normally flowering" in w for w in recipe.warnings)


@pytest.mark.parametrize(
    ("prompt", "looks"),
    [
        (
            "Photo of the Grande Naine bananas next to the Lady Finger. The Grande Naine have "
            "big green bunches hanging under blue bags, while the Lady Finger leaves are "
            "streaked with black all over.",
            [("Grand Nain", "Healthy"), ("Lady Finger", "Ill")],
        ),
        (
            "the winter wheat on the north side is already heading, while the spring wheat to "
            "the south is still leafy and hasn't headed yet. Taken in June.",
            [("Winter Wheat", "Reproductive"), ("Spring Wheat", "Vegetative")],
        ),
        (
            "Snapshot of a corn field: the stalks are dry and tan, the cobs hang down.",
            [("Dent", "Maturation")],
        ),
        (
            "a wheat field where the ears have bleached to the colour of straw and are "
            "drooping, and a strawberry field alongside full of white flowers",
            [("Winter Wheat", "Maturation"), ("Elsanta", "Reproductive")],
        ),
        (
            "Red Baron onions, the tops all fallen over",
            [("Red Baron", "Maturation")],
        ),
        (
            "Another one from the walk last February: an orange grove in full colour, trees "
            "loaded, next to a field of little cabbages that have just been planted out.",
            [("Valencia", "Maturation"), ("Savoy", "Vegetative")],
        ),
        (
            "Two transplanted blocks: California Wonder peppers on 1.5 m beds and Roma "
            "tomatoes; peppers to the north, both at fruit set in July.",
            [("California Wonder", "Reproductive"), ("Roma", "Reproductive")],
        ),
    ],
)
def test_visual_cues_of_the_g56_photos(prompt: str, looks: list[tuple[str, str]]) -> None:
    recipe = generate(prompt).recipe
    said = [
        (f.variety, f.health if value in ("Healthy", "Ill") else f.stage)
        for f, (_, value) in zip(recipe.fields, looks, strict=True)
    ]
    assert said == looks


def test_transplanted_alone_is_still_young() -> None:
    assert [f.stage for f in generate("tomatoes, transplanted").recipe.fields] == ["Vegetative"]


def test_after_leaf_fall_is_winter_not_two_seasons() -> None:
    recipe = generate(
        "Photo of the Williams' Bon Chretien trees after leaf fall, hoarfrost on the bare "
        "branches, a row of wooden bins stacked by the hedge and a low winter sun."
    ).recipe
    assert [(f.variety, f.season) for f in recipe.fields] == [("Williams", "Winter")]


def test_down_under_the_leaves_is_no_hemisphere() -> None:
    recipe = generate(
        "Snapped at the research station in July: a plot of Lollo with deep red frilly "
        "leaves, and a plot of Boston lettuce whose leaves are covered in yellow blotches with "
        "white down under them."
    ).recipe
    assert [(f.season, f.health) for f in recipe.fields] == [
        ("Summer", "Healthy"),
        ("Summer", "Ill"),
    ]
    assert [f.season for f in generate("apples in October down under").recipe.fields] == ["Spring"]


def test_a_hay_stack_is_scenery() -> None:
    recipe = generate(
        "Drone pic over the Spelt plot and the Flint corn, right next to it. Blue tarp on a "
        "hay stack in the corner."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Spelt", "Flint"]


def test_winter_cereals_are_not_the_maize_named_before() -> None:
    recipe = generate(
        "Photo taken mid-October from the cab of the combine: the maize ahead is brown and "
        "dry, ready to go, and behind the hedge the winter cereals are just emerging as green "
        "lines."
    ).recipe
    assert [(f.crop, f.stage) for f in recipe.fields] == [
        ("Maize", "Maturation"),
        ("Wheat", "Vegetative"),
    ]


def test_each_after_a_list_is_not_the_field_said_after_it() -> None:
    recipe = generate(
        "Drone mapping test: an apple orchard and a pear orchard, 2 ha each, with a 0.5 ha "
        "cherry block between them."
    ).recipe
    areas = [f.geometry.size_m[0] * f.geometry.size_m[1] for f in recipe.fields]
    assert areas == pytest.approx([20000, 20000, 5000], rel=1e-3)
    without = generate("an apple orchard and a pear orchard, 2 ha each, with a cherry block")
    assert "size" not in without.recipe.fields[2].stated


def test_each_after_every_field_named_is_still_every_field() -> None:
    recipe = generate(
        "Put a potato field between a maize field and a wheat field, 4 ha each. Potato ridges "
        "75 cm, maize at 80,000 plants/ha."
    ).recipe
    assert {round(f.geometry.size_m[0] * f.geometry.size_m[1], -2) for f in recipe.fields} == {
        40000
    }


def test_one_bed_each_of_a_list_said_side_by_side(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Robot weeding demo: three 1.5 m beds next to each other, one each of lettuce, onions "
        "and carrots, onions on the middle bed."
    )
    recipe = generate(prompt).recipe
    # (the bed centres: one bed's width each; one bed each, not three)
    assert [f.agronomy.row_spacing_m for f in recipe.fields] == [1.5, 1.5, 1.5]
    assert [f.bed_count for f in recipe.fields] == [1, 1, 1]
    assert ("between", "Onion", ("Lettuce", "Carrot")) in crop_relations(prompt)


def test_long_and_wide_said_together_is_the_fields_size() -> None:
    recipe = generate(
        "The Dent corn field is 400 m long and 250 m wide, rows 76 cm apart. South of it is a "
        "200 by 250 m field of Durum."
    ).recipe
    assert recipe.fields[0].geometry.size_m == (250.0, 400.0)
    assert recipe.fields[0].agronomy.row_spacing_m == 0.76


def test_a_direction_after_a_list_with_bracketed_measures(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "LiDAR benchmark farm: Jonagored apples (3.5 m rows), Chardonnay vines (2.5 m rows) "
        "and Regina cherries (5 m rows) in three blocks from west to east in that order, every "
        "block with rows running N-S."
    )
    assert ("west_of", "Jonagold", ("Chardonnay",)) in relations
    assert ("west_of", "Chardonnay", ("Regina",)) in relations


def test_vines_listed_after_fields_of_no_vine_crop_are_a_vineyard() -> None:
    recipe = generate(
        "the whole farm in winter: bare apple trees, dormant vines and a field of cabbages"
    ).recipe
    assert [(f.crop, f.season) for f in recipe.fields] == [
        ("Apple", "Winter"),
        ("Grape", "Winter"),
        ("Cabbage", "Winter"),
    ]
    # (the haulm of potatoes named before stays theirs)
    potatoes = generate("Russet potatoes, vines dying back and a wheat field").recipe
    assert [f.crop for f in potatoes.fields] == ["Potato", "Wheat"]


def test_two_plots_that_touch_are_next_to_each_other(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Our polytunnel door is open in this shot and you can see outside: California Wonder "
        "peppers with big blocky green fruit on the left, San Marzano tomatoes on the right "
        "hanging heavy and red. The two plots touch, only a narrow path between."
    )
    assert {kind for kind, _, _ in relations} == {"next_to", "west_of"}
    assert len(generate("apples with a touch of frost").recipe.fields) == 1


def test_a_count_of_beds_before_a_list_of_as_many_is_a_bed_each() -> None:
    recipe = generate("three 1.5 m beds: lettuce, onions and carrots").recipe
    assert [(f.crop, f.bed_count) for f in recipe.fields] == [
        ("Lettuce", 1),
        ("Onion", 1),
        ("Carrot", 1),
    ]
    # (more beds than members: the count is each member's)
    six = generate("six 1.5 m beds: lettuce, onions and carrots").recipe
    assert [f.bed_count for f in six.fields] == [6, 6, 6]

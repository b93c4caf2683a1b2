"""Text of blind set g44 (issue 8): each miss of its blind run, fixed as the general
mechanism (plots "arranged 2 by 2"; scenery in a photo; fields said as "the one beyond
it"; labels placed between commas; the middle of three; looks said in turn; ...)."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, SceneRecipe, generate


def test_plots_arranged_two_by_two() -> None:
    recipe = generate(
        "Four 25 x 25 m plots for drone altitude calibration, arranged 2 by 2: wheat in the NW "
        "corner, maize NE, potatoes SW, carrots SE."
    ).recipe
    assert [f.crop for f in recipe.fields] == ["Wheat", "Maize", "Potato", "Carrot"]
    assert all(f.geometry.size_m == pytest.approx((25.0, 25.0)) for f in recipe.fields)
    relations = {(r.kind, r.subject, r.objects) for r in recipe.relations}
    assert ("north_of", "wheat_plot_1", ("potato_plot_1",)) in relations
    assert ("west_of", "wheat_plot_1", ("maize_plot_1",)) in relations


def test_boxes_and_a_grader_are_scenery_not_unknown_crops() -> None:
    # (refused as the unknown crop "boxes" before; the phantom field "at the top of the
    # shot" still adds is left for the next round)
    recipe = generate(
        "the onion field, tops flattened and drying off, ready for lifting; the grader and "
        "big boxes stand at the top of the shot."
    ).recipe
    assert recipe.fields[0].crop == "Onion"
    assert recipe.fields[0].stage == "Maturation"


def test_a_row_of_boxes_standing_on_the_headland_is_no_field_and_no_row() -> None:
    field, *others = generate(
        "This is the 4 ha onion field, tops flattened and drying off, ready for lifting; the "
        "grader and a row of big boxes stand on the 8 m headland at the top of the shot."
    ).recipe.fields
    assert others == []
    assert field.geometry.headland_m == 8.0
    width, length = field.geometry.size_m
    assert width * length == pytest.approx(40_000, rel=0.001)


def test_fruiting_and_starting_to_ripen_is_the_fruit_ripening() -> None:
    recipe = generate(
        "Tunnel 1 San Marzano, tunnel 2 beef tomatoes, tunnel 3 Roma - all fruiting and "
        "starting to ripen."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["San Marzano", "Beefsteak", "Roma"]
    assert {f.stage for f in recipe.fields} == {"Maturation"}
    assert generate("a tomato field, all fruiting and ripening").recipe.fields[0].stage == (
        "Maturation"
    )


def test_flowering_and_ripe_is_still_two_stages() -> None:
    with pytest.raises(PromptError, match="both Maturation and Reproductive"):
        generate("a tomato field, flowering and ripe")


@pytest.mark.parametrize(
    "placed", ["next door is only young plants so far", "beside it is young plants"]
)
def test_what_a_field_placed_by_the_one_before_is_said_to_be_is_its_own(placed: str) -> None:
    cherry, strawberry = generate(
        f"The cherry orchard is white with blossom, and the strawberry field {placed}."
    ).recipe.fields
    assert (cherry.crop, cherry.stage) == ("Cherry", "Reproductive")
    assert (strawberry.crop, strawberry.stage) == ("Strawberry", "Vegetative")


def test_a_block_of_a_variety_names_its_crop() -> None:
    apple, pear = generate(
        "Pink Lady block planted at 3,000 trees/ha on 3.5 m rows, and next to it a block of "
        "Conference with rows 3.5 m apart and a tree every metre."
    ).recipe.fields
    assert (apple.crop, apple.variety) == ("Apple", "Pink Lady")
    assert (pear.crop, pear.variety) == ("Pear", "Conference")
    assert pear.agronomy.row_spacing_m == pytest.approx(3.5)
    assert pear.agronomy.in_row_spacing_m == pytest.approx(1.0)


@pytest.mark.parametrize(
    "prompt",
    [
        "Plot A is Kordia cherries, 40 by 60 m. Plot B, directly south of A, is Regina, "
        "40 by 80 m.",
        "Kordia cherries, 40 by 60 m. Regina, directly south of the Kordia cherries, 40 by 80 m.",
    ],
)
def test_a_field_placed_between_commas_keeps_its_own_size(prompt: str) -> None:
    recipe = generate(prompt).recipe
    kordia, regina = recipe.fields
    assert (kordia.variety, kordia.geometry.size_m) == ("Kordia", (40.0, 60.0))
    assert (regina.variety, regina.geometry.size_m) == ("Regina", (40.0, 80.0))
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        ("south_of", regina.id, (kordia.id,))
    ]


@pytest.mark.parametrize(
    "prompt",
    [
        "Facing north from the farmyard: the near wheat field is straw-coloured with drooping "
        "heads, ready to combine, and the one beyond it, further north, is still green.",
        "a ripe wheat field, and beyond it another one, still green",
    ],
)
def test_the_one_beyond_it_is_another_field_of_the_crop(prompt: str) -> None:
    near, far = generate(prompt).recipe.fields
    assert near.crop == far.crop == "Wheat"
    assert near.stage == "Maturation"
    assert far.stage != "Maturation"


def test_the_one_beyond_it_after_two_crops_is_no_new_field() -> None:
    assert len(generate("wheat and maize, and the one beyond it is green").recipe.fields) == 2


def test_a_crop_said_to_be_its_ripe_colour_is_ripe() -> None:
    recipe = generate(
        "In the photo two tomato fields lie either side of a wheat field, the tomatoes full "
        "of red fruit ready to pick and the wheat golden. Pickers' bus parked on the verge."
    ).recipe
    assert [(f.crop, f.stage) for f in recipe.fields] == [
        ("Tomato", "Maturation"),
        ("Tomato", "Maturation"),
        ("Wheat", "Maturation"),
    ]
    # a variety's own colour is its name, not a look
    apples = generate("the apples golden in spring").recipe.fields[0]
    assert (apples.variety, apples.stage) == ("Golden Delicious", "Reproductive")


def _between(recipe: SceneRecipe) -> list[tuple[str, set[str]]]:
    return [(r.subject, set(r.objects)) for r in recipe.relations if r.kind == "between"]


@pytest.mark.parametrize(
    ("prompt", "middle", "sides"),
    [
        (
            "From the top of the dyke you can see three plots side by side: Iceberg lettuce, "
            "then Savoy cabbage, then Nantes carrots.",
            "Cabbage",
            {"Lettuce", "Carrot"},
        ),
        (
            "Our three potato varieties in one shot: Bintje closest to the camera, Russet in "
            "the middle and Agria at the back, all in full flower.",
            "Russet Burbank",
            {"Bintje", "Agria"},
        ),
        (
            "Taken from the trailer: Beefsteak tomatoes staked in the first plot, Padron "
            "peppers next along, and California Wonder on the far side of the Padron.",
            "Padron",
            {"Beefsteak", "California Wonder"},
        ),
    ],
)
def test_the_middle_of_three(prompt: str, middle: str, sides: set[str]) -> None:
    recipe = generate(prompt).recipe
    name = {
        f.id: (f.variety if f.crop in ("Potato", "Pepper", "Tomato") else f.crop)
        for f in recipe.fields
    }
    assert [(name[s], {name[o] for o in objects}) for s, objects in _between(recipe)] == [
        (middle, sides)
    ]


def test_a_middle_said_wins_over_the_order_named() -> None:
    recipe = generate(
        "potatoes, carrots & onions, 3 strips nxt to each other, onions in the middle"
    ).recipe
    onion = next(f.id for f in recipe.fields if f.crop == "Onion")
    assert [s for s, _ in _between(recipe)] == [onion]


def test_each_plot_after_a_relation_is_every_plot() -> None:
    recipe = generate(
        "For the drone altimetry test put a potato plot between a wheat plot and a maize "
        "plot. Each plot 30 m wide, 100 m long, rows north-south in all three."
    ).recipe
    assert [f.geometry.size_m for f in recipe.fields] == [(30.0, 100.0)] * 3


def test_the_untreated_one_and_the_sprayed_one_are_the_two_plots() -> None:
    untreated, sprayed = generate(
        "Two identical potato plots for the disease-detection drone, 40 rows each at 90 cm: "
        "the untreated one full of late blight, the sprayed one clean."
    ).recipe.fields
    assert (untreated.health, sprayed.health) == ("Ill", "Healthy")
    assert untreated.row_count == sprayed.row_count == 40
    assert untreated.agronomy.row_spacing_m == sprayed.agronomy.row_spacing_m == pytest.approx(0.9)


def test_members_placed_by_a_side_of_the_farm_go_on_listing() -> None:
    recipe = generate(
        "We've got six fields: three of wheat on the north side of the farm and three of "
        "maize on the south side."
    ).recipe
    assert [f.crop for f in recipe.fields] == ["Wheat"] * 3 + ["Maize"] * 3


def test_a_field_in_a_zone_of_its_own_is_no_list_with_the_one_before() -> None:
    corn, tomatoes, strawberries = generate(
        "sweetcorn at the back, a patch of tomatoes in the middle - black blotchy stems and "
        "leaves - and strawberries at the front."
    ).recipe.fields
    assert (corn.health, tomatoes.health, strawberries.health) == ("Healthy", "Ill", "Healthy")

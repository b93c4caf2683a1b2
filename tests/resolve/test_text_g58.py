"""Text of blind set g58 (issue 8): its misses fixed as general mechanisms (plant parts
listed after a look; "heading" as going somewhere; a crop "in rows across a field"; two
plots and what is on each side; "the same row bearing"; "4 more beds"; "on 3 m
squares"; plots "10 m apart"; "right next to each other"; a weak variety beside another
variety; a walk past a field; a count of buildings before the crops in them; "one
either side of the farmhouse, east and west"; compass labels; a half split in two;
cows in a paddock; "went in only last week"; 80 ha of wheat)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_fruit_listed_after_a_look_of_every_plant_is_no_field() -> None:
    scene = recipe(
        "Aerial picture of the trial: 12 rows of Jalapeños and 12 rows of Cayenne side by side, "
        "all rows running north-south and every plant covered in flowers and small fruits. A "
        "weather station sits in the corner."
    )
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Pepper", "Jalapeno"),
        ("Pepper", "Cayenne"),
    ]
    assert all(f.stage == "Reproductive" for f in scene.fields)


def test_heading_somewhere_is_no_stage_and_rows_across_a_field_are_the_crops() -> None:
    scene = recipe(
        "The photo shows young cabbage transplants, four leaves or so, in rows across a brown "
        "field, and the first lettuces next to them, also just planted. A tractor and planter "
        "are heading away toward the hedge."
    )
    assert [(f.crop, f.stage) for f in scene.fields] == [
        ("Cabbage", "Vegetative"),
        ("Lettuce", "Vegetative"),
    ]
    # (heading as the ears do is still a stage)
    assert recipe("wheat heading in June").fields[0].stage == "Reproductive"


def test_two_plots_and_what_is_on_each_side(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two plantations divided by a wire fence, bananas on one side and oranges on the "
        "other. A boy on a scooter is riding along the fence."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Banana", "Orange"]
    assert crop_relations(prompt) == {("next_to", "Orange", ("Banana",))}


def test_the_same_row_bearing_is_the_field_befores() -> None:
    scene = recipe(
        "Field tomatos, rows 1.5 m apart, 2 plants per metre, 20 rows of 45 m, row bearing "
        "120°, plus a pepper plot with the same row bearing right next to it."
    )
    assert [(f.crop, f.row_bearing_deg) for f in scene.fields] == [
        ("Tomato", pytest.approx(120)),
        ("Pepper", pytest.approx(120)),
    ]


def test_more_beds_of_another_crop_are_beds_not_fields() -> None:
    scene = recipe(
        "Onion sets, 4 beds, 1.8 m c/c, 6 rows per bed, 6 cm in-row; next to them lettuce on "
        "4 more beds of 1.8 m with 4 rows per bed."
    )
    onion, lettuce = scene.fields
    assert (onion.crop, lettuce.crop) == ("Onion", "Lettuce")
    assert (onion.bed_count, lettuce.bed_count) == (4, 4)
    assert (onion.agronomy.rows_per_bed, lettuce.agronomy.rows_per_bed) == (6, 4)
    assert lettuce.agronomy.row_spacing_m == pytest.approx(1.8)


def test_planted_on_squares_is_a_square_grid_not_plots() -> None:
    (banana,) = recipe(
        "Big Mike bananas on 3 m squares, 400 plants, black Sigatoka streaks on the leaves."
    ).fields
    assert (banana.variety, banana.health) == ("Gros Michel", "Ill")
    assert (banana.agronomy.row_spacing_m, banana.agronomy.in_row_spacing_m) == (3.0, 3.0)


def test_plots_some_metres_apart_is_no_row_spacing() -> None:
    beefsteak, cherry = recipe(
        "Beefsteak tomatoes and cherry tomatoes, two plots 10 m apart, 1.8 m and 1.5 m rows "
        "respectively."
    ).fields
    assert (beefsteak.variety, cherry.variety) == ("Beefsteak", "Cherry")
    assert (beefsteak.agronomy.row_spacing_m, cherry.agronomy.row_spacing_m) == (1.8, 1.5)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        ("2 fields of spuds right nxt 2 each other", {("next_to", "Potato", ("Potato",))}),
        (
            "big mike bananas w/ lady finger bananas right beside em",
            {("next_to", "Lady Finger", ("Gros Michel",))},
        ),
        (
            "Navel oranges with Valencia oranges beside them",
            {("next_to", "Valencia", ("Navel",))},
        ),
    ],
)
def test_fields_right_beside_each_other(
    named_relations: Callable[[str], NamedRelations], prompt: str, expected: NamedRelations
) -> None:
    assert named_relations(prompt) == expected


def test_what_a_walk_past_a_field_reaches_lies_beyond_it(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "The orchard is Jonagold and sits just north of the farmhouse; carry on north past it "
        "and you hit our winter wheat."
    )
    assert crop_relations(prompt) == {("north_of", "Wheat", ("Apple",))}


def test_a_count_of_buildings_is_no_count_of_the_crops_in_them() -> None:
    scene = recipe(
        "In our three greenhouses we grow San Marzano, Beefsteak and cherry tomatoes, one "
        "variety per house."
    )
    assert [f.variety for f in scene.fields] == ["San Marzano", "Beefsteak", "Cherry"]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "Two wheat fields, one either side of the farmhouse, east and west.",
            {("east_of", "Wheat", ("Wheat",))},
        ),
        (
            "north: vines. south: fruit trees. in between: potatoes.",
            {
                ("north_of", "Grape", ("Potato",)),
                ("south_of", "Orange", ("Potato",)),
                ("between", "Potato", ("Grape", "Orange")),
                ("north_of", "Grape", ("Orange",)),
            },
        ),
        (
            "The east half of the farm is maize; the west half is split between a potato field "
            "to the north and an onion field to the south.",
            {
                ("north_of", "Potato", ("Onion",)),
                ("west_of", "Potato", ("Maize",)),
                ("west_of", "Onion", ("Maize",)),
            },
        ),
    ],
)
def test_sides_said_as_labels_and_halves(
    crop_relations: Callable[[str], NamedRelations], prompt: str, expected: NamedRelations
) -> None:
    assert crop_relations(prompt) == expected


def test_cows_in_the_back_paddock_are_no_field() -> None:
    with pytest.raises(PromptError, match="names no crop"):
        generate(
            "Where the old barn stood there's now a machine shed and a concrete yard, with a "
            "fence along the road and cows in the back paddock."
        )


def test_plants_that_went_in_last_week_are_young() -> None:
    albion, elsanta = recipe(
        "At the north end the Albion strawberries are ripe; at the south end the Elsanta "
        "plants went in only last week."
    ).fields
    assert (albion.stage, elsanta.stage) == ("Maturation", "Vegetative")


@pytest.mark.parametrize(
    ("prompt", "hectares"),
    [
        ("We farm 120 ha in total: 70 ha wheat, 30 ha maize and 20 ha potatoes.", [70, 30, 20]),
        (
            "The whole farm is one 80 hectare wheat field, with a hawthorn hedge round the "
            "outside and a pylon in the middle.",
            [80],
        ),
    ],
)
def test_a_large_wheat_farm_is_built_thinned(prompt: str, hectares: list[float]) -> None:
    scene = recipe(prompt)
    assert [f.geometry.area_m2 / 10_000 for f in scene.fields] == pytest.approx(hectares, rel=0.01)
    assert scene.fields[0].placement.plants_per_instance > 10

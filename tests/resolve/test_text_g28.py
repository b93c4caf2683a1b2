"""Text of blind set g28, casual and farm (issue 8): "mildewy", "neither has any
disease", a count of a crop's plots in brackets or between commas, "a healthy one next
to it", a closing "the pair of em", "on the north beds", a farm named by its crop before
its one field, "each in a field of its own" and "Left: corn. Middle: spuds. Right: ..."."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_health_words_of_casual_text() -> None:
    (lettuce,) = recipe("cos lettuce bolting in july, kinda mildewy ngl").fields
    assert (lettuce.variety, lettuce.stage, lettuce.health) == ("Romaine", "Reproductive", "Ill")
    cabbages, apples = recipe(
        "golden acre cabbages right beside some golden delicious trees, neither has any disease 🙂"
    ).fields
    assert (cabbages.health, apples.health, "health" in apples.stated) == (
        "Healthy",
        "Healthy",
        True,
    )


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("bing cherries (one block) squeezed between 2 lapins blocks lol", ["Cherry"] * 3),
        ("cherries, two blocks, next to wheat", ["Cherry", "Cherry", "Wheat"]),
        ("cherries (two blocks) next to wheat", ["Cherry", "Cherry", "Wheat"]),
        # (after a list, the count is the list's; beds are one field's beds)
        (
            "can u do lettuce, cabbage and onions, 3 fields, w/ the lettuce in the middle of "
            "the other 2",
            ["Lettuce", "Cabbage", "Onion"],
        ),
        ("Elsanta strawberries, 6 beds, two rows per bed, beds on 1.5 m centres", ["Strawberry"]),
    ],
)
def test_a_count_of_a_crops_plots_said_after_it(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_a_crops_plots_said_after_it_are_placed(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations("bing cherries (one block) squeezed between 2 lapins blocks lol") == {
        ("between", "Bing", ("Lapins", "Lapins"))
    }


@pytest.mark.parametrize(
    ("prompt", "looks"),
    [
        (
            "need a wheat field w/ yellow rust all over it and a healthy one nxt to it, for a "
            "disease dataset",
            [("Wheat", "Ill"), ("Wheat", "Healthy")],
        ),
        ("a ripe wheat field and a young one next to it", [("Wheat", "Healthy")] * 2),
        ("ripe wheat and a young one next to it", [("Wheat", "Healthy")] * 2),
        (
            "a wheat field and a pear orchard, and a small one beside it",
            [("Wheat", "Healthy"), ("Pear", "Healthy"), ("Pear", "Healthy")],
        ),
    ],
)
def test_one_more_field_of_the_crop_just_named(prompt: str, looks: list[tuple[str, str]]) -> None:
    fields = recipe(prompt).fields
    assert [(f.crop, f.health) for f in fields] == looks
    assert any(r.subject == fields[-1].id for r in recipe(prompt).relations)


def test_a_closing_the_pair_of_them() -> None:
    fields = recipe(
        "a field of sweet corn 🌽 nxt 2 a field of cherry tomatoes, ripe, aug, the pair of em"
    ).fields
    assert [(f.variety, f.stage, f.season) for f in fields] == [
        ("Sweet Corn", "Maturation", "Summer"),
        ("Cherry", "Maturation", "Summer"),
    ]


def test_members_on_the_north_and_south_beds(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Salad farm. Cos on the north beds, crisphead on the south beds, everything harvest-ready."
    )
    assert [(f.variety, f.stage) for f in recipe(prompt).fields] == [
        ("Romaine", "Maturation"),
        ("Iceberg", "Maturation"),
    ]
    assert named_relations(prompt) == {("north_of", "Romaine", ("Iceberg",))}


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        (
            "Just a spud farm, honestly. One big field of spuds, a muddy track round it and "
            "the old barn sitting in the corner.",
            "Potato",
        ),
        (
            "A lettuce farm, just one huge field of lettuces, the young plants only just set out.",
            "Lettuce",
        ),
    ],
)
def test_a_farm_named_by_its_crop_before_its_one_field(prompt: str, crop: str) -> None:
    assert [f.crop for f in recipe(prompt).fields] == [crop]


def test_each_in_a_field_of_its_own() -> None:
    fields = recipe(
        "We grow three different vegetables plus one cereal, each in a field of its own."
    ).fields
    assert [f.category for f in fields] == ["Vegetables"] * 3 + ["Cereals"]
    assert len({f.crop for f in fields}) == 4


def test_left_middle_and_right_as_labels(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations("Left: corn. Middle: spuds. Right: cabbages. That's the farm.")
    assert ("west_of", "Maize", ("Potato",)) in relations
    assert ("west_of", "Potato", ("Cabbage",)) in relations


def test_near_a_place_and_further_past_a_landmark(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Our block near Mildura in Australia has Chardonnay vines north of the house and "
        "Valencia oranges further south, past the house. It's December and the vines are "
        "flowering."
    )
    assert [(f.crop, f.season) for f in recipe(prompt).fields] == [
        ("Grape", "Summer"),
        ("Orange", "Summer"),
    ]
    assert named_relations(prompt) == {("north_of", "Chardonnay", ("Valencia",))}
    # (near a field, not a place: still beside it)
    assert named_relations("a vineyard near the wheat") == {("next_to", "Grape", ("Wheat",))}

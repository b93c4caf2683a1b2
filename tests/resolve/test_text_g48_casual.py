"""Text of blind set g48's casual genre (issue 8): each miss of its blind run fixed as
the general mechanism (a field said under another on a map of the farm; "smthn w/" a
crop; a list said again as its fields after "so", "that is", "i.e.")."""

from __future__ import annotations

import pytest

from agrirecipe import SceneRecipe, generate


def _crops(recipe: SceneRecipe) -> list[str | None]:
    return [f.crop for f in recipe.fields]


def _relations(recipe: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in recipe.relations}


@pytest.mark.parametrize(
    "prompt",
    [
        "cabage up top (north) & letuce under it",
        "cabbage at the top, lettuce beneath it",
        "cabbage in the north and lettuce underneath that one",
    ],
)
def test_a_field_under_another_on_a_map_lies_south_of_it(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert _crops(recipe) == ["Cabbage", "Lettuce"]
    assert ("south_of", "lettuce_field_1", ("cabbage_field_1",)) in _relations(recipe) or (
        "north_of",
        "cabbage_field_1",
        ("lettuce_field_1",),
    ) in _relations(recipe)


def test_under_them_with_no_map_places_nothing() -> None:
    # sheep grazing under the trees: no field, no relation
    recipe = generate("a Gala apple orchard with a few sheep grazing under them").recipe
    assert _crops(recipe) == ["Apple"]
    assert not recipe.relations


@pytest.mark.parametrize("something", ["smthn", "something", "sumthin"])
def test_something_with_a_crop_is_a_field_of_it(something: str) -> None:
    recipe = generate(f"{something} w/ cereals & {something} w/ fruit idk, 2 fields").recipe
    assert len(recipe.fields) == 2
    assert recipe.fields[0].crop in ("Wheat", "Maize")
    assert recipe.fields[1].crop not in ("Wheat", "Maize")


def test_something_with_the_light_is_no_field() -> None:
    assert _crops(generate("a wheat field and something with the light").recipe) == ["Wheat"]


@pytest.mark.parametrize(
    "prompt",
    [
        "lol my gran wants 'some veg and a few fruit trees' so like 1 veg field & 1 orchard "
        "i guess",
        "some veg and a few fruit trees, that is one veg field and one orchard",
    ],
)
def test_a_list_said_again_as_its_fields_is_one_list(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert len(recipe.fields) == 2
    assert recipe.fields[1].crop in ("Apple", "Pear", "Cherry", "Orange")


def test_a_list_said_again_after_ie_keeps_its_varieties() -> None:
    recipe = generate(
        "roma tomatoes and bintje potatoes, i.e. one tomato field and one potato field"
    ).recipe
    assert [(f.crop, f.variety) for f in recipe.fields] == [
        ("Tomato", "Roma"),
        ("Potato", "Bintje"),
    ]


def test_a_list_followed_by_other_crops_is_not_said_again() -> None:
    recipe = generate("wheat and maize, so one potato field and one maize field").recipe
    assert len(recipe.fields) == 4


def test_or_so_says_nothing_again() -> None:
    recipe = generate(
        "Pinot Noir rows about 2.5 m apart with a vine every 1.6 m or so, and right beside "
        "it is a small Chardonnay block."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Pinot Noir", "Chardonnay"]

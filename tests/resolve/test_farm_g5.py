"""Farm, casual and photo text of blind set g5 (issue 8): thirds and paddocks as zones,
"top to bottom" lists, a view "looking east", scenery zones, demonyms, lower-case
"n" for "and", month abbreviations, and new visual cues."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in scene.relations}


def test_thirds_of_a_farm_are_zones() -> None:
    scene = recipe(
        "The farm's split by hedges into three: the west third is spuds, the middle third "
        "corn, and the east third strawberries."
    )
    west, middle, east = (f.id for f in scene.fields)
    assert {("west_of", west, (middle,)), ("west_of", middle, (east,))} <= relations(scene)


def test_compass_paddocks_are_placed() -> None:
    scene = recipe(
        "north paddock: Lapins cherrys, 1 ha. south paddock: Albion strawbery beds, half a hectare"
    )
    cherry, strawberry = (f.id for f in scene.fields)
    assert ("north_of", cherry, (strawberry,)) in relations(scene)


def test_top_to_bottom_lists_from_north_to_south() -> None:
    scene = recipe("Top to bottom the farm goes: vineyard, then grain, then greens.")
    vines, grain, greens = (f.id for f in scene.fields)
    assert {("north_of", vines, (grain,)), ("north_of", grain, (greens,))} <= relations(scene)


def test_looking_east_lists_from_the_viewer() -> None:
    scene = recipe(
        "Looking east from the barn roof: potatoes closest to me, then the wheat, then the "
        "maize right up against the woods."
    )
    potatoes, wheat, maize = (f.id for f in scene.fields)
    assert {("west_of", potatoes, (wheat,)), ("west_of", wheat, (maize,))} <= relations(scene)


def test_looking_north_leaves_placing_to_the_zones() -> None:
    scene = recipe(
        "Looking north from the yard: wheat at the far north end, potatoes in the middle, and "
        "strawberries closest to me at the south end."
    )
    wheat, potatoes, strawberries = (f.id for f in scene.fields)
    assert ("north_of", wheat, (potatoes,)) in relations(scene)
    assert ("north_of", potatoes, (strawberries,)) in relations(scene)


def test_a_zone_of_scenery_is_not_a_fields_zone() -> None:
    scene = recipe(
        "left side of the farm is leafy greens, rigth side is grain, and theres a duck pond "
        "in the middle"
    )
    greens, grain = (f.id for f in scene.fields)
    assert relations(scene) == {("west_of", greens, (grain,))}


@pytest.mark.parametrize(
    "prompt",
    [
        "can u make pinot nero on the left n chardonnay on the right, spring",
        "pinot nero on the left 'n' chardonnay on the right",
    ],
)
def test_lower_case_n_is_and(prompt: str) -> None:
    scene = recipe(prompt)
    assert [f.variety for f in scene.fields] == ["Pinot Noir", "Chardonnay"]
    assert ("west_of", scene.fields[0].id, (scene.fields[1].id,)) in relations(scene)


def test_capital_n_is_still_north() -> None:
    assert recipe("wheat, rows N-S").fields[0].row_bearing_deg == 0


def test_month_abbreviation_and_demonym() -> None:
    assert recipe("navel oranges, ripe, its dec so like xmas vibes").fields[0].season == "Winter"
    chile = generate(
        "On the Chilean farm the Bing cherries are ripe in December", resolver="hybrid"
    )
    assert chile.recipe.fields[0].season == "Summer"


def test_hay_shed_is_scenery() -> None:
    (field,) = recipe("Past the cattle grid and the hay shed there's our strawberry patch").fields
    assert field.crop == "Strawberry"


@pytest.mark.parametrize(
    ("prompt", "attribute", "value"),
    [
        ("a 3 hectare wheat field with the ears just coming out", "stage", "Reproductive"),
        ("Banana plants, each with a big purple flower bud hanging", "stage", "Reproductive"),
        ("a vineyard, first leaves just unfolding", "stage", "Vegetative"),
        ("Pear trees with blackened blossom clusters and a shepherd's crook", "health", "Ill"),
    ],
)
def test_new_visual_cues(prompt: str, attribute: str, value: str) -> None:
    assert getattr(recipe(prompt).fields[0], attribute) == value

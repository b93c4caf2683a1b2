"""Placement said the way people say it (issue 8): a count of plots after a comma that
sums up the crops named, "one above the other", fields named between two opposite
zones, and a direction that places scenery rather than a field."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, tuple(r.objects)) for r in scene.relations}


@pytest.mark.parametrize(
    ("prompt", "varieties"),
    [
        (
            "dwarf cavendish & lady finger bananas, 2 plots, one above the other",
            ["Cavendish", "Lady Finger"],
        ),
        ("Gala and Fuji apples, two blocks, each 1 ha", ["Gala", "Fuji"]),
    ],
)
def test_a_count_of_plots_after_the_crops_sums_them_up(prompt: str, varieties: list[str]) -> None:
    scene = recipe(prompt)
    assert [f.variety for f in scene.fields] == varieties


def test_a_count_that_does_not_sum_up_the_crops_still_asks_for_fields() -> None:
    scene = recipe("wheat and maize, 3 plots")
    assert len(scene.fields) == 5
    assert [f.crop for f in scene.fields[:2]] == ["Wheat", "Maize"]


@pytest.mark.parametrize(
    ("prompt", "kind"),
    [
        ("lady finger and cavendish bananas, 2 plots, one above the other", "north_of"),
        ("a maize field and a carrot field, one next to the other", "next_to"),
        ("Nantes carrots and Red Baron onions, one west of the other", "west_of"),
    ],
)
def test_one_beside_the_other_relates_the_two_named_in_order(prompt: str, kind: str) -> None:
    scene = recipe(prompt)
    first, second = (f.id for f in scene.fields)
    assert relations(scene) == {(kind, first, (second,))}


def test_fields_named_between_two_opposite_zones_are_in_the_middle() -> None:
    scene = recipe(
        "Aerial shot from the church tower: the orchard at the north end, then wheat, then "
        "strawberries at the south end, with the village road running along the east side."
    )
    orchard, wheat, strawberries = (f.id for f in scene.fields)
    found = relations(scene)
    assert ("north_of", orchard, (wheat,)) in found
    assert ("north_of", wheat, (strawberries,)) in found
    # the road is placed on the east side, not the strawberries beside the wheat
    assert not any(kind in ("east_of", "west_of", "next_to") for kind, _, _ in found)


def test_a_field_after_the_last_zone_is_not_put_in_the_middle() -> None:
    scene = recipe("maize at the top, potatoes in the middle, carrots at the bottom, then onions")
    maize, potatoes, carrots, onions = (f.id for f in scene.fields)
    found = relations(scene)
    assert {("north_of", maize, (potatoes,)), ("north_of", potatoes, (carrots,))} <= found
    assert not any(
        onions in (subject, *objects) for kind, subject, objects in found if kind == "north_of"
    )


@pytest.mark.parametrize(
    "prompt",
    [
        "Wide shot from the top of the water tower: potatoes closest to the camera, then a band "
        "of cabbages, then maize furthest back, each block separated by a grassy track.",
        "Looking down from the pergola: Riesling on the terrace nearest us, Cabernet in the "
        "middle and Pinot Noir furthest out.",
        "Panorama from the silo: Walla Walla onions in the west field, Imperator carrots in the "
        "middle one and Danvers carrots in the east field.",
    ],
)
def test_the_field_named_between_the_near_and_the_far_one_is_between_them(prompt: str) -> None:
    scene = recipe(prompt)
    first, middle, last = (f.id for f in scene.fields)
    assert ("between", middle, (first, last)) in relations(scene)
    # a photo's depth is no compass side
    assert not any(
        kind == "north_of" and middle in (subject, *objects)
        for kind, subject, objects in relations(scene)
        if "west field" not in prompt
    )


def test_a_photo_looking_east_keeps_its_compass_order() -> None:
    scene = recipe(
        "Looking east from the barn roof: potatoes closest to me, then the wheat, then the "
        "maize right up against the woods at the far east end."
    )
    potatoes, wheat, maize = (f.id for f in scene.fields)
    assert {("west_of", potatoes, (wheat,)), ("west_of", wheat, (maize,))} <= relations(scene)


def test_one_field_is_not_two_sides_of_another() -> None:
    scene = recipe("Gala in between Gala , Gala")
    assert not any(kind == "between" for kind, _, _ in relations(scene))


def relation_crops(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    name = {f.id: f.variety for f in scene.fields}
    return {(r.kind, name[r.subject], tuple(name[o] for o in r.objects)) for r in scene.relations}


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "north 2 south: wheat then maize then spuds",
            {("north_of", "Winter Wheat", ("Dent",)), ("north_of", "Dent", ("Bintje",))},
        ),
        (
            "Nantes carrots hug the north boundary, the Sturon onions take the south end, and "
            "there's Cos lettuce in between.",
            {("between", "Romaine", ("Nantes", "Sturon"))},
        ),
        (
            "Padrón peppers on the west side, Cayenne on the east side, and a sweetcorn patch "
            "south of both.",
            {("south_of", "Sweet Corn", ("Padron",)), ("south_of", "Sweet Corn", ("Cayenne",))},
        ),
        (
            "tomatos then peppers then lettuce, each one beside the last",
            {("next_to", "Roma", ("California Wonder",))},
        ),
        (
            "The Jonagold orchard is just north of the farmhouse, and directly south of the "
            "orchard, across the lane, there's a 3 hectare block of Bintje potatoes.",
            {("south_of", "Bintje", ("Jonagold",))},
        ),
    ],
)
def test_farm_placements_said_in_everyday_words(
    prompt: str, expected: set[tuple[str, str, tuple[str, ...]]]
) -> None:
    found = relation_crops(recipe(prompt))
    # "next to" reads both ways
    found |= {(k, o[0], (s,)) for k, s, o in found if k == "next_to"}
    assert expected <= found


def test_a_crop_in_the_north_orchard_is_placed_not_doubled() -> None:
    scene = recipe(
        "Durondeau pears in the north orchard, and below them to the south a field of "
        "Centenary strawberries, with beehives along the boundary."
    )
    assert [f.variety for f in scene.fields] == ["Durondeau", "Malling Centenary"]
    assert ("north_of", "Durondeau", ("Malling Centenary",)) in relation_crops(scene)

"""Development-set misses left from earlier blind sets (issue 8): fields said to adjoin
("a vine block adjoining an apple block"), a fronted placement whose object is described
before the new field ("Beside the Gala block, where the apples are colouring up, there's
..."), "on the south side of a ..." after the field it places, a plot "behind" a field
named before, the vines of a farm whose other fields cannot hold them, a field along a
compass edge as a zone, "further north again, past the lane, ..." from the field before,
"around the farmhouse: wheat to the north of it, maize to the south, ..." as zones, "2,000
m² in total, plus a 1,000 m² cabbage block" (the first field's own total), and the end of
a "with" list ("with late blight, blackened leaves and collapsed plants") as its field's,
"the one 12 hectare block and it's all wheat", a comparison heading whose fields are
named after its colon, members placed "one east of the other" then told apart by their
sides, a disease named of a lush field."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "A vine block (25 rows, 2.2 m apart, vines every metre) adjoining an apple block "
            "(20 rows, 3.2 m apart, trees every 0.9 m).",
            {("next_to", "Grape", ("Apple",))},
        ),
        (
            "A pear plot of 5 rows x 20 trees, and adjoining it a cherry plot with 5 rows.",
            {("next_to", "Cherry", ("Pear",))},
        ),
    ],
)
def test_a_field_adjoining_another(
    named_relations: Callable[[str], NamedRelations], prompt: str, expected: NamedRelations
) -> None:
    assert named_relations(prompt) == expected


def test_a_fronted_placement_past_a_description_of_its_object(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Beside the Gala block, where the apples are colouring up, there's a block of Lapins "
        "cherries with mottled, curling leaves."
    )
    gala, lapins = recipe(prompt).fields
    assert (gala.variety, gala.stage, lapins.variety, lapins.health) == (
        "Gala",
        "Maturation",
        "Lapins",
        "Ill",
    )
    assert named_relations(prompt) == {("next_to", "Lapins", ("Gala",))}


def test_on_the_south_side_of_a_field_after_the_field_it_places(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Golden Acre cabbage, 70 cm rows, on the south side of a Golden Delicious apple block "
        "with 3.5 m rows."
    )
    assert named_relations(prompt) == {("south_of", "Golden Acre", ("Golden Delicious",))}
    # (the side of a building is no relation)
    assert named_relations("On the north side of a farmhouse, a cabbage plot.") == set()


def test_a_plot_behind_a_field_named_before(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "we've got conferance pears by the road, and over the other side of the road Granny "
        "smiths, plus a patch of Sturon onoins behind the pears"
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Conference", "Granny Smith", "Sturon"]
    assert named_relations(prompt) == {("next_to", "Sturon", ("Conference",))}
    # (scenery behind a field is still scenery)
    assert named_relations("Conference pears with a barn behind the pears, and wheat") == set()


def test_vines_placed_on_a_farm_whose_fields_cannot_hold_them() -> None:
    scene = recipe("orchard north of the veg garden, and the vines south of the veg garden")
    orchard, garden, vines = scene.fields
    assert orchard.crop in ("Apple", "Pear", "Cherry", "Orange")
    assert (garden.category, vines.crop) == ("Vegetables", "Grape")
    placed = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert ("north_of", orchard.id, (garden.id,)) in placed
    assert ("south_of", vines.id, (garden.id,)) in placed
    # (the vines of the Riesling named before are still its vines)
    (riesling,) = recipe("Riesling north of the barn, and the vines south of the house").fields
    assert riesling.variety == "Riesling"


def test_a_field_along_a_compass_edge_is_a_zone(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "From the drone you can see three fields: wheat at the north end, potatoes in the "
        "middle and maize along the southern edge by the road."
    )
    relations = named_relations(prompt)
    assert ("north_of", "Wheat", ("Potato",)) in relations
    assert ("north_of", "Potato", ("Maize",)) in relations


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "The orchard north of the farmhouse is all Conference pears; further north again, "
            "past the lane, there's a block of winter wheat.",
            {("north_of", "Winter Wheat", ("Conference",))},
        ),
        (
            "Conference pears. Further south, past the old farm track, a block of winter wheat.",
            {("south_of", "Winter Wheat", ("Conference",))},
        ),
    ],
)
def test_further_on_past_scenery_is_further_than_the_field_before(
    named_relations: Callable[[str], NamedRelations], prompt: str, expected: NamedRelations
) -> None:
    assert named_relations(prompt) == expected


@pytest.mark.parametrize(
    "prompt",
    [
        "Four fields around the farmhouse: wheat to the north of it, maize to the south, "
        "potatoes to the east and cabbages to the west.",
        "Four fields around the farmhouse: wheat to the north, maize to the south, potatoes "
        "to the east and cabbages to the west.",
    ],
)
def test_fields_on_each_side_of_a_centre_are_zones(
    named_relations: Callable[[str], NamedRelations], prompt: str
) -> None:
    assert named_relations(prompt) == {
        ("north_of", "Wheat", ("Maize",)),
        ("west_of", "Cabbage", ("Potato",)),
    }


def test_a_fields_own_total_before_another_field_added() -> None:
    lettuce, cabbage = recipe(
        "A lettuce block for a harvest robot: 8 plants per m², 35 cm rows, 2,000 m² in total, "
        "plus a 1,000 m² cabbage block east of it at 4 plants per m²."
    ).fields
    assert lettuce.geometry.size_m[0] * lettuce.geometry.size_m[1] == pytest.approx(2000, rel=0.01)
    assert cabbage.geometry.size_m[0] * cabbage.geometry.size_m[1] == pytest.approx(1000, rel=0.01)


@pytest.mark.parametrize(
    "prompt",
    [
        "Russet on the left in full flower, Fontane on the right with late blight, blackened "
        "leaves and collapsed plants. Overcast, the sprayer sitting in a tramline.",
        "Russet in full flower, Fontane with late blight, blackened leaves and collapsed plants.",
    ],
)
def test_the_end_of_a_with_list_is_its_fields(prompt: str) -> None:
    russet, fontane = recipe(prompt).fields
    assert (russet.variety, russet.health) == ("Russet Burbank", "Healthy")
    assert (fontane.variety, fontane.health) == ("Fontane", "Ill")


@pytest.mark.parametrize("said", ["it's all wheat", "it's wheat"])
def test_it_is_all_the_crop_of_the_one_block(said: str) -> None:
    (field,) = recipe(f"We only farm the one 12 hectare block and {said}.").fields
    assert field.crop == "Wheat"
    assert field.geometry.size_m[0] * field.geometry.size_m[1] == pytest.approx(120000, rel=0.01)


def test_a_comparison_heading_whose_fields_are_named_after_the_colon() -> None:
    fields = recipe(
        "Cherry vs cherry-tomato confusion test for the classifier: a Lapins cherry block with "
        "rows 5 m apart and trees 3 m apart, and beside it 4 rows of cherry tomatoes at 1.5 m."
    ).fields
    assert [(f.crop, f.variety) for f in fields] == [("Cherry", "Lapins"), ("Tomato", "Cherry")]


def test_members_placed_one_against_the_other_then_told_apart_by_their_sides() -> None:
    north, south = recipe(
        "Two potato fields, one north of the other; the north one has blight, the south one "
        "is clean."
    ).fields
    assert (north.health, south.health) == ("Ill", "Healthy")
    assert [
        (r.kind, r.subject, r.objects)
        for r in recipe(
            "Two cherry orchards, one east of the other; the eastern one is white with blossom, "
            "the western one not yet."
        ).relations
    ][:1] == [("east_of", "cherry_orchard_1", ("cherry_orchard_2",))]


def test_a_disease_named_of_a_lush_field_makes_it_ill() -> None:
    (wheat,) = recipe(
        "Winter wheat, photo taken in late April. Lush and dark green, shin high, with a bit of "
        "yellow rust striping on the lower leaves. Skylarks overhead."
    ).fields
    assert wheat.health == "Ill"


def test_a_field_said_healthy_and_diseased_is_still_refused() -> None:
    with pytest.raises(PromptError, match="both healthy and ill"):
        recipe("a healthy wheat field with yellow rust")

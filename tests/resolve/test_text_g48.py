"""Text of blind set g48 (issue 8): each miss of its blind run fixed as the general
mechanism (a farm said to hold only scenery; bare patches and cabbage palms; southern
cities; the near ridges; exceptions said "apart from"; a side opening a clause after a
semicolon; "is all fruit trees"; a verb that agrees with the subject, not the field it is
placed against; vines after fields whose plants are never vines; "both of them")."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, SceneRecipe, generate


def _crops(recipe: SceneRecipe) -> list[str | None]:
    return [f.crop for f in recipe.fields]


def _relations(recipe: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in recipe.relations}


def test_a_farm_said_to_hold_only_scenery_is_refused() -> None:
    with pytest.raises(PromptError, match="only scenery"):
        generate(
            "Describe our farm for the drone survey: farmhouse, two sheds, gravel lanes, a "
            "pond with geese and a hedge down the middle."
        )


def test_a_farm_said_alone_still_stands_for_a_few_fields() -> None:
    assert len(generate("a mixed farm in spring").recipe.fields) >= 2


@pytest.mark.parametrize(
    "prompt",
    [
        "Winter wheat in mid-April, tillering away and dark green, tramlines showing up "
        "clearly from the footpath and lapwings on the bare patch by the pond.",
        "Winter wheat in April, a muddy patch by the gate.",
    ],
)
def test_a_bare_patch_is_no_field(prompt: str) -> None:
    assert _crops(generate(prompt).recipe) == ["Wheat"]


def test_cabbage_palms_are_trees_of_the_scenery() -> None:
    recipe = generate(
        "From the Florida grove in December: Hamlin trees on the east side loaded with ripe "
        "fruit, Valencia Late on the west side with the fruit still hard and green. Sandy "
        "track, cabbage palms and a water tower."
    ).recipe
    assert _crops(recipe) == ["Orange", "Orange"]


def test_a_southern_city_sets_the_hemisphere() -> None:
    recipe = generate(
        "Ladyfinger bananas in our backyard in Brisbane this January, one bunch of small "
        "fruit going yellow and ready to cut."
    ).recipe
    assert recipe.environment.hemisphere == "south"
    assert recipe.fields[0].season == "Summer"


def test_the_near_ridges_and_the_furthest_away() -> None:
    recipe = generate(
        "From the bridge you can see three strips: carrots on the near ridges, onions in the "
        "middle and cabbages furthest away, all looking healthy."
    ).recipe
    carrots, onions, cabbages = (f.id for f in recipe.fields)
    assert ("between", onions, (carrots, cabbages)) in _relations(recipe)


@pytest.mark.parametrize("word", ["apart from", "except", "except for"])
def test_an_exception_is_said_of_its_own_field(word: str) -> None:
    recipe = generate(
        "Plot 1: Bintje potatoes, flowering. Plot 2: Nantes carrots, just emerged. It's mid "
        f"June and everything is clean {word} a bit of blight on the potatoes."
    ).recipe
    assert [(f.crop, f.health) for f in recipe.fields] == [
        ("Potato", "Ill"),
        ("Carrot", "Healthy"),
    ]


def test_a_side_opening_a_clause_after_a_semicolon_places_the_field_after_it() -> None:
    recipe = generate(
        "Two strawberry blocks either side of the farm track. On the east, Albion on 12 "
        "raised beds, two rows per bed, beds on 1.5 m centres; on the west, Elsanta in the "
        "same layout but only 8 beds."
    ).recipe
    albion, elsanta = recipe.fields
    assert ("east_of", albion.id, (elsanta.id,)) in _relations(recipe)
    assert (albion.row_count, elsanta.row_count) == (24, 16)


def test_a_place_that_is_all_fruit_trees() -> None:
    recipe = generate(
        "Bottom of the farm, near the river, is maize. The middle is root veg and the top is "
        "all fruit trees."
    ).recipe
    assert [f.category for f in recipe.fields] == ["Cereals", "Vegetables", "Fruits"]


def test_a_verb_agrees_with_its_subject_not_the_field_it_is_placed_against() -> None:
    recipe = generate(
        "A vineyard, a wheat field, and the tomatoes next to the vineyard have late blight."
    ).recipe
    health = {f.crop: f.health for f in recipe.fields}
    assert health == {"Grape": "Healthy", "Wheat": "Healthy", "Tomato": "Ill"}


def test_vines_after_fields_whose_plants_are_never_vines_are_a_vineyard() -> None:
    recipe = generate("the pear orchard has fire blight, the vines have downy mildew").recipe
    assert [(f.crop, f.health) for f in recipe.fields] == [("Pear", "Ill"), ("Grape", "Ill")]


def test_the_vines_of_tomatoes_stay_their_plants() -> None:
    assert _crops(generate("tomatoes, the vines are wilting").recipe) == ["Tomato"]


def test_both_of_them_after_a_relation() -> None:
    recipe = generate(
        "Kordia and Regina cherries in two blocks side by side, with the Riesling vines "
        "below both of them to the south."
    ).recipe
    kordia, regina, riesling = (f.id for f in recipe.fields)
    assert {("south_of", riesling, (kordia,)), ("south_of", riesling, (regina,))} <= _relations(
        recipe
    )


def test_a_crop_said_again_after_a_heading_is_its_counted_members() -> None:
    recipe = generate(
        "Cereal strips for a yield-monitor simulation: a maize strip between two wheat "
        "strips, each strip 30 m wide and 300 m long. Maize in 75 cm rows running "
        "north-south, wheat drilled at 15 cm."
    ).recipe
    assert _crops(recipe) == ["Maize", "Wheat", "Wheat"]
    assert [f.agronomy.row_spacing_m for f in recipe.fields[1:]] == [0.15, 0.15]


def test_inches_said_as_in_before_a_plant_spacing() -> None:
    field = generate(
        "synthetic scene of spuds for a row-following camera: 48 rows on 36-inch centers, "
        "12 in seed piece spacing, 1000 ft rows running E-W"
    ).recipe.fields[0]
    assert field.agronomy.in_row_spacing_m == pytest.approx(0.3048)

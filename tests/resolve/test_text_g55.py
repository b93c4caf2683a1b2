"""Text of blind set g55 (issue 8): its misses fixed as general mechanisms (a colour said
with a crop's name; a variety misspelt as an everyday word before its crop; a farm where
nothing is planted; "behind"; "all hanging with ripe fruit"; ...)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import AgrirecipeError, generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def test_a_crop_name_said_as_the_colour_of_marks_is_no_crop() -> None:
    recipe = generate(
        "Gala on the north side of the windbreak and Golden Delicious on the south side, and "
        "the Golden Delicious have scab all over, olive spots on the leaves and corky brown "
        "marks on the fruit. September, dull light."
    ).recipe
    assert [(f.variety, f.health) for f in recipe.fields] == [
        ("Gala", "Healthy"),
        ("Golden Delicious", "Ill"),
    ]
    with pytest.raises(AgrirecipeError, match="olive"):
        generate("an olive grove")


def test_a_variety_misspelt_as_an_everyday_word_before_its_crop() -> None:
    recipe = generate("fontaine potatoes north of sturon onions, 1ha each, june").recipe
    assert [f.variety for f in recipe.fields] == ["Fontane", "Sturon"]


def test_onions_lifted_and_drying_are_mature() -> None:
    recipe = generate(
        "Nantes carrots and Red Baron onions in neighbouring beds; the onions have been lifted "
        "and are drying on top of the soil, the carrots still lush and green. August, cloudy."
    ).recipe
    assert [(f.crop, f.stage) for f in recipe.fields][1] == ("Onion", "Maturation")


def test_the_same_size_and_spacing_is_both() -> None:
    recipe = generate(
        "Spätburgunder vineyard: rows 2 m, vines 1 m, 3 ha, flowering in June, with a "
        "Chardonnay block of the same size and spacing to the south."
    ).recipe
    assert [(f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in recipe.fields] == [
        (2.0, 1.0),
        (2.0, 1.0),
    ]
    assert len({f.geometry.size_m for f in recipe.fields}) == 1


def test_the_front_of_a_farm_by_its_road(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Chilli farm, three blocks: Jalapeños nearest the road, Cayenne in the middle and "
        "California Wonder at the back, all in flower."
    )
    assert {kind for kind, _, _ in relations} == {"between"}


def test_all_hanging_with_ripe_fruit_is_every_listed_field() -> None:
    recipe = generate(
        "Three pepper plots in a row at the community farm: California Wonder, then "
        "jalapeños, then cayenne, all hanging with ripe red fruit. Late August, sunny."
    ).recipe
    assert [f.stage for f in recipe.fields] == ["Maturation"] * 3


def test_a_field_placed_against_both_fields_before(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "A field of tomatoes south of a field of corn, and to the west of both an orchard."
    )
    west = {objects for kind, _, objects in relations if kind == "west_of"}
    assert west == {("Tomato",), ("Maize",)}


def test_a_size_in_a_run_of_measures_said_of_each() -> None:
    recipe = generate(
        "Butterhead and Cos plots, Butterhead west of Cos, 9 plants/m2 each, 15 x 15 m"
    ).recipe
    assert [f.geometry.size_m for f in recipe.fields] == [(15.0, 15.0), (15.0, 15.0)]


def test_a_farm_where_nothing_is_planted_is_refused() -> None:
    with pytest.raises(AgrirecipeError, match="nothing is grown"):
        generate(
            "Our farm has a farmhouse, two barns, a pond and a lane lined with poplars, plus "
            "the tractor shed. Nothing is planted this year."
        )


def test_a_field_behind_another_is_next_to_it() -> None:
    recipe = generate(
        "An orchard of fruit trees in full blossom behind a field of young lettuces. April, "
        "bright but very windy."
    ).recipe
    assert [f.category for f in recipe.fields] == ["Fruits", "Vegetables"]
    assert [r.kind for r in recipe.relations] == ["next_to"]
    # (scenery behind a field places nothing)
    assert generate("wheat with a barn behind it").recipe.relations == ()


# --- leftovers of g55, fixed after it moved into the development set ---------------------


def test_four_parcels_by_the_compass_are_a_plus_not_a_line(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Our vineyard is in four parcels - Riesling to the north, Pinot Nero to the south, "
        "Chardonnay to the east, Cabernet to the west."
    )
    assert ("north_of", "Riesling", ("Pinot Noir",)) in relations
    assert ("east_of", "Chardonnay", ("Cabernet Sauvignon",)) in relations
    # (the east parcel lies beside the north and south ones, not in line between them)
    assert not any(kind == "between" for kind, _, _ in relations)


def test_a_middle_field_between_compass_parcels_is_still_between(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Five fields: wheat in the north, carrots in the south, onions in the east, maize in "
        "the west, and potatoes in the middle."
    )
    assert ("between", "Potato", ("Wheat", "Carrot")) in relations
    assert [r for r in relations if r[0] == "between"] == [
        ("between", "Potato", ("Wheat", "Carrot"))
    ]


def test_a_cue_of_the_field_before_keeps_the_last_fields_look_its_own() -> None:
    recipe = generate(
        "Field A: 50 x 120 m of Durum, heading out. Field B, next to it: 3 acres of Popcorn, "
        "young plants."
    ).recipe
    assert [(f.variety, f.stage) for f in recipe.fields] == [
        ("Durum", "Reproductive"),
        ("Popcorn", "Vegetative"),
    ]


@pytest.mark.parametrize(
    "prompt",
    [
        "the lower field is cabbage and thats it for crops, rest of the farm is yard, sheds "
        "and a muck heap",
        "the lower field is cabbage and thats it",
        "cabbage, that's all for the fields",
        "just one cabbage field, nothing else in the way of crops",
        "one cabbage field and no other plots",
        "a cabbage field, no more fields",
    ],
)
def test_closing_words_that_there_is_nothing_else_ask_for_no_field(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert [f.crop for f in recipe.fields] == ["Cabbage"]


def test_measures_after_a_field_named_again_are_the_placed_fields() -> None:
    recipe = generate(
        "grape vines, 9 ft rows, 6 ft between vines, 2.5 acres, rows running north-south. plus "
        "1 acre of cherries south of the vines at 16 x 8 ft"
    ).recipe
    assert [
        (f.crop, f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in recipe.fields
    ] == [
        ("Grape", pytest.approx(2.7432), pytest.approx(1.8288)),
        ("Cherry", pytest.approx(4.8768), pytest.approx(2.4384)),
    ]
    # (a new field placed against keeps the measures said after it)
    new = generate("1 acre of cherries south of a vineyard at 3 x 1.5 m").recipe
    assert [f.agronomy.row_spacing_m for f in new.fields if f.crop == "Grape"] == [3.0]

"""Text of blind set g57 (issue 8): its misses fixed as general mechanisms (a label with its
size before what it grows; "at the end of" a field; a crop asked about, then its plot; a
livestock paddock; a side's garden; "baby plants"; ears only just emerging; "as I caught
it"; a plot made by "-ed" ("ridged plots"))."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def test_a_label_with_its_size_before_what_it_grows() -> None:
    recipe = generate(
        "Field A, 3 ha: Agria potatoes, healthy. Field B, 2.5 ha: Winter Wheat, yellow rust. "
        "Field C, 1 ha: Red Express cabbage, fine. Field D, 0.5 ha: Lollo lettuce, downy mildew."
    ).recipe
    assert [(f.crop, f.variety, f.health) for f in recipe.fields] == [
        ("Potato", "Agria", "Healthy"),
        ("Wheat", "Winter Wheat", "Ill"),
        ("Cabbage", "Red Express", "Healthy"),
        ("Lettuce", "Lollo Rosso", "Ill"),
    ]
    assert [f.geometry.area_m2 for f in recipe.fields] == pytest.approx(
        [30000, 25000, 10000, 5000], rel=0.01
    )


def test_a_label_with_its_size_in_brackets_then_placed(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "Field A (3 ha): Agria potatoes. Field B (50 x 80 m): wheat, north of A."
    recipe = generate(prompt).recipe
    assert [f.crop for f in recipe.fields] == ["Potato", "Wheat"]
    assert recipe.fields[0].geometry.area_m2 == pytest.approx(30000, rel=0.01)
    assert sorted(recipe.fields[1].geometry.size_m) == [50.0, 80.0]
    assert crop_relations(prompt) == {("north_of", "Wheat", ("Potato",))}


def test_at_the_end_of_a_field_places_against_it(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "a 50 by 80 m maize field next to a 30 by 80 m strip of carrots, and a small salad "
        "plot at the end of the carrots"
    )
    assert [f.crop for f in generate(prompt).recipe.fields] == ["Maize", "Carrot", "Lettuce"]
    assert crop_relations(prompt) == {
        ("next_to", "Maize", ("Carrot",)),
        ("next_to", "Lettuce", ("Carrot",)),
    }


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("popcorn?? can u even do that. a popcorn field w/ tassels out pls", ["Maize"]),
        (
            "idk smth w/ grapes maybe? like a vineyard in autumn and a lil strawberry patch",
            ["Grape", "Strawberry"],
        ),
    ],
)
def test_a_crop_asked_about_then_its_plot_is_one_field(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in generate(prompt).recipe.fields] == crops


def test_another_variety_after_a_title_is_still_its_own_field() -> None:
    fields = generate("Gala. a Fuji orchard").recipe.fields
    assert [(f.crop, f.variety) for f in fields] == [("Apple", "Gala"), ("Apple", "Fuji")]


def test_a_livestock_paddock_is_no_field() -> None:
    fields = generate(
        "Picture the yard with the red tractor shed; behind it the sheep paddock, and then two "
        "arable fields, one in wheat and one in maize, with a hawthorn hedge between them."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Wheat", "Maize"]


def test_a_garden_on_a_side_is_where_the_crop_is(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Romaine in the north garden, crisphead in the south garden, both harvest-ready in "
        "September."
    )
    fields = generate(prompt).recipe.fields
    assert [(f.crop, f.variety, f.stage) for f in fields] == [
        ("Lettuce", "Romaine", "Maturation"),
        ("Lettuce", "Iceberg", "Maturation"),
    ]
    assert crop_relations(prompt) == {("north_of", "Lettuce", ("Lettuce",))}


def test_baby_plants_are_young() -> None:
    fields = generate("cabbages north, lettuces south, both baby plants").recipe.fields
    assert [(f.crop, f.stage) for f in fields] == [
        ("Cabbage", "Vegetative"),
        ("Lettuce", "Vegetative"),
    ]


def test_ears_only_just_emerging_is_heading() -> None:
    field = generate(
        "Snap of our dinkel field on a grey morning, still green with the ears only just "
        "emerging, a tractor track cut through it and rooks everywhere."
    ).recipe.fields[0]
    assert (field.crop, field.variety, field.stage) == ("Wheat", "Spelt", "Reproductive")


def test_as_i_caught_it_is_the_photographer_not_a_disease() -> None:
    fields = generate(
        "The experimental farm, as I caught it: a strip of Flint corn and a strip of Popcorn, "
        "both tasselling, with a grass path and a weather station between them."
    ).recipe.fields
    assert [(f.variety, f.health) for f in fields] == [("Flint", "Healthy"), ("Popcorn", "Healthy")]
    caught = generate("potatoes with blight, and the carrots beside them caught it too")
    assert [f.health for f in caught.recipe.fields] == ["Ill", "Ill"]


def test_a_plot_made_by_ed_is_no_unknown_crop() -> None:
    fields = generate(
        "Ridged plots, 75 cm centres, 30 ridges apiece: Fontane potatoes in one, Chantenay "
        "carrots in the adjoining one."
    ).recipe.fields
    assert [(f.crop, f.variety) for f in fields] == [("Potato", "Fontane"), ("Carrot", "Chantenay")]
    assert [(f.bed_count, f.agronomy.row_spacing_m) for f in fields] == [(30, 0.75), (30, 0.75)]

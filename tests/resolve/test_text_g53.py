"""Text of blind set g53 (issue 8): its misses fixed as general mechanisms (the near and
the far side; a bare "apart" said before the rows' spacing; "the trees" of the tree crop
named; a month said "around march"; a side a field shares ...)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def _fields(prompt: str) -> list[tuple[str, str, str]]:
    return [(f.crop, f.stage, f.season) for f in generate(prompt).recipe.fields]


def test_fields_on_the_near_and_the_far_side_of_a_ditch() -> None:
    fields = _fields(
        "Two fields split by a drainage ditch: on the near side strawberries with ripe red "
        "fruit, on the far side lettuce that's bolting, tall with flower stalks shooting up."
    )
    assert [(crop, stage) for crop, stage, _ in fields] == [
        ("Strawberry", "Maturation"),
        ("Lettuce", "Reproductive"),
    ]


def test_a_bare_apart_said_before_the_rows_spacing_is_the_plants() -> None:
    [field] = generate(
        "Among the vines: they're planted 6 feet apart in rows 10 feet apart."
    ).recipe.fields
    assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == pytest.approx(
        (3.048, 1.8288)
    )


@pytest.mark.parametrize(
    ("prompt", "stages"),
    [
        (
            "Chardonnay in May, the tiny flower clusters just opening on the shoots",
            ["Reproductive"],
        ),
        (
            "Our Centenary strawberries in full fruit, bright red, and the Sonata beds right "
            "beside them still just flowering.",
            ["Maturation", "Reproductive"],
        ),
    ],
)
def test_looks_of_flowers_opening_and_of_full_fruit(prompt: str, stages: list[str]) -> None:
    assert [stage for _, stage, _ in _fields(prompt)] == stages


def test_the_trees_are_the_tree_crop_named_not_the_field_described_before() -> None:
    fields = _fields(
        "I caught cherry tomatoes in a field right next to a cherry orchard; the tomatoes are "
        "red and ready, the trees are just leafing out."
    )
    assert [(crop, stage) for crop, stage, _ in fields] == [
        ("Tomato", "Maturation"),
        ("Cherry", "Vegetative"),
    ]


def test_each_bed_or_row_just_counted_is_as_long_as_each_says() -> None:
    [field] = generate(
        "strawberry beds on 60-inch centers, 2 rows per bed, plants 12 in apart, 20 beds, "
        "each 300 ft"
    ).recipe.fields
    assert field.row_length_m == pytest.approx(91.44)


def test_the_same_row_width_is_the_rows_spacing_of_the_field_before() -> None:
    recipe = generate(
        "field corn at 80,000 plants/ha on 76 cm rows, and Popcorn at 70,000 plants/ha on the "
        "same row width."
    ).recipe
    assert [f.agronomy.row_spacing_m for f in recipe.fields] == [0.76, 0.76]


def test_each_as_a_plot_of_says_what_each_field_is() -> None:
    recipe = generate(
        "For robot navigation we need four different vegetables, each as a plot of 8 rows at "
        "0.75 m."
    ).recipe
    assert len(recipe.fields) == 4
    assert {f.category for f in recipe.fields} == {"Vegetables"}
    assert {f.agronomy.row_spacing_m for f in recipe.fields} == {0.75}


def test_a_side_a_field_shares_with_another(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Pear orchard, 1 ha, 3.5 m row spacing. It shares its north edge with 1 ha of "
        "cherries on 4.5 m rows."
    )
    assert relations == {("north_of", "Cherry", ("Pear",))}


@pytest.mark.parametrize(
    ("prompt", "season"),
    [
        ("navel oranges & valencia oranges in nz around march, all ripe", "Fall"),
        ("lettuce and onions in like may?? idk what varieties dont care", "Spring"),
    ],
)
def test_a_month_said_around_or_after_a_filler(prompt: str, season: str) -> None:
    assert {s for _, _, s in _fields(prompt)} == {season}
    # (an everyday "may" is still no month)
    assert {s for _, _, s in _fields("I would like may be some apples")} == {"Summer"}

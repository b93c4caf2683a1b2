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


def _variety_relations(prompt: str) -> set[tuple[str, str | None, tuple[str | None, ...]]]:
    recipe = generate(prompt).recipe
    variety = {f.id: f.variety for f in recipe.fields}
    return {
        (r.kind, variety[r.subject], tuple(variety[o] for o in r.objects)) for r in recipe.relations
    }


def test_a_direction_closing_its_part_places_the_field_of_that_part() -> None:
    prompt = (
        "Onion sets trial for the vision team. Red Baron plot, 5 m x 20 m, to the north; "
        "Sturon plot of the same size to the south of it. Rows 30 cm apart, bulbs every "
        "10 cm, in both."
    )
    relations = _variety_relations(prompt)
    assert ("north_of", "Red Baron", ("Sturon",)) in relations or (
        "south_of",
        "Sturon",
        ("Red Baron",),
    ) in relations
    assert ("north_of", "Sturon", ("Red Baron",)) not in relations
    assert [f.geometry.size_m for f in generate(prompt).recipe.fields] == [(5.0, 20.0), (5.0, 20.0)]


def test_measures_going_on_after_a_sentence_that_opens_with_the_beds() -> None:
    recipe = generate(
        "Sonata: 10 beds. Albion: 6 beds. Beds on 1.2 m centres, 2 rows a bed, 25 cm plant "
        "spacing. Albion plot directly north of Sonata."
    ).recipe
    assert [(f.variety, f.bed_count, f.agronomy.in_row_spacing_m) for f in recipe.fields] == [
        ("Sonata", 10, 0.25),
        ("Albion", 6, 0.25),
    ]


def test_a_crop_named_again_for_both_fields_keeps_what_follows_for_both() -> None:
    recipe = generate(
        "Camera test with cayenne chillies and California Wonder bell peppers next to each "
        "other. Beds 1.5 m, plants 45 cm apart, peppers fruiting and ripe."
    ).recipe
    assert [f.stage for f in recipe.fields] == ["Maturation", "Maturation"]


def test_the_vines_said_with_a_verb_are_every_vineyard_named() -> None:
    both = generate(
        "Colchagua valley, Chile: Cabernet in the north block, Chardonnay in the south "
        "block, and the vines are flowering in November."
    ).recipe
    assert [f.stage for f in both.fields] == ["Reproductive", "Reproductive"]
    # (half of them, or the vines of one block, are still one field's)
    half = generate(
        "Cabernet in the north block, Chardonnay in the south block. Half the vines show mildew."
    ).recipe
    assert [f.health for f in half.fields] == ["Healthy", "Ill"]


def test_a_gap_between_the_two_fields_sets_them_side_by_side() -> None:
    relations = _variety_relations(
        "durum wheat and dinkel strips, 3 x 50 m each, 15 cm drill rows, half a metre gap "
        "between them"
    )
    assert relations == {("next_to", "Durum", ("Spelt",))}


def test_backs_onto_is_next_to(crop_relations: Callable[[str], NamedRelations]) -> None:
    relations = crop_relations(
        "The Bartlett pear block backs straight onto a field of Golden Acre cabbages."
    )
    assert relations == {("next_to", "Pear", ("Cabbage",))}


@pytest.mark.parametrize(
    "prompt",
    [
        "fruit trees all along the west side, veg in the middle and a block of grain over on "
        "the east side",
        "apple trees along the western boundary, carrots in the middle and wheat along the "
        "eastern one",
    ],
)
def test_zones_along_a_side_said_with_all_or_with_one(
    prompt: str, crop_relations: Callable[[str], NamedRelations]
) -> None:
    relations = crop_relations(prompt)
    west = {crop for kind, crop, _ in relations if kind == "west_of"}
    assert west & {"Apple", "Pear", "Cherry", "Orange"}
    assert any(kind == "between" for kind, _, _ in relations)


def test_a_landmark_said_first_is_what_it_stands_for(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "The farmhouse is in the middle. Wheat to the north of it, maize to the south, and "
        "a potato field between the two cereal fields."
    )
    assert [f.crop for f in generate(prompt).recipe.fields] == ["Wheat", "Maize", "Potato"]
    relations = crop_relations(prompt)
    assert ("north_of", "Wheat", ("Maize",)) in relations
    assert ("between", "Potato", ("Wheat", "Maize")) in relations

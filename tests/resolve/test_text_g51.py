"""Text of blind set g51 (issue 8): each miss of its blind run fixed as the general
mechanism (a colour that only a ripe crop shows, said of its fruit; looks of a crop just
planted, ripening or dormant; a category member of a joint heading; a crop's own plants
counted per metre of row; members named by their side; a look said with "is all")."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def _fields(prompt: str) -> list[tuple[str, str, str, str]]:
    return [(f.crop, f.stage, f.season, f.health) for f in generate(prompt).recipe.fields]


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        ("Cabernet vines with the bunches gone nearly black", "Grape"),
        ("a block of Chardonnay where the grapes are golden", "Grape"),
        ("Cayenne peppers gone bright red on every plant", "Pepper"),
        ("Walla Walla onions, bulbs big and sitting on top of the soil, tops gone over", "Onion"),
        ("Flint corn, cobs husked back to show red and orange kernels, dry and hard", "Maize"),
        ("San Marzano tomatoes, long red fruits hanging in bunches and ready for sauce", "Tomato"),
        ("an onion field in July, the tops starting to fall over", "Onion"),
    ],
)
def test_a_ripe_look_is_maturation(prompt: str, crop: str) -> None:
    [(got, stage, _, health)] = _fields(prompt)
    assert (got, stage, health) == (crop, "Maturation", "Healthy")


def test_the_leaves_colour_is_no_ripe_colour() -> None:
    [(_, stage, _, _)] = _fields("a Chardonnay vineyard in June with the leaves golden green")
    assert stage != "Maturation"


def test_red_streaks_on_ripe_fruit_are_no_disease() -> None:
    [(_, stage, _, health)] = _fields(
        "a blood orange grove, the fruit turned deep orange with red streaks"
    )
    assert (stage, health) == ("Maturation", "Healthy")


def test_plants_just_put_in_are_young() -> None:
    [(_, stage, _, _)] = _fields(
        "The strawberry field - plants only just put in, tiny little things on the black plastic."
    )
    assert stage == "Vegetative"


def test_bare_trees_rimed_with_frost_are_in_winter() -> None:
    fields = _fields("Granny trees still bare and rimed with frost, Conference pears beside them")
    assert [season for _, _, season, _ in fields] == ["Winter", "Winter"]


def test_is_all_said_of_one_field_stays_its_own() -> None:
    fields = _fields(
        "the corn south of the track is all tasselled out, and north of the track there's a "
        "field of wheat, heads drooping"
    )
    assert [(crop, stage) for crop, stage, _, _ in fields] == [
        ("Maize", "Reproductive"),
        ("Wheat", "Maturation"),
    ]


def test_a_category_member_of_a_joint_heading_is_no_extra_field() -> None:
    fields = _fields(
        "Fruit and veg in this one: an apple orchard with red fruit and, next to it, a big "
        "vegetable plot."
    )
    assert len(fields) == 2 and fields[0][0] == "Apple"


def test_a_crops_own_plants_per_metre_are_a_spacing_not_fields() -> None:
    recipe = generate(
        "Sturon and Red Baron onion strips next to each other, each 6 m x 50 m, 30 cm rows, "
        "10 onions per metre of row."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Sturon", "Red Baron"]
    assert all(f.agronomy.in_row_spacing_m == pytest.approx(0.1) for f in recipe.fields)


def test_plants_per_metre_naming_the_only_crop_keep_it() -> None:
    recipe = generate("plant 40 carrots per metre in 30 cm rows").recipe
    assert [f.crop for f in recipe.fields] == ["Carrot"]


def test_zones_at_the_north_and_south_are_placed(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations("wheat at the north, maize in the middle, potatoes at the south")
    assert {("north_of", "Wheat", ("Maize",)), ("north_of", "Maize", ("Potato",))} <= relations


def test_a_side_said_past_a_description_places_the_field_before(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Winter Wheat just emerged, thin green lines, on the west side of the lane, and "
        "January King cabbages on the east side."
    )
    assert ("west_of", "Wheat", ("Cabbage",)) in relations
    assert ("west_of", "Cabbage", ("Wheat",)) not in relations


def test_a_member_named_by_its_side_then_a_look() -> None:
    prompt = (
        "Two potato fields, one on either side of the lane. The one on the east side has got "
        "blight, the west one looks fine."
    )
    recipe = generate(prompt).recipe
    health = {f.id: f.health for f in recipe.fields}
    east = [r.subject for r in recipe.relations if r.kind == "east_of"]
    assert east and all(health[s] == "Ill" for s in east)
    assert sorted(health.values()) == ["Healthy", "Ill"]


def test_each_side_named_after_a_colon_is_one_field_a_side(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "Veg on both sides of the maize field: onions to the west of it, cabbages to the east."
    assert sorted(crop for crop, _, _, _ in _fields(prompt)) == ["Cabbage", "Maize", "Onion"]
    relations = crop_relations(prompt)
    assert {("west_of", "Onion", ("Maize",)), ("east_of", "Cabbage", ("Maize",))} <= relations


def test_a_label_placed_against_a_bare_letter_then_named_after_and_is(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Block A is Gala apples, 12 rows, 3.4 m between the rows and a tree every metre. "
        "Block B sits immediately east of A and is Williams pears planted on 3.5 m rows."
    )
    recipe = generate(prompt).recipe
    assert [(f.variety, f.agronomy.row_spacing_m) for f in recipe.fields] == [
        ("Gala", 3.4),
        ("Williams", 3.5),
    ]
    assert crop_relations(prompt) == {("east_of", "Pear", ("Apple",))}


def test_a_capitalised_name_a_plot_holds_is_its_variety() -> None:
    recipe = generate(
        "Along the top of the plantation we have Big Mike. Below that is a block of Grande "
        "Naine, and right at the bottom the Ladyfinger bananas."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Gros Michel", "Grand Nain", "Lady Finger"]


@pytest.mark.parametrize("closing", ["thx a lot", "thanks!", "cheers"])
def test_a_side_said_last_before_a_sign_off_still_places_the_field(
    closing: str, crop_relations: Callable[[str], NamedRelations]
) -> None:
    relations = crop_relations(f"apples up north, cherries in the middle, pears south. {closing}")
    assert ("south_of", "Pear", ("Cherry",)) in relations

"""Text of blind set g20 (issue 8): colours of a plant's parts, a loose few fruit, a
variety name that opens a description, quarters named bare, a count of fields said after
their crop, fields on both sides, named sides of plots already placed between, varieties
named again beside a member, "and so are", véraison, a joke taken back, a crop left to
the reader's choice, colours listed with "and", and an article that belongs to a row; and
development misses of the same kinds (a member on either side, a compass side opening a
clause, sides of scenery)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        # a colour crop word before a part of a plant is its colour
        ("Nantes carrots with their orange shoulders poking out of the ridges", ["Carrot"]),
        ("Flint corn, husks pulled back on the cobs to show the orange and red kernels", ["Maize"]),
        # a loose few of the fruit of a crop named, after "with"
        (
            "A Gala leaf with scab spots, with a couple of apples behind it, cracked and corky.",
            ["Apple"],
        ),
        ("Kordia cherries, with a few cherries split after the rain", ["Cherry"]),
        # fruit after a clause that only says how the plants look
        ("Jonagold with scab, velvety olive spots on the leaves and split fruit.", ["Apple"]),
        # colours listed with "and" are one thing's colours, not two fields
        ("Bintje potatoes in flower, white and purple blooms across the whole field", ["Potato"]),
        # "a double row": the article is the row's, not a count of one field of plants
        (
            "Strawberry beds 1.4 m centre to centre, each carrying a double row of plants, and "
            "our onion plot west of them.",
            ["Strawberry", "Onion"],
        ),
        # a joke taken back ("jk") is no field
        ("cabage patch kid lol jk, just a cabbage field pls", ["Cabbage"]),
    ],
)
def test_no_phantom_field(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_a_plant_part_word_does_not_make_a_colour_of_the_crop() -> None:
    (orchard,) = recipe("an orange grove, orange trees with green leaves").fields
    assert orchard.crop == "Orange"
    pear, *apples = recipe("a pear orchard with a couple of apple blocks").fields
    assert pear.crop == "Pear" and [a.crop for a in apples] == ["Apple", "Apple"]


@pytest.mark.parametrize(
    ("prompt", "crop", "variety"),
    [
        (
            "Centenary on the table-top gutters in July, berries deep red and glossy",
            "Strawberry",
            "Malling Centenary",
        ),
        ("Lollo looking lovely this week, frilly dark red heads on black plastic", "Lettuce", None),
        (
            "Cos ready to cut, long upright heads, the rig working the far end of the field",
            "Lettuce",
            "Romaine",
        ),
    ],
)
def test_a_weak_variety_name_that_opens_a_description(
    prompt: str, crop: str, variety: str | None
) -> None:
    (field,) = recipe(prompt).fields
    assert field.crop == crop
    if variety is not None:
        assert field.variety == variety


def test_a_weak_variety_name_with_no_plants_is_no_field() -> None:
    with pytest.raises(Exception, match="no crop or field"):
        recipe("Flint walls around the yard")


def test_quarters_named_bare(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Four quarters round the yard. North-west quarter is maize, north-east is wheat, "
        "south-west onions and south-east carrots."
    )
    assert named_relations(prompt) == {
        ("north_of", "Maize", ("Onion",)),
        ("north_of", "Wheat", ("Carrot",)),
        ("west_of", "Maize", ("Wheat",)),
        ("west_of", "Onion", ("Carrot",)),
    }


def test_a_count_of_fields_said_after_their_crop() -> None:
    fields = recipe("The farm is mostly wheat - three fields of them - and one maize field.").fields
    assert [f.crop for f in fields] == ["Wheat", "Wheat", "Wheat", "Maize"]
    fields = recipe("We grow Gala apples (2 blocks of them) and pears").fields
    assert [f.crop for f in fields] == ["Apple", "Apple", "Pear"]


def test_fields_on_both_sides(named_relations: Callable[[str], NamedRelations]) -> None:
    fields = recipe(
        "A maize plot of 10 rows at 76 cm, flanked on both sides by wheat drilled "
        "at 12.5 cm. Every plot 8 m wide and 60 m long."
    ).fields
    assert [f.crop for f in fields] == ["Maize", "Wheat", "Wheat"]
    assert [f.agronomy.row_spacing_m for f in fields[1:]] == [0.125, 0.125]
    assert named_relations("potatoes flanked on either side by onion strips") == {
        ("between", "Potato", ("Onion", "Onion"))
    }


def test_sides_named_after_a_field_placed_between(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "carrots (nantes) between 2 onion fields, sturon on one side red baron on the other"
    assert named_relations(prompt) == {("between", "Nantes", ("Sturon", "Red Baron"))}
    assert len(recipe(prompt).fields) == 3
    # (a side "of" something is no second member: "on one side of the ravine and ...")
    fields = recipe(
        "two banana plots, Cavendish on one side of the ravine and Gros Michel on the other"
    ).fields
    assert [f.variety for f in fields] == ["Cavendish", "Gros Michel"]


def test_varieties_named_again_beside_a_member(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "Our lettuce fields in a row: Iceberg in the middle, between the Cos and the Bibb."
    assert named_relations(prompt) == {("between", "Iceberg", ("Romaine", "Butterhead"))}


def test_so_are_says_the_same_of_the_next_field() -> None:
    cherries, strawberries = recipe(
        "In March the Kordia cherries by the barn are ripe for picking, and so are the "
        "strawberries in the field beside them."
    ).fields
    assert (cherries.stage, strawberries.stage) == ("Maturation", "Maturation")


def test_bunches_going_purple_is_veraison() -> None:
    (vines,) = recipe("Pinot Noir block in August, the bunches going purple").fields
    assert vines.stage == "Maturation"


@pytest.mark.parametrize(
    ("prompt", "count", "category"),
    [
        ("some fruit fields pls, whatever fruit u like", 2, "Fruits"),
        ("3 fields, any vegetables", 3, "Vegetables"),
    ],
)
def test_a_crop_left_to_the_readers_choice(prompt: str, count: int, category: str) -> None:
    fields = recipe(prompt).fields
    assert len(fields) == count
    assert {f.category for f in fields} == {category}


def test_a_choice_joined_by_and_is_a_field() -> None:
    wheat, other = recipe("wheat and any vegetable").fields
    assert (wheat.crop, other.category) == ("Wheat", "Vegetables")
    assert [f.crop for f in recipe("wheat, any vegetable").fields][:1] == ["Wheat"]
    assert len(recipe("wheat, any vegetable").fields) == 2


# --- development-set misses of the same kinds (g13, g18) ---


def test_a_member_on_either_side_fills_a_counted_list(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "3 plots: carrots in the middle, onions either side of it"
    assert [f.crop for f in recipe(prompt).fields] == ["Carrot", "Onion", "Onion"]
    assert named_relations(prompt) == {("between", "Carrot", ("Onion", "Onion"))}


def test_a_compass_side_opening_a_clause_names_its_plot(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "East plot, 30 x 80 m, Bintje potatoes; west plot, 30 x 80 m, Sturon onions."
    assert named_relations(prompt) == {("west_of", "Sturon", ("Bintje",))}


def test_members_of_a_counted_list_placed_by_sides_of_scenery() -> None:
    fields = recipe(
        "We have two orchards, Gala on the east side of the barn and Conference on the west side."
    ).fields
    assert [f.variety for f in fields] == ["Gala", "Conference"]


def test_a_slip_of_between_still_places_between(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "i want sturon onions betwen two carrot fields, nantes on one side chantenay on the other"
    )
    assert named_relations(prompt) == {("between", "Sturon", ("Nantes", "Chantenay"))}
    assert len(recipe(prompt).fields) == 3


def test_a_look_after_two_named_crops_with_a_placement_after_it() -> None:
    # ("navel oranges" holds its heads in another order than its words)
    first, second = recipe(
        "hamlin & navel oranges both ripe, hamlins west of the navels, july"
    ).fields
    assert (first.stage, second.stage) == ("Maturation", "Maturation")


def test_the_plural_of_the_crop_every_member_grows_describes_them_all() -> None:
    first, second = recipe(
        "two vineyard blocks: Pinot Nero on the west, Riesling on the east. Shot in early "
        "July with the grapes ripening."
    ).fields
    assert (first.stage, second.stage) == ("Maturation", "Maturation")

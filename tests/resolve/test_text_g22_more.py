"""More text of blind set g22 (issue 8): ages and times are no counts, "a couple of beds
of", a word for a crop's plants put in a place of its own, a crop said again with a verb
after "and", "azimuth 250 degrees", "trees 1.5 m" after the rows, "the identical
layout", orders with brackets and scenery first, "ready to strip", people words, a title
before a list of one crop's plots, headings of two kinds, and "in a plantation" after
what a test is for."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def crops(prompt: str) -> list[str]:
    return [f.crop for f in recipe(prompt).fields]


def test_ages_and_times_are_no_counts() -> None:
    assert crops("Lollo Rosso planted only ten days ago, little frilly red rosettes") == ["Lettuce"]
    assert crops("lettuce sown 3 weeks ago") == ["Lettuce"]
    (apples,) = recipe("10 year old apple trees").fields
    assert apples.geometry.size_m == (60.0, 100.0)  # no orchard of ten trees


def test_a_couple_of_beds_of_one_crop() -> None:
    assert crops("a couple of beds of strawberries at the front") == ["Strawberry"]
    (lettuce,) = recipe("a couple of rows of lettuce").fields
    assert lettuce.row_count == 2


def test_the_vines_in_a_place_of_their_own_after_other_crops() -> None:
    assert crops(
        "apple trees nearest, pear trees beyond them and the vines on the hill, all leafless"
    ) == ["Apple", "Pear", "Grape"]
    # the vines of a vineyard named before are its own
    assert crops("Riesling on the slope, and the vines on the wires are bare") == ["Grape"]


def test_a_crop_said_again_with_a_verb_after_and() -> None:
    (gala,) = recipe(
        "the Royal Gala block in late September. The leaves have velvety spots and some "
        "apples have brown corky patches."
    ).fields
    assert (gala.variety, gala.health) == ("Gala", "Ill")
    assert crops("a Gala block and pears are ripe") == ["Apple", "Pear"]


def test_a_row_azimuth_above_180_degrees() -> None:
    (cherries,) = recipe(
        "sweet cherries for a canopy-density scan, 14 ft rows, 8 ft in-row, 320 trees, "
        "row azimuth 250 degrees, fruit ripe, June"
    ).fields
    assert cherries.geometry.rotation_deg == pytest.approx(-70.0)


def test_trees_and_a_length_after_the_rows() -> None:
    hamlin, navel = recipe(
        "two citrus blocks: Hamlin (rows 6 m apart, trees 3 m) and Washington Navel "
        "(rows 7 m apart, trees 4 m), with the Hamlin to the south."
    ).fields
    assert (hamlin.agronomy.in_row_spacing_m, navel.agronomy.in_row_spacing_m) == (3.0, 4.0)


def test_the_identical_layout_and_the_same_centres() -> None:
    tomatoes, peppers = recipe(
        "tomato plants for the stereo camera test, 36 inch rows, 18 inches between plants, "
        "10 rows, 150 ft long; and a pepper plot with the identical layout east of the tomatoes"
    ).fields
    assert (peppers.row_count, peppers.row_length_m) == (10, tomatoes.row_length_m)
    _onions, lettuce = recipe(
        "onion beds for weeder test - 4 beds, 4 rows per bed, beds 1.8 m center to center. "
        "plus a lettuce plot alongside, 3 beds same centres, 3 rows per bed"
    ).fields
    assert lettuce.agronomy.row_spacing_m == 1.8


def test_orders_past_brackets_and_scenery(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations(
        "going from west to east: a tomato strip (6 rows, 1.5 m apart), then a pepper strip "
        "(6 rows, 0.9 m apart), then a cabbage strip (6 rows, 0.75 m apart)."
    ) >= {("west_of", "Tomato", ("Pepper",)), ("west_of", "Pepper", ("Cabbage",))}
    assert named_relations(
        "From the road heading north you cross a hedge, then the strawberry beds, then the "
        "apple orchard, then the woods."
    ) == {("south_of", "Strawberry", ("Apple",))}


def test_verbs_and_people_are_no_fields() -> None:
    wheat = recipe(
        "Two wheat paddocks on our Australian farm, one each side of the creek, both golden "
        "and ready to strip in November."
    ).fields
    assert [(f.crop, f.stage) for f in wheat] == [("Wheat", "Maturation")] * 2
    lettuce, cabbage = recipe(
        "Lettuce field right after transplanting, tiny plugs in neat beds with two guys "
        "pulling fleece over them, and beside it a cabbage field, heads firm and ready."
    ).fields
    assert (lettuce.stage, cabbage.crop) == ("Vegetative", "Cabbage")


def test_a_title_before_a_list_of_one_crops_plots() -> None:
    fields = recipe(
        "Potato variety trial for the phenotyping robot. Four plots in a line from north to "
        "south: Bintje, Fontane, Agria, Russet Burbank, each 4 rows x 15 m at 75 cm."
    ).fields
    assert [f.variety for f in fields] == ["Bintje", "Fontane", "Agria", "Russet Burbank"]
    fields = recipe(
        "Strawberry variety comparison for a picking robot: Elsanta, Sonata and Albion in "
        "three adjacent plots with Sonata in the middle. 10 beds per plot on 1.5 m centres."
    ).fields
    assert [(f.variety, f.bed_count) for f in fields] == [
        ("Elsanta", 10),
        ("Sonata", 10),
        ("Albion", 10),
    ]


def test_a_heading_of_two_kinds() -> None:
    assert crops(
        "grain and veg test strips - a corn strip of 12 rows at 75 cm and a spud strip of "
        "8 rows at 75 cm south of it"
    ) == ["Maize", "Potato"]
    assert crops("fruit and veg plots: an apple plot and a carrot plot") == ["Apple", "Carrot"]


def test_a_plantation_after_what_a_test_is_for() -> None:
    assert crops(
        "banana plants in the classic double-row system: pairs of rows 1 m apart, plants "
        "2.25 m apart along the row. It's for a robot navigation test in a plantation."
    ) == ["Banana"]


def test_livestock_in_a_paddock_is_no_field() -> None:
    from agrirecipe import PromptError

    with pytest.raises(PromptError):
        recipe(
            "The farm in winter: frosted hedgerows, a frozen pond, sheep in the paddock and "
            "smoke from the farmhouse chimney."
        )
    # (sheep grazing an orchard leave the orchard a field of trees)
    assert crops("sheep grazing in the orchard of Gala") == ["Apple"]


def test_brown_silks_are_ripe_sweetcorn() -> None:
    (corn,) = recipe("Sweetcorn the day before we picked it - cobs fat, silks gone brown").fields
    assert corn.stage == "Maturation"


def test_a_capitalised_weak_name_before_a_variety_of_its_crop() -> None:
    fields = recipe(
        "Big Mike in the first block, Ladyfinger in the second and Dwarf Cavendish in the third"
    ).fields
    assert [f.variety for f in fields] == ["Gros Michel", "Lady Finger", "Cavendish"]


def test_a_month_to_come_is_not_the_scenes() -> None:
    fields = recipe(
        "the Gala being picked, and the Pink Lady that won't be ready until November. "
        "Taken late August."
    ).fields
    assert {f.season for f in fields} == {"Summer"}


def test_a_crop_then_the_same() -> None:
    _stuttgarter, walla = recipe(
        "Stuttgarter at 30 cm rows and 8 cm in-row, Walla Walla the same, and nothing else"
    ).fields
    assert (walla.agronomy.row_spacing_m, walla.agronomy.in_row_spacing_m) == (0.3, 0.08)


def test_bare_quarters_before_and(named_relations: Callable[[str], NamedRelations]) -> None:
    relations = named_relations("apples NW, vines NE, wheat SW and carrots SE.")
    assert {("west_of", "Wheat", ("Carrot",)), ("north_of", "Apple", ("Wheat",))} <= relations

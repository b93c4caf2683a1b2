"""Text of blind set g21 (issue 8): a counted list going on past a semicolon, crops left
to chance, areas in words after the first, rows named by a crop word, "it" said twice of
one field, "the same bearing", slips of "running", ridges measured in inches, a plot said
to be adjacent; then where a plot word is where the crop grows, fruit growing on, rows
named by number, places' and makers' names, "each" of rows, "both" of members listed
after it, a patch where damage shows, "on the other side of", "on one bed and on the
next", labels between slashes, typos whose nearest name changes a word, and "a foot"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_counted_list_goes_on_past_a_semicolon() -> None:
    fields = recipe(
        "Scan of two orchards: a 2-acre Comice block, 3.5 m rows, with fire blight on a lot of "
        "the trees; and east of it a 1 acre Gala block on 3.4 m rows."
    ).fields
    assert [f.crop for f in fields] == ["Pear", "Apple"]


def test_crops_left_to_chance() -> None:
    fields = recipe("my boss wants 4 random crops, idk").fields
    assert len(fields) == 4


def test_areas_in_words_after_the_first() -> None:
    tomatoes, onions = recipe("three hectares of tomatoes and two of onions").fields
    assert (tomatoes.geometry.area_m2, onions.geometry.area_m2) == pytest.approx(
        (30000, 20000), rel=0.001
    )
    # ("one of them": a member of the fields named, no area)
    (apples,) = recipe("two acres of apples and one of them is scabby").fields
    assert apples.health == "Ill"


def test_rows_named_by_a_crop_word_are_that_crops() -> None:
    fields = recipe(
        "strawberries in the middle, a vineyard to the west of them and an apple orchard to "
        "the east; strawberry beds on 1.5 m centres, vine rows 2.4 m apart, apple rows 3.6 m "
        "apart"
    ).fields
    spacing = {f.crop: f.agronomy.row_spacing_m for f in fields}
    assert (spacing["Grape"], spacing["Apple"]) == (2.4, 3.6)


def test_it_said_twice_is_one_field(named_relations: Callable[[str], NamedRelations]) -> None:
    relations = named_relations(
        "A cherry orchard with a pear orchard north of it and an apple orchard south of it"
    )
    assert ("north_of", "Pear", ("Cherry",)) in relations
    assert ("south_of", "Apple", ("Cherry",)) in relations


def test_rows_on_the_same_bearing() -> None:
    maize, wheat = recipe(
        "two plots next to each other: dent corn in 75 cm rows laid out at 30 degrees from "
        "north, and spring wheat in 15 cm rows on the same bearing"
    ).fields
    assert (round(maize.row_bearing_deg), round(wheat.row_bearing_deg)) == (30, 30)


def test_a_slip_of_running_and_ridges_in_inches() -> None:
    (potatoes,) = recipe("spuds, 30 ridges 75cm apart, rows runing NW-SE").fields
    assert round(potatoes.row_bearing_deg) == 135
    (carrots,) = recipe("Nantes carrots on 30 in ridges with 2 rows per ridge").fields
    assert (carrots.agronomy.row_spacing_m, carrots.agronomy.rows_per_bed) == (0.762, 2)


def test_a_plot_said_to_be_adjacent(named_relations: Callable[[str], NamedRelations]) -> None:
    assert named_relations("Sturon onions, half an acre, plus an adjacent Bintje plot") == {
        ("next_to", "Sturon", ("Bintje",))
    }
    # (an adjacent hedge is scenery, no field)
    assert len(recipe("a wheat field with an adjacent hedge").fields) == 1


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        # a plot word after the crop, past words about how it stands, is where it grows
        (
            "Savoy cabbages in January, dusted with frost, standing in neat rows in a wet field "
            "with the tractor ruts full of water.",
            ["Cabbage"],
        ),
        # the fruit growing on is no field of fruit
        (
            "two plots: Comice pears, fruit swelling, and beside them Bing cherries",
            ["Pear", "Cherry"],
        ),
        # a row named by its number
        ("This is row 4 of the Kordia cherries, fruit splitting after rain", ["Cherry"]),
        # a place's name, a maker's name, scenery
        ("near the town of Valencia: an orange grove with green fruit", ["Orange"]),
        ("Taken on my Fuji camera: Gala trees in blossom", ["Apple"]),
        (
            "Big Mike and Cavendish side by side in the botanic garden plot, both with "
            "hands of fruit",
            ["Banana", "Banana"],
        ),
        # a word for plants that names a crop, opening the prompt before another crop
        (
            "Bare vines pruned back to the wire, frost on the posts, and the apple trees along "
            "the lane are bare too.",
            ["Grape", "Apple"],
        ),
    ],
)
def test_no_phantom_field_and_no_missing_one(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_what_is_said_and_who_it_is_said_of() -> None:
    # "each" after a count of rows is each row, not each field
    potatoes, carrots = recipe(
        "Bintje on the big field, 24 rows at 75 cm, each 150 m long; alongside it Nantes "
        "carrots on 75 cm ridges, two rows per ridge."
    ).fields
    assert (potatoes.row_count, carrots.agronomy.rows_per_bed) == (24, 2)
    # "both" said of the members listed after it
    first, second = recipe(
        "Both our plots, the lettuce and the cabbage, have some disease this spring."
    ).fields
    assert (first.health, second.health) == ("Ill", "Ill")
    # a patch where the leaves show damage is a part of the field named before
    carrots, potatoes = recipe(
        "carrot field, but there's a patch in the middle where the leaves have gone brown with "
        "dark spots. the potato field next door looks fine."
    ).fields
    assert (carrots.health, potatoes.health) == ("Ill", "Healthy")


def test_places_said_in_other_words(named_relations: Callable[[str], NamedRelations]) -> None:
    assert (
        "between",
        "Spelt",
        ("Agria", "January King"),
    ) in named_relations(
        "Agria potatoes in the big field, a strip of spelt beside it, and on the other side of "
        "the spelt a January King cabbage plot."
    )
    assert ("next_to", "Jalapeno", ("Padron",)) in named_relations(
        "Padron peppers on one bed and Jalapenos on the next, both with little green fruit."
    )
    relations = named_relations("top: bing cherries / middle: agria / bottom: durum")
    assert ("north_of", "Agria", ("Durum",)) in relations
    prompt = "Two veg plots, onions directly north of the carrots. Onion rows 30 cm; carrots 45 cm."
    assert [f.crop for f in recipe(prompt).fields] == ["Onion", "Carrot"]


def test_a_typo_whose_nearest_name_changes_a_word() -> None:
    (bananas,) = recipe("grand nane bananas, ripe").fields
    assert bananas.variety == "Grand Nain"


def test_a_unit_said_as_a_word() -> None:
    (lettuce,) = recipe("Rows of Iceberg lettuce a foot apart").fields
    assert lettuce.agronomy.row_spacing_m == pytest.approx(0.3048)

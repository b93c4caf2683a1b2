"""Text of blind set g60 (issue 8): its misses fixed as general mechanisms (a plot whose
two sides hold the fields; "a row of pollard willows" and "dusted white"; the trees' own
blossom; "rows 100 m E-W"; "each one hectare"; a list said again after a colon; a total of
rows the members split; "34 inch rows 12 in apart"; "a tunnel block"; "1 N of the other";
a misspelt list counted after it; a run of measures before "+"; "the vines" opening an
order; words about a member inside a directed row; "and both lie east of"; one size or
grid each for counted plots)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_plot_whose_two_sides_hold_the_fields() -> None:
    scene = recipe(
        "pic of the feild by the barn, tomatos on one side and peppers on the other, both "
        "looking sick with dark spots all over the leaves"
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Tomato", "Ill"), ("Pepper", "Ill")]
    # (a field of its own crop beside them is still one)
    scene = recipe("a wheat field, tomatoes on one side and peppers on the other")
    assert [f.crop for f in scene.fields] == ["Wheat", "Tomato", "Pepper"]


def test_a_row_of_scenery_and_a_word_with_a_verb_ending() -> None:
    (wheat,) = recipe(
        "Frosty January picture of the winter wheat, only a few inches tall, tramlines "
        "dusted white and a row of pollard willows along the ditch."
    ).fields
    assert (wheat.variety, wheat.season, wheat.health) == ("Winter Wheat", "Winter", "Healthy")
    assert "rows" not in wheat.stated
    assert min(wheat.geometry.size_m) >= 10
    # (a row of a crop is still one row)
    (lettuce,) = recipe("a row of lettuce").fields
    assert lettuce.row_count == 1


def test_the_trees_own_blossom_and_the_veg_just_through() -> None:
    trees, veg = recipe(
        "The picture shows fruit trees behind a vegetable patch, the trees pink with "
        "blossom and the veg only just poking through the soil. Washing line and a "
        "greenhouse off to the right."
    ).fields
    assert trees.crop in ("Apple", "Pear", "Cherry", "Orange")
    assert (trees.stage, veg.stage) == ("Reproductive", "Vegetative")


def test_a_row_length_then_its_direction() -> None:
    (potatoes,) = recipe(
        "Sim scene request - Bintje potatoes, 24 rows at 0.75 m, 0.33 m between plants, rows "
        "100 m E-W, 6 m headland. Crop flowering, mid June."
    ).fields
    assert potatoes.row_bearing_deg % 180 == pytest.approx(90)
    assert potatoes.row_length_m == pytest.approx(100)
    assert potatoes.row_count == 24


def test_each_one_hectare() -> None:
    oranges, bananas = recipe(
        "Subtropical sim tile - an orange grove at 7 m x 4 m next to a banana block at 3 x 3 m, "
        "each one hectare."
    ).fields
    for field in (oranges, bananas):
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(10_000, rel=0.01)
    assert (oranges.agronomy.row_spacing_m, bananas.agronomy.row_spacing_m) == (7.0, 3.0)


def test_a_list_said_again_after_a_colon(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "We need vines and cherries for the trellis-detection net: a 1.5 acre vinyard with 3 m "
        "rows and 2 m between vines, then a cherry block on its east side at 4.6 x 2.4 m."
    )
    vines, cherries = recipe(prompt).fields
    assert (vines.crop, cherries.crop) == ("Grape", "Cherry")
    width, length = vines.geometry.size_m
    assert width * length == pytest.approx(1.5 * 4046.8564, rel=0.01)
    assert (vines.agronomy.row_spacing_m, vines.agronomy.in_row_spacing_m) == (3.0, 2.0)
    assert (cherries.agronomy.row_spacing_m, cherries.agronomy.in_row_spacing_m) == (4.6, 2.4)
    assert crop_relations(prompt) == {("east_of", "Cherry", ("Grape",))}


def test_a_total_of_rows_the_members_split() -> None:
    savoy, red = recipe(
        "Split plot, 20 rows total at 75 x 45 cm: the first 10 rows Savoy, the other 10 rows "
        "Red Express, the two halves side by side."
    ).fields
    assert (savoy.variety, red.variety) == ("Savoy", "Red Express")
    for field in (savoy, red):
        assert field.row_count == 10
        assert field.agronomy.row_spacing_m == pytest.approx(0.75)
        assert field.agronomy.in_row_spacing_m == pytest.approx(0.45)


def test_inch_rows_with_plants_inches_apart(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "spuds planted in 34 inch rows 12 in apart, 48 rows, 500 ft long; east of them 12 "
        "rows of corn on the same 34 inch spacing"
    )
    potatoes, corn = recipe(prompt).fields
    assert potatoes.row_count == 48
    assert potatoes.agronomy.row_spacing_m == pytest.approx(0.8636)
    assert potatoes.agronomy.in_row_spacing_m == pytest.approx(0.3048)
    assert corn.row_count == 12
    assert crop_relations(prompt) == {("east_of", "Maize", ("Potato",))}


def test_a_tunnel_block_is_a_field(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Pinot Nero rows 2.2 m apart, north of a tunnel block of Albion strawberries with 10 "
        "beds on 1.5 m centres."
    )
    assert named_relations(prompt) == {("north_of", "Pinot Noir", ("Albion",))}


def test_one_compass_letter_of_the_other() -> None:
    scene = recipe("2 veggie plots, 1 N of the other, thx")
    assert len(scene.fields) == 2
    assert [r.kind for r in scene.relations] == ["north_of"]


def test_a_misspelt_list_counted_after_it() -> None:
    scene = recipe("oranges: valenica + hamlin, 2 groves, both flowering, spring")
    assert [(f.variety, f.stage, f.season) for f in scene.fields] == [
        ("Valencia", "Reproductive", "Spring"),
        ("Hamlin", "Reproductive", "Spring"),
    ]


def test_a_run_of_measures_before_the_next_field() -> None:
    cherries, pears = recipe(
        "cherry orchard (lapins) rows 4.5m apart, trees every 2.5m, 12 rows + pear orchard "
        "(durondeau) west of it w/ rows 12ft apart"
    ).fields
    assert cherries.row_count == 12
    assert "rows" not in pears.stated
    assert pears.agronomy.row_spacing_m == pytest.approx(3.6576)


def test_the_vines_open_an_order(crop_relations: Callable[[str], NamedRelations]) -> None:
    prompt = "from north to south it goes: the vines, then the greens, then the cereals"
    vines, greens, cereals = recipe(prompt).fields
    assert vines.crop == "Grape"
    assert greens.crop in ("Lettuce", "Cabbage")
    assert cereals.crop in ("Wheat", "Maize")
    assert {(r.kind, r.subject, r.objects) for r in recipe(prompt).relations} >= {
        ("north_of", vines.id, (greens.id,)),
        ("north_of", greens.id, (cereals.id,)),
    }


def test_words_about_a_member_inside_a_directed_row(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Stripes from top to bottom: Durum wheat that's heading, young Flint corn, then Savoy "
        "cabbages."
    )
    assert ("north_of", "Durum", ("Flint",)) in relations
    assert ("north_of", "Flint", ("Savoy",)) in relations
    assert not any(kind == "next_to" for kind, _, _ in relations)


def test_both_of_two_placed_fields(named_relations: Callable[[str], NamedRelations]) -> None:
    relations = named_relations(
        "The Malling Centenary strawberries are west of the Sonata ones, and both lie east of "
        "the Nantes carrots."
    )
    assert {
        ("west_of", "Malling Centenary", ("Sonata",)),
        ("east_of", "Sonata", ("Nantes",)),
        ("east_of", "Malling Centenary", ("Nantes",)),
    } <= relations


def test_one_size_or_grid_each_for_counted_plots() -> None:
    conventional, dense = recipe(
        "Two orange blocks at different densities - conventional 7.2 x 3.8 m and "
        "super-high-density 3.7 x 1.2 m. SHD block west of the conventional one."
    ).fields
    assert (conventional.agronomy.row_spacing_m, conventional.agronomy.in_row_spacing_m) == (
        7.2,
        3.8,
    )
    assert (dense.agronomy.row_spacing_m, dense.agronomy.in_row_spacing_m) == (3.7, 1.2)
    first, second = recipe("two apple orchards, 100 x 50 m and 60 x 40 m").fields
    assert (first.geometry.size_m, second.geometry.size_m) == ((100.0, 50.0), (60.0, 40.0))

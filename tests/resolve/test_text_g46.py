"""Text of blind set g46 (issue 8): each miss of its blind run, fixed as the general
mechanism (fields in a strip; scenery of grain; a look then its place; likenesses of
other crops; rows of one row; sizes said "wide, long"; lists counted after them; fields
between "the two blocks"; sides said with a bare look; walks from boundary to fence)."""

from __future__ import annotations

import pytest

from agrirecipe import SceneRecipe, generate


def _crops(recipe: SceneRecipe) -> list[str | None]:
    return [f.crop for f in recipe.fields]


def _relations(recipe: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in recipe.relations}


def test_three_fields_in_a_strip_up_the_slope() -> None:
    recipe = generate(
        "Three fields in a strip running up the slope in this shot: wheat turning golden at "
        "the foot, onions in the middle, cabbages up by the hedge."
    ).recipe
    assert _crops(recipe) == ["Wheat", "Onion", "Cabbage"]
    wheat, onions, cabbages = (f.id for f in recipe.fields)
    assert ("between", onions, (wheat, cabbages)) in _relations(recipe)


def test_a_look_then_where_it_is_is_the_field_before() -> None:
    recipe = generate(
        "Lettuce heads tight and ready to cut in the near field, and past them onions with "
        "the tops flopped over, ready for lifting."
    ).recipe
    assert _crops(recipe) == ["Lettuce", "Onion"]


def test_a_grain_tower_is_scenery() -> None:
    recipe = generate(
        "This one's from the grain tower: three potato strips, Bintje in the north, Agria "
        "in the middle and Fontane in the south, all in flower."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Bintje", "Agria", "Fontane"]


def test_a_shape_of_another_crop_is_a_look() -> None:
    field = generate(
        "San Marzano tomatos on tall stakes, long plum-shaped fruit going red, August."
    ).recipe.fields[0]
    assert (field.variety, field.stage) == ("San Marzano", "Maturation")


def test_the_plot_next_over() -> None:
    recipe = generate(
        "Picking-arm test plots, 20 rows each at 1.5 m x 0.5 m: Roma in one plot, cherry "
        "tomatoes in the plot next over."
    ).recipe
    roma, cherry = recipe.fields
    assert ("next_to", cherry.id, (roma.id,)) in _relations(recipe)


def test_a_misspelt_crop_counting_its_ridges() -> None:
    recipe = generate(
        "ridge-following demo: 20 potatoe ridges on 75 cm centres and, 10 m to the east, 20 "
        "carrot ridges, also 75 cm, two rows per ridge; all rows 150 m long"
    ).recipe
    assert _crops(recipe) == ["Potato", "Carrot"]


def test_a_size_said_wide_comma_long_before_its_plots() -> None:
    recipe = generate(
        "Testing the robot's headland turns: three 12 m wide, 80 m long strips, peppers, "
        "tomatoes and cabbages from north to south."
    ).recipe
    assert [f.geometry.size_m for f in recipe.fields] == [(12.0, 80.0)] * 3


def test_trees_of_one_row_apart_are_the_trees_spacing() -> None:
    cherries, _ = generate(
        "One row of 40 Bing cherry trees, 2.5 m apart, next to a 10 x 20 m Sturon onion plot."
    ).recipe.fields
    assert cherries.row_count == 1
    assert cherries.agronomy.in_row_spacing_m == pytest.approx(2.5)


def test_a_list_of_kinds_counted_after_it() -> None:
    recipe = generate("grain + grain + veg lol 3 fields").recipe
    assert [f.category for f in recipe.fields] == ["Cereals", "Cereals", "Vegetables"]


@pytest.mark.parametrize(
    "prompt",
    [
        "agria AND bintje AND russet spuds lol, 3 plots, blight in all 3 ugh, aug",
        "lollo rosso, romaine & iceberg - 3 salad plots, young, april",
    ],
)
def test_a_list_counted_after_it_in_chat(prompt: str) -> None:
    assert len(generate(prompt).recipe.fields) == 3


def test_a_weak_name_listed_among_fruit() -> None:
    recipe = generate(
        "royal gala (ripe) + conference (ripe) + kordia cherries (ripe) 3 blocks"
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Gala", "Conference", "Kordia"]


def test_a_colour_is_no_variety_among_fruit() -> None:
    recipe = generate(
        "Here's the Chardonnay in late September, bunches golden and ready to pick, with the "
        "Pinot Noir block next to it also ripe."
    ).recipe
    assert _crops(recipe) == ["Grape", "Grape"]


def test_a_crop_alone_then_its_plot_past_a_sentence() -> None:
    assert _crops(generate("grapse. thats it. just a vinyard in fall").recipe) == ["Grape"]


def test_a_plot_said_like_after_a_crop() -> None:
    recipe = generate(
        "idk just lettuces?? like a small 20x20 m patch & a bigger one w cabbages"
    ).recipe
    assert _crops(recipe) == ["Lettuce", "Cabbage"]
    assert recipe.fields[0].geometry.size_m == (20.0, 20.0)


def test_our_only_crop_is_the_field_named_next() -> None:
    recipe = generate(
        "Beyond the hedge at the bottom of the yard is our only crop, a field of corn."
    ).recipe
    assert _crops(recipe) == ["Maize"]


@pytest.mark.parametrize(
    "prompt",
    [
        "North of the yard is a paddock of Durum, south of the yard a paddock of dent corn, "
        "and the Padron peppers sit between the two paddocks.",
        "Granny Smith on the west block, Durondeau pears on the east block, and a strip of "
        "Cayenne chillies between the two blocks, all in summer.",
    ],
)
def test_between_the_two_blocks_named(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert len(recipe.fields) == 3
    first, second, middle = (f.id for f in recipe.fields)
    between = [(r.subject, set(r.objects)) for r in recipe.relations if r.kind == "between"]
    assert between == [(middle, {first, second})]


def test_between_the_two_plots_opening_a_prompt_asks_for_them() -> None:
    recipe = generate("Between the two orchards there's a vegetable garden.").recipe
    assert len(recipe.fields) == 3


def test_between_two_fields_counted_past_words_about_them() -> None:
    recipe = generate(
        "Between my two maize fields, both Dent, I've got a strip of Sonata strawberries."
    ).recipe
    first, second, strawberries = recipe.fields
    assert ("between", strawberries.id, (first.id, second.id)) in _relations(recipe)


def test_the_grove_named_again_then_a_field() -> None:
    recipe = generate(
        "West of the Hamlin grove is the Gros Michel block, and east of the grove the Dwarf "
        "Cavendish."
    ).recipe
    hamlin, gros_michel, cavendish = recipe.fields
    assert ("east_of", cavendish.id, (hamlin.id,)) in _relations(recipe)
    assert ("west_of", gros_michel.id, (hamlin.id,)) in _relations(recipe)


def test_a_walk_from_the_north_boundary_to_the_south_fence() -> None:
    recipe = generate(
        "From the north boundary down to the south fence it goes citrus, then bananas, then "
        "a vegetable strip."
    ).recipe
    citrus, bananas, veg = (f.id for f in recipe.fields)
    assert {("north_of", citrus, (bananas,)), ("north_of", bananas, (veg,))} <= _relations(recipe)


def test_sides_of_two_counted_fields_with_a_bare_look() -> None:
    recipe = generate(
        "Two cabbage fields either side of the drainage ditch, the eastern one with black "
        "rot, the western one clean."
    ).recipe
    assert [f.health for f in recipe.fields] == ["Ill", "Healthy"]


def test_a_few_acres_of_all_is_still_a_size() -> None:
    field = generate("All 5 acres behind the barn are down to cabbages this winter.").recipe
    width, length = field.fields[0].geometry.size_m
    assert width * length == pytest.approx(5 * 4046.8564, rel=0.001)

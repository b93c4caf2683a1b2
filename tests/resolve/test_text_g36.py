"""Text of blind set g36 (issue 8): counted members that add up to the count ("4 plots, 2
of potatoes and 2 of onions"), "one per variety (...)", a middle member between the
two listed after it, "each strip with a 3 m headland", "seeded 7.5 cm apart", "same 6 m /
3 m layout", "of equal area", a texting "4 me", an arrow ("west→east"), a rough count
closing the sentence, "going golden and translucent", "its rows" of a sentence's subject,
a verb after a field's placement ("next door have fire blight"), working north, the last
of a "then" list joined by "and", a field across the whole bottom, "minus 2 metres",
"all in one big 60 ha block", "one north of the other" counting both, "in one field and
... in the other", "planted exactly the same way" and "a few chillies mixed in"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_counted_members_that_add_up_to_the_count() -> None:
    fields = recipe(
        "Field robot test with 4 plots, 2 of potatoes and 2 of onions, each 10 m x 30 m."
    )
    assert [f.crop for f in fields.fields] == ["Potato", "Potato", "Onion", "Onion"]
    assert {f.geometry.size_m for f in fields.fields} == {(10.0, 30.0)}


def test_one_per_variety_before_a_bracketed_list() -> None:
    fields = recipe(
        "Lettuce phenotyping layout, 4 plots of 6 beds each, one per variety (Romaine, Iceberg, "
        "Butterhead, Lollo Rosso). Beds 1.2 m wide centre to centre, 3 rows per bed, 30 cm "
        "in-row."
    ).fields
    assert [f.variety for f in fields] == ["Romaine", "Iceberg", "Butterhead", "Lollo Rosso"]
    for field in fields:
        assert (field.agronomy.rows_per_bed, field.agronomy.in_row_spacing_m) == (3, 0.3)


def test_a_middle_member_between_two_listed_after_it(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Three apple blocks, 10 rows each, rows 3.5 m apart: Fuji in the middle, with Cripps "
        "Pink on one side and Golden Delicious on the other."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["Fuji", "Pink Lady", "Golden Delicious"]
    assert named_relations(prompt) == {("between", "Fuji", ("Pink Lady", "Golden Delicious"))}


def test_measures_of_each_plot_and_a_seeded_spacing() -> None:
    savoy, red = recipe(
        "Savoy and Red Express cabbage strips, 20 rows each at 60 cm, 40 cm in-row, each strip "
        "with a 3 m headland. Savoy strip north of the Red Express."
    ).fields
    assert savoy.geometry.headland_m == red.geometry.headland_m == 3.0
    north, south = recipe(
        "Onion bed test: Walla Walla on the north plot, Red Baron on the south plot, 10 beds "
        "apiece (1.5 m centres, 4 rows/bed), seeded 7.5 cm apart."
    ).fields
    assert north.agronomy.in_row_spacing_m == south.agronomy.in_row_spacing_m == 0.075


def test_a_slashed_grid_and_an_equal_area() -> None:
    _, moro = recipe(
        "Citrus test site. Block 1: Navel, 120 trees, rows 6 m apart and 3 m between trees. "
        "Block 2, just east of block 1: blood oranges, 80 trees, same 6 m / 3 m layout."
    ).fields
    assert (moro.agronomy.row_spacing_m, moro.agronomy.in_row_spacing_m) == (6.0, 3.0)
    carrots, onions = recipe(
        "carrots sown at 150 plants per m2 on a 0.2 ha plot, with an onion plot of equal area "
        "adjoining it"
    ).fields
    for field in (carrots, onions):
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(2000.0, rel=0.01)


def test_casual_for_me_an_arrow_and_a_late_rough_count(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert len(recipe("sum wheat 4 me pls, 1 ha, drilled rows 12.5cm apart").fields) == 1
    relations = named_relations(
        "flint corn, field corn & popping corn, 3 plots side by side west→east in that order"
    )
    assert {("west_of", "Flint", ("Dent",)), ("west_of", "Dent", ("Popcorn",))} <= relations
    fields = recipe("some fields of fruit trees w/ fire blight, like 2 or 3").fields
    assert len(fields) == 2
    assert {f.health for f in fields} == {"Ill"}


def test_white_grapes_going_golden_and_its_rows() -> None:
    (block,) = recipe(
        "Chardonnay block in mid-August: bunches hanging under the leaves, berries going golden "
        "and translucent."
    ).fields
    assert block.stage == "Maturation"
    maize, wheat = recipe(
        "Looking across the road: the maize field is south of the wheat, and you can see its "
        "rows run east-west. The wheat is ripe and straw-coloured, the maize still green."
    ).fields
    assert "row_direction" in maize.stated
    assert "row_direction" not in wheat.stated


def test_a_verb_after_a_fields_placement_is_that_fields() -> None:
    gala, pears, cherries = recipe(
        "Farm walk notes: the Gala block looks great, the Williams pears next door have fire "
        "blight, and the Kordia cherries on the far side of the pears are fine."
    ).fields
    assert (gala.health, pears.health, cherries.health) == ("Healthy", "Ill", "Healthy")


def test_rows_of_fields_walked_and_listed(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Starting at the southern boundary and working north: greens first, then potatoes, then "
        "tomatoes, and the vines along the very top."
    )
    assert ("south_of", "Tomato", ("Grape",)) in relations
    relations = named_relations(
        "Straight behind the house are the Fuji trees, then the Pink Lady further back, and the "
        "Golden Delicious out on the far boundary."
    )
    assert ("between", "Pink Lady", ("Fuji", "Golden Delicious")) in relations
    relations = named_relations(
        "Looking at the farm map: vegetables on the left, fruit on the right, and cereals across "
        "the whole bottom."
    )
    assert {("south_of", "Wheat", ("Pepper",)), ("south_of", "Wheat", ("Orange",))} <= relations


def test_a_negative_spacing_said_in_words_is_refused() -> None:
    with pytest.raises(PromptError, match="positive"):
        generate("Lay out the vineyard by the chapel with the rows at minus 2 metres spacing.")


def test_the_plot_a_crop_is_all_in_and_its_mixed_in_plants() -> None:
    (cereals,) = recipe(
        "We're a pure arable farm - just cereals this year, all in one big 60 ha block."
    ).fields
    width, length = cereals.geometry.size_m
    assert width * length == pytest.approx(600_000.0, rel=0.01)
    (peppers,) = recipe(
        "The plot behind the barn is all capsicum this year, bell types with a few chillies "
        "mixed in."
    ).fields
    assert peppers.crop == "Pepper"


def test_one_and_the_other_said_of_two_members() -> None:
    fields = recipe(
        "Two veg plots, one north of the other, and a wheat field off to the east of both."
    ).fields
    assert [f.category for f in fields] == ["Vegetables", "Vegetables", "Cereals"]
    spring, dinkel = recipe(
        "Two wheats growing side by side, Spring Wheat in one field and dinkel in the other."
    ).fields
    assert (spring.variety, dinkel.variety) == ("Spring Wheat", "Spelt")


def test_planted_exactly_the_same_way() -> None:
    chardonnay, pinot = recipe(
        "The Chardonnay block has rows 2.5 m apart running NE-SW with a 6 m headland, and the "
        "Pinot Noir block south of it is planted exactly the same way."
    ).fields
    for field in (chardonnay, pinot):
        assert field.agronomy.row_spacing_m == 2.5
        assert field.geometry.headland_m == 6.0
        assert field.geometry.rotation_deg == pytest.approx(-45.0)

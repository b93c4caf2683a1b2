"""Text of blind set g57 (issue 8) fixed after it moved in: a spacing said bare after a
crop in a list of spacings ("maize on 75 cm"); a plural heading before counted plots; row
directions given one to each plot; a block's own measures after a colon; measures "per
plot" of the crop a sentence is about; a plot that separates two others; a farm's area
shared out ("25 of them", "the rest"); "between X on one side and Y on the other"; a
centre of scenery with fields around it; "the middle strip" of a listed row; the middle
said after a row word; a row ordered past bracketed looks; past one of the two hedges a
field lies between; measures after a label ("Tomato plots: 10 rows each, 1.5 m apart.")
are the labelled plots; "Same again in a second cabbage plot" is the whole planting again;
a list of row spacings each with its unit ("with 50 cm and 75 cm rows")."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_bare_spacing_after_a_crop_in_a_list_of_row_spacings() -> None:
    scene = recipe(
        "Robot navigation course with three strips of 12 rows each: potatoes on 90 cm rows, "
        "maize on 75 cm, wheat on 15 cm."
    )
    assert [f.crop for f in scene.fields] == ["Potato", "Maize", "Wheat"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == pytest.approx([0.9, 0.75, 0.15])
    assert [f.row_count for f in scene.fields] == [12, 12, 12]
    assert all("row_spacing" in f.stated for f in scene.fields)


def test_a_plural_heading_before_counted_plots_of_a_crop() -> None:
    scene = recipe(
        "Seeding-rate strips for the NDVI camera: three wheat plots of 10 m x 2 m at 100, 150 "
        "and 200 plants/m²."
    )
    assert [f.crop for f in scene.fields] == ["Wheat"] * 3
    assert [f.plants_per_ha for f in scene.fields] == pytest.approx(
        [1_000_000, 1_500_000, 2_000_000], rel=0.01
    )
    assert all(sorted(f.geometry.size_m) == [2.0, 10.0] for f in scene.fields)
    # ("seeding rate" is what the trial varies, not a misspelt "seedling")
    assert all("stage" not in f.stated for f in scene.fields)


def test_row_directions_given_one_to_each_plot() -> None:
    scene = recipe(
        "Three corn plots with 30 in rows, one with rows north-south, one east-west and one NE-SW."
    )
    assert [f.row_bearing_deg for f in scene.fields] == pytest.approx([0, 90, 45])
    assert [f.agronomy.row_spacing_m for f in scene.fields] == pytest.approx([0.762] * 3)


def test_one_plot_with_rows_one_way_and_one_the_other_is_no_placement() -> None:
    scene = recipe("two vineyards, one with rows north-south and one east-west")
    assert [f.row_bearing_deg for f in scene.fields] == pytest.approx([0, 90])
    assert scene.relations == ()


def test_a_blocks_measures_after_its_colon_are_its_own(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "For the vineyard robot we want a Spätburgunder block of 30 rows, 2.5 m row spacing, "
        "vines every 1.2 m, rows 90 m. Directly south of it, a Chardonnay block: 20 rows at "
        "2.2 m, vines 1 m apart, also 90 m rows."
    )
    pinot, chardonnay = recipe(prompt).fields
    assert (pinot.variety, chardonnay.variety) == ("Pinot Noir", "Chardonnay")
    assert (pinot.row_count, chardonnay.row_count) == (30, 20)
    assert (pinot.agronomy.row_spacing_m, chardonnay.agronomy.row_spacing_m) == (2.5, 2.2)
    assert (pinot.agronomy.in_row_spacing_m, chardonnay.agronomy.in_row_spacing_m) == (1.2, 1.0)
    assert (pinot.row_length_m, chardonnay.row_length_m) == pytest.approx((90, 90))
    assert crop_relations(prompt) == {("south_of", "Grape", ("Grape",))}


def test_measures_per_plot_belong_to_the_crop_the_sentence_is_about(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Weed-detection dataset: two carrot plots separated by an onion plot. Carrots on 75 cm "
        "ridges with two rows per ridge, 25 ridges per plot. Onions in single rows 30 cm "
        "apart, a bulb every 10 cm, 60 rows."
    )
    scene = recipe(prompt)
    assert [f.crop for f in scene.fields] == ["Carrot", "Carrot", "Onion"]
    assert [f.bed_count for f in scene.fields[:2]] == [25, 25]
    assert all(f.agronomy.rows_per_bed == 2 for f in scene.fields[:2])
    onion = scene.fields[2]
    assert (onion.row_count, onion.agronomy.row_spacing_m) == (60, 0.3)
    assert onion.agronomy.in_row_spacing_m == pytest.approx(0.1)
    assert crop_relations(prompt) == {("between", "Onion", ("Carrot", "Carrot"))}


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "two wheat fields separated by a strip of carrots. The wheat is ripe.",
            {("between", "Carrot", ("Wheat", "Wheat"))},
        ),
        # (scenery that separates them is no field: they stand side by side)
        ("two wheat fields separated by a hedge", {("next_to", "Wheat", ("Wheat",))}),
    ],
)
def test_a_plot_that_separates_two_others_is_between_them(
    crop_relations: Callable[[str], NamedRelations], prompt: str, expected: NamedRelations
) -> None:
    assert crop_relations(prompt) == expected


@pytest.mark.parametrize(
    "prompt",
    [
        "We farm 40 acres: 25 of them in dent corn and the rest in durum.",
        "We farm 40 acres: 25 of them in dent corn and 15 in durum.",
    ],
)
def test_a_farms_area_shared_out_by_the_number_and_the_rest(prompt: str) -> None:
    corn, durum = recipe(prompt).fields
    assert (corn.variety, durum.variety) == ("Dent", "Durum")
    acre = 4046.8564
    assert corn.geometry.area_m2 == pytest.approx(25 * acre, rel=0.01)
    assert durum.geometry.area_m2 == pytest.approx(15 * acre, rel=0.01)
    assert corn.row_count > 100  # (25 acres of corn: not 25 plants on the whole farm)


def test_of_them_after_a_count_of_plots_is_of_the_plots() -> None:
    scene = recipe("We have 12 ha: 4 apple blocks, 2 of them Gala")
    assert [f.variety for f in scene.fields][:2] == ["Gala", "Gala"]
    assert len(scene.fields) == 4
    assert all(f.variety != "Gala" for f in scene.fields[2:])


def test_the_rest_shared_by_several_crops_keeps_no_size() -> None:
    scene = recipe("A 100-acre farm: 50 acres of wheat, the rest maize and potatoes")
    assert [f.crop for f in scene.fields] == ["Wheat", "Maize", "Potato"]
    assert "size" in scene.fields[0].stated
    assert all("size" not in f.stated for f in scene.fields[1:])


def test_between_one_side_and_the_other(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "Our potato ground lies between the wheat on one side and the carrots on the other."
    assert crop_relations(prompt) == {("between", "Potato", ("Wheat", "Carrot"))}


def test_fields_around_scenery_in_the_middle(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "I want the whole farm: house in the middle, vines to the north, an orange grove to "
        "the south, tomatoes east and peppers west."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Grape", "Orange", "Tomato", "Pepper"]
    assert crop_relations(prompt) == {
        ("north_of", "Grape", ("Orange",)),
        ("west_of", "Pepper", ("Tomato",)),
    }


def test_a_field_in_the_middle_keeps_the_others_against_it(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "a vineyard in the middle, wheat to the north and maize to the south"
    relations = crop_relations(prompt)
    assert ("north_of", "Wheat", ("Grape",)) in relations
    assert ("south_of", "Maize", ("Grape",)) in relations


def test_the_middle_strip_of_a_listed_row_is_its_middle_member(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Three strips across my photo, left to right onions, lettuces and carrots, with a man "
        "hoeing the middle strip and a white van on the track."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Onion", "Lettuce", "Carrot"]
    assert ("between", "Lettuce", ("Onion", "Carrot")) in crop_relations(prompt)
    blighted = recipe("three strips: onions, lettuce and carrots, the middle strip has blight")
    assert [f.health for f in blighted.fields] == ["Healthy", "Ill", "Healthy"]


def test_the_middle_said_after_a_row_word_orders_the_row(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "potatos, carrots and onions. 3 fields in a row w/ the potatos in the middle"
    assert crop_relations(prompt) == {("between", "Potato", ("Carrot", "Onion"))}


def test_a_row_is_ordered_past_the_members_bracketed_looks(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "so on the farm we've got Savoy cabbage (bit of black rot), Red Baron onions (fine) "
        "and Iceberg lettuce (fine), all in a line north to south"
    )
    assert [f.health for f in recipe(prompt).fields] == ["Ill", "Healthy", "Healthy"]
    relations = crop_relations(prompt)
    assert ("north_of", "Cabbage", ("Onion",)) in relations
    assert ("north_of", "Onion", ("Lettuce",)) in relations


@pytest.mark.parametrize(
    "prompt",
    [
        "Between the two hedgerows is the strawberry ground, with wheat on the north side of "
        "the top hedge and a field of onions south of the bottom hedge.",
        "The strawberry ground lies between the two hedges, with wheat on the north side of "
        "the top hedge and a field of onions south of the bottom hedge.",
    ],
)
def test_past_one_of_the_two_things_a_field_lies_between_is_past_the_field(
    crop_relations: Callable[[str], NamedRelations], prompt: str
) -> None:
    relations = crop_relations(prompt)
    assert ("north_of", "Wheat", ("Strawberry",)) in relations
    assert ("south_of", "Onion", ("Strawberry",)) in relations


def test_measures_after_a_label_are_the_labelled_plots() -> None:
    # (g55-engineering-28: the tomato plots' row spacing went to the strawberry beds too,
    # and the beds were refused)
    scene = recipe(
        "Strawberries sandwiched between two tomato plots. Tomato plots: 10 rows each, 1.5 m "
        "apart. Strawberry plot: 12 beds, 1.5 m centres, 2 rows per bed."
    )
    strawberries, *tomatoes = scene.fields
    assert [f.crop for f in tomatoes] == ["Tomato", "Tomato"]
    for tomato in tomatoes:
        assert tomato.row_count == 10
        assert tomato.agronomy.row_spacing_m == pytest.approx(1.5)
    assert strawberries.agronomy.rows_per_bed == 2
    assert strawberries.agronomy.row_spacing_m == pytest.approx(1.5)
    assert strawberries.agronomy.bed_row_spacing_m < 1.5


def test_the_same_again_is_the_whole_planting() -> None:
    # (g55-engineering-18: the second plot had only the first one's size)
    first, second = recipe(
        "Cabbage transplants at 75 x 45 cm, 12 rows of 40 m, leave a 3 m headland all round. "
        "Same again in a second cabbage plot right beside the first one."
    ).fields
    for field in (first, second):
        assert field.row_count == 12
        assert field.row_length_m == pytest.approx(40)
        assert field.agronomy.row_spacing_m == pytest.approx(0.75)
        assert field.agronomy.in_row_spacing_m == pytest.approx(0.45)
        assert field.geometry.headland_m == pytest.approx(3)
    # (a size said again is still the size)
    lettuce, cabbage = recipe("a 30 x 40 m lettuce plot and the same again of cabbage").fields
    assert lettuce.geometry.size_m == cabbage.geometry.size_m == (30.0, 40.0)


def test_a_list_of_row_spacings_each_with_its_unit() -> None:
    # (g54-engineering-78 in part: "50 cm and 75 cm rows" gave both plots 75 cm)
    narrow, wide = recipe("two corn plots with 50 cm and 75 cm rows").fields
    assert (narrow.agronomy.row_spacing_m, wide.agronomy.row_spacing_m) == (0.5, 0.75)
    # (two measures of one field are no list: "at 75 cm and 9 plants/m2")
    _wheat, maize = recipe(
        "wheat, 0.5 ha, 12.5 cm drill rows, 150 plants per m2, rows E-W; right next to it 0.5 "
        "ha of maize at 75 cm and 9 plants/m2, rows in the same direction"
    ).fields
    assert maize.agronomy.row_spacing_m == pytest.approx(0.75)
    spacing = maize.agronomy.row_spacing_m * maize.agronomy.in_row_spacing_m
    assert 10_000 / spacing == pytest.approx(90_000, rel=0.01)  # plants per hectare

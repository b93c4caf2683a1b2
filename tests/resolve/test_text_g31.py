"""Text of blind set g31 (issue 8): beds counted with their rows ("8 raised beds with two
rows of plants on each"), "on 30 in. rows", a count said again as different crops, "as
two neighbouring plots", "the same bed spec", bed centres said with "between", a fronted
"Between the two orchards", the bottom two thirds, "top" as no crop, a cereal greening
up, "a healthy stand", "New Zealand orchard, a single block of Royal Gala", two
sentences joined by "and" keeping their own health, an order said before the farm's
place, and looks of disease caught from a neighbour or heads rotting."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_beds_counted_with_their_rows_are_the_fields_beds() -> None:
    (elsanta,) = recipe(
        "Our Elsanta beds in June, the berries bright red and ready to pick. I counted 8 "
        "raised beds with two rows of plants on each, straw between them, and the pickers' "
        "crates are stacked by the farm track."
    ).fields
    assert (elsanta.variety, elsanta.stage) == ("Elsanta", "Maturation")
    assert {"beds", "rows_per_bed"} <= set(elsanta.stated)
    assert elsanta.bed_count == 8 and elsanta.agronomy.rows_per_bed == 2


def test_rows_in_inches_written_in_dot() -> None:
    (corn,) = recipe(
        "Field corn at 34,000 plants per acre on 30 in. rows, 40 acres. Drone stand count on "
        "the young plants."
    ).fields
    assert corn.agronomy.row_spacing_m == pytest.approx(0.762)
    assert corn.plants_per_ha == pytest.approx(84_015.8, rel=0.01)
    assert corn.geometry.area_m2 == pytest.approx(161_874, rel=0.01)


def test_a_count_said_again_as_different_crops() -> None:
    fields = recipe(
        "Could you generate three vegetable strips for the robot? Each 10 rows x 20 m at 0.5 m "
        "row spacing, and three different crops please."
    ).fields
    assert len(fields) == 3
    assert len({f.crop for f in fields}) == 3
    assert {f.category for f in fields} == {"Vegetables"}


def test_plots_said_neighbouring_with_as(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Red Baron and Walla Walla onions as two neighbouring plots, both 24 rows x 50 m, "
        "30 cm rows, ten plants per metre of row, rows at a bearing of 60 degrees."
    )
    assert named_relations(prompt) == {("next_to", "Walla Walla", ("Red Baron",))}


def test_the_same_bed_spec() -> None:
    iceberg, boston = recipe(
        "Iceberg transplants at 75,000 plants/ha: 20 beds of 80 m, 1 m bed centres, 3 rows per "
        "bed. Then 10 beds of Boston lettuce with the same bed spec, east of the iceberg."
    ).fields
    assert (iceberg.variety, boston.variety) == ("Iceberg", "Butterhead")
    assert (boston.agronomy.rows_per_bed, boston.agronomy.row_spacing_m) == (3, 1.0)
    assert boston.bed_count == 10


def test_bed_centres_said_with_between() -> None:
    fields = recipe(
        "Three strawberry plots, west to east: Sonata, Centenary, Elsanta. Each plot is 5 beds "
        "with 1.2 m between bed centres, 2 rows per bed, beds 60 m long."
    ).fields
    assert [f.variety for f in fields] == ["Sonata", "Malling Centenary", "Elsanta"]
    assert all(f.agronomy.row_spacing_m == 1.2 and f.bed_count == 5 for f in fields)


def test_a_fronted_between_two_counted_fields(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    scene = recipe("Between the two orchards there's a vegetable garden.")
    first, second, garden = scene.fields
    assert garden.category == "Vegetables"
    assert {(r.kind, r.subject, frozenset(r.objects)) for r in scene.relations} == {
        ("between", garden.id, frozenset((first.id, second.id)))
    }


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("Top third of the farm is stone fruit, the bottom two thirds are grain.", 2),
        (
            "In March the farm looks like this: a flock of sheep in the top paddock, wheat "
            "greening up in the two big fields, and the orchard about to blossom.",
            3,
        ),
        (
            "Our whole finca on Tenerife is Chiquita bananas, the bunches hanging and ripening "
            "in August, a healthy stand.",
            1,
        ),
        ("New Zealand orchard, a single block of Royal Gala, harvest-ready in March, healthy.", 1),
    ],
)
def test_words_that_ask_for_no_more_fields(prompt: str, crops: int) -> None:
    assert len(recipe(prompt).fields) == crops


def test_a_cereal_greening_up_is_young_not_ill() -> None:
    fields = recipe(
        "In March the farm looks like this: a flock of sheep in the top paddock, wheat greening "
        "up in the two big fields, and the orchard about to blossom."
    ).fields
    wheat = [f for f in fields if f.crop == "Wheat"]
    assert [(f.stage, f.health) for f in wheat] == [("Vegetative", "Healthy")] * 2
    (orange,) = recipe("Valencia oranges with greening").fields
    assert orange.health == "Ill"


def test_two_sentences_joined_by_and_keep_their_own_health() -> None:
    grapes, corn, lettuce = recipe(
        "in septmber the grapes r ripe, the corn is nearly there and the lettuce has got mildew"
    ).fields
    assert (grapes.stage, corn.crop, corn.health, lettuce.health) == (
        "Maturation",
        "Maize",
        "Healthy",
        "Ill",
    )
    both = recipe("the corn and the lettuce have mildew").fields
    assert [f.health for f in both] == ["Ill", "Ill"]


def test_an_order_said_before_the_farms_place(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Top to bottom on our hillside farm in Madeira: Gros Michel bananas, then a strip of "
        "Dwarf Cavendish, then the Hamlin oranges."
    )
    assert ("north_of", "Gros Michel", ("Cavendish",)) in relations
    assert ("north_of", "Cavendish", ("Hamlin",)) in relations


@pytest.mark.parametrize(
    "prompt",
    [
        "The outdoor tomatos got late blight: dark water-soaked lesions on leaves and stems, "
        "white mould underneath, the fruit going brown. The potato patch beside them caught it "
        "as well. Wet August, a hosepipe coiled by the water butt.",
        "January King cabbages, purple-tinged outer leaves stiff with frost, and beside them "
        "the last of the Red Express, split heads rotting in the mud. Shot in February.",
    ],
)
def test_a_neighbour_ill_too(prompt: str) -> None:
    first, second = recipe(prompt).fields
    assert first.crop in ("Tomato", "Cabbage")
    assert second.health == "Ill"


def test_a_sugar_beet_clamp_is_scenery() -> None:
    (wheat,) = recipe(
        "The wheat has only just emerged, thin green lines in the brown soil, and there's "
        "hoarfrost on the leaves this December morning. Tramlines, and a sugar beet clamp by "
        "the road."
    ).fields
    assert (wheat.stage, wheat.season) == ("Vegetative", "Winter")


def test_a_few_rows_on_beds_of_a_width_and_identical_beds() -> None:
    imperator, chantenay = recipe(
        "For the root-imaging rover: 1 acre of Imperator carrots, 3 rows on 40-inch beds, and a "
        "second acre of Chantenay on identical beds north of it."
    ).fields
    for field in (imperator, chantenay):
        assert (field.agronomy.rows_per_bed, field.agronomy.row_spacing_m) == (3, 1.016)
        assert field.geometry.area_m2 == pytest.approx(4046.86, rel=0.01)
    # (twenty rows on 1.5 m beds are the field's rows, not rows on each bed)
    (lettuce,) = recipe("lettuce, 20 rows on 1.5 m beds").fields
    assert lettuce.agronomy.rows_per_bed == 1 and lettuce.row_count == 20


def test_a_count_said_bare_after_a_labelled_block() -> None:
    one, two = recipe(
        "Two orange blocks for the sprayer-drone path planner, both at 6 m between rows and 4 m "
        "between trees. Block 1 has 200 trees; block 2 has 300 and lies east of block 1."
    ).fields
    assert (one.nominal_plant_count, two.nominal_plant_count) == (200, 300)


def test_a_variety_listed_bare_then_named_with_its_plot(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "For a robotic pruning test we want staked San Marzano and Beefsteak tomatoes in two "
        "plots. San Marzano: 6 single rows 1.5 m apart, plants 50 cm apart, 40 m rows. "
        "Beefsteak plot to the south of it: 4 rows 1.8 m apart, 60 cm in-row, same 40 m row "
        "length. Rows E-W throughout."
    )
    assert [f.variety for f in recipe(prompt).fields] == ["San Marzano", "Beefsteak"]
    assert named_relations(prompt) == {("south_of", "Beefsteak", ("San Marzano",))}
    # (a second block of a variety named with its own block is still a second field)
    assert len(recipe("a Gala block, and a second Gala block north of it").fields) == 2

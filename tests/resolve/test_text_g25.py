"""Text of blind set g25 (issue 8): a count of plants said again without its noun ("40
Regina cherry trees and 60 Bing", "Kordia with 8 rows, Regina with 6"), a colour that
is a crop's name before "fruit", the plots a list is in said after it, ground with
nothing on it, a plot's two halves, a count after a list, "one field of each", plants
per plot, measures in inches written "in" and in brackets, a planting grid with a word
for its kind, "24-ridge plots", an order said after a list, "goldn acre"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe._errors import PromptError
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def counted(field: object) -> int:
    return int(field.nominal_plant_count)  # type: ignore[attr-defined]


def test_a_count_said_again_without_its_noun() -> None:
    regina, bing = recipe(
        "Two little blocks behind the house, 40 Regina cherry trees and 60 Bing, both white "
        "with blossom and bees everywhere. April."
    ).fields
    assert (regina.variety, counted(regina), bing.variety, counted(bing)) == (
        "Regina",
        40,
        "Bing",
        60,
    )
    fields = recipe("120 Gala apple trees, 80 Fuji and 60 Jonagold").fields
    assert [(f.variety, counted(f)) for f in fields] == [
        ("Gala", 120),
        ("Fuji", 80),
        ("Jonagold", 60),
    ]
    kordia, regina = recipe(
        "Cherry test rows for the shake-harvester sim: a Kordia block and a Regina block, "
        "adjacent, both 4.6 m x 2.4 m, Kordia with 8 rows, Regina with 6, rows N-S."
    ).fields
    assert (kordia.row_count, regina.row_count) == (8, 6)


def test_a_colour_named_like_a_crop_before_fruit() -> None:
    for prompt in (
        "About 3 acres of sweet peppers in this one, red, yellow and orange fruit all "
        "coloured up. Late September.",
        "sweet peppers with orange fruit",
    ):
        assert [f.crop for f in recipe(prompt).fields] == ["Pepper"]
    # (fruit of no other crop named: the oranges themselves)
    assert [f.crop for f in recipe("a grove loaded with orange fruit").fields] == ["Orange"]


def test_the_plots_a_list_is_in_said_after_it(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Navel oranges at 7 x 4 m and Moro blood oranges at 6 x 3 m, adjacent blocks of 150 "
        "trees each, harvest-ready, January."
    )
    navel, moro = recipe(prompt).fields
    assert (navel.variety, moro.variety) == ("Navel", "Moro")
    assert counted(navel) == counted(moro) == 150
    assert (navel.agronomy.row_spacing_m, moro.agronomy.row_spacing_m) == (7.0, 6.0)
    assert named_relations(prompt) == {("next_to", "Moro", ("Navel",))}
    gala, fuji = recipe("Gala and Fuji in adjacent 2 ha blocks").fields
    assert gala.geometry.area_m2 == pytest.approx(20000, rel=0.01)
    assert fuji.geometry.area_m2 == pytest.approx(20000, rel=0.01)


def test_roots_as_the_plants_a_spacing_is_between() -> None:
    (carrots,) = recipe(
        "Nantes carrots, harvest-ready, October scene: 20 ridges on 75 cm, twin rows per "
        "ridge, about 2 cm between roots."
    ).fields
    assert (carrots.bed_count, carrots.agronomy.rows_per_bed) == (20, 2)
    assert carrots.agronomy.in_row_spacing_m == pytest.approx(0.02)


def test_bare_ground_is_no_field() -> None:
    with pytest.raises(PromptError):
        recipe(
            "Set up a drone test area: gravel track, two tractors, a weather mast and a "
            "post-and-wire fence around a bare 50 x 50 m patch of ground."
        )


def test_a_plots_two_halves() -> None:
    fields = recipe("vineyard w chardonay on one side & pinot noire on the other").fields
    assert [f.variety for f in fields] == ["Chardonnay", "Pinot Noir"]


@pytest.mark.parametrize(
    ("prompt", "varieties"),
    [
        (
            "omg ok flint corn & dent corn 2 fields fall both dried down n ready for harvest",
            ["Flint", "Dent"],
        ),
        (
            "roma toms & beef tomatoes & cherry toms lol 3 plots summer",
            ["Roma", "Beefsteak", "Cherry"],
        ),
        (
            "Cabbage farm: Savoy, Red Express, January King and Golden Acre, one field of each.",
            ["Savoy", "Red Express", "January King", "Golden Acre"],
        ),
    ],
)
def test_a_count_said_after_a_list(prompt: str, varieties: list[str]) -> None:
    assert [f.variety for f in recipe(prompt).fields] == varieties


def test_plants_per_plot() -> None:
    chardonnay, pinot = recipe(
        "Two blocks of vines, 8 ft rows with 6 ft between vines, 500 vines per block: "
        "Chardonnay on the north side, Pinot Noir on the south side."
    ).fields
    assert (chardonnay.variety, pinot.variety) == ("Chardonnay", "Pinot Noir")
    assert counted(chardonnay) == counted(pinot) == 500
    assert chardonnay.agronomy.row_spacing_m == pytest.approx(8 * 0.3048)
    # (a count of plants in one plot still names its crop)
    assert [f.crop for f in recipe("1200 vines in one block").fields] == ["Grape"]


def test_measures_in_inches() -> None:
    (corn,) = recipe(
        "sweet corn at tasseling for a July drone flight -- 30-inch rows, 32 of them, 150 m "
        "long, 8 in. between plants"
    ).fields
    assert (corn.row_count, corn.agronomy.row_spacing_m) == (32, pytest.approx(0.762))
    corn, wheat = recipe(
        "US test site, imperial units please: a 100 ft x 300 ft corn block on 30 in rows and, "
        "east of it, a 100 ft x 300 ft wheat block drilled at 7.5 in."
    ).fields
    assert wheat.agronomy.row_spacing_m == pytest.approx(7.5 * 0.0254)
    (carrots,) = recipe(
        "Danvers carrots with Alternaria leaf blight, September: 12 ridges at 30 in, 2 rows "
        "per ridge, 20 m rows."
    ).fields
    assert (carrots.bed_count, carrots.agronomy.row_spacing_m) == (12, pytest.approx(0.762))
    dent, flint = recipe(
        "Two maize hybrids side by side: dent corn at 85,000 plants/ha and flint corn at "
        "95,000/ha, both on 30 in (76.2 cm) rows, 16 rows each, rows north-south."
    ).fields
    assert dent.agronomy.row_spacing_m == flint.agronomy.row_spacing_m == pytest.approx(0.762)


def test_a_planting_grid_with_a_word_for_its_kind() -> None:
    valencia, hamlin = recipe(
        "Citrus block comparison for the canopy-LiDAR team: Valencia at a conventional "
        "7.2 x 3.8 m and Hamlin at super-high density, 3.7 x 1.2 m. Hamlin block directly "
        "north of the Valencia block, each 1 ha."
    ).fields
    assert (valencia.agronomy.row_spacing_m, valencia.agronomy.in_row_spacing_m) == (7.2, 3.8)
    assert valencia.geometry.area_m2 == pytest.approx(10000, rel=0.01)
    assert (hamlin.agronomy.row_spacing_m, hamlin.agronomy.in_row_spacing_m) == (3.7, 1.2)


def test_plots_counted_in_ridges_and_rows() -> None:
    bintje, agria = recipe(
        "Two potato varieties for the late-blight drone: Bintje (blighted) and Agria (healthy) "
        "in adjacent 24-ridge plots, ridges on 75 cm, 33 cm between tubers."
    ).fields
    assert (bintje.bed_count, agria.bed_count) == (24, 24)
    assert (bintje.health, agria.health) == ("Ill", "Healthy")
    (maize,) = recipe("a 12-row maize block").fields
    assert maize.row_count == 12


def test_an_order_said_after_a_list(named_relations: Callable[[str], NamedRelations]) -> None:
    assert named_relations(
        "Onion trio for a bulb-counting camera: Sturon, Red Baron and Stuttgarter Riesen, "
        "laid out north to south, each 6 beds of 4 rows on 1.5 m centres, 8 cm in the row."
    ) >= {("north_of", "Sturon", ("Red Baron",)), ("north_of", "Red Baron", ("Stuttgarter",))}


def test_a_typo_inside_a_name_with_a_unit_word() -> None:
    cabbages, _ = recipe("goldn acre cabbages nxt to a goldn delicious orchard").fields
    assert cabbages.variety == "Golden Acre"
    (wheat,) = recipe("5 acre whaet fild").fields
    assert wheat.geometry.area_m2 == pytest.approx(5 * 4046.8564224, rel=0.01)


def test_a_sign_of_pests_or_a_telling_cue_beats_a_general_look() -> None:
    (lettuce,) = recipe(
        "Cos lettuce in long beds, upright dark-green heads, but slug holes and slime trails "
        "all over the outer leaves. Wet morning in September."
    ).fields
    assert lettuce.health == "Ill"
    (spelt,) = recipe(
        "A field of dinkel in May, still green and knee-high with no ears out yet"
    ).fields
    assert spelt.stage == "Vegetative"
    (wheat,) = recipe("wheat still green").fields
    assert wheat.stage == "Reproductive"  # (the look alone still says it)
    (bananas,) = recipe(
        "Chiquita bananas on the plantation, the purple flower hanging off the end of each new "
        "bunch"
    ).fields
    assert bananas.stage == "Reproductive"


def test_a_month_said_with_the_plot_the_fields_stand_on() -> None:
    navel, valencia = recipe(
        "Navel and Valencia Late blocks side by side on a terrace in the Algarve in March - the "
        "Navels loaded with ripe fruit, the Valencias still in flower."
    ).fields
    assert navel.season == valencia.season == "Spring"


@pytest.mark.parametrize(
    ("prompt", "relation"),
    [
        (
            "A hazel hedge separates our Golden Delicious apples, hanging yellow and ready to "
            "pick, from a field of January King cabbages.",
            ("next_to", "Golden Delicious", ("January King",)),
        ),
        (
            "Two onion fields meet at the hedge. The Sturon looks fine, but the Walla Walla has "
            "pale elongated lesions on the leaves.",
            ("next_to", "Walla Walla", ("Sturon",)),
        ),
        (
            "an orchard in full blossom, a vineyard down by the river, and between the two a "
            "strip of strawberries on straw.",
            ("between", "Strawberry", ("Orange", "Grape")),
        ),
        (
            "Grain maize at 80,000 plants/ha on the big field and, beside it, sweetcorn at "
            "65,000 plants per hectare.",
            ("next_to", "Sweet Corn", ("Maize",)),
        ),
        (
            "Bintje (blighted) and Agria (healthy) in adjacent 24-ridge plots, ridges on 75 cm.",
            ("next_to", "Agria", ("Bintje",)),
        ),
    ],
)
def test_fields_said_to_touch(
    prompt: str,
    relation: tuple[str, str, tuple[str, ...]],
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert relation in named_relations(prompt)


def test_orders_and_places(named_relations: Callable[[str], NamedRelations]) -> None:
    assert named_relations(
        "Starting from the bottom: grain, then greens, then the orchard up top."
    ) >= {
        ("south_of", "Wheat", ("Cabbage",)),
        ("south_of", "Cabbage", ("Apple",)),
    }
    # (each placed where said: not the order named)
    assert named_relations(
        "Three pear blocks in a line: Conference at the west end, Comice at the east end and "
        "Williams between them."
    ) >= {("between", "Williams", ("Conference", "Doyenne du Comice"))}
    assert named_relations(
        "Lollo and Bibb lettuce in adjacent beds, both west of the Imperator carrots."
    ) >= {("west_of", "Lollo Rosso", ("Imperator",)), ("west_of", "Butterhead", ("Imperator",))}


def test_no_two_of_them_the_same_crop() -> None:
    fields = recipe(
        "Two cereal fields and two veg fields, and no two of them the same crop."
    ).fields
    assert len(fields) == 4
    assert len({f.crop for f in fields}) == 4


def test_a_crop_on_both_sides_of_scenery_is_two_fields() -> None:
    left, right = recipe(
        "Photo taken from the ditch bank with cereals on both sides of the track - the field on "
        "the left still green and leafy, the one on the right golden with the heads bent right "
        "over."
    ).fields
    assert {left.category, right.category} == {"Cereals"}
    assert right.stage == "Maturation"
    assert [f.crop for f in recipe("wheat on both sides of the track").fields] == ["Wheat"] * 2


def test_a_crop_on_both_sides_of_a_field(named_relations: Callable[[str], NamedRelations]) -> None:
    fields = recipe("onions on both sides of the potatoes").fields
    assert sorted(f.crop for f in fields) == ["Onion", "Onion", "Potato"]
    assert named_relations("onions on both sides of the potatoes") == {
        ("between", "Potato", ("Onion", "Onion"))
    }


def test_a_walk_from_the_field_furthest_one_way(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations(
        "From the church tower you can make out three of our fields: Agria potatoes furthest "
        "north, then a strip of Stuttgarter onions, and Chantenay carrots at the southern end."
    ) >= {("north_of", "Agria", ("Stuttgarter",)), ("north_of", "Stuttgarter", ("Chantenay",))}

"""Text of blind set g30 (issue 8): compass letters as an order ("in a row, w to e"), one
side said of one of two fields ("hamlin on the left"), the crop named again with another
variety in brackets, a season taken back ("summer... jk make it autumn"), a heading that
counts one field, the side plots of a farm said one after the other, zones numbered with
their side in brackets, "one per quarter", fields that "run right up to" another, holes
chewed in the leaves, a second bed count "also on 1.5 m centres", ripe bunches and fresh
shoots, "red-orange" cobs, weather in the west, a plot said after a crop's look, "Pinto
Noir", and "the winter one" of Winter Wheat and Spring Wheat."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_compass_letters_give_the_order_of_a_row(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "tomatoes (beefsteak) + tomatoes (roma) + peppers (california wonder) in a row, w to e"
    scene = recipe(prompt)
    assert [f.variety for f in scene.fields] == ["Beefsteak", "Roma", "California Wonder"]
    assert not any("row_direction" in f.stated for f in scene.fields)
    relations = named_relations(prompt)
    assert ("west_of", "Beefsteak", ("Roma",)) in relations
    assert ("west_of", "Roma", ("California Wonder",)) in relations


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "hamlin + valencia orange groves, hamlin on the left",
            ("west_of", "Hamlin", ("Valencia",)),
        ),
        (
            "sonata strawbs & elsanta strawberries, sonata up north, both ripe in june",
            ("north_of", "Sonata", ("Elsanta",)),
        ),
        (
            "hiya!! need savoy cabbage & golden acre cabbage, savoy on the left",
            ("west_of", "Savoy", ("Golden Acre",)),
        ),
    ],
)
def test_one_side_said_of_one_of_two_fields(
    named_relations: Callable[[str], NamedRelations],
    prompt: str,
    expected: tuple[str, str, tuple[str, ...]],
) -> None:
    assert named_relations(prompt) == {expected}


def test_both_fields_on_one_side_place_neither(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations("wheat and maize on the left") == set()


def test_a_season_taken_back() -> None:
    fields = recipe("lady finger bananas nxt 2 gros michel, summer... jk make it autumn").fields
    assert [(f.variety, f.season) for f in fields] == [
        ("Lady Finger", "Fall"),
        ("Gros Michel", "Fall"),
    ]
    (pears,) = recipe("healthy pears, sorry i mean ill pears").fields
    assert pears.health == "Ill"


def test_a_heading_that_counts_one_field() -> None:
    (gala,) = recipe(
        "We went down to a single crop a few years back: one 4 ha block of Gala apples. This "
        "April it's in full blossom, not a spot of scab, and the packing shed sits at its south "
        "end."
    ).fields
    assert (gala.variety, gala.stage, gala.health) == ("Gala", "Reproductive", "Healthy")
    assert gala.geometry.size_m[0] * gala.geometry.size_m[1] == pytest.approx(40_000, rel=0.01)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "On the banana farm the south block is Grande Naine and the north block is Lady "
            "Finger.",
            {("south_of", "Grand Nain", ("Lady Finger",))},
        ),
        (
            "the south block is Gala and the north block is Fuji.",
            {("south_of", "Gala", ("Fuji",))},
        ),
    ],
)
def test_side_plots_said_one_after_the_other(
    named_relations: Callable[[str], NamedRelations], prompt: str, expected: NamedRelations
) -> None:
    assert named_relations(prompt) == expected


def test_numbered_zones_with_their_side_in_brackets(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "Zone 1 (north end): Bing cherries. Zone 2: Doyenné du Comice pears. Zone 3 (south "
        "end): Fuji apples."
    )
    assert ("north_of", "Bing", ("Doyenne du Comice",)) in relations
    assert ("north_of", "Doyenne du Comice", ("Fuji",)) in relations


def test_one_per_quarter_is_no_member(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Four different crops, one per quarter: maize in the north-west quarter, wheat "
        "north-east, potatoes south-west, carrots south-east."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Maize", "Wheat", "Potato", "Carrot"]
    assert named_relations(prompt) == {
        ("north_of", "Maize", ("Potato",)),
        ("north_of", "Wheat", ("Carrot",)),
        ("west_of", "Maize", ("Wheat",)),
        ("west_of", "Potato", ("Carrot",)),
    }


def test_a_field_running_right_up_to_another(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "The Golden Acre cabbages run right up to the Golden Delicious trees."
    assert named_relations(prompt) == {("next_to", "Golden Acre", ("Golden Delicious",))}


def test_holes_chewed_in_the_leaves() -> None:
    (cabbages,) = recipe(
        "From the yard you look straight over our only field - about 2 hectares of cabbages, "
        "with big holes chewed in the leaves."
    ).fields
    assert cabbages.health == "Ill"


def test_beds_also_on_the_same_centres() -> None:
    elsanta, albion = recipe(
        "Block A is Elsanta strawberries, 10 raised beds on 1.5 m centres, two rows per bed, "
        "beds 60 m long. Right next to it Block B is Albion, 6 beds, also on 1.5 m centres."
    ).fields
    assert {"beds", "bed_width"} <= set(albion.stated)
    assert (albion.agronomy.row_spacing_m, elsanta.agronomy.row_spacing_m) == (1.5, 1.5)
    assert elsanta.agronomy.rows_per_bed == 2


@pytest.mark.parametrize(
    ("prompt", "crop", "stage"),
    [
        (
            "A vineyard on the steep slope above the river, bunches purple and hanging heavy, "
            "pickers with crates between the rows, late afternoon sun.",
            "Grape",
            "Maturation",
        ),
        (
            "two fields of spuds in the shot, one in full flower and the other freshly "
            "emerged, a stone barn between them",
            "Potato",
            "Vegetative",
        ),
    ],
)
def test_looks_of_ripe_bunches_and_fresh_shoots(prompt: str, crop: str, stage: str) -> None:
    last = recipe(prompt).fields[-1]
    assert (last.crop, last.stage) == (crop, stage)


def test_a_colour_joined_to_orange_is_no_orange_field(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Late August photo: a strip of Flint corn with the red-orange cobs ripening, next to a "
        "field of Popcorn that is still tasselling."
    )
    flint, popcorn = recipe(prompt).fields
    assert (flint.variety, flint.stage, popcorn.variety, popcorn.stage) == (
        "Flint",
        "Maturation",
        "Popcorn",
        "Reproductive",
    )
    assert named_relations(prompt) == {("next_to", "Flint", ("Popcorn",))}
    # (the blood orange by its colour is still a variety)
    (moro,) = recipe("a block of red oranges").fields
    assert moro.variety == "Moro"


def test_leaves_collapsed_under_a_fuzz_are_ill() -> None:
    onions, wheat = recipe(
        "I photographed a half-hectare plot of onions whose leaves have yellowed and collapsed "
        "under a grey-violet fuzz; the wheat field north of it looks clean."
    ).fields
    assert (onions.health, wheat.health) == ("Ill", "Healthy")


def test_weather_in_the_west_places_no_field(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "the corn's waist high and deep green, rows running north to south, a centre pivot "
        "parked over it, and along its east side a strip of onions. big thunderclouds building "
        "in the west"
    )
    assert named_relations(prompt) == {("east_of", "Onion", ("Maize",))}


@pytest.mark.parametrize(
    ("prompt", "area"),
    [
        (
            "Spelt in ear and just flowering, a 2 ha field edged by a hawthorn hedge, taken in "
            "June.",
            20_000,
        ),
        (
            "Cavendish bananas on Martinique in March, hands of fruit fat and ready to cut, a "
            "1.5 ha block with the cableway running through it.",
            15_000,
        ),
    ],
)
def test_a_plot_said_after_the_crops_looks_is_its_plot(prompt: str, area: float) -> None:
    (field,) = recipe(prompt).fields
    assert field.geometry.size_m[0] * field.geometry.size_m[1] == pytest.approx(area, rel=0.01)


def test_two_letters_swapped_in_a_two_word_variety() -> None:
    (vines,) = recipe(
        "Pinto Noir vines in flower, the tiny green clusters just opening, June, the winery "
        "roof in the background."
    ).fields
    assert (vines.variety, vines.stage) == ("Pinot Noir", "Reproductive")


def test_a_member_named_by_the_first_word_of_its_variety() -> None:
    fields = recipe(
        "Snapshot of the Winter Wheat and Spring Wheat plots next to each other in April, the "
        "winter one much taller and darker."
    ).fields
    assert [(f.variety, f.season) for f in fields] == [
        ("Winter Wheat", "Spring"),
        ("Spring Wheat", "Spring"),
    ]


def test_three_plots_of_a_list_of_three(named_relations: Callable[[str], NamedRelations]) -> None:
    fields = recipe(
        "hyperspectral calibration strips: three 12 x 100 m strips of winter wheat, spelt and "
        "durum, all drilled at 15 cm, with 3 m grass tracks between them"
    ).fields
    assert [f.variety for f in fields] == ["Winter Wheat", "Spelt", "Durum"]
    assert all(f.geometry.size_m == (12.0, 100.0) for f in fields)
    assert all(f.agronomy.row_spacing_m == 0.15 for f in fields)


def test_rows_the_same_way_as_the_field_before() -> None:
    for prompt, bearing in (
        (
            "Cabbage field for the robot, 75cm rows, 45cm apart in the row, 2 ha, rows EW. West "
            "of it a 3 ha maize field, same row direction.",
            90.0,
        ),
        (
            "tomatoes at 3.3 plants per m², rows 1.5 m apart, 1 ha, rows running 20 degrees "
            "west of north; a 0.5 ha pepper plot beside it with rows the same way",
            160.0,
        ),
    ):
        fields = recipe(prompt).fields
        assert [f.row_bearing_deg for f in fields] == [bearing, bearing]
        assert all("row_direction" in f.stated for f in fields)


def test_sizes_said_apiece() -> None:
    savoy, red = recipe(
        "cabbage plots for training weed-detection nets: Savoy and Red Express, 0.5 ha apiece, "
        "70 cm rows, 40 cm in-row, 8 m headland. The Red Express plot sits east of the Savoy one."
    ).fields
    for field in (savoy, red):
        assert field.geometry.size_m[0] * field.geometry.size_m[1] == pytest.approx(5000, rel=0.01)


def test_a_grid_of_one_distance() -> None:
    bananas, citrus = recipe(
        "tropical test site: banana block west of a citrus block; bananas on a 3 m grid, citrus "
        "6 m between rows and 3 m in the row, rows N-S in both"
    ).fields
    assert (bananas.agronomy.row_spacing_m, bananas.agronomy.in_row_spacing_m) == (3.0, 3.0)
    assert bananas.agronomy.rows_per_bed == 1
    assert (citrus.agronomy.row_spacing_m, citrus.agronomy.in_row_spacing_m) == (6.0, 3.0)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "Two maize plots to compare row widths for our LiDAR: one at 30-inch rows, one at "
            "36-inch rows, the 30-inch plot west of the 36-inch plot",
            [0.762, 0.9144],
        ),
        (
            "two wheat plots, one at 12 cm rows and the other at 25 cm rows; the 25 cm one is "
            "north of the 12 cm one",
            [0.12, 0.25],
        ),
    ],
)
def test_members_named_again_by_their_measure(prompt: str, expected: list[float]) -> None:
    scene = recipe(prompt)
    assert [f.agronomy.row_spacing_m for f in scene.fields] == pytest.approx(expected)
    first, second = (f.id for f in scene.fields)
    ((kind, subject, objects),) = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert (kind, subject, objects) in {
        ("west_of", first, (second,)),
        ("north_of", second, (first,)),
    }

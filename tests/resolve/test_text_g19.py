"""Text of blind set g19 (issue 8): fields a counted list still lacks named later, scenery
trees and grass strips, berries and fruit of the field named, purposes about a crop, a
heading of plural plots, settings written as "beds = 10", measures side by side in
brackets, looks of late blight and of ripening, short month names, long typos, sides of a
farm and of a view."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "Looking across the valley you can see three fields: cabbages nearest to me, a strip "
            "of onions in between, and a field of sweetcorn up the hill.",
            ["Cabbage", "Onion", "Maize"],
        ),
        (
            "Cold clear morning in the pear orchard, hoarfrost on every branch; there's a "
            "pruning trailer on the grass strip.",
            ["Pear"],
        ),
        (
            "pasta wheat in southern Italy in early June, the ears turning gold. An old stone "
            "farmhouse and cypress trees on the ridge",
            ["Wheat"],
        ),
        (
            "pic of strawbery plants in a field with loads of ripe red berries under the leaves",
            ["Strawberry"],
        ),
        (
            "Bell peppers with dark scabby spots on the fruit and speckled leaves.",
            ["Pepper"],
        ),
        (
            "Vineyard test blocks for a grape-yield camera, three blocks from west to east: "
            "Chardonnay, Riesling, Cabernet.",
            ["Grape", "Grape", "Grape"],
        ),
        (
            "Navel and blood orange blocks side by side for citrus canopy scans, 200 trees each.",
            ["Orange", "Orange"],
        ),
        (
            "banana and orange plots next to each other, both with 6 m between rows? It's for a "
            "tropical-orchard SLAM test.",
            ["Banana", "Orange"],
        ),
        (
            "The wheat field lies between the corn and the potatoes, with hawthorn hedges on "
            "both sides.",
            ["Wheat", "Maize", "Potato"],
        ),
        (
            "Half a hectare each of Cos lettuce and Savoy cabbage, side by side inside the old "
            "walled garden, both still young.",
            ["Lettuce", "Cabbage"],
        ),
    ],
)
def test_no_phantom_field(prompt: str, crops: list[str]) -> None:
    # (each gave a field of a crop chosen at random, or one field too many, or was refused)
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_a_count_of_fields_said_after_them() -> None:
    assert len(recipe("fruit & veg fields, like 4 or 5 of em").fields) == 4
    # (a list after the count is still the list)
    assert [f.crop for f in recipe("the plots, 3 of them, wheat maize and potatoes").fields] == [
        "Wheat",
        "Maize",
        "Potato",
    ]


def test_settings_and_symbols_in_an_engineering_spec() -> None:
    (onions,) = recipe(
        "spec: crop = onion (Sturon sets); beds = 10; bed pitch 1.8 m centre to centre; "
        "6 rows/bed; row length 100 m; orientation NW-SE"
    ).fields
    assert (onions.variety, onions.bed_count, onions.agronomy.rows_per_bed) == ("Sturon", 10, 6)
    assert onions.agronomy.row_spacing_m == 1.8
    (maize,) = recipe("Maize plot, 24 rows @ 76 cm, 150 m row length").fields
    assert (maize.row_count, maize.agronomy.row_spacing_m) == (24, 0.76)
    # ("three cultivars: ..." is a list's heading, not a setting)
    assert (
        len(
            recipe(
                "Cabbage set with three cultivars: Red Express, January King and Golden Acre."
            ).fields
        )
        == 3
    )


def test_row_measures_read_in_more_ways() -> None:
    with pytest.raises(PromptError, match="positive"):
        recipe("Cabbage rows spaced -75 cm, plants 45 cm apart, for a robot test.")
    (cabbage,) = recipe("Cabbage rows spaced 75 cm, plants 45 cm apart").fields
    assert (cabbage.agronomy.row_spacing_m, cabbage.agronomy.in_row_spacing_m) == (0.75, 0.45)
    # a bare "spacing" after the rows' spacing is the plants' in the row
    (savoy,) = recipe("Savoy cabbage, 12 rows, 0.75 m rows, 0.4 m spacing").fields
    assert (savoy.agronomy.row_spacing_m, savoy.agronomy.in_row_spacing_m) == (0.75, 0.4)
    # the rows' spacing beside the plants' in brackets
    gros, cavendish = recipe(
        "Two banana blocks, both at 1,000 plants/ha (rows 5 m, plants 2 m apart): Gros Michel "
        "on the north side, Dwarf Cavendish on the south."
    ).fields
    for banana in (gros, cavendish):
        assert (banana.agronomy.row_spacing_m, banana.agronomy.in_row_spacing_m) == (5.0, 2.0)
    # "one vine every 1.2 m" is the vines' spacing, not a field of one vine
    (pinot,) = recipe(
        "Spätburgunder block - 40 rows x 100 m, 2.5 m row spacing, one vine every 1.2 m, rows "
        "at 30 degrees from north."
    ).fields
    assert (pinot.agronomy.in_row_spacing_m, round(pinot.row_bearing_deg)) == (1.2, 30)
    # a count of vines names the crop
    vines, cherries = recipe(
        "1,200 vines in 24 rows, with a cherry block of 90 trees south of the vines."
    ).fields
    assert (vines.crop, vines.row_count, cherries.crop) == ("Grape", 24, "Cherry")
    # "the other one rows e-w": "one" is the field, not one row
    first, second = recipe("two potato fields, one w rows n-s, other one rows e-w").fields
    assert (round(first.row_bearing_deg), round(second.row_bearing_deg)) == (0, 90)
    assert first.row_count > 1 and second.row_count > 1


@pytest.mark.parametrize(
    ("prompt", "stage", "health"),
    [
        (
            "The spuds are in trouble, dark wet-looking patches on the leaves and a lot of plants "
            "collapsing along the wheelings.",
            None,
            "Ill",
        ),
        (
            "the conference pears hanging heavy, skins turning from green to yellowish",
            "Maturation",
            None,
        ),
        ("Cabernet with the bunches coloured up almost black", "Maturation", None),
        ("California Wonder bell peppers that have turned red", "Maturation", None),
        ("a vinyard on the south slope of the farm, the grapes turning colour", "Maturation", None),
    ],
)
def test_looks_of_disease_and_ripening(prompt: str, stage: str | None, health: str | None) -> None:
    (field,) = recipe(prompt).fields
    if stage is not None:
        assert field.stage == stage
    if health is not None:
        assert field.health == health


def test_a_look_said_of_one_member() -> None:
    first, second = recipe(
        "two potato fields separated by a farm track, one of them in white flower and the other "
        "only just emerging."
    ).fields
    assert (first.stage, second.stage) == ("Reproductive", "Vegetative")


@pytest.mark.parametrize(
    ("prompt", "season"),
    [
        ("lollo roso lettuce sept, bolting a bit", "Fall"),
        ("durondeau pears in full bloom nov", "Fall"),
    ],
)
def test_a_short_month_name_anywhere(prompt: str, season: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.season == season


def test_typos_of_long_names_and_of_little_words() -> None:
    carrots, _ = recipe("chantney carrots young, june, and a cabbage patch too").fields
    assert carrots.variety == "Chantenay"
    # ("teh" was refused as an unknown crop)
    orchard, potatoes = recipe("teh orchard is east of the hous, potatos west of it").fields
    assert (orchard.category, potatoes.crop) == ("Fruits", "Potato")
    # (a two-word phrase two letters off is no typo: "fruit fat" is not "fruit set")
    (pears,) = recipe("Williams pears, the fruit fat and turning yellow, late August").fields
    assert pears.stage == "Maturation"
    (nantes,) = recipe("nantes carrots rdy 2 pull, its oct b4 the frosts").fields
    assert nantes.season == "Fall"


def test_sizes_said_as_a_total_of_beds_and_an_acre_and_a_half() -> None:
    (lettuce,) = recipe("Lettuces in long beds under fleece. About 0.5 ha in total.").fields
    assert lettuce.geometry.area_m2 == pytest.approx(5000, rel=0.01)
    (chillies,) = recipe("An acre and a half of chillies by the farm shop.").fields
    assert chillies.geometry.area_m2 == pytest.approx(1.5 * 4046.8564224, rel=0.01)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "riesling in the middle w/ pinot noir on one side & cabernet on the other",
            {("between", "Riesling", ("Pinot Noir", "Cabernet Sauvignon"))},
        ),
        (
            "imperator carots & danvers carots, danvers one east",
            {("east_of", "Danvers", ("Imperator",))},
        ),
        (
            "a wheat field & a maize field 50x200m each, wheat north of maize ty",
            {("north_of", "Wheat", ("Maize",))},
        ),
        (
            "Dent corn on the 2 ha east field with a 6 m headland, flint corn on the 1 ha west "
            "field.",
            {("east_of", "Dent", ("Flint",))},
        ),
        (
            "left of the yard there's a vineyard, on the right a strawberry field",
            {("west_of", "Grape", ("Strawberry",))},
        ),
        (
            "Two plots for the weeding robot, one beside the other: onions in 30 cm rows and "
            "carrots in 45 cm rows.",
            {("next_to", "Carrot", ("Onion",))},
        ),
    ],
)
def test_sides_of_a_farm_and_of_a_view(
    prompt: str, expected: NamedRelations, named_relations: Callable[[str], NamedRelations]
) -> None:
    assert named_relations(prompt) == expected
    assert len(recipe(prompt).fields) == len({n for r in expected for n in (r[1], *r[2])})


def test_measures_said_for_each_or_both_or_also() -> None:
    # "also on 1.2 m rows": the field named last, not the one named again before it
    tomatoes, peppers = recipe(
        "tomatos on rows 1.2 m apart, 33,333 plants/ha, and peppers east of the tomatoes, also "
        "on 1.2 m rows"
    ).fields
    assert (tomatoes.crop, peppers.crop, peppers.agronomy.row_spacing_m) == (
        "Tomato",
        "Pepper",
        1.2,
    )
    # "Both blocks:" and the measures after the colon
    for block in recipe(
        "Put a Cripps Pink block west of a Jonagored block. Both blocks: 15 rows of 80 m, rows "
        "3.2 m apart, 0.8 m between trees."
    ).fields:
        assert (block.row_count, block.agronomy.row_spacing_m) == (15, 3.2)
    # "Half a hectare each of A and B"
    for field in recipe(
        "Half a hectare each of Cos lettuce and Savoy cabbage, both still young."
    ).fields:
        assert field.geometry.area_m2 == pytest.approx(5000, rel=0.01)
    # "each a 20 x 30 m plot": what each field is
    fields = recipe("Three different vegetables, each a 20 x 30 m plot with 0.75 m rows.").fields
    assert len(fields) == 3
    assert {(f.category, f.geometry.size_m) for f in fields} == {("Vegetables", (20.0, 30.0))}


def test_a_field_placed_again_by_its_cover(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Strawberry field under long plastic tunnels, Elsanta I think. Right next to the tunnels "
        "is an open field of Lollo Rosso."
    )
    assert named_relations(prompt) == {("next_to", "Lollo Rosso", ("Elsanta",))}


@pytest.mark.parametrize("prompt", ["a bed of Cos", "a few beds of Cos", "beds of Cos"])
def test_what_the_only_plot_is_of_names_its_crop(prompt: str) -> None:
    # (a weak variety name after "of": a field of a crop chosen at random before)
    assert [(f.crop, f.variety) for f in recipe(prompt).fields] == [("Lettuce", "Romaine")]


def test_a_crop_named_before_its_counted_plots() -> None:
    # "Wheat micro-plots ...: two adjacent plots": the two plots are the wheat's (they were
    # fields of a crop chosen at random, refused for rows narrower than a pepper plant)
    ill, clean = recipe(
        "Wheat micro-plots for a rust-detection drone: two adjacent plots, 1.5 m x 10 m each, "
        "12 cm drill rows, one with yellow rust and one clean."
    ).fields
    assert (ill.crop, ill.health, clean.crop, clean.health) == ("Wheat", "Ill", "Wheat", "Healthy")
    # an everyday word before plots whose crops are named after them names no crop
    prompt = (
        "Compact plot pair for the weeding robot's camera: strawberries on 1.5 m beds with 2 "
        "rows per bed, south of a lettuce block with 30 cm in-row spacing."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Strawberry", "Lettuce"]

"""Text of blind set g17 (issue 8): a count left out for the next plot ("Chardonnay has 20
rows, Cabernet 16"), rows of so many plants, rootstocks, a purpose's compound, headings
before a dash or of plural crops, labels referred to as subjects or by number words,
"<crop> one" for a field named before, sides in brackets and in casual text, sizes in
brackets, emojis inside words, grids said "3.2 m rows at 1.25 m", and relations said
"20 m south of them", "on their east side" or "whose rows run east-west"."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

#: The fixture named_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        # a count left out for the next plot
        (
            "Vineyard dataset: a Chardonay block east of a Cabernet block, both 3.0 m rows with "
            "vines every 1.8 m; Chardonnay has 20 rows, Cabernet 16. Harvest time, September.",
            ["Grape", "Grape"],
        ),
        # rows of so many plants
        (
            "Orchard scene for the LiDAR SLAM benchmark: 300 pear trees in 10 rows of 30, 3.6 m "
            "between rows, and a 7 m headland with a grass track on it.",
            ["Pear"],
        ),
        # a rootstock
        (
            "Block A is Jonagored on M9, 40 rows 3.5 m apart with a tree every metre; block B, "
            "south of it, is Durondeau pears, rows also 3.5 m apart and 1.2 m between trees.",
            ["Apple", "Pear"],
        ),
        # a purpose's compound
        (
            "Sim scene for the greenhouse-to-field transfer test: a lettuce plot and a cabbage "
            "plot, 50 x 20 m each, lettuce at 10 plants per m², cabbage at 30,000 plants/ha.",
            ["Lettuce", "Cabbage"],
        ),
        # a joint heading, its members named again after it
        (
            "Cherry and pear rows for the frost-camera project: a block of Bing and a block of "
            "Durondeau, Bing east of the Durondeau. Bing 4.5 x 2.5 m, Durondeau 3.5 x 1.0 m.",
            ["Cherry", "Pear"],
        ),
        # a plural crop heading counted plots
        (
            "Wheat plots for the phenotyping rover: two strips, 18 m x 60 m each, drilled at "
            "12.5 cm. West strip winter wheat at 250 plants/m², east strip pasta wheat at 300 "
            "plants/m².",
            ["Wheat", "Wheat"],
        ),
        # a heading before a dash
        (
            "sensor test field - 3 plots side by side, west to east: wheat, maize, potatoes. "
            "each plot 20 x 50 m.",
            ["Wheat", "Maize", "Potato"],
        ),
        # "<crop> one", a side said twice, a size in brackets
        ("fruit field and a veg field pls, fruit one north of the veg one", None),
        ("potatos: agria & fontane, 2 fields 1ha each, agria one south of the fontane", None),
        (
            "hiii i want riesling vines & chardonnay vines, riesling on the left chardonnay on "
            "the right, both ripe in sept",
            ["Grape", "Grape"],
        ),
        (
            "valencia oranges & moro oranges, valencia one bigger (4ha) moro one 2ha, nxt 2 "
            "each other",
            ["Orange", "Orange"],
        ),
        # a member named again by a relation, the listing going on
        (
            "we farm three fields: wheat up by the woods, potatoes right next to the wheat, and "
            "a bit of lettuce near the yard",
            ["Wheat", "Potato", "Lettuce"],
        ),
    ],
)
def test_no_phantom_fields(prompt: str, crops: list[str] | None) -> None:
    fields = recipe(prompt).fields
    assert len(fields) == 2 if crops is None else [f.crop for f in fields] == crops


def test_sizes_and_counts_said_in_casual_words() -> None:
    valencia, moro = recipe(
        "valencia oranges & moro oranges, valencia one bigger (4ha) moro one 2ha"
    ).fields
    assert valencia.geometry.size_m[0] * valencia.geometry.size_m[1] == pytest.approx(
        40_000, rel=0.001
    )
    assert moro.geometry.size_m[0] * moro.geometry.size_m[1] == pytest.approx(20_000, rel=0.001)
    assert len(recipe("some veg fields, like 3 or 4, near a farmhouse").fields) == 3
    (strawberries,) = recipe("a straw🍓berry field, half an acre, pls and thx").fields
    assert strawberries.crop == "Strawberry"
    # a unit stays a unit, a rootstock is one only in capitals
    (wheat,) = recipe("wheat plot, 15 cm rows, 200 plants per m2").fields
    assert wheat.agronomy.in_row_spacing_m == pytest.approx(1 / (200 * 0.15))


def test_grids_said_with_at_and_with_the_unit_once() -> None:
    (apples,) = recipe("Golden Delicious apple block: 3.2 m rows at 1.25 m (2,500 trees/ha)").fields
    assert (apples.agronomy.row_spacing_m, apples.agronomy.in_row_spacing_m) == (3.2, 1.25)
    scene = generate(
        "one block of Bartlett pears: 2,800 trees/ha, 3.5 x 1.0 m, 12 rows, each 120 m",
        resolver="hybrid",
    )
    (pears,) = scene.recipe.fields
    assert (pears.agronomy.row_spacing_m, pears.agronomy.in_row_spacing_m) == (3.5, 1.0)
    # the density said rounded is kept as the grid says, with a warning
    assert any("2,800 plants/ha read as said roughly" in w for w in scene.recipe.warnings)


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "Thinning robot test, three lettuce plots: plot 1 Cos, plot 2 Iceberg, plot 3 Lollo "
            "Rosso. Plot 2 sits between plots 1 and 3.",
            ("between", "Iceberg", ("Romaine", "Lollo Rosso")),
        ),
        (
            "Field one: Russet potatoes, 60 rows. Field two, south of field one: Fontane, 50 rows.",
            ("south_of", "Fontane", ("Russet Burbank",)),
        ),
        (
            "Two fields: cherry trees at 5 x 3 m and, 20 m south of them, a plum tomato plot.",
            ("south_of", "Roma", ("Cherry",)),
        ),
        (
            "Dataset capture, two apple blocks: Granny (west) and Fuji (east). 4 m between rows",
            ("west_of", "Granny Smith", ("Fuji",)),
        ),
        (
            "spuds: 18 rows at 90 cm, 150 m rows. On their east side a corn block, 30 rows at "
            "75 cm.",
            ("east_of", "Maize", ("Potato",)),
        ),
        (
            "cabernet & pinot nero vines, cab south of the pinot",
            ("south_of", "Cabernet Sauvignon", ("Pinot Noir",)),
        ),
        (
            "cripps pink apples 2ha & bartlett pears 1ha, apples w of the pears",
            ("west_of", "Pink Lady", ("Williams",)),
        ),
        (
            "we farm three fields: wheat up by the woods, potatoes right next to the wheat, and "
            "a bit of lettuce near the yard",
            ("next_to", "Potato", ("Wheat",)),
        ),
    ],
)
def test_relations_said_in_other_words(
    prompt: str,
    expected: tuple[str, str, tuple[str, ...]],
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert expected in named_relations(prompt)


def test_a_relative_clause_of_rows_is_the_field_just_named() -> None:
    chardonnay, riesling = recipe(
        "Chardonnay vineyard with rows running north-south, 2.5 m apart; east of it a Riesling "
        "block whose rows run east-west."
    ).fields
    assert chardonnay.geometry.rotation_deg % 180 == 0
    assert riesling.geometry.rotation_deg % 180 == 90


def test_two_weak_variety_names_of_one_crop_name_it_together() -> None:
    fields = recipe(
        "Albion on the table-tops and Centenary in the soil beds next to them, both full of "
        "ripe red berries; pickers in blue tabards working the Albion."
    ).fields
    assert [(f.crop, f.variety) for f in fields] == [
        ("Strawberry", "Albion"),
        ("Strawberry", "Malling Centenary"),
    ]
    assert len(recipe("Albion and Centenary").fields) == 2


def test_where_the_photo_is_taken_from_and_a_rusty_chain_are_scenery() -> None:
    fields = recipe(
        "From the terrace: an orchard in full blossom on the slope and a vineyard down below "
        "it, blue sky, a white van on the road."
    ).fields
    assert [f.category for f in fields] == ["Fruits", "Fruits"]
    assert fields[1].crop == "Grape"
    spelt, durum = recipe(
        "Spelt on the near side of the hedge and durum beyond it, both still green with the "
        "ears just coming out. Skylarks, huge sky, a gate with a rusty chain."
    ).fields
    assert (spelt.health, durum.health) == ("Healthy", "Healthy")


def test_beds_placed_side_by_side_are_plots_and_the_same_spec_is_the_whole_planting() -> None:
    cos, lollo = recipe(
        "June, overcast. My shot of two beds side by side, Cos lettuce and Lollo Rosso, both "
        "ready to cut, drip tape along the rows."
    ).fields
    assert (cos.variety, lollo.variety) == ("Romaine", "Lollo Rosso")
    assert cos.geometry.size_m == lollo.geometry.size_m
    ripe, young = recipe(
        "need lettuce for the robot's camera, 35 cm x 30 cm spacing, 40 rows, 20 m lenght, "
        "rows due east-west, at harvest. Plus a second lettuce plot with the same spec 10 m to "
        "the west, just planted."
    ).fields
    for field in (ripe, young):
        assert (field.row_count, field.agronomy.in_row_spacing_m) == (40, 0.3)
        assert field.geometry.rotation_deg % 180 == 90
    assert (ripe.stage, young.stage) == ("Maturation", "Vegetative")

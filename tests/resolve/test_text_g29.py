"""Text of blind set g29 (issue 8): a new field brought in after a fronted placement
("Next to the Navel oranges we've just planted a block of Valencia"), bare trees as
winter, a variety opening a photo ("A shot of the Big Mike bunches"), golden light, the
picture's own article, plots said adjacent after a comma or with their size, an
identical-sized plot, a row of three placed one by one, sizes of counted plots, a spec's
bracketed labels, a name placed then measured, and members named again by their look."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    "prompt",
    [
        "Next to the Navel oranges we've just planted a new block of Valencia Late, knee-high "
        "saplings so far.",
        "Next to the Navel oranges is a new block of Valencia Late.",
    ],
)
def test_a_new_field_after_a_fronted_placement(
    named_relations: Callable[[str], NamedRelations], prompt: str
) -> None:
    assert [f.variety for f in recipe(prompt).fields] == ["Navel", "Valencia"]
    assert named_relations(prompt) == {("next_to", "Valencia", ("Navel",))}


def test_trees_standing_bare_are_in_winter() -> None:
    (apples,) = recipe(
        "These are our Jonagored trees standing completely bare, not a leaf on them, and the "
        "pruning crew at work."
    ).fields
    assert (apples.variety, apples.season) == ("Jonagold", "Winter")


def test_a_variety_opening_a_photo() -> None:
    (bananas,) = recipe(
        "A shot of the Big Mike bunches hanging under their blue bags, the fingers fat and "
        "ready to cut."
    ).fields
    assert (bananas.variety, bananas.stage) == ("Gros Michel", "Maturation")
    # (a name that is only a common word, with nothing grown: still nothing to build)
    with pytest.raises(PromptError):
        recipe("A photo of the Flint walls around the yard, the stones grey")


def test_golden_light_is_no_variety() -> None:
    fields = recipe(
        "This is our Fuji orchard in late October, apples fully red now. Low golden sun "
        "coming through the rows."
    ).fields
    assert [f.variety for f in fields] == ["Fuji"]


def test_the_pictures_own_article_counts_no_plots() -> None:
    fields = recipe(
        "The picture is a wide view of some vegetable plots and a small orchard behind a "
        "wooden gate, with two people weeding by hand."
    ).fields
    assert [f.category for f in fields] == ["Vegetables", "Vegetables", "Fruits"]


@pytest.mark.parametrize(
    ("prompt", "count", "size"),
    [
        (
            "Fuji and Golden Delicious, two adjacent blocks, each 30 rows of 150 m with rows "
            "3.5 m apart and 1.2 m between trees.",
            2,
            None,
        ),
        (
            "Crop-row detection benchmark: three different vegetables in three adjacent "
            "10 m x 40 m plots.",
            3,
            (10.0, 40.0),
        ),
    ],
)
def test_plots_said_adjacent(prompt: str, count: int, size: tuple[float, float] | None) -> None:
    scene = recipe(prompt)
    assert len(scene.fields) == count
    assert {r.kind for r in scene.relations} == {"next_to"}
    if size is not None:
        assert [f.geometry.size_m for f in scene.fields] == [size] * count


def test_an_identical_sized_plot() -> None:
    wheat, corn = recipe(
        "GNSS-RTK guidance test on a wheat strip 20 ft wide by 400 ft long, drilled on "
        "7.5-inch rows, and an identical-sized strip of corn on 30-inch rows next to it."
    ).fields
    assert corn.geometry.size_m == wheat.geometry.size_m == pytest.approx((6.096, 121.92))


def test_a_row_of_three_placed_one_by_one(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations(
        "Sensor test, three 30 m x 30 m plots in a line: peppers in the middle, tomatoes on "
        "the west side, cabbages on the east side."
    ) >= {("between", "Pepper", ("Tomato", "Cabbage")), ("west_of", "Tomato", ("Pepper",))}


def test_the_sizes_of_counted_plots(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Weed-mapping flight over two potato fields of 3 ha and 1.5 ha, the smaller one west "
        "of the larger, both with rows 75 cm apart running NE-SW."
    )
    areas = [f.geometry.size_m[0] * f.geometry.size_m[1] for f in recipe(prompt).fields]
    assert areas == [pytest.approx(30_000), pytest.approx(15_000)]
    assert named_relations(prompt) == {("west_of", "Potato", ("Potato",))}


def test_a_specs_bracketed_labels(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "plot spec v2 for the sim: [plot1] crop=potato, rows=20, row_spacing=0.75m, "
        "row_length=80m; [plot2] crop=maize, rows=20, row_spacing=0.75m, row_length=80m, "
        "placed east of plot1"
    )
    assert [(f.crop, f.agronomy.row_spacing_m) for f in recipe(prompt).fields] == [
        ("Potato", 0.75),
        ("Maize", 0.75),
    ]
    assert named_relations(prompt) == {("east_of", "Maize", ("Potato",))}


def test_a_name_placed_then_measured(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Bird-netting robot test in two cherry blocks, both in full blossom. Kordia: 10 rows, "
        "rows 4.6 m apart, trees 2.4 m apart. Regina, north of the Kordia block: 12 rows, rows "
        "5 m apart, trees 2.7 m apart."
    )
    assert [
        (f.variety, f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m)
        for f in recipe(prompt).fields
    ] == [("Kordia", 4.6, 2.4), ("Regina", 5.0, 2.7)]
    assert named_relations(prompt) == {("north_of", "Regina", ("Kordia",))}


@pytest.mark.parametrize(
    ("prompt", "looks", "placed"),
    [
        (
            "Two sweet corn plantings, 16 rows each on 36-inch spacing: one still vegetative "
            "at about V5, the other tasseling. The young planting is on the south side.",
            [("Vegetative", "Healthy"), ("Reproductive", "Healthy")],
            (0, "south_of", 1),
        ),
        (
            "Two wheat fields: one with rust, the other healthy. The diseased field is on the "
            "south side.",
            [("Maturation", "Ill"), ("Maturation", "Healthy")],
            (0, "south_of", 1),
        ),
        (
            "two wheat fields, one ripe, one young; the young field is north",
            [("Maturation", "Healthy"), ("Vegetative", "Healthy")],
            (1, "north_of", 0),
        ),
    ],
)
def test_members_named_again_by_their_look(
    prompt: str, looks: list[tuple[str, str]], placed: tuple[int, str, int]
) -> None:
    scene = recipe(prompt)
    assert [(f.stage, f.health) for f in scene.fields] == looks
    subject, kind, other = placed
    assert [(r.subject, r.kind, r.objects) for r in scene.relations] == [
        (scene.fields[subject].id, kind, (scene.fields[other].id,))
    ]


@pytest.mark.parametrize(
    ("prompt", "relations"),
    [
        (
            "Thermal camera test on onions: 25 beds on 1.6 m centres. On the north side of the "
            "onions, a cabbage plot of 10 rows at 75 cm.",
            {("north_of", "Cabbage", ("Onion",))},
        ),
        # (a side of scenery places the field in that part of the farm)
        (
            "The Conference pears are on the north side of the farmhouse. South of the pears, "
            "past the yard, we've about 3 ha of Bintje.",
            {("north_of", "Conference", ("Bintje",))},
        ),
    ],
)
def test_on_the_side_of_a_field(
    named_relations: Callable[[str], NamedRelations], prompt: str, relations: NamedRelations
) -> None:
    assert named_relations(prompt) == relations

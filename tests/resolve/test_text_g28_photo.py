"""Text of blind set g28, photo and engineering (issue 8): fields said to touch
("adjoining blocks", "adjacent tunnels", "separated only by a hedge", "just across the
ditch"), what lies beyond as the viewer faces, "the vines" named again as a relation's
object, two "it"s of one field, row-end roses, "a fox trotting", a second plot after
"with a", bed lengths, alleys between double rows, a plot size said with its headland,
a grid of plots, a row of three with one between, labels placed before "=", members'
own plants and measures, and a crop heading its plots."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import UnknownCropError, generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "relations"),
    [
        (
            "Sweetcorn and popping corn in adjoining blocks, both tasselling.",
            {("next_to", "Popcorn", ("Sweet Corn",))},
        ),
        (
            "Sonata and Albion strawberries are in adjacent tunnels.",
            {("next_to", "Albion", ("Sonata",))},
        ),
        (
            "two wheat fields separated only by a hawthorn hedge, walkers on the footpath",
            {("next_to", "Wheat", ("Wheat",))},
        ),
        (
            "Our wheat in May, with the neighbour's onions just across the ditch.",
            {("next_to", "Onion", ("Wheat",))},
        ),
        # (after a comma, of fields placed already: the track is only scenery)
        (
            "Bartlett pears on the left, Bing cherries on the right, separated by a gravel track.",
            {("west_of", "Williams", ("Bing",))},
        ),
    ],
)
def test_fields_said_to_touch(
    named_relations: Callable[[str], NamedRelations], prompt: str, relations: NamedRelations
) -> None:
    assert named_relations(prompt) == relations


def test_a_field_across_the_ditch_from_the_house_is_no_relation() -> None:
    fields = recipe("The field across the ditch from our house is wheat, gone straw-coloured.")
    assert [f.crop for f in fields.fields] == ["Wheat"]
    assert fields.relations == ()


@pytest.mark.parametrize(
    ("prompt", "relations"),
    [
        (
            "I was facing due north from the gate when I took this: potatoes in the "
            "foreground and a wheat field beyond them.",
            {("north_of", "Wheat", ("Potato",))},
        ),
        (
            "Facing west, cabbages up close and onions just beyond them.",
            {("west_of", "Onion", ("Cabbage",))},
        ),
        # (no way faced: beyond is only further off)
        (
            "Potatoes in the foreground and a wheat field beyond them.",
            {("next_to", "Wheat", ("Potato",))},
        ),
    ],
)
def test_what_lies_beyond_as_the_viewer_faces(
    named_relations: Callable[[str], NamedRelations], prompt: str, relations: NamedRelations
) -> None:
    assert named_relations(prompt) == relations


def test_the_vines_as_the_object_of_a_relation(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "This photo shows a vineyard, a cherry orchard and a pear orchard, the cherries lying "
        "between the vines and the pears, everything bare in midwinter."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Grape", "Cherry", "Pear"]
    assert named_relations(prompt) == {("between", "Cherry", ("Grape", "Pear"))}


def test_two_its_of_one_field(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Big wheat field in the middle of the picture; south of it is a small carrot plot "
        "and east of it a field of sweet peppers."
    )
    assert named_relations(prompt) == {
        ("south_of", "Carrot", ("Wheat",)),
        ("east_of", "Pepper", ("Wheat",)),
    }
    # (the same way twice is a walk: each "it" the field named last)
    assert named_relations(
        "A vineyard, with a pear orchard north of it, and north of it an apple orchard."
    ) >= {("north_of", "Apple", ("Pear",))}


def test_row_end_roses_are_scenery_and_a_field_of_roses_is_refused() -> None:
    fields = recipe(
        "Two vineyard blocks side by side, Riesling and Cabernet, roses at the end of each "
        "row. Both are in flower, but the Riesling leaves are curled and mottled."
    ).fields
    assert [(f.variety, f.health) for f in fields] == [
        ("Riesling", "Ill"),
        ("Cabernet Sauvignon", "Healthy"),
    ]
    with pytest.raises(UnknownCropError, match="roses"):
        recipe("a field of roses")


def test_a_word_with_one_more_letter_in_front_is_no_typo() -> None:
    (pears,) = recipe("pear trees bare and dormant, a fox trotting across").fields
    assert (pears.season, pears.health) == ("Winter", "Healthy")


def test_a_sized_plot_after_with_a_is_a_field_of_its_own(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "About 5 ha of maize with a 1 ha field of onions right beside it, seen from the road."
    maize, onions = recipe(prompt).fields
    assert (maize.crop, onions.crop) == ("Maize", "Onion")
    assert maize.geometry.size_m[0] * maize.geometry.size_m[1] == pytest.approx(50_000, rel=1e-3)
    assert onions.geometry.size_m[0] * onions.geometry.size_m[1] == pytest.approx(10_000, rel=1e-3)
    assert named_relations(prompt) == {("next_to", "Onion", ("Maize",))}


@pytest.mark.parametrize(
    ("prompt", "length"),
    [
        ("Jalapeños, 12 beds on 1.5 m centres, two rows a bed, 45 cm in-row, beds 35 m.", 35.0),
        ("Sonata strawberries: 30 beds on 1.4 m centres, 100 m beds running east-west.", 100.0),
    ],
)
def test_the_length_of_beds(prompt: str, length: float) -> None:
    (field,) = recipe(prompt).fields
    assert "row_length" in field.stated
    planted = field.geometry.size_m[1] - 2 * field.geometry.headland_m
    assert planted == pytest.approx(length, abs=field.agronomy.in_row_spacing_m)


def test_alleys_between_double_rows() -> None:
    (bananas,) = recipe(
        "Grande Naine bananas in double rows with 3.75 m alleys, 2.25 m between plants along "
        "the row, 1,840 plants/ha."
    ).fields
    agronomy = bananas.agronomy
    assert agronomy.rows_per_bed == 2
    assert agronomy.row_spacing_m - agronomy.bed_row_spacing_m == pytest.approx(3.75)
    density = 10_000 * 2 / (agronomy.row_spacing_m * agronomy.in_row_spacing_m)
    assert density == pytest.approx(1840, rel=1e-3)
    (vines,) = recipe("bananas in double rows 1 m apart with 3.75 m alleys").fields
    assert (vines.agronomy.bed_row_spacing_m, vines.agronomy.row_spacing_m) == (1.0, 4.75)
    (apples,) = recipe("apples, 4.5 m alleys, 1 m between trees").fields
    assert (apples.agronomy.rows_per_bed, apples.agronomy.row_spacing_m) == (1, 4.5)


def test_a_plot_size_said_with_its_headland_is_kept() -> None:
    (peppers,) = recipe(
        "Pimientos de Padrón in single rows 90 cm apart, 40 cm in the row, 18 rows of 30 m "
        "with a 2 m headland all round; the whole plot is 20 x 34 m."
    ).fields
    assert (peppers.geometry.size_m, peppers.geometry.headland_m) == ((20.0, 34.0), 2.0)


def test_a_grid_of_plots_is_no_planting_grid() -> None:
    fields = recipe(
        "2 x 2 grid of 25 x 25 m test plots for the ground robot: maize NW, wheat NE, "
        "potatoes SW, carrots SE."
    ).fields
    assert [f.geometry.size_m for f in fields] == [(25.0, 25.0)] * 4
    assert all("row_spacing" not in f.stated for f in fields)


@pytest.mark.parametrize(
    ("prompt", "relations"),
    [
        (
            "Sensor cart run over three 10 x 30 m plots in a line: Albion strawberries in the "
            "middle, between Iceberg lettuce and Red Baron onions.",
            {("between", "Albion", ("Iceberg", "Red Baron"))},
        ),
        (
            "three plots in a row: wheat, then maize, then potatoes, with a ditch between the "
            "wheat and the maize.",
            {
                ("next_to", "Maize", ("Wheat",)),
                ("next_to", "Potato", ("Maize",)),
                ("between", "Maize", ("Wheat", "Potato")),
                ("next_to", "Wheat", ("Maize",)),
            },
        ),
    ],
)
def test_a_row_of_three_with_one_between(
    named_relations: Callable[[str], NamedRelations], prompt: str, relations: NamedRelations
) -> None:
    assert named_relations(prompt) == relations


def test_a_label_placed_before_an_equals_sign(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Plot A = Bintje potatoes, 16 ridges at 75 cm, ridges 50 m long. Plot B directly east "
        "of A = Nantes carrots, 10 ridges, same 75 cm ridge width, 2 rows per ridge."
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Potato", "Carrot"]
    assert named_relations(prompt) == {("east_of", "Nantes", ("Bintje",))}


def test_members_own_plants_and_measures() -> None:
    first, second = recipe(
        "two vinyard blocks for the spraying drone. block 1: 30 rows of vines, 2.5 m inter-row, "
        "1.2 m vine to vine. block 2, north of block 1: 20 rows, 2 m inter-row, 1 m vine to "
        "vine. all rows 120 m, orientation NE-SW"
    ).fields
    assert [
        (f.crop, f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in (first, second)
    ] == [("Grape", 2.5, 1.2), ("Grape", 2.0, 1.0)]
    one, other = recipe(
        "two maize plots of 0.4 ha each: plot 1 at 90,000 plants/ha on 70 cm rows, plot 2 "
        "east of plot 1 at 70,000 plants/ha on 90 cm rows."
    ).fields
    assert (one.agronomy.row_spacing_m, other.agronomy.row_spacing_m) == (0.7, 0.9)


def test_a_crop_heading_its_plots(named_relations: Callable[[str], NamedRelations]) -> None:
    prompt = (
        "Canopy-volume LiDAR study in Washington Navel: a super-high-density block, 20 rows "
        "at 3.7 m with trees 1.2 m apart and 150 m rows, and south of it a conventional "
        "block, 10 rows at 7.2 m with trees 3.8 m apart."
    )
    fields = recipe(prompt).fields
    assert [(f.crop, f.variety, f.agronomy.row_spacing_m) for f in fields] == [
        ("Orange", "Navel", 3.7),
        ("Orange", "Navel", 7.2),
    ]
    assert named_relations(prompt) == {("south_of", "Navel", ("Navel",))}

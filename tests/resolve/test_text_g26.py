"""Text of blind set g26 (issue 8): a colour said of the sky or the sun, "both blocks ...:"
before a list, "ridges with a spacing of -75 cm", "two plots one beside the other, each
...", a variety and its other name in brackets, a plot named again before another
("north of the orchard again a big block of ..."), "strawb", a lone lowercase variety in
a prompt of row measures, a placement said before the member it places."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe._errors import PromptError
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        (
            "Cripps Pink block in mid-October. Apples have coloured up beautifully, the "
            "pickers' bins are stacked along the grass alley and the sun is low and golden.",
            "Apple",
        ),
        (
            "Wheat field after the summer storm: big patches flattened, the ears going grey and "
            "mouldy, and the sky still orange in the west.",
            "Wheat",
        ),
    ],
)
def test_a_colour_said_of_the_sky_or_the_sun(prompt: str, crop: str) -> None:
    assert [f.crop for f in recipe(prompt).fields] == [crop]
    # (a crop said after the sky is still a field)
    assert [f.crop for f in recipe("under a grey sky, oranges").fields] == ["Orange"]


def test_both_plots_before_a_list() -> None:
    fields = recipe(
        "It's late September and both blocks of the vineyard are ripe: Chardonnay on the east "
        "slope, Riesling on the west slope."
    ).fields
    assert [f.variety for f in fields] == ["Chardonnay", "Riesling"]


def test_a_spacing_said_of_ridges_or_rows() -> None:
    (potatoes,) = recipe("Potato ridges with a spacing of 75 cm, 20 ridges").fields
    assert potatoes.agronomy.row_spacing_m == pytest.approx(0.75)
    with pytest.raises(PromptError, match=r"-0\.75"):
        recipe("Potato ridges with a spacing of -75 cm, 20 ridges, for a simulator edge case.")
    (maize,) = recipe("maize rows with a spacing of 70 cm").fields
    assert maize.agronomy.row_spacing_m == pytest.approx(0.7)


def test_two_plots_one_beside_the_other_each(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two salad plots one beside the other, each 6 beds on 1.2 m centres with 3 rows per bed."
    )
    fields = recipe(prompt).fields
    assert [(f.crop, f.bed_count, f.agronomy.rows_per_bed) for f in fields] == [
        ("Lettuce", 6, 3),
        ("Lettuce", 6, 3),
    ]
    assert named_relations(prompt) == {("next_to", "Lettuce", ("Lettuce",))}


def test_a_variety_and_its_other_name_in_brackets() -> None:
    fields = recipe(
        "two banana plots next to each other: Big Mike (Gros Michel) at 3 x 3 m and Ladyfinger "
        "at 2.5 x 2.5 m, 150 plants per plot"
    ).fields
    assert [f.variety for f in fields] == ["Gros Michel", "Lady Finger"]


def test_a_plot_named_again_before_another(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "so the farm - Conference pear orchard just north of the farmhouse, and north of the "
        "orchard again a big block of Winter Wheat. south of the yard we've got Bintje spuds"
    )
    assert [f.crop for f in recipe(prompt).fields] == ["Pear", "Wheat", "Potato"]
    assert ("north_of", "Winter Wheat", ("Conference",)) in named_relations(prompt)
    # (a copula between: the plot it is, not another)
    (vines,) = recipe(
        "The only crop we have is a small block of grapevines behind the house, leaves "
        "blotched with yellow oil spots."
    ).fields
    assert (vines.crop, vines.health) == ("Grape", "Ill")


def test_clipped_and_lowercase_names() -> None:
    (strawberries,) = recipe("strawb field, 8 beds, 2 rows per bed, beds on 1.5m centres").fields
    assert (strawberries.crop, strawberries.bed_count) == ("Strawberry", 8)
    (lettuce,) = recipe(
        "lollo for the leaf-segmentation camera: beds on 1.2 m centres, 4 rows per bed, 25 cm "
        "in the row, 6 beds, rows 30 m long, ready to cut in September"
    ).fields
    assert (lettuce.variety, lettuce.bed_count) == ("Lollo Rosso", 6)


@pytest.mark.parametrize(
    ("prompt", "relation"),
    [
        (
            "Orchard dataset, two blocks: Bing cherries (4.6 m x 2.4 m, 6 rows) and, 20 m to "
            "the east, Durondeau pears (3.5 m x 1 m, 10 rows). Drone altitude 40 m.",
            ("east_of", "Durondeau", ("Bing",)),
        ),
        ("Bing cherries and, to the east, Durondeau pears", ("east_of", "Durondeau", ("Bing",))),
    ],
)
def test_placements_said_around_a_field(
    prompt: str,
    relation: tuple[str, str, tuple[str, ...]],
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations(prompt) == {relation}

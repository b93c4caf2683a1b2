"""Text of blind set g26 left over after its first fixes (issue 8): a picture of the crop
drawn between it and its place ("wheat 🌾 south"), a labelled plot placed before it is
named ("plot 2 is 10 m west of plot 1 and is wheat"), a distance before a relation that
opens its clause, and a placement said again as touching ("east of that field, right up
against it, onions"), what a copula says after a placement ("the wheat north of the maize
is ripe"), the month of picking."""

from __future__ import annotations

from collections.abc import Callable

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_crop_picture_between_a_crop_and_its_place(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations("wheat 🌾 south, potatoes middle, carrots north")
    assert ("south_of", "Wheat", ("Potato",)) in relations
    assert ("north_of", "Carrot", ("Potato",)) in relations
    # (a picture glued to its word, or with the colour selector, is read the same way)
    fields = generate("corn🌽 30 inch rows, 12 of them", resolver="hybrid").recipe.fields
    assert [(f.crop, f.row_count) for f in fields] == [("Maize", 12)]
    assert named_relations("carrots 🥕 north, jalapeños 🌶️ south") == {
        ("north_of", "Carrot", ("Jalapeno",))
    }


def test_a_labelled_plot_placed_before_it_is_named(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "LiDAR occlusion test: plot 1 is maize, 20 rows at 0.75 m; plot 2 is 10 m west of "
        "plot 1 and is wheat on 12.5 cm rows; plot 3 is 10 m west of plot 2 and is potatoes "
        "on 75 cm ridges."
    )
    fields = generate(prompt, resolver="hybrid").recipe.fields
    assert [(f.crop, f.agronomy.row_spacing_m) for f in fields] == [
        ("Maize", 0.75),
        ("Wheat", 0.125),
        ("Potato", 0.75),
    ]
    relations = named_relations(prompt)
    assert ("west_of", "Wheat", ("Maize",)) in relations
    assert ("west_of", "Potato", ("Wheat",)) in relations


def test_a_distance_before_a_relation_that_opens_its_clause(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations("a maize field; 10 m west of the maize, a wheat field") == {
        ("west_of", "Wheat", ("Maize",))
    }


def test_a_placement_said_again_as_touching(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    relations = named_relations(
        "West of the yard there's a potato field; the leaves are curled and blotchy, probably "
        "blight. East of that field, right up against it, onions."
    )
    assert ("east_of", "Onion", ("Potato",)) in relations


def test_what_is_said_after_a_placement_is_said_of_its_subject() -> None:
    fields = recipe("the wheat north of the maize is ripe").fields
    assert [(f.crop, f.stage, "stage" in f.stated) for f in fields] == [
        ("Wheat", "Maturation", True),
        ("Maize", fields[1].stage, False),
    ]
    scene = recipe(
        "February, and the Sonata strawberries next to the blood orange grove are covered in "
        "ripe fruit."
    )
    strawberries, oranges = scene.fields
    assert (strawberries.stage, strawberries.season) == ("Maturation", "Winter")
    assert "stage" not in oranges.stated
    # (ripe strawberries in February are kept as asked, with a warning)
    assert any("not normally mature" in w for w in scene.warnings)
    # (a placement that opens its sentence places the field after it, which the words
    # after the copula describe)
    wheat, maize = recipe("Next to the wheat the maize is ripe").fields
    assert (maize.stage, "stage" in wheat.stated) == ("Maturation", False)


def test_the_month_of_picking_is_ripe_fruit() -> None:
    fields = recipe(
        "Williams pears on the south side, Lapins cherries on the north side, both orchards "
        "picked in August."
    ).fields
    assert [(f.crop, f.stage, f.season) for f in fields] == [
        ("Pear", "Maturation", "Summer"),
        ("Cherry", "Maturation", "Summer"),
    ]

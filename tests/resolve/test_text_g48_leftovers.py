"""g48 misses left after its round (issue 8), fixed as general mechanisms: a member of a
heading's list counted two as the ends of "between"; a crop word joined to a colour in a
side member's look ("yellow-orange stripes of rust"); a member labelled by a plot that says
its crop ("two blocks. Vineyard: ...")."""

from __future__ import annotations

import pytest

from agrirecipe import SceneRecipe, generate


def _relations(recipe: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in recipe.relations}


@pytest.mark.parametrize(
    "prompt",
    [
        "Cereal strips for a yield-monitor simulation: a maize strip between two wheat strips, "
        "each strip 30 m wide and 300 m long. Maize in 75 cm rows running north-south, wheat "
        "drilled at 15 cm.",
        "Three strips: a maize strip between two wheat strips.",
    ],
)
def test_a_member_between_a_member_counted_two(prompt: str) -> None:
    recipe = generate(prompt).recipe
    assert [f.crop for f in recipe.fields] == ["Maize", "Wheat", "Wheat"]
    assert ("between", "maize_strip_1", ("wheat_strip_1", "wheat_strip_2")) in _relations(recipe)


def test_a_side_members_look_with_a_colour_joined_to_a_crop_word() -> None:
    recipe = generate(
        "Two wheat fields either side of the farm track. The east one is lush and dark green; "
        "the west one has yellow-orange stripes of rust running down the leaves. Telegraph "
        "poles along the track and a skylark somewhere overhead."
    ).recipe
    assert [(f.crop, f.health) for f in recipe.fields] == [
        ("Wheat", "Healthy"),
        ("Wheat", "Ill"),
    ]
    assert ("east_of", "wheat_field_1", ("wheat_field_2",)) in _relations(recipe)


def test_a_side_member_that_names_a_crop_still_names_its_field() -> None:
    recipe = generate("Two orchards. The north one has orange trees; the south one is Gala apples.")
    assert [f.crop for f in recipe.recipe.fields] == ["Orange", "Apple"]


def test_a_member_labelled_by_a_plot_that_says_its_crop() -> None:
    recipe = generate(
        "UAV multispectral flight, two blocks. Vineyard: 30 rows, 2.5 m row spacing, vines "
        "every 1.6 m, rows run N-S. South of the vineyard a cherry block with 8 rows 4.6 m "
        "apart and a tree every 2.4 m."
    ).recipe
    assert [(f.crop, f.row_count) for f in recipe.fields] == [("Grape", 30), ("Cherry", 8)]
    assert ("south_of", "cherry_block_1", ("grape_vineyard_1",)) in _relations(recipe)


def test_two_labelled_plots_are_the_two_blocks() -> None:
    recipe = generate("Two blocks. Vineyard: 20 rows. Orchard: 10 rows of Gala.").recipe
    assert [(f.crop, f.row_count) for f in recipe.fields] == [("Grape", 20), ("Apple", 10)]

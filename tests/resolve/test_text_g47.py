"""Text of blind set g47 (issue 8): each miss of its blind run, fixed as the general
mechanism (a square grid said kind first; counts of beds or rows listed after them;
a list after a direction and a dash; bare left and right; a look of emergence; what
"it" is; a plural the farm has; "east again"; vines placed by scenery; a field between
two landmarks)."""

from __future__ import annotations

import pytest

from agrirecipe import SceneRecipe, generate
from agrirecipe.resolve._geometry import find_geometry
from agrirecipe.resolve._lexicon import tokenize


def _crops(recipe: SceneRecipe) -> list[str | None]:
    return [f.crop for f in recipe.fields]


def _relations(recipe: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in recipe.relations}


@pytest.mark.parametrize(
    ("prompt", "spacing"),
    [
        ("Grande Naine banana plot for canopy LiDAR: square 3 m grid, 12 rows.", 3.0),
        ("an apple orchard on a square 4 m spacing", 4.0),
    ],
)
def test_a_square_grid_said_kind_first(prompt: str, spacing: float) -> None:
    agronomy = generate(prompt).recipe.fields[0].agronomy
    assert (agronomy.row_spacing_m, agronomy.in_row_spacing_m) == (spacing, spacing)


def test_counts_of_beds_listed_after_a_count_of_beds() -> None:
    recipe = generate(
        "Veg test garden for the weeding robot: four beds of lettuce, four of onions, four "
        "of carrots, every bed on 1.5 m centres."
    ).recipe
    assert _crops(recipe) == ["Lettuce", "Onion", "Carrot"]
    assert all(f.bed_count == 4 for f in recipe.fields)


def test_counts_of_rows_listed_after_a_count_of_rows() -> None:
    recipe = generate("10 rows of maize and 6 of potatoes, 76 cm apart").recipe
    assert [(f.crop, f.row_count) for f in recipe.fields] == [("Maize", 10), ("Potato", 6)]


def test_some_of_the_rows_are_no_count_of_rows() -> None:
    found = find_geometry(tokenize("10 rows of maize and 2 of them are weedy"))
    assert [(m.key, m.value) for m in found] == [("rows", 10.0)]


@pytest.mark.parametrize("mark", ["-", "—", ":"])
def test_a_list_after_a_direction_and_a_dash(mark: str) -> None:
    recipe = generate(f"from north to south {mark} potatoes, corn, wheat").recipe
    potatoes, maize, wheat = (f.id for f in recipe.fields)
    assert {("north_of", potatoes, (maize,)), ("north_of", maize, (wheat,))} <= _relations(recipe)


def test_left_and_right_said_bare() -> None:
    recipe = generate("cereals left, fruit right. thx!!").recipe
    cereals, fruit = recipe.fields
    assert ("west_of", cereals.id, (fruit.id,)) in _relations(recipe)


def test_a_bare_left_needs_a_side_across_from_it() -> None:
    recipe = generate(
        "potatoes with a few tubers left, wheat at the top, carrots at the bottom"
    ).recipe
    potatoes = recipe.fields[0].id
    assert not any(potatoes in (r.subject, *r.objects) for r in recipe.relations)


def test_plants_breaking_through_the_hills_have_emerged() -> None:
    field = generate(
        "Spud field in Maine, rows 36 inches apart, plants just breaking through the hills, "
        "and an old potato harvester rusting in the corner."
    ).recipe.fields[0]
    assert (field.crop, field.stage) == ("Potato", "Vegetative")


@pytest.mark.parametrize(
    "prompt",
    [
        "just the one field behind the dairy sheds, and it's carrots",
        "a field behind the sheds, and it is carrots",
    ],
)
def test_what_it_is_names_the_crop_of_the_plot_before(prompt: str) -> None:
    assert _crops(generate(prompt).recipe) == ["Carrot"]


@pytest.mark.parametrize(
    ("prompt", "fruit"),
    [
        ("The farm's got some fruit fields and a couple of cereal fields.", 2),
        ("The farm has several fruit fields.", 3),
    ],
)
def test_the_farms_article_is_not_the_fields(prompt: str, fruit: int) -> None:
    recipe = generate(prompt).recipe
    assert sum(f.category == "Fruits" for f in recipe.fields) == fruit


def test_east_again_is_past_the_last_one() -> None:
    recipe = generate(
        "Behind the house there's the Jonagored block, east of that the Pink Lady block, "
        "and east again the Fuji."
    ).recipe
    jonagored, pink_lady, fuji = (f.id for f in recipe.fields)
    assert ("east_of", pink_lady, (jonagored,)) in _relations(recipe)
    assert ("east_of", fuji, (pink_lady,)) in _relations(recipe)


def test_vines_placed_by_scenery_are_a_vineyard_between_landmarks() -> None:
    recipe = generate(
        "Between the house and the road is the strawberry field, the vines are across the "
        "road, and there's an orchard along the east side of the strawberries."
    ).recipe
    assert _crops(recipe)[:2] == ["Strawberry", "Grape"]
    strawberries, _, orchard = (f.id for f in recipe.fields)
    assert _relations(recipe) == {("east_of", orchard, (strawberries,))}


def test_vines_of_the_crop_named_stay_its_plants() -> None:
    assert _crops(generate("a tomato field, the vines are on stakes").recipe) == ["Tomato"]

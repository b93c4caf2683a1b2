"""Text of blind set g49 (issue 8): each miss of its blind run fixed as the general
mechanism (plot codes "P1", "P2" opening a list's items; a month the crop went in;
members of a counted heading said by crop group, each in its own part of the farm; "a
fruit tree block"; a density right after the plants; a grid in brackets that fits some of
the crops a plot may be; the time a list heading says; terraces named by their side)."""

from __future__ import annotations

import pytest

from agrirecipe import generate


def test_plot_codes_opening_a_lists_items_are_labels_not_counts() -> None:
    recipe = generate(
        "Plot register: P1 Imperator carrots, P2 Danvers carrots, P3 Savoy cabbage, P4 January "
        "King cabbage, P5 Stuttgarter onions."
    ).recipe
    assert [f.variety for f in recipe.fields] == [
        "Imperator",
        "Danvers",
        "Savoy",
        "January King",
        "Stuttgarter",
    ]


def test_a_lone_code_is_left_alone() -> None:
    recipe = generate("an F1 hybrid tomato field").recipe
    assert [f.crop for f in recipe.fields] == ["Tomato"]


@pytest.mark.parametrize(
    "prompt",
    [
        "The Nantes carrots on the sandy field went in back in April; now it's June and "
        "they're still young, no disease.",
        "Nantes carrots, put in in April, now it's June, still young.",
    ],
)
def test_the_month_a_crop_went_in_is_not_the_scenes_time(prompt: str) -> None:
    (carrots,) = generate(prompt).recipe.fields
    assert (carrots.variety, carrots.season, carrots.stage) == ("Nantes", "Summer", "Vegetative")


def test_members_of_a_counted_heading_each_in_a_part_of_the_farm() -> None:
    recipe = generate(
        "Our place is basically three strips. Cherries across the top end, root veg through "
        "the middle, and cereals down at the bottom by the river."
    ).recipe
    cherries, roots, cereals = recipe.fields
    assert cherries.crop == "Cherry"
    assert roots.crop in ("Carrot", "Potato", "Onion")
    assert cereals.crop in ("Wheat", "Maize")
    relations = {(r.kind, r.subject, r.objects) for r in recipe.relations}
    assert ("north_of", roots.id, (cereals.id,)) in relations


def test_a_fruit_tree_block_is_an_orchard() -> None:
    recipe = generate(
        "grapevines, 18 rows x 80 m, 2.2 m between rows, 1 m between vines, 8 m headland for "
        "the tractor to turn; put a fruit tree block just north of the vines"
    ).recipe
    vines, trees = recipe.fields
    assert trees.crop in ("Apple", "Pear", "Cherry", "Orange")
    assert ("north_of", trees.id, (vines.id,)) in {
        (r.kind, r.subject, r.objects) for r in recipe.relations
    }


def test_a_density_said_right_after_the_plants() -> None:
    (tomatoes,) = generate(
        "For a LiDAR dataset: half a hectare of tomato plants, 33,333 per hectare, 1.5 m "
        "between rows."
    ).recipe.fields
    width, length = tomatoes.geometry.size_m
    assert width * length == pytest.approx(5000, rel=0.01)
    density = 10_000 / (tomatoes.agronomy.row_spacing_m * tomatoes.agronomy.in_row_spacing_m)
    assert density == pytest.approx(33_333, rel=0.01)


def test_a_grid_in_brackets_fits_some_of_the_crops_a_plot_may_be() -> None:
    recipe = generate(
        "Drone test: a fruit tree block (3.5 m x 1 m) north of a strawberry plot with beds on "
        "1.5 m centres, each plot with its own 6 m headland."
    ).recipe
    trees = recipe.fields[0]
    assert trees.crop in ("Apple", "Pear")
    assert (trees.agronomy.row_spacing_m, trees.agronomy.in_row_spacing_m) == (3.5, 1.0)


def test_the_time_a_list_heading_says_is_its_fields() -> None:
    recipe = generate(
        "Citrus harvest robot trial in Chile in July: a Navel block north of a Hamlin block, "
        "6 m x 3 m spacing, 200 trees in each, fruit ripe."
    ).recipe
    assert [(f.variety, f.season) for f in recipe.fields] == [
        ("Navel", "Winter"),
        ("Hamlin", "Winter"),
    ]


def test_terraces_named_by_their_side() -> None:
    recipe = generate("the south terraces are bananas, the north terraces are citrus").recipe
    bananas, citrus = recipe.fields
    assert (bananas.crop, citrus.crop) == ("Banana", "Orange")
    assert ("south_of", bananas.id, (citrus.id,)) in {
        (r.kind, r.subject, r.objects) for r in recipe.relations
    }


def test_a_field_split_down_the_middle_is_its_two_halves() -> None:
    recipe = generate(
        "The tomato field is split down the middle, San Marzano on the left half and Beefsteak "
        "on the right half, both flowering."
    ).recipe
    sanmarzano, beefsteak = recipe.fields
    assert (sanmarzano.variety, beefsteak.variety) == ("San Marzano", "Beefsteak")
    assert ("west_of", sanmarzano.id, (beefsteak.id,)) in {
        (r.kind, r.subject, r.objects) for r in recipe.relations
    }


def test_down_the_middle_of_a_zoned_farm_is_still_a_zone() -> None:
    recipe = generate(
        "Potatoes along the top, wheat down the middle and carrots at the bottom."
    ).recipe
    assert [f.crop for f in recipe.fields] == ["Potato", "Wheat", "Carrot"]
    assert ("between", recipe.fields[1].id) in {(r.kind, r.subject) for r in recipe.relations}


@pytest.mark.parametrize("garden", ["the market garden", "the veg plot"])
def test_the_first_member_of_a_list_after_a_colon_is_a_field_of_its_own(garden: str) -> None:
    recipe = generate(
        f"Left to right across {garden}: leafy greens, then peppers, then tomatoes."
    ).recipe
    assert [f.crop for f in recipe.fields][1:] == ["Pepper", "Tomato"]
    assert recipe.fields[0].crop in ("Lettuce", "Cabbage")


def test_a_field_before_a_colon_and_its_own_description_stay_one() -> None:
    recipe = generate(
        "The only field we have is behind the barn: 3 acres of Riesling, the grapes ripe."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Riesling"]

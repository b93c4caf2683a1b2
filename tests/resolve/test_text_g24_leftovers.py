"""Engineering text left over from blind set g24 (issue 8): two plots of one crop told
apart by labels ("Field A: ... Field B, east of A: ...") or by "one ... the other ...",
each with its own row measures; "rows N-S at 75 cm"; "same row count and spacing"; "a
single tomato row"; "beds of the same width"; a member's own block said after it; "three
tree blocks"; "it" after a field placed by a landmark is the landmark."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    "prompt",
    [
        "Two maize fields for our autonomous tractor's path planner, both with 12 m "
        "headlands. Field A: 200 x 150 m, rows N-S at 70 cm. Field B, east of A: 0.8 ha, "
        "rows east-west, also at 70 cm.",
        "Two maize fields, both with 12 m headlands. Field 1: 200 x 150 m, rows N-S at "
        "70 cm. Field 2, east of field 1: 0.8 ha, rows east-west, also at 70 cm.",
        "Two maize fields, both with 12 m headlands. One is 200 x 150 m, rows N-S at 70 cm. "
        "The other, east of the first, is 0.8 ha, rows east-west, also at 70 cm.",
        "Two maize fields, both with 12 m headlands: one 200 x 150 m, rows N-S at 70 cm; the "
        "other 0.8 ha, rows east-west, also at 70 cm, east of the first.",
    ],
)
def test_two_plots_of_one_crop_each_with_its_own_rows(
    prompt: str, named_relations: Callable[[str], NamedRelations]
) -> None:
    first, second = recipe(prompt).fields
    assert first.geometry.size_m == (200.0, 150.0)
    assert second.geometry.area_m2 == pytest.approx(8000, rel=0.01)
    assert (first.row_bearing_deg, second.row_bearing_deg) == (0.0, 90.0)
    assert (first.agronomy.row_spacing_m, second.agronomy.row_spacing_m) == (0.7, 0.7)
    assert first.geometry.headland_m == second.geometry.headland_m == 12.0
    assert named_relations(prompt) == {("east_of", "Maize", ("Maize",))}


def test_the_direction_and_spacing_of_rows_in_one_phrase() -> None:
    (maize,) = recipe("a maize field, rows N-S at 70 cm").fields
    assert (maize.row_bearing_deg, maize.agronomy.row_spacing_m) == (0.0, 0.7)
    (apples,) = recipe("apple orchard, rows e-w on 3.5 m, trees 1 m apart").fields
    assert (apples.row_bearing_deg, apples.agronomy.row_spacing_m) == (90.0, 3.5)


def test_the_same_row_count_and_spacing() -> None:
    a, b = recipe(
        "Headland-turning test, two maize blocks. Block A: 24 rows at 70 cm, rows 100 m, 10 m "
        "headland. Block B, directly north of A: same row count and spacing but only a 6 m "
        "headland."
    ).fields
    assert (a.row_count, b.row_count) == (24, 24)
    assert (a.agronomy.row_spacing_m, b.agronomy.row_spacing_m) == (0.7, 0.7)
    assert (a.geometry.headland_m, b.geometry.headland_m) == (10.0, 6.0)
    # (the count alone leaves the spacing the crop's own)
    _, c = recipe(
        "A maize block of 24 rows at 70 cm, and north of it a second maize block with the "
        "same number of rows"
    ).fields
    assert (c.row_count, c.agronomy.row_spacing_m) == (24, 0.75)


def test_a_single_row_of_a_crop() -> None:
    tomatoes, chillies = recipe(
        "Small test garden for the manipulator arm: a single tomato row 20 m long with plants "
        "every 60 cm, and next to it two rows of chillies, 50 cm apart in the row."
    ).fields
    assert (tomatoes.crop, tomatoes.row_count, tomatoes.row_length_m) == ("Tomato", 1, 20.0)
    assert (chillies.crop, chillies.row_count) == ("Pepper", 2)


def test_beds_of_the_same_width() -> None:
    salad, onions = recipe(
        "Autonomous hoe trial, two plots side by side: salad on 10 beds, 1.5 m bed centres, "
        "4 rows per bed; onions on 10 beds of the same width with 6 rows per bed."
    ).fields
    assert salad.agronomy.row_spacing_m == onions.agronomy.row_spacing_m == 1.5
    assert (salad.agronomy.rows_per_bed, onions.agronomy.rows_per_bed) == (4, 6)


def test_a_members_own_block_said_after_it(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two banana blocks for the tropical sim. Dwarf Cavendish planted on a 2 x 2 m grid, "
        "block 50 m by 40 m. Lady Finger on a 3 x 3 m grid, block 40 m by 40 m, placed west "
        "of the Cavendish."
    )
    cavendish, lady_finger = recipe(prompt).fields
    assert (cavendish.variety, cavendish.geometry.size_m) == ("Cavendish", (50.0, 40.0))
    assert (lady_finger.variety, lady_finger.geometry.size_m) == ("Lady Finger", (40.0, 40.0))
    assert named_relations(prompt) == {("west_of", "Lady Finger", ("Cavendish",))}


def test_blocks_counted_with_what_they_grow() -> None:
    fields = recipe(
        "Sensor calibration site with three tree blocks, 8 rows each at 4 m row spacing: "
        "apples, cherries, and a pear block between the apples and the cherries."
    ).fields
    assert [f.crop for f in fields] == ["Apple", "Cherry", "Pear"]
    assert {f.row_count for f in fields} == {8}
    # (a count of trees for each of more plots than a scene holds)
    orchards = recipe("two 120-tree cherry orchards").fields
    assert len(orchards) == 2
    assert all("plant_count" in f.stated and f.nominal_plant_count == 120 for f in orchards)


def test_it_after_a_landmark_is_the_landmark(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    assert named_relations(
        "wheat north of the farmhouse, maize south of it, potatoes east of it and cabbages "
        "west of it"
    ) == {("north_of", "Wheat", ("Maize",)), ("east_of", "Potato", ("Cabbage",))}
    # (a field placed against a field, not scenery: "it" is that field)
    assert named_relations("wheat north of the maize, potatoes east of it") == {
        ("north_of", "Wheat", ("Maize",)),
        ("east_of", "Potato", ("Maize",)),
    }

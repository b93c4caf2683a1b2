"""plan_rows: stated rows, beds, counts and spacings -> the numbers a field is built with."""

from __future__ import annotations

import math

import pytest

from agrirecipe import PromptError
from agrirecipe.enrich import plan_rows
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.layout import FieldRequest, pack_fields


def plan(knowledge: KnowledgeBase, crop: str, **stated: float):  # type: ignore[no-untyped-def]
    return plan_rows(
        stated,
        knowledge.crop_file(crop),
        label=crop.lower(),
        size_m=None,
        area_m2=None,
        default_size_m=knowledge.default_field_size_m(crop),
        default_headland_m=knowledge.default_headland_m(crop),
    )


def test_rows_and_length_fix_the_planted_block(knowledge: KnowledgeBase) -> None:
    result = plan(knowledge, "Maize", rows=10, row_length_m=80.0, row_spacing_m=0.76)
    width, length = result.size_m
    usable_w = width - 2 * result.headland_m
    # The kernel's rule: floor(usable / spacing) + 1 rows.
    assert math.floor(usable_w / 0.76 + 1e-9) + 1 == 10
    assert math.isclose(length - 2 * result.headland_m, 80.0)
    assert result.stated == ["rows", "row_length", "row_spacing"]


def test_rows_share_beds(knowledge: KnowledgeBase) -> None:
    result = plan(knowledge, "Strawberry", rows=12, beds=6)
    assert result.rows_per_bed == 2 and result.row_spacing_m == 1.5


def test_rows_said_with_their_spacing_are_single_rows(knowledge: KnowledgeBase) -> None:
    """Bananas grow in double rows by default; "12 rows, 3 m apart" are 12 single rows."""
    assert plan(knowledge, "Banana").rows_per_bed == 2
    result = plan(knowledge, "Banana", rows=12, row_spacing_m=3.0, in_row_spacing_m=3.0)
    assert (result.rows_per_bed, result.row_spacing_m) == (1, 3.0)


def test_the_rows_said_fit_on_the_bed_said(knowledge: KnowledgeBase) -> None:
    """ "12 beds at 1.5 m, 4 rows per bed": the rows share the bed, never overhang it."""
    for crop, per_bed in (("Lettuce", 4), ("Onion", 5), ("Strawberry", 3)):
        result = plan(knowledge, crop, beds=12, bed_width_m=1.5, rows_per_bed=per_bed)
        assert result.rows_per_bed == per_bed
        assert result.bed_row_spacing_m * (per_bed - 1) < 1.5


def test_rows_that_do_not_share_beds_evenly_are_refused(knowledge: KnowledgeBase) -> None:
    with pytest.raises(PromptError, match="evenly"):
        plan(knowledge, "Strawberry", rows=7, beds=3)


def test_rows_that_fill_no_whole_usual_bed_are_single_rows(knowledge: KnowledgeBase) -> None:
    """ "a row of peppers": one row of a crop usually on twin-row beds, planted single."""
    result = plan(knowledge, "Pepper", rows=1)
    assert result.rows_per_bed == 1
    assert result.row_spacing_m == pytest.approx(1.45 / 2)
    assert any("planted as single rows" in w for w in result.warnings)
    with pytest.raises(PromptError, match="do not fill beds"):
        plan(knowledge, "Pepper", rows=3, rows_per_bed=2)


def test_a_count_that_makes_no_even_block_is_planted_and_said(
    knowledge: KnowledgeBase,
) -> None:
    result = plan(knowledge, "Apple", plant_count=97)
    assert result.warnings and "97 plants" in result.warnings[0]


def test_a_headland_wider_than_the_field_is_refused(knowledge: KnowledgeBase) -> None:
    with pytest.raises(PromptError, match="headland"):
        plan_rows(
            {"headland_m": 30.0},
            knowledge.crop_file("Lettuce"),
            label="lettuce",
            size_m=(20.0, 20.0),
            area_m2=None,
            default_size_m=(30.0, 60.0),
            default_headland_m=2.0,
        )


def test_a_bearing_turns_the_field_clockwise_from_north(knowledge: KnowledgeBase) -> None:
    assert plan(knowledge, "Wheat", row_bearing_deg=30.0).rotation_deg == -30.0


def test_turned_fields_are_packed_without_overlap() -> None:
    requests = [
        FieldRequest("a", 20.0, 80.0, 1.0, -30.0),
        FieldRequest("b", 20.0, 80.0, 1.0, 0.0),
        FieldRequest("c", 40.0, 10.0, 0.0, -90.0),
    ]
    geometry = pack_fields(requests)
    from agrirecipe.recipe._models import _rectangles_overlap

    names = list(geometry)
    for i, first in enumerate(names):
        for second in names[i + 1 :]:
            assert not _rectangles_overlap(geometry[first], geometry[second])
    assert geometry["a"].rotation_deg == -30.0
    assert min(x for x, _ in geometry["a"].corners_m()) >= -1e-9


def test_a_size_said_with_the_rows_is_the_field(knowledge: KnowledgeBase) -> None:
    """ "36 m x 60 m: 12 rows 3 m apart": the field is 36 m wide, its border what is left."""
    result = plan_rows(
        {"rows": 12, "row_spacing_m": 3.0, "in_row_spacing_m": 3.0},
        knowledge.crop_file("Banana"),
        label="banana",
        size_m=(36.0, 60.0),
        area_m2=None,
        default_size_m=knowledge.default_field_size_m("Banana"),
        default_headland_m=knowledge.default_headland_m("Banana"),
    )
    assert result.size_m == (36.0, 60.0)
    usable = 36.0 - 2 * result.headland_m
    assert math.floor(usable / 3.0 + 1e-9) + 1 == 12


def test_density_and_in_row_spacing_set_the_bed_spacing_of_double_rows(
    knowledge: KnowledgeBase,
) -> None:
    result = plan(knowledge, "Banana", rows_per_bed=2, in_row_spacing_m=2.25, plants_per_ha=1840.0)
    assert result.rows_per_bed == 2
    assert result.in_row_spacing_m == pytest.approx(2.25)
    density = 10_000 * 2 / (result.row_spacing_m * result.in_row_spacing_m)
    assert density == pytest.approx(1840, rel=1e-3)


def test_a_count_of_plants_fills_the_area_said(knowledge: KnowledgeBase) -> None:
    row_plan = plan_rows(
        {"row_spacing_m": 3.4, "plant_count": 2900},
        knowledge.crop_file("Apple"),
        label="gala",
        size_m=None,
        area_m2=10_000.0,
        default_size_m=knowledge.default_field_size_m("Apple"),
        default_headland_m=knowledge.default_headland_m("Apple"),
    )
    width, length = row_plan.size_m
    assert width * length == pytest.approx(10_000.0, rel=1e-6)
    headland = row_plan.headland_m
    inner_w, inner_l = width - 2 * headland, length - 2 * headland
    # every tree stands inside the headland, rows 3.4 m apart
    beds = math.floor(inner_w / 3.4 + 0.5)
    per_row = math.ceil(2900 / beds)
    assert (per_row - 0.5) * row_plan.in_row_spacing_m <= inner_l + 1e-6
    assert beds * per_row >= 2900
    assert row_plan.plant_count == 2900

"""Text of blind set g43 (issue 8): labelled members whose rows are said "each row 100 m
long", "6 beds ... with 2 rows each", "drilled at 12.5 cm, 25 cm and 37.5 cm" and "the 25 cm
plot", cotton-wool clouds, "in the same state", "a seagull on every other bed", "in one
field and ... in the next", "beginning to colour", "...; a whole grove of sick-looking
trees", "carrots (nantes) east of them", "wait theres only wheat & corn", "wheat wheat and
more wheat", "Left to right along the road we've got ...", "a 30 by 60 ft bed", "north of
both onion fields a field of ...", "each block right up against the one before"."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import FieldSpec


def _relations(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in generate(prompt).recipe.relations}


def _one(prompt: str) -> FieldSpec:
    (field,) = generate(prompt).recipe.fields
    return field


def test_each_row_long_is_no_measure_of_every_field() -> None:
    potatoes, wheat = generate(
        "two plots for the drone mapping trial. plot A: potatoes, 30 rows, 75 cm apart, each "
        "row 100 m long. plot B: wheat drilled on 12.5 cm rows, 40 x 100 m, directly south of "
        "plot A"
    ).recipe.fields
    assert (potatoes.row_count, potatoes.agronomy.row_spacing_m) == (30, pytest.approx(0.75))
    assert potatoes.row_length_m == pytest.approx(100.0)
    assert wheat.agronomy.row_spacing_m == pytest.approx(0.125)
    assert wheat.geometry.size_m == pytest.approx((40.0, 100.0))


def test_rows_each_after_beds_are_rows_per_bed() -> None:
    strawberries, lettuce = generate(
        "Two bed systems for the vision team, next to each other: strawberries, 6 beds on "
        "1.5 m centres with 2 rows each, and lettuce, 6 beds on 1.5 m centres with 3 rows each."
    ).recipe.fields
    assert (strawberries.agronomy.rows_per_bed, lettuce.agronomy.rows_per_bed) == (2, 3)
    assert strawberries.row_count == 12 and lettuce.row_count == 18


def test_a_list_of_drilling_widths_and_a_member_named_by_one() -> None:
    prompt = (
        "row-spacing experiment for the camera: three wheat plots, 10 x 50 m each, drilled at "
        "12.5 cm, 25 cm and 37.5 cm; the 25 cm plot sits between the other two"
    )
    fields = generate(prompt).recipe.fields
    assert [f.agronomy.row_spacing_m for f in fields] == pytest.approx([0.125, 0.25, 0.375])
    assert _relations(prompt) == {("between", "wheat_plot_2", ("wheat_plot_1", "wheat_plot_3"))}


def test_cotton_wool_clouds_are_sky() -> None:
    field = _one(
        "rows of Conference pear trees smothered in white blossom, a blue sky with a few "
        "cotton-wool clouds"
    )
    assert (field.crop, field.stage) == ("Pear", "Reproductive")


def test_a_field_in_the_same_state_as_the_one_before() -> None:
    fields = generate(
        "You can see Stuttgarter Riesen onions in the near field, bulbs sitting on top of the "
        "soil and tops flat, ready to lift, and a field of Sturon beyond the ditch in the same "
        "state. August, dry."
    ).recipe.fields
    assert [f.stage for f in fields] == ["Maturation", "Maturation"]


def test_a_bird_on_every_other_bed_is_no_field() -> None:
    field = _one(
        "Strawberry beds on 1.5 m centres, two rows per bed, the plants just planted through "
        "the black plastic and a seagull on every other bed."
    )
    assert field.crop == "Strawberry"


def test_one_field_and_the_next() -> None:
    assert _relations(
        "flint corn in one field and Spring Wheat in the next, both just emerged"
    ) == {("next_to", "wheat_field_1", ("maize_field_1",))}


def test_grapes_beginning_to_colour_are_ripening() -> None:
    assert _one("A Pinot Nero vineyard, the grapes beginning to colour").stage == "Maturation"


def test_a_grove_of_sick_trees_after_a_semicolon_is_the_same_field() -> None:
    field = _one(
        "Our orange trees in this shot have blotchy, mottled yellow leaves; a whole grove of "
        "sick-looking trees along a dusty road."
    )
    assert (field.crop, field.health) == ("Orange", "Ill")


def test_a_pronoun_after_a_bracketed_variety_points_back() -> None:
    relations = _relations(
        "ok so: spuds (bintje) 50x100m, carrots (nantes) east of them, onions (sturon) west of "
        "the spuds"
    )
    assert ("east_of", "carrot_field_1", ("potato_field_1",)) in relations
    assert ("west_of", "onion_field_1", ("potato_field_1",)) in relations


def test_a_count_taken_back_after_wait() -> None:
    fields = generate(
        "3 different cereals... wait theres only wheat & corn right? ok just those 2 then"
    ).recipe.fields
    assert [f.crop for f in fields] == ["Wheat", "Maize"]


def test_a_crop_said_again_and_again_then_more() -> None:
    fields = generate("wheat wheat and more wheat lol, 3 fields of it, spring").recipe.fields
    assert [f.crop for f in fields] == ["Wheat"] * 3


def test_a_row_walked_along_scenery_from_left_to_right() -> None:
    assert _relations(
        "Left to right along the road we've got 2 ha of Fontane potatoes, then 1.5 ha of Dent "
        "maize, then 3 ha of Spelt."
    ) >= {
        ("west_of", "potato_field_1", ("maize_field_1",)),
        ("west_of", "maize_field_1", ("wheat_field_1",)),
    }


def test_a_bed_sized_with_one_unit_for_both_sides() -> None:
    tomatoes, peppers = generate(
        "a 30 by 60 ft bed of San Marzano tomatoes and, right next to it, a 20 by 60 ft bed of "
        "Jalapeños."
    ).recipe.fields
    assert tomatoes.geometry.size_m == pytest.approx((9.144, 18.288), abs=0.01)
    assert peppers.geometry.size_m == pytest.approx((6.096, 18.288), abs=0.01)


def test_a_field_placed_against_both_fields_named_before() -> None:
    assert _relations(
        "Red Baron and Sturon onions side by side, and north of both onion fields a field of "
        "Danvers carrots."
    ) >= {
        ("north_of", "carrot_field_1", ("onion_field_1",)),
        ("north_of", "carrot_field_1", ("onion_field_2",)),
    }


def test_each_field_against_the_one_before() -> None:
    assert _relations(
        "Walking down the lane you pass Washington Navel oranges first, then Hamlin, then Moro, "
        "each block right up against the one before."
    ) == {
        ("next_to", "orange_orchard_2", ("orange_orchard_1",)),
        ("next_to", "orange_orchard_3", ("orange_orchard_2",)),
    }

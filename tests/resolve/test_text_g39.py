"""Text of blind set g39 (issue 8): fixes after its blind run (kinds of cloud, purposes of
a robot test, a prickly pear hedge, one plot said as the count of the one field, a
misspelt "naval", "yellow-green fruit", rows "pointing" at a bearing, cabbages either side
of "a" carrot plot, twin rows on a bed, "rows 5 m" of an orchard, relative "that", "the
older leaves all shrivelled", "look ok", "all healthy apart from ...", "below it, so
south of ...", "mostly grain on this farm")."""

from __future__ import annotations

import pytest

from agrirecipe import UnknownCropError, generate


def _fields(prompt: str) -> list[tuple[str, str, str]]:
    return [(f.crop, f.variety, f.health) for f in generate(prompt).recipe.fields]


def test_kinds_of_cloud_are_sky() -> None:
    fields = generate(
        "Photo down a vineyard row. Bunches are colouring up dark blue, rows are 2.5 m apart "
        "with a vine every 1.5 m along the wire. Swallows and some wispy cirrus."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Grape"]


def test_what_a_robot_test_follows_is_no_plot() -> None:
    fields = generate(
        "Bed-following test. Two strawberry tunnels with 6 beds each, and a lettuce plot of 6 "
        "beds in between them; all beds on 1.5 m centres."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Strawberry", "Strawberry", "Lettuce"]


def test_a_prickly_pear_hedge_is_scenery_and_prickly_pears_unknown() -> None:
    fields = generate(
        "Holiday picture from Sicily: a grove of blood oranges with the fruit just starting "
        "to blush, and right next to it a Valencia Late block in flower. Dry stone wall and "
        "a prickly pear hedge in front."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Orange", "Orange"]
    with pytest.raises(UnknownCropError):
        generate("a prickly pear plantation")


@pytest.mark.parametrize(
    ("prompt", "crop"),
    [
        ("veggies. any. just 1 field", None),
        (
            "Only one field on the smallholding, a cabbage patch roughly 30 by 40 m down past "
            "the chicken coop.",
            "Cabbage",
        ),
    ],
)
def test_one_plot_said_as_the_count_of_the_one_field(prompt: str, crop: str | None) -> None:
    (field,) = generate(prompt).recipe.fields
    assert crop is None or field.crop == crop


def test_a_plot_named_by_its_crop_is_no_count() -> None:
    fields = generate(
        "Our little valley in September: a vineyard on one slope, the river at the bottom, "
        "and an apple orchard on the other side with the trees heavy with red fruit."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Grape", "Apple"]


def test_naval_oranges_and_yellow_green_pears() -> None:
    assert _fields("naval oranges ripe in december, healthy trees") == [
        ("Orange", "Navel", "Healthy")
    ]
    (pears,) = generate(
        "Williams' Bon Chrétien pears in my photo, big yellow-green fruit ready to pick at "
        "the end of August, a wasp on every one."
    ).recipe.fields
    assert (pears.variety, pears.stage) == ("Williams", "Maturation")


def test_rows_pointing_west_of_north() -> None:
    (potatoes,) = generate(
        "Potatoes, 24 rows at 0.75 m, rows pointing 10 degrees west of north and 120 m long, "
        "to test GNSS row guidance."
    ).recipe.fields
    assert potatoes.row_bearing_deg == pytest.approx(170.0)


def test_a_crop_on_either_side_of_a_plot_said_with_a() -> None:
    fields = generate(
        "UAV trial layout with cabbages on either side of a carrot plot. Cabbages: 8 rows at "
        "0.75 m. Carrots: 4 ridges, 2 rows per ridge."
    ).recipe
    assert sorted(f.crop for f in fields.fields) == ["Cabbage", "Cabbage", "Carrot"]
    assert [r.kind for r in fields.relations] == ["between"]
    # (a list on either side keeps its members one each side)
    listed = generate("ripe Durondeau and Williams pears on either side of a Jonagored block")
    assert sorted(f.variety for f in listed.recipe.fields) == ["Durondeau", "Jonagold", "Williams"]
    (between,) = [r for r in listed.recipe.relations if r.kind == "between"]
    assert between.subject.startswith("apple")


def test_twin_rows_on_each_bed_with_their_spacing() -> None:
    (peppers,) = generate(
        "Pepper test plot: 5 beds on 1.5 m centres, twin rows on each bed (45 cm between the "
        "two rows), plants 45 cm apart in the row, beds 30 m long."
    ).recipe.fields
    assert (peppers.bed_count, peppers.agronomy.rows_per_bed) == (5, 2)


def test_orchard_rows_said_bare_in_brackets() -> None:
    fields = generate(
        "For drone calibration: a vineyard (rows 2.5 m) north of an orchard (rows 5 m), which "
        "is itself north of a strawberry field (beds 1.5 m)."
    ).recipe.fields
    assert [f.agronomy.row_spacing_m for f in fields] == [2.5, 5.0, 1.5]


def test_a_relative_that_is_about_the_field_named_last() -> None:
    assert [
        h
        for _, _, h in _fields(
            "plot 1 Elsanta strawberries with the fruit ripening, plot 2 Red Baron onions that "
            "have caught downy mildew, plot 3 Nantes carrots just emerged. all of this in june"
        )
    ] == ["Healthy", "Ill", "Healthy"]


def test_all_of_the_leaves_is_not_every_field() -> None:
    assert _fields(
        "zoomed in on the carots: dark brown spots with yellow rings round them and the older "
        "leaves all shrivelled. the onions in the field next to them look ok."
    ) == [("Carrot", "Nantes", "Ill"), ("Onion", "Sturon", "Healthy")]


def test_all_healthy_apart_from_one() -> None:
    assert [
        h
        for _, _, h in _fields(
            "Three fields along the lane: potatoes, onions, carrots. All healthy apart from the "
            "onions, which have downy mildew."
        )
    ] == ["Healthy", "Ill", "Healthy"]


def test_a_picture_side_said_again_in_compass_words() -> None:
    relations = generate(
        "Aerial photo with north at the top. A maize field with the rows running north-south, "
        "and directly below it, so south of the maize, a field of cabbages."
    ).recipe.relations
    assert [(r.kind, r.subject, r.objects) for r in relations] == [
        ("south_of", "cabbage_field_1", ("maize_field_1",))
    ]


def test_mostly_grain_on_this_farm() -> None:
    fields = generate(
        "Mostly grain on this farm: three cereal fields around the yard, plus one small "
        "strawberry patch by the house."
    ).recipe.fields
    assert len(fields) == 4 and fields[-1].crop == "Strawberry"

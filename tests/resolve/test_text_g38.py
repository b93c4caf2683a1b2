"""Text of blind set g38 (issue 8), first fixes: a juice plant is scenery, plants "planted at
zero spacing" are refused, and "the ears fully out" is a cereal's flowering stage."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, UnknownCropError, generate


def test_a_juice_plant_is_scenery() -> None:
    (hamlin,) = generate(
        "Hamlin orange trees in Florida in December, fruit just coloured up and ready for the "
        "juice plant, a trailer of bins on the sandy track."
    ).recipe.fields
    assert (hamlin.variety, hamlin.stage) == ("Hamlin", "Maturation")


def test_plants_set_at_zero_spacing_are_refused() -> None:
    with pytest.raises(PromptError, match="positive"):
        generate("Vineyard with the vines planted at zero spacing, next to a wheat field.")


def test_ears_fully_out() -> None:
    fields = generate(
        "The Winter Wheat field is north of the durum, both with a 6 m headland left for the "
        "sprayer to turn on, and the ears fully out on both in late May."
    ).recipe.fields
    assert [(f.variety, f.stage) for f in fields] == [
        ("Winter Wheat", "Reproductive"),
        ("Durum", "Reproductive"),
    ]


# --- the rest of the g38 round -------------------------------------------------------


def _crops(prompt: str) -> list[tuple[str, str | None]]:
    return [(f.crop, f.variety) for f in generate(prompt).recipe.fields]


def _relations(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in generate(prompt).recipe.relations}


def test_a_count_of_fields_then_a_list_after_a_comma() -> None:
    fields = generate(
        "Looking down from the hill you can make out four fields, maize, wheat, potatoes and "
        "a vineyard, with a tractor working in the maize and hedges around each one."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Maize", "Wheat", "Potato", "Grape"]


def test_fields_one_behind_the_other_keep_their_count() -> None:
    fields = generate(
        "Photo from the gate: three different vegetable fields one behind the other, all with "
        "healthy dark green leaves, and a quad bike in the nearest one."
    ).recipe.fields
    assert len(fields) == 3 and len({f.crop for f in fields}) == 3


def test_two_fields_either_side_of_a_road_are_next_to_each_other() -> None:
    result = generate(
        "Two fields of cereals either side of the farm road, both golden and ready for the "
        "combine, under a huge blue sky."
    )
    a, b = (f.id for f in result.recipe.fields)
    assert {(r.kind, frozenset((r.subject, *r.objects))) for r in result.recipe.relations} == {
        ("next_to", frozenset((a, b)))
    }
    # (not when a third field is placed after them)
    assert (
        len(
            generate(
                "Two spud fields either side of the lane and an onion field past the duck pond."
            ).recipe.fields
        )
        == 3
    )


def test_a_side_word_after_a_variety_in_brackets() -> None:
    relations = _relations(
        "beefsteak tomatos north, onions (sturon) middle, carrots (danvers) south"
    )
    assert ("north_of", "tomato_field_1", ("onion_field_1",)) in relations
    assert ("between", "onion_field_1", ("tomato_field_1", "carrot_field_1")) in relations


def test_further_that_way_is_past_the_field_furthest_that_way() -> None:
    relations = _relations(
        "Sonata strawberries east of the Danvers carrots, and Regina cherries further east still."
    )
    assert ("east_of", "cherry_orchard_1", ("strawberry_field_1",)) in relations
    assert ("east_of", "cherry_orchard_1", ("carrot_field_1",)) not in relations


def test_a_crop_right_after_each_other_is_a_new_clause() -> None:
    assert _crops("riesling & chardonnay vineyards nxt to each other grapes ripening, sept") == [
        ("Grape", "Riesling"),
        ("Grape", "Chardonnay"),
    ]


def test_a_lower_case_variety_listed_after_a_field_of_its_crop() -> None:
    fields = generate("sonata strawbs 10 beds & albion 8 beds side by side").recipe.fields
    assert [(f.variety, f.bed_count) for f in fields] == [("Sonata", 10), ("Albion", 8)]


def test_the_middle_one_is_the_member_in_the_middle() -> None:
    fields = generate(
        "Three potato fields in a line along the lane. The middle one has blight, the other "
        "two look fine."
    ).recipe.fields
    assert [f.health for f in fields] == ["Healthy", "Ill", "Healthy"]
    fields = generate("Three potato fields in a line. The second one has blight.").recipe.fields
    assert [f.health for f in fields] == ["Healthy", "Ill", "Healthy"]


def test_one_big_orchard_of_three_blocks() -> None:
    for prompt in (
        "jonagold n conferance pears n kordia cherries, one big orchard but 3 blocks pls",
        "jonagold n conferance pears n kordia cherries, one big orchard",
    ):
        assert _crops(prompt) == [
            ("Apple", "Jonagold"),
            ("Pear", "Conference"),
            ("Cherry", "Kordia"),
        ]


def test_a_plot_announced_in_a_heading_is_the_one_field_of_its_crop() -> None:
    fields = generate(
        "Orchard plus vineyard for the drone. 120 cherry trees, 4.5 m between rows and 2.5 m "
        "between trees; next to them 20 rows of grapes at 2.5 m."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Cherry", "Grape"]
    assert (fields[1].row_count, fields[1].agronomy.row_spacing_m) == (20, 2.5)


def test_the_same_row_and_plant_spacing() -> None:
    fields = generate(
        "Cabbage plots for the weed-detection model: Savoy and Red Express, 0.75 m rows, 45 cm "
        "in-row, each plot 20 rows of 50 m, and a January King plot between them at the same "
        "row and plant spacing."
    ).recipe.fields
    assert [f.variety for f in fields] == ["Savoy", "Red Express", "January King"]
    assert (fields[2].agronomy.row_spacing_m, fields[2].agronomy.in_row_spacing_m) == (0.75, 0.45)


def test_rows_per_plot_after_a_full_list_and_a_bare_spacing() -> None:
    fields = generate(
        "We're testing row-following on three crops with different spacings: lettuce at 35 cm, "
        "cabbage at 75 cm and tomatoes at 150 cm, 12 rows per plot, plots laid out east to "
        "west in that order."
    ).recipe.fields
    assert [(f.crop, f.row_count, f.agronomy.row_spacing_m) for f in fields] == [
        ("Lettuce", 12, 0.35),
        ("Cabbage", 12, 0.75),
        ("Tomato", 12, 1.5),
    ]


def test_a_bare_spacing_after_a_crop_is_the_one_its_range_holds() -> None:
    fields = generate(
        "Three orchard blocks for the spraying drone, 10 rows in each: apples at 3.5 m, pears "
        "at 3.6 m, cherries at 4.8 m, with the pear block between the other two."
    ).recipe.fields
    assert [f.agronomy.row_spacing_m for f in fields] == [3.5, 3.6, 4.8]


def test_labelled_members_of_a_counted_heading() -> None:
    fields = generate(
        "Two-block orchard for the mapping robot. Granny Smith: 15 rows, 3.4 m between rows, "
        "1 m between trees. Conferance pears: 15 rows, 3.5 m between rows, 1 m between trees. "
        "Pears north of the apples, rows E-W in both."
    ).recipe.fields
    assert [(f.variety, f.agronomy.row_spacing_m) for f in fields] == [
        ("Granny Smith", 3.4),
        ("Conference", 3.5),
    ]


def test_a_share_of_the_farms_size() -> None:
    wheat = generate(
        "A 100-acre farm: half in wheat, the other half split between maize and potatoes."
    ).recipe.fields[0]
    assert wheat.crop == "Wheat"
    assert abs(wheat.geometry.size_m[0] * wheat.geometry.size_m[1] - 202342.8) < 300
    fields = generate("A 100-acre farm: 50 acres of wheat, the rest maize and potatoes.").recipe
    assert [f.crop for f in fields.fields] == ["Wheat", "Maize", "Potato"]


def test_hops_are_an_unknown_crop() -> None:
    with pytest.raises(UnknownCropError):
        generate(
            "Hop bines climbing the strings all the way to the top wires, the old oast house "
            "in the background and a grey sky."
        )


def test_a_weak_variety_made_the_head_of_its_plot_keeps_its_variety() -> None:
    assert _crops(
        "Photo from my uncle's grove outside Valencia, taken in January. The Navel trees are "
        "loaded with bright orange fruit ready to pick."
    ) == [("Orange", "Navel")]


def test_one_corner_of_a_field_is_no_field() -> None:
    fields = generate(
        "Aerial shot from our survey flight: Agria potatoes in the north field, Spelt in the "
        "middle and Chantenay carrots along the south edge. In one corner of the carrots the "
        "leaves have dark lesions with yellow rims."
    ).recipe.fields
    assert [(f.crop, f.health) for f in fields] == [
        ("Potato", "Healthy"),
        ("Wheat", "Healthy"),
        ("Carrot", "Ill"),
    ]


def test_spots_on_a_lot_of_the_fruit() -> None:
    fields = generate(
        "In the polytunnel photo there are beef tomatoes down one side and California Wonder "
        "peppers next to them down the other, the peppers with dark raised scabby spots on a "
        "lot of the fruit."
    ).recipe.fields
    assert [(f.crop, f.health) for f in fields] == [("Tomato", "Healthy"), ("Pepper", "Ill")]


def test_measures_said_of_both_then_each_members_own() -> None:
    fields = generate(
        "For the camera rig test we want two adjacent plots, rows 50 m long in both. West "
        "plot: Bintje potatoes, 30 rows at 75 cm. East plot: Nantes carrots, 20 ridges on "
        "75 cm centres, 2 rows per ridge."
    ).recipe.fields
    assert [(f.row_count, f.bed_count, f.row_length_m) for f in fields] == [
        (30, 30, 50.0),
        (40, 20, 50.0),
    ]

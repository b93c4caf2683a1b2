"""Text of blind set g42 (issue 8) and the leftovers fixed with it: a kind listed again in
a list joined by commas only ("sweetcorn, popcorn, sweetcorn"), a bare letter label placed
by a relation word ("A west of B"), a container word said as a verb ("holding a GNSS
pole"), numbers before unknown words and scenery ("two reflective targets"), "south of the
wheat, maize" after a plural, "both sit south of", "the same number of rows", a title
before the plural listing its fields, measures said before a colon list, "2 x 2 plots",
"24 m wide and 200 m long each", "fruit ripening" before the crops, fruit yellowing on
the branch, "twin rows on beds 1.5 m centre to centre", "three side-by-side strips", a
place said of scenery, "X in the middle" of three, an orchard after a lettuce field,
"100m x 60m rows", "valencia east")."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import FieldSpec


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("sweetcorn, popcorn, sweetcorn", ["Maize", "Maize", "Maize"]),
        ("apples, pears, apples", ["Apple", "Pear", "Apple"]),
        ("carrots, onions, carrots, onions", ["Carrot", "Onion", "Carrot", "Onion"]),
    ],
)
def test_a_kind_listed_again_with_commas_only_is_another_field(
    prompt: str, crops: list[str]
) -> None:
    assert [f.crop for f in generate(prompt).recipe.fields] == crops


def test_a_list_named_again_after_a_stop_is_the_same_fields() -> None:
    fields = generate("wheat and maize; wheat, maize both ripe").recipe.fields
    assert [f.crop for f in fields] == ["Wheat", "Maize"]


def _relations(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in generate(prompt).recipe.relations}


@pytest.mark.parametrize(
    "prompt",
    [
        "plot A carrots, plot B onions, A west of B",
        "plot A carrots, plot B onions. A directly west of B",
    ],
)
def test_a_bare_letter_label_placed_by_a_relation_word_after_it(prompt: str) -> None:
    assert _relations(prompt) == {("west_of", "carrot_field_1", ("onion_field_1",))}


def _one(prompt: str) -> FieldSpec:
    (field,) = generate(prompt).recipe.fields
    return field


@pytest.mark.parametrize(
    "prompt",
    [
        "LiDAR calibration scene: empty gravel yard, a parked tractor, two reflective targets "
        "on tripods, a person holding a GNSS pole, overcast sky.",
        "Drone calibration scene: a GNSS base station, three ground control points and a "
        "person holding a survey pole.",
    ],
)
def test_scenery_counted_or_held_is_no_field(prompt: str) -> None:
    with pytest.raises(PromptError, match="only scenery"):
        generate(prompt)


def test_a_holding_is_still_a_farm() -> None:
    assert len(generate("our holding: some fruit and veg").recipe.fields) == 2


def test_a_member_named_after_a_fronted_relation_is_its_subject() -> None:
    assert _relations(
        "two arable plots of 1 ha each: wheat drilled at 12.5 cm row spacing, and south of "
        "the wheat, maize in 75 cm rows."
    ) == {("south_of", "maize_plot_1", ("wheat_plot_1",))}


def test_both_said_with_the_second_of_two_fields() -> None:
    relations = _relations(
        "2 ha of wheat, 0.5 ha of onions and 0.5 ha of carrots. Onions and carrots both sit "
        "south of the wheat, with the carrots east of the onions."
    )
    assert ("south_of", "onion_field_1", ("wheat_field_1",)) in relations or (
        "south_of",
        "onion_plot_1",
        ("wheat_plot_1",),
    ) in relations
    assert len([r for r in relations if r[0] == "south_of"]) == 2


def test_the_same_number_of_rows_with_a_spacing_of_its_own() -> None:
    cabbage, lettuce = generate(
        "a cabbage field with rows 30 in apart, 24 rows of 200 ft, plus a lettuce plot east of "
        "it with the same number of rows on 14-inch spacing."
    ).recipe.fields
    assert cabbage.row_count == lettuce.row_count == 24
    assert lettuce.agronomy.row_spacing_m == pytest.approx(0.3556)


def test_a_title_before_the_plural_that_lists_its_fields() -> None:
    fields = generate(
        "Cherry harvest robot trial, late June, fruit ripe. Two blocks: Kordia with 10 rows and "
        "Regina with 10 rows, rows 4.6 m apart, trees every 2.4 m; Regina is east of Kordia."
    ).recipe.fields
    assert [(f.variety, f.stage, f.row_count) for f in fields] == [
        ("Kordia", "Maturation", 10),
        ("Regina", "Maturation", 10),
    ]


def test_measures_said_before_a_colon_list_are_every_members() -> None:
    riesling, pinot = generate(
        "Vineyard scene, both blocks in bloom in June, rows east-west, 2.0 m between rows and "
        "1.1 m between vines: Riesling (20 rows) on the north side, Pinot Noir (16 rows) on the "
        "south side."
    ).recipe.fields
    for field, rows in ((riesling, 20), (pinot, 16)):
        assert field.row_count == rows
        assert field.agronomy.row_spacing_m == pytest.approx(2.0)
        assert field.agronomy.in_row_spacing_m == pytest.approx(1.1)
        assert field.row_bearing_deg == pytest.approx(90.0)


def test_a_grid_of_plots_counted_by_rows_and_columns() -> None:
    fields = generate(
        "Sensor calibration grid, 2 x 2 plots of 20 x 20 m: maize in the NW plot, wheat in the "
        "NE, potatoes SW, carrots SE."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Maize", "Wheat", "Potato", "Carrot"]
    assert all(f.geometry.size_m == pytest.approx((20.0, 20.0)) for f in fields)
    assert len(generate("3 x 2 plots of wheat").recipe.fields) == 6
    assert _one("a 2 x 3 m plot of carrots").geometry.size_m == pytest.approx((2.0, 3.0))


def test_a_side_long_each_after_a_width_is_the_plots_size() -> None:
    fields = generate(
        "three strips, 24 m wide and 200 m long each, all rows east-west. Wheat at 15 cm rows, "
        "corn at 75 cm, potatoes at 90 cm"
    ).recipe.fields
    assert [f.geometry.size_m for f in fields] == [pytest.approx((24.0, 200.0))] * 3


def test_fruit_ripening_said_before_the_crops_is_theirs() -> None:
    fields = generate(
        "Ripeness classifier data, August, fruit ripening: three tomato plots north to south - "
        "beefsteak, San Marzano, cherry tomatoes. Each 6 rows at 1.5 m, 0.5 m between plants."
    ).recipe.fields
    assert [(f.crop, f.stage) for f in fields] == [("Tomato", "Maturation")] * 3


@pytest.mark.parametrize(
    "prompt",
    [
        "The Williams' Bon Chretien pears in this shot are yellowing on the branch and the first "
        "bins are already out between the rows.",
        "A Dwarf Cavendish plantation on Crete shot in October, bunches fat and starting to "
        "yellow, stone terraces and goats on the hill.",
    ],
)
def test_fruit_changing_colour_on_the_plant_is_ripening(prompt: str) -> None:
    field = _one(prompt)
    assert (field.stage, field.health) == ("Maturation", "Healthy")


def test_twin_rows_on_beds_then_their_centres() -> None:
    field = _one("the capsicum field - twin rows on beds 1.5 m centre to centre")
    assert field.agronomy.rows_per_bed == 2
    assert field.agronomy.row_spacing_m == pytest.approx(1.5)


def test_side_by_side_strips_one_in_the_middle_and_scenery_in_the_foreground() -> None:
    prompt = (
        "Chantenay, Imperator and Danvers carrots in three side-by-side strips, Imperator in "
        "the middle, all with lush dark tops. Overcast, and my boots in the foreground."
    )
    assert [f.variety for f in generate(prompt).recipe.fields] == [
        "Chantenay",
        "Imperator",
        "Danvers",
    ]
    assert ("between", "carrot_field_2", ("carrot_field_1", "carrot_field_3")) in _relations(prompt)


def test_an_orchard_after_a_lettuce_field_is_a_field_of_its_own() -> None:
    fields = generate(
        "Photo from the tractor cab: strawberries on my right, a lettuce field on my left and "
        "straight ahead, past the gate, the orchard with the pickers' ladders."
    ).recipe.fields
    assert [f.crop for f in fields][:2] == ["Strawberry", "Lettuce"]
    assert len(fields) == 3 and fields[2].crop in ("Apple", "Pear", "Cherry", "Orange")


def test_a_size_then_rows_running_a_way() -> None:
    popcorn, flint = generate(
        "popcorn field 100m x 60m rows running east west, and a flint corn field same size "
        "north of it"
    ).recipe.fields
    assert popcorn.geometry.size_m == flint.geometry.size_m == pytest.approx((100.0, 60.0))
    assert popcorn.row_bearing_deg == pytest.approx(90.0)


def test_a_bare_side_after_a_field_named_again_last() -> None:
    assert _relations("hamlin & valencia oranges, ripe, jan, valencia east") == {
        ("east_of", "orange_orchard_2", ("orange_orchard_1",))
    }

"""Text of blind set g54 (issue 8): its misses fixed as general mechanisms (the kind of a
farm said before its fields; a plot named before a colon; livestock grazing a paddock; a
crop taken back at once; labels placed against a member named again; ...)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import AgrirecipeError, generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def _crops(prompt: str) -> list[str]:
    return [f.crop for f in generate(prompt).recipe.fields]


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        # the farm's kind, said of the whole, is no field of its own
        (
            "It's a small fruit farm really, just one block of Conference pears behind the "
            "packing shed, in full bloom this April and all healthy.",
            ["Pear"],
        ),
        ("It's a fruit farm, a block of pears and a cherry orchard.", ["Pear", "Cherry"]),
        # a plot of no crop named before a colon is the name of the field after it
        (
            "Home paddock: a 100 by 60 m patch of Walla Walla onions, tops fallen over and "
            "ready to lift, summer.",
            ["Onion"],
        ),
        # livestock grazing a paddock: pasture, no field
        (
            "Cows graze the paddock by the road, there's a maize field behind them and a "
            "wheat field beyond that, and the river runs along the back.",
            ["Maize", "Wheat"],
        ),
        # "one orchard" after the crop, with nothing named after it: its one plot
        (
            "Just Regina cherries on this farm, one orchard, fruit ripening in July, a few "
            "trees with brown rot.",
            ["Cherry"],
        ),
        # a question about how many fields asks for none
        (
            "Mixed farm, can't remember exactly how many fields: some fruit up by the house, "
            "some vegetables lower down.",
            ["Banana", "Lettuce"],
        ),
    ],
)
def test_words_about_the_farm_ask_for_no_field(prompt: str, crops: list[str]) -> None:
    got = generate(prompt).recipe.fields
    assert len(got) == len(crops)
    if "Mixed farm" in prompt:
        assert [f.category for f in got] == ["Fruits", "Vegetables"]
    else:
        assert [f.crop for f in got] == crops


def test_a_free_choice_after_a_crop_is_no_look_of_it() -> None:
    recipe = generate("some veg & some fruit idk whatever looks nice").recipe
    assert [f.category for f in recipe.fields] == ["Vegetables", "Fruits"]


def test_the_like_of_casual_talk_after_plots_keeps_them_plots() -> None:
    assert len(generate("a few wheat fields idk like whatever number u want").recipe.fields) >= 2


def test_a_size_said_each_after_the_last_of_two() -> None:
    recipe = generate("jonagored & gala half an acre each, ripe apples, fall ofc").recipe
    assert [f.geometry.area_m2 for f in recipe.fields] == pytest.approx(
        [2023.43, 2023.43], rel=0.01
    )


def test_a_crop_taken_back_at_once_is_not_refused() -> None:
    assert _crops("hmm idk maybe spinach? no wait, lettuce. a lettuce field") == ["Lettuce"]
    assert _crops("olive grove? no, I mean a pear orchard") == ["Pear"]
    # (still refused when it stays asked for)
    with pytest.raises(AgrirecipeError):
        generate("an olive grove. Actually also a pear orchard")


def test_zero_spacing_between_the_plants_is_refused() -> None:
    with pytest.raises(AgrirecipeError, match="positive"):
        generate("Six beds of Sonata strawberries with zero spacing between the plants.")


def test_a_whole_side_lies_beyond_each_quarter_across_from_it(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "fruit trees across the north, a vegetable garden in the south-east corner and "
        "cereals in the south-west"
    )
    north = {objects[0] for kind, _, objects in relations if kind == "north_of"}
    assert len(north) == 2


def test_a_label_placed_against_a_member_named_again() -> None:
    recipe = generate(
        "Two potato plots for the drone NDVI comparison. Plot A: Bintje, 20 ridges at 75 cm, "
        "rows 60 m long. Plot B, immediately east of A: Agria, also 20 ridges at 75 cm and "
        "60 m rows. Rows in both plots run east-west."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Bintje", "Agria"]
    assert [f.row_bearing_deg for f in recipe.fields] == [90.0, 90.0]
    variety = {f.id: f.variety for f in recipe.fields}
    assert {(r.kind, variety[r.subject], variety[r.objects[0]]) for r in recipe.relations} == {
        ("east_of", "Agria", "Bintje")
    }


def test_identical_row_and_tree_spacing_is_the_field_befores() -> None:
    recipe = generate(
        "sweet cherry block on Gisela 6 - 4.9 m between rows, 2.7 m between trees, 180 "
        "trees, rows at 30 degrees from north. directly south of it a 120-tree pear block "
        "with identical row and tree spacing"
    ).recipe
    assert [f.crop for f in recipe.fields] == ["Cherry", "Pear"]
    pear = recipe.fields[1].agronomy
    assert (pear.row_spacing_m, pear.in_row_spacing_m) == (4.9, 2.7)


def test_a_plot_one_drill_width_wide() -> None:
    [field] = generate(
        "Spelt plot, 2.5 m drill width x 60 m, 12.5 cm rows, seedlings in November"
    ).recipe.fields
    assert field.geometry.size_m == (2.5, 60.0)
    assert field.agronomy.row_spacing_m == 0.125


def test_beds_of_the_same_width() -> None:
    recipe = generate(
        "Test bay for the soft-fruit robot: Albion strawberries on 6 beds (1.52 m centres, 2 "
        "rows each) and next to them Butterhead lettuce on 6 beds of the same 1.52 m width "
        "with 4 rows each."
    ).recipe
    assert [
        (f.bed_count, f.agronomy.row_spacing_m, f.agronomy.rows_per_bed) for f in recipe.fields
    ] == [
        (6, 1.52, 2),
        (6, 1.52, 4),
    ]


def test_a_list_counted_again_with_a_member_named_after_it() -> None:
    recipe = generate(
        "Nantes vs Imperator: two carrot plots, 10 m wide and 50 m long, on 75 cm ridges with "
        "two rows a ridge, the Imperator plot to the south."
    ).recipe
    assert [f.variety for f in recipe.fields] == ["Nantes", "Imperator"]
    variety = {f.id: f.variety for f in recipe.fields}
    assert {(r.kind, variety[r.subject], variety[r.objects[0]]) for r in recipe.relations} == {
        ("south_of", "Imperator", "Nantes")
    }


def test_a_row_spacing_said_apart_respectively() -> None:
    recipe = generate(
        "Tropical fruit sim: an orange grove with 8 rows and a banana block with 10 rows, rows "
        "6 m and 3 m apart respectively, bananas west of the oranges."
    ).recipe
    assert [(f.row_count, f.agronomy.row_spacing_m) for f in recipe.fields] == [(8, 6.0), (10, 3.0)]


def test_a_density_unit_said_after_the_last_value() -> None:
    recipe = generate(
        "Two wheat plots, one at 90 and one at 180 plants/m², each 2 m x 10 m, the denser one "
        "to the east."
    ).recipe
    assert sorted(round(f.plants_per_ha) for f in recipe.fields) == [900_000, 1_800_000]


def test_beds_said_wide_after_the_beds() -> None:
    [field] = generate(
        "Walla Walla onion beds, 1.5 m wide, 4 rows each, 12 beds, plants 12 cm apart; it's "
        "May and they're young plants."
    ).recipe.fields
    assert (field.bed_count, field.agronomy.row_spacing_m, field.agronomy.rows_per_bed) == (
        12,
        1.5,
        4,
    )


def test_a_closing_row_direction_after_fields_said_of_each() -> None:
    recipe = generate(
        "Bibb lettuce and Stuttgarter onions, two 0.25 ha plots each with a 4 m headland, the "
        "onions south of the lettuce, rows E-W"
    ).recipe
    assert [f.row_bearing_deg for f in recipe.fields] == [90.0, 90.0]


def test_measures_before_a_dash_that_opens_the_list() -> None:
    recipe = generate(
        "Lettuce variety strip for the leaf-segmentation dataset: three 1.5 m beds, 4 rows per "
        "bed, 30 cm in-row - Cos, Lollo, Iceberg, in that order from north to south."
    ).recipe
    assert [(f.agronomy.row_spacing_m, f.agronomy.rows_per_bed) for f in recipe.fields] == [
        (1.5, 4)
    ] * 3


def test_a_member_named_again_by_its_bare_plot_noun_to_place_it() -> None:
    recipe = generate(
        "Two plots for drone mapping: an orchard 60 x 120 m with 4 m rows and a vegetable "
        "field 60 x 120 m with 0.75 m rows, orchard east of the veg."
    ).recipe
    assert [f.agronomy.row_spacing_m for f in recipe.fields] == [4.0, 0.75]
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        ("east_of", recipe.fields[0].id, (recipe.fields[1].id,))
    ]

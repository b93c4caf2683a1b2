"""Text of blind set g40 (issue 8): fixes after its blind run (rows "west of north" after
any row or bed word, "75 cm ridges x 35 cm", "cabernet's north", comparatives that tell
plots apart, "No crop at all", compass terraces, sides of one landmark said as labels,
"alternaria spotting", "4-row beds at 1.8 m centres")."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate


def _relations(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in generate(prompt).recipe.relations}


def test_ridges_west_of_north() -> None:
    (agria,) = generate(
        "Agria seed potatoes every 30 cm on 90 cm ridges, 48 ridges, 250 m long, ridges at "
        "30 degrees west of north"
    ).recipe.fields
    assert agria.row_bearing_deg == pytest.approx(150.0)


def test_rows_by_plants_said_with_x() -> None:
    (fontane,) = generate("Fontane potatoes, 75 cm ridges x 35 cm, 2 ha").recipe.fields
    assert fontane.agronomy.in_row_spacing_m == pytest.approx(0.35)
    (riesling,) = generate(
        "Riesling vineyard, 2.4 m rows x 1.5 m between vines, 20 rows 120 m long"
    ).recipe.fields
    assert (riesling.row_count, riesling.agronomy.in_row_spacing_m) == (20, 1.5)


def test_a_side_said_with_an_apostrophe_s() -> None:
    assert _relations("a cabernet vineyard and a riesling one, cabernet's north. harvest time") == {
        ("north_of", "grape_vineyard_1", ("grape_vineyard_2",))
    }


def test_a_comparative_before_a_plot_is_no_crop() -> None:
    fields = generate(
        "Stand-count ground truth: two maize plots on 75 cm rows, one at 9 plants/m2 and one "
        "at 7 plants/m2, the denser plot to the east."
    ).recipe.fields
    assert [f.crop for f in fields] == ["Maize", "Maize"]


def test_no_crop_at_all_is_refused() -> None:
    with pytest.raises(PromptError, match="no field"):
        generate(
            "Drone calibration field: bare soil, three checkerboard targets, a weather mast "
            "and a tractor parked at the gate. No crop at all."
        )


def test_fields_on_compass_terraces() -> None:
    relations = _relations(
        "Our block near Hawke's Bay, New Zealand: Royal Gala apples on the northern terrace, "
        "Pinot Noir vines on the southern terrace, late March and everything ready to pick."
    )
    assert [k for k, _, _ in relations] == ["north_of"]


def test_two_sides_of_one_landmark_said_as_labels() -> None:
    assert _relations(
        "East of the barn: Savoy cabbage. West of the barn: January King. Both ready for "
        "harvest in December."
    ) == {("east_of", "cabbage_field_1", ("cabbage_field_2",))}


def test_alternaria_spotting_is_a_disease() -> None:
    fields = generate(
        "Field 1: Agria potatoes on 75 cm ridges, just emerged. Field 2: Nantes carrots, some "
        "alternaria spotting on the leaves. Field 3: Sturon onions bulbing up."
    ).recipe.fields
    assert [f.health for f in fields] == ["Healthy", "Ill", "Healthy"]


def test_rows_per_bed_said_before_the_beds() -> None:
    fields = generate(
        "Walla Walla and Red Baron onions, both on 4-row beds at 1.8 m centres with 10 cm "
        "in-row spacing. Walla Walla block north of the Red Baron."
    ).recipe.fields
    assert [(f.agronomy.rows_per_bed, f.agronomy.row_spacing_m) for f in fields] == [
        (4, 1.8),
        (4, 1.8),
    ]


def test_a_part_of_the_farm_with_its_size_in_brackets() -> None:
    orchard, veg = generate(
        "Split the farm in half: the northern half (10 ha) is orchard, the southern half "
        "(10 ha) is vegetables."
    ).recipe.fields
    for field in (orchard, veg):
        width, length = field.geometry.size_m
        assert width * length == pytest.approx(100_000, rel=0.01)
    assert (orchard.category, veg.category) == ("Fruits", "Vegetables")


def test_members_placed_by_a_packing_shed_go_on_listing() -> None:
    fields = generate(
        "We grow citrus on two blocks, Valencia Late to the west of the packing shed and "
        "Washington Navel to the east of it. Both blocks are in bloom in April."
    ).recipe.fields
    assert [(f.variety, f.stage) for f in fields] == [
        ("Valencia", "Reproductive"),
        ("Navel", "Reproductive"),
    ]


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("potatoes and cabbages, 4 fields in total", ["Potato", "Potato", "Cabbage", "Cabbage"]),
        ("some potatoes & cabbages, idk 3 or 4 fields total", ["Potato", "Potato", "Cabbage"]),
        ("wheat, maize and potatoes, 3 fields in total", ["Wheat", "Maize", "Potato"]),
    ],
)
def test_a_total_count_after_named_crops(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in generate(prompt).recipe.fields] == crops


def test_the_counted_fields_of_a_kind_named_again() -> None:
    # "the two sweetcorn plots": the two named before, not two more
    scene = generate(
        "Cross-pollination sensor study, sweetcorn / popcorn / sweetcorn, each plot 12 rows "
        "on 76 cm, popcorn in between the two sweetcorn plots."
    )
    assert [f.variety for f in scene.recipe.fields] == ["Sweet Corn", "Popcorn", "Sweet Corn"]
    first, popcorn, last = (f.id for f in scene.recipe.fields)
    assert {(r.kind, r.subject, frozenset(r.objects)) for r in scene.recipe.relations} == {
        ("between", popcorn, frozenset({first, last}))
    }


def test_the_plants_of_one_field_placed_against_another() -> None:
    assert (
        "east_of",
        "grape_vineyard_1",
        ("pear_orchard_1",),
    ) in _relations(
        "Vineyard and pear orchard side by side - vines on 2.5 m rows, pear trees on 3.5 m "
        "rows, the vines east of the pears."
    )
    assert _relations("a vineyard and a wheat field, the vines north of the wheat") == {
        ("north_of", "grape_vineyard_1", ("wheat_field_1",))
    }


def test_a_label_with_its_place_in_brackets_before_its_crop() -> None:
    scene = generate(
        "Strip 1 (west end) dent corn, strip 2 flint corn, strip 3 (east end) popcorn; each "
        "strip is 24 rows at 75 cm."
    )
    assert [f.variety for f in scene.recipe.fields] == ["Dent", "Flint", "Popcorn"]
    assert all(f.row_count == 24 for f in scene.recipe.fields)
    dent, flint, popcorn = (f.id for f in scene.recipe.fields)
    relations = {(r.kind, r.subject, r.objects) for r in scene.recipe.relations}
    assert {("west_of", dent, (flint,)), ("west_of", flint, (popcorn,))} <= relations


def test_a_name_placed_to_the_west_of_another_then_measured() -> None:
    scene = generate(
        "Cherry orchard with two blocks for the harvest-assist platform. Kordia: 5 rows, "
        "4.5 m between rows, 2.5 m in-row. Regina, to the west of the Kordia: 6 rows at "
        "4.8 m x 2.7 m. All rows north-south."
    )
    kordia, regina = scene.recipe.fields
    assert (kordia.variety, kordia.row_count, regina.variety, regina.row_count) == (
        "Kordia",
        5,
        "Regina",
        6,
    )
    assert regina.agronomy.row_spacing_m == pytest.approx(4.8)
    assert ("west_of", regina.id, (kordia.id,)) in {
        (r.kind, r.subject, r.objects) for r in scene.recipe.relations
    }


def test_a_mixed_farm_does_not_make_its_fields_descriptions() -> None:
    fields = generate(
        "a mixed farm with some fruit, some veg and a couple of cereal fields"
    ).recipe.fields
    categories = [f.category for f in fields]
    assert categories.count("Fruits") == 1 and categories.count("Vegetables") == 1
    assert categories.count("Cereals") == 2


def test_a_field_said_to_look_so_too() -> None:
    lettuce, cabbage = generate(
        "lettuce bolting lol forgot to harvest, the cabbages too"
    ).recipe.fields
    assert (lettuce.crop, cabbage.crop) == ("Lettuce", "Cabbage")
    assert lettuce.stage == cabbage.stage == "Reproductive"
    wheat, maize = generate("wheat with rust and maize too").recipe.fields
    assert wheat.health == maize.health == "Ill"
    # a field that says its own look keeps it
    _, carrots, onions = generate("potatoes with blight, carrots too, onions fine").recipe.fields
    assert (carrots.health, onions.health) == ("Ill", "Healthy")


def test_a_kind_listed_again_in_a_plain_list_is_another_field() -> None:
    scene = generate("sweetcorn, popcorn and sweetcorn, popcorn between the two sweetcorn plots.")
    assert [f.variety for f in scene.recipe.fields] == ["Sweet Corn", "Popcorn", "Sweet Corn"]
    assert [f.variety for f in generate("Valencia, Hamlin and Valencia").recipe.fields] == [
        "Valencia",
        "Hamlin",
        "Valencia",
    ]
    # named again to be placed: the same field
    carrots = generate("imperator and danvers carrots, imperator north of danvers").recipe
    assert [f.variety for f in carrots.fields] == ["Imperator", "Danvers"]

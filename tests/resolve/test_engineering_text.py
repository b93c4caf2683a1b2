"""Test-plot requests as engineers write them (issue 8, blind set g1 engineering):
counted plots listed after a colon with each member's own measures, rows of plots in a
compass order, the site around the plots."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def crop_of(scene: SceneRecipe, field_id: str) -> str:
    return next(f.crop for f in scene.fields if f.id == field_id)


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {
        (r.kind, crop_of(scene, r.subject), tuple(crop_of(scene, o) for o in r.objects))
        for r in scene.relations
    }


def test_counted_plots_are_the_members_listed_after_them() -> None:
    scene = recipe(
        "Three 10 m x 25 m plots for the weeding robot: first Cos lettuce with rows 35 cm "
        "apart and 30 cm between heads, then Savoy cabbage at 75 cm rows and 45 cm in the "
        "row, then Sturon onions in 30 cm rows, one plant every 10 cm."
    )
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Lettuce", "Romaine"),
        ("Cabbage", "Savoy"),
        ("Onion", "Sturon"),
    ]
    # the shared size goes to every member, each member's measures to itself alone
    assert {f.geometry.size_m for f in scene.fields} == {(10.0, 25.0)}
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.35, 0.75, 0.3]
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [0.3, 0.45, 0.1]


def test_a_comma_before_and_does_not_end_the_list() -> None:
    scene = recipe(
        "two plots side by side, each 30 x 60 m: wheat drilled at 12.5 cm row spacing, "
        "and potatoes on 75 cm ridges"
    )
    assert [f.crop for f in scene.fields] == ["Wheat", "Potato"]
    assert scene.fields[0].agronomy.row_spacing_m == 0.125


def test_details_in_brackets_stay_with_their_member() -> None:
    scene = recipe(
        "three plots: carrots (75 cm ridges, 2 rows per ridge), onions in the middle "
        "(30 cm rows), then potatoes (75 cm ridges)"
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Onion", "Potato"]
    assert scene.fields[0].agronomy.rows_per_bed == 2
    assert scene.fields[1].agronomy.row_spacing_m == 0.3
    assert ("between", "Onion", ("Carrot", "Potato")) in relations(scene)


def test_from_west_to_east_orders_the_row() -> None:
    before = recipe(
        "three strips, each 18 m wide and 200 m long, from west to east: wheat, potatoes, maize"
    )
    after = recipe("a pepper plot, a lettuce plot and a cabbage plot in a line from north to south")
    assert {("west_of", "Wheat", ("Potato",)), ("west_of", "Potato", ("Maize",))} <= relations(
        before
    )
    assert {f.geometry.size_m for f in before.fields} == {(18.0, 200.0)}
    assert {("north_of", "Pepper", ("Lettuce",)), ("north_of", "Lettuce", ("Cabbage",))} <= (
        relations(after)
    )
    # the packer follows: the wheat strip lies west of the potatoes
    wheat, potato = (next(f for f in before.fields if f.crop == c) for c in ("Wheat", "Potato"))
    assert wheat.geometry.origin_m[0] < potato.geometry.origin_m[0]


def test_the_site_and_scenery_it_lies_along_are_not_fields() -> None:
    scene = recipe(
        "Hoeing-robot test strip along the farm track, three plots: carrots, onions, potatoes"
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Onion", "Potato"]
    assert not scene.relations  # "along the farm track" relates no two fields


def test_details_after_the_list_with_each_go_to_every_member() -> None:
    scene = recipe(
        "three maize strips: field corn, flint corn and popping corn, 8 rows each at 76 cm, "
        "150 m long"
    )
    assert [f.variety for f in scene.fields] == ["Dent", "Flint", "Popcorn"]
    assert {f.row_count for f in scene.fields} == {8}
    assert {f.agronomy.row_spacing_m for f in scene.fields} == {0.76}


def test_a_member_placed_against_the_one_before_keeps_the_listing() -> None:
    scene = recipe(
        "two vineyard blocks, rows 80 m long: Chardonnay, 30 rows at 2.5 m; Riesling north of "
        "it, 25 rows at 2 m. October, grapes harvest-ready."
    )
    assert [(f.variety, f.row_count, f.stage) for f in scene.fields] == [
        ("Chardonnay", 30, "Maturation"),
        ("Riesling", 25, "Maturation"),
    ]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [2.5, 2.0]
    assert ("north_of", "Grape", ("Grape",)) in relations(scene)


def test_a_disease_a_dataset_is_for_is_not_the_plants_health() -> None:
    scene = recipe(
        "Late-blight detection dataset: two potato plots, the east plot Bintje with late "
        "blight, the west plot healthy Fontane"
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Bintje", "Ill"),
        ("Fontane", "Healthy"),
    ]
    (field,) = recipe("a potato field for a blight-spotting drone").fields
    assert field.health == "Healthy"
    assert "health" not in field.stated


def test_rows_of_a_length_and_a_closing_sentence_of_row_measures() -> None:
    (field,) = recipe("cherry tomatoes: 20 rows of 50 m, 1.6 m between rows").fields
    assert (field.row_count, field.row_length_m) == (20, 50.0)
    scene = recipe(
        "Chantenay carrots on 20 ridges at 75 cm centres, two rows per ridge; Red Baron "
        "onions in 12 rows spaced 30 cm. Rows are 60 m."
    )
    assert [(f.crop, f.row_length_m) for f in scene.fields] == [("Carrot", 60.0), ("Onion", 60.0)]
    assert scene.fields[0].bed_count == 20


def test_one_and_north_of_it_one_more() -> None:
    scene = recipe(
        "LiDAR stand-count benchmark: two maize plots, 20 rows x 50 m each at 75 cm row "
        "spacing; one sown at 75,000 plants/ha and, north of it, one at 95,000 plants/ha."
    )
    assert [f.plants_per_ha for f in scene.fields] == [75_000, 95_000]
    (relation,) = scene.relations
    assert (relation.kind, relation.subject, relation.objects) == (
        "north_of",
        scene.fields[1].id,
        (scene.fields[0].id,),
    )


def test_as_many_fields_as_announced_listed_after_a_comma() -> None:
    generated = generate(
        "test orchard with two blocks, 150 cherry trees in the western block and 300 apple "
        "trees in the eastern one; rows N-S in both",
        resolver="hybrid",
    )
    scene = generated.recipe
    counts = [generated.layout.field(f.id).nominal_plant_count for f in scene.fields]
    assert [f.crop for f in scene.fields] == ["Cherry", "Apple"]
    assert counts == [150, 300]
    assert ("west_of", "Cherry", ("Apple",)) in relations(scene)
    assert {f.row_bearing_deg for f in scene.fields} == {0.0}


def test_a_relation_that_opens_its_sentence() -> None:
    scene = recipe(
        "peppers on 10 beds, 1.5 m bed centres, two rows to a bed, 30 m rows; west of the "
        "peppers an onion plot of 60 x 40 m with rows 30 cm apart"
    )
    assert [f.crop for f in scene.fields] == ["Pepper", "Onion"]
    assert scene.fields[0].agronomy.rows_per_bed == 2
    assert relations(scene) == {("west_of", "Onion", ("Pepper",))}


def test_fields_named_again_in_a_list_are_not_new_fields() -> None:
    scene = recipe(
        "cabbages between a potato plot and an onion plot, all rows east-west; cabbage and "
        "potato rows 75 cm apart, onion rows 30 cm"
    )
    assert [f.crop for f in scene.fields] == ["Cabbage", "Potato", "Onion"]
    assert [f.agronomy.row_spacing_m for f in scene.fields][1:] == [0.75, 0.3]


def test_labelled_blocks_and_references_to_their_labels() -> None:
    scene = recipe(
        "Orchard layout for the spraying-drone trials. Block A: Jonagored apples, 20 rows, "
        "rows 3.5 m apart. Block B, directly north of A: Conference pears, 15 rows, 3.8 m "
        "between rows, 1.2 m between trees. All rows run north-south."
    )
    assert [(f.crop, f.row_count) for f in scene.fields] == [("Apple", 20), ("Pear", 15)]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [3.5, 3.8]
    assert {f.row_bearing_deg for f in scene.fields} == {0.0}
    assert relations(scene) == {("north_of", "Pear", ("Apple",))}


def test_labels_nobody_refers_to_change_nothing() -> None:
    from agrirecipe.resolve._labels import resolve_labels

    text = "Plot 1: wheat. Plot 2: maize, 30 m wide."
    assert resolve_labels(text, lambda phrase: ()) == (text, [])


def test_same_spacing_and_a_closing_sentence_about_the_trees() -> None:
    scene = recipe(
        "two sweet cherry blocks: Kordia, 10 rows at 4.6 m with 2.4 m in-row; Regina directly "
        "south, same spacing, 8 rows. Trees in bloom, mid-April."
    )
    assert [(f.variety, f.row_count, f.stage) for f in scene.fields] == [
        ("Kordia", 10, "Reproductive"),
        ("Regina", 8, "Reproductive"),
    ]
    assert {(f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in scene.fields} == {
        (4.6, 2.4)
    }
    assert relations(scene) == {("south_of", "Cherry", ("Cherry",))}


def test_purpose_words_marks_and_styles_are_not_crops() -> None:
    scene = recipe(
        "Weed/crop segmentation dataset, two plots: carrots, 2 rows per 75 cm ridge, 30 ridges; "
        "and letuce at 80,000 heads per ha, 16 rows of 50 m, 30 cm in-row, rows running "
        "north-east."
    )
    assert [f.crop for f in scene.fields] == ["Carrot", "Lettuce"]
    lettuce = scene.fields[1]
    assert lettuce.row_bearing_deg == 45.0
    # density and in-row spacing said, the rows are as far apart as they make
    assert lettuce.agronomy.row_spacing_m == pytest.approx(10_000 / (80_000 * 0.3), rel=1e-3)
    (vines,) = recipe("US-style vinyard for a pruning robot: 30 rows, 10 ft row spacing").fields
    assert (vines.crop, vines.row_count, vines.agronomy.row_spacing_m) == ("Grape", 30, 3.048)


def test_counted_plots_whose_members_follow_in_sentences_of_their_own() -> None:
    scene = recipe(
        "Weeding-bot trial in May on two bed plots. Lollo Rosso: 4 beds on 1.2 m centres, 4 "
        "rows per bed, young plants. Beside it, Imperator carrots: 16 ridges on 75 cm, two "
        "rows per ridge. Beds and ridges run NW-SE with a 3 m headland."
    )
    assert [(f.variety, f.bed_count) for f in scene.fields] == [
        ("Lollo Rosso", 4),
        ("Imperator", 16),
    ]
    assert {f.row_bearing_deg for f in scene.fields} == {135.0}
    assert relations(scene) == {("next_to", "Carrot", ("Lettuce",))}


def test_a_member_named_again_by_its_variety_is_that_member() -> None:
    scene = recipe(
        "two pear blocks, rows 3.5 m apart, trees 1.25 m in the row: Doyenné du Comice, 16 rows, "
        "and Durondeau, 12 rows, east of the Comice. The trees are white with blossom."
    )
    assert [(f.variety, f.row_count, f.stage) for f in scene.fields] == [
        ("Doyenne du Comice", 16, "Reproductive"),
        ("Durondeau", 12, "Reproductive"),
    ]
    assert {f.agronomy.in_row_spacing_m for f in scene.fields} == {1.25}
    assert relations(scene) == {("east_of", "Pear", ("Pear",))}


def test_measures_after_a_plural_noun_shared_by_a_list() -> None:
    scene = recipe(
        "Bing and Sweetheart Lapins cherry blocks, 180 trees each, 5 m rows with 3 m in-row"
    )
    assert [f.variety for f in scene.fields] == ["Bing", "Lapins"]
    assert {(f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in scene.fields} == {
        (5.0, 3.0)
    }


def test_the_one_between_the_other_two_of_a_listed_three() -> None:
    scene = recipe(
        "three maize strips: field corn, flint corn and popping corn, 8 rows each at 76 cm, "
        "with the popping corn between the other two"
    )
    (relation,) = scene.relations
    ids = {f.variety: f.id for f in scene.fields}
    assert (relation.kind, relation.subject, set(relation.objects)) == (
        "between",
        ids["Popcorn"],
        {ids["Dent"], ids["Flint"]},
    )


def test_words_after_a_field_named_again_describe_the_new_field() -> None:
    scene = recipe(
        "vines, 2.5 m rows; a wheat plot to the south of the vineyard, 25 x 100 m. Bananas on "
        "2.5 m square spacing, and south of the bananas a citrus block of 1.5 ha."
    )
    sizes = {f.crop: f.geometry.size_m for f in scene.fields}
    assert sizes["Wheat"] == (25.0, 100.0)
    assert {("south_of", "Wheat", ("Grape",)), ("south_of", "Orange", ("Banana",))} <= relations(
        scene
    )


def test_measures_after_each_stay_with_every_field() -> None:
    scene = recipe(
        "a pepper plot, a lettuce plot and a cabbage plot in a line from north to south, each "
        "20 x 30 m, rows at 90° from north"
    )
    assert {(f.geometry.size_m, f.row_bearing_deg) for f in scene.fields} == {((20.0, 30.0), 90.0)}


def test_a_field_named_by_its_compass_position() -> None:
    from agrirecipe.resolve._sides import place_leading_directions

    assert place_leading_directions("the east plot is Bintje, the west plot Fontane") == (
        "Bintje in the eastern block, Fontane in the western block"
    )
    # a compass position after a preposition is already a placement
    text = "cherry trees in the western block and apple trees in the eastern one"
    assert place_leading_directions(text) == text
    scene = recipe(
        "two potato plots: the east plot is Bintje with late blight, the west plot healthy Fontane"
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Bintje", "Ill"),
        ("Fontane", "Healthy"),
    ]
    assert ("east_of", "Potato", ("Potato",)) in relations(scene)


def test_a_grid_named_as_rows_by_plants() -> None:
    tomatoes, _ = recipe(
        "a 0.5 ha block of tomatoes at 1.5 m x 0.5 m (row x plant) and a 0.5 ha block of "
        "peppers, twin rows on 1.5 m beds with 45 cm in-row spacing"
    ).fields
    assert tomatoes.crop == "Tomato"
    assert (tomatoes.agronomy.row_spacing_m, tomatoes.agronomy.in_row_spacing_m) == (1.5, 0.5)
    (oranges,) = recipe(
        "a high-density blood orange block (3.7 m x 1.2 m, rows x trees), 12 rows of 90 m"
    ).fields
    assert (oranges.agronomy.row_spacing_m, oranges.agronomy.in_row_spacing_m) == (3.7, 1.2)


def test_metres_between_rows_and_between_trees() -> None:
    (field,) = recipe(
        "200 Valencia orange trees at 7 m between rows and 4 m between trees, rows NE-SW"
    ).fields
    assert (field.agronomy.row_spacing_m, field.agronomy.in_row_spacing_m) == (7.0, 4.0)


def test_a_crop_joined_to_a_robot_task_names_the_task() -> None:
    scene = recipe(
        "Apple-counting scene, two blocks: 6 rows of Fuji and, east of them, 6 rows of Granny "
        "Smith; all rows 3.5 m apart and 100 m long"
    )
    assert [f.variety for f in scene.fields] == ["Fuji", "Granny Smith"]
    assert [f.crop for f in recipe("an apple test plot").fields] == ["Apple"]


def test_a_plural_without_a_number_takes_the_whole_list() -> None:
    scene = recipe(
        "Fruit-detection camera plots: Jalapeño, Padrón and California Wonder peppers, 4 beds "
        "each, twin rows on 1.5 m beds, 45 cm in the row."
    )
    assert [f.variety for f in scene.fields] == ["Jalapeno", "Padron", "California Wonder"]
    with pytest.raises(PromptError, match="announces 2"):
        recipe("two plots: wheat, maize and potatoes")


def test_measures_said_of_each_or_both_go_to_every_field() -> None:
    pears = recipe(
        "a Doyenné du Comice block next to a Durondeau block for the orchard sprayer test; "
        "both 10 rows at 3.8 m, a tree every 1.2 m, rows running NW-SE"
    )
    assert {
        (f.row_count, f.agronomy.in_row_spacing_m, round(f.row_bearing_deg)) for f in pears.fields
    } == {(10, 1.2, 135)}
    tomatoes = recipe(
        "Beefsteak tomatoes with late blight and healthy San Marzano south of them, 8 rows "
        "each at 1.5 m, 60 cm in-row."
    )
    assert [
        (f.variety, f.health, f.row_count, f.agronomy.in_row_spacing_m) for f in tomatoes.fields
    ] == [
        ("Beefsteak", "Ill", 8, 0.6),
        ("San Marzano", "Healthy", 8, 0.6),
    ]
    vines = recipe(
        "Vineyard-robot benchmark in September: a Pinot Noir block south of a Chardonnay "
        "block, each 20 rows x 100 m, 2.2 m row spacing, 1 m vine spacing, grapes at harvest."
    )
    assert [f.variety for f in vines.fields] == ["Pinot Noir", "Chardonnay"]
    assert {
        (f.row_count, f.agronomy.row_spacing_m, f.agronomy.in_row_spacing_m) for f in vines.fields
    } == {(20, 2.2, 1.0)}


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        # a planting grid after "at", with or without "each"
        ("Dwarf Cavendish bananas at 2 x 2 m", {"row_spacing_m": 2.0, "in_row_spacing_m": 2.0}),
        ("150 orange trees each at 6 m x 3 m", {"row_spacing_m": 6.0, "in_row_spacing_m": 3.0}),
        # beds and rows with their length
        (
            "Red Baron onions on 1.8 m beds, 6 rows per bed, 20 beds of 100 m",
            {"row_length_m": 100.0},
        ),
        ("a Cabernet block, 8 ft rows, 40 rows each 300 ft", {"row_length_m": 91.44}),
        ("Boston lettuce, 10 beds, 1.6 m centre to centre, 4 rows per bed", {"row_spacing_m": 1.6}),
        ("Fontane potatoes (30 rows, 0.9 m)", {"row_spacing_m": 0.9}),
        (
            "Russet potatoes, 30 rows on 36 in spacing, seed pieces every 12 in",
            {"in_row_spacing_m": 0.3048},
        ),
    ],
)
def test_more_ways_of_saying_the_grid(prompt: str, expected: dict[str, float]) -> None:
    field = recipe(prompt).fields[0]
    values = {
        "row_spacing_m": field.agronomy.row_spacing_m,
        "in_row_spacing_m": field.agronomy.in_row_spacing_m,
        "row_length_m": field.row_length_m,
    }
    for key, value in expected.items():
        assert values[key] == pytest.approx(value, rel=0.01), key


def test_zero_spacing_between_rows_is_impossible() -> None:
    with pytest.raises(PromptError, match="positive"):
        recipe("12 rows of cabbage, 50 m long, with zero spacing between the rows")


def test_a_number_with_a_unit_never_counts_fields() -> None:
    scene = recipe(
        "a cherry orchard and a pear orchard side by side, 8 rows of 60 m each; row spacing "
        "4.5 m in the cherries and 3.5 m in the pears."
    )
    assert [f.crop for f in scene.fields] == ["Cherry", "Pear"]
    assert scene.fields[0].agronomy.row_spacing_m == 4.5


def test_member_details_with_bare_row_words_keep_the_listing_going() -> None:
    scene = generate(
        "two plots for the drone flight: Bintje potatoes on 20 ridges at 75 cm centres, ridges "
        "100 m long, and directly east of them a Nantes carrot plot of 10 ridges (75 cm, 2 rows "
        "per ridge)",
        resolver="hybrid",
    ).recipe
    assert [f.crop for f in scene.fields] == ["Potato", "Carrot"]  # no phantom third plot
    potatoes, carrots = scene.fields
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("east_of", carrots.id, (potatoes.id,))
    ]
    assert potatoes.agronomy.row_spacing_m == pytest.approx(0.75)
    assert carrots.agronomy.rows_per_bed == 2


def test_a_bare_measure_after_a_sibling_s_spacing_is_the_same_spacing() -> None:
    scene = generate(
        "Riesling at 1.8 m row spacing and Spätburgunder at 2.0 m, both 1.0 m between vines "
        "and 25 rows; the Riesling block lies north of the Spätburgunder.",
        resolver="hybrid",
    ).recipe
    riesling, pinot = scene.fields
    assert (riesling.variety, pinot.variety) == ("Riesling", "Pinot Noir")
    assert riesling.agronomy.row_spacing_m == pytest.approx(1.8)
    assert pinot.agronomy.row_spacing_m == pytest.approx(2.0)
    assert pinot.agronomy.in_row_spacing_m == pytest.approx(1.0)
    assert "row_spacing" in pinot.stated


def test_a_list_of_values_for_several_plots_gives_one_to_each() -> None:
    scene = generate(
        "seeding-rate trial for the NDVI sensor: three wheat plots of 3 x 12 m at 100, 150 and "
        "200 plants per m2",
        resolver="hybrid",
    ).recipe
    densities = [
        round(1 / (f.agronomy.row_spacing_m * f.agronomy.in_row_spacing_m)) for f in scene.fields
    ]
    assert densities == [100, 150, 200]
    assert {f.geometry.size_m for f in scene.fields} == {(3.0, 12.0)}
    spacings = generate("two maize plots with rows 50 and 75 cm apart", resolver="hybrid").recipe
    assert [f.agronomy.row_spacing_m for f in spacings.fields] == [0.5, 0.75]
    one = generate("maize at 80,000 plants/ha", resolver="hybrid").recipe
    assert len(one.fields) == 1  # a thousands separator is not a list

"""Text of blind set g32 and the g31 leftovers (issue 8): a misspelt plot word before its
side, a vegetable garden that holds no wheat, a weak variety after a plot's label, "The
vineyard north of it is Pinot Nero", a placement past scenery on the way, "it's a 3
hectare field", fruit in bins and dropped fruit, compass letters as sides, "a couple"
without "of", words joined by "and" to words said of both, a test field heading plots of
one crop, many beds of a crop as one field's beds, beds of a length on their centres,
rows along a length said to run a way, a field "in between" said last; and the g31
leftovers: "from the gate the whole field looks scorched", "the Jalapeño beds beside
them", a weak variety alone past "the field" said again, an order past a bracket, vines
placed past scenery, "Left of it is our Bintje", a fronted "Between the orchard and the
vines", the top field as a zone."""

from __future__ import annotations

from collections.abc import Callable

from agrirecipe import generate
from agrirecipe.layout import field_parameters, place_field, place_field_array
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_the_whole_field_said_past_a_place_is_the_field_named() -> None:
    (carrots,) = recipe(
        "Close-up of the carrot tops: dark lesions with yellow halos all over them, and from "
        "the gate the whole field looks scorched. Sunny September afternoon, the irrigation "
        "boom folded up by the hedge."
    ).fields
    assert (carrots.crop, carrots.health, carrots.season) == ("Carrot", "Ill", "Fall")
    # ... and a field of another crop said so is still a field
    maize, wheat = recipe("a maize field, and beside it the whole field of wheat is ripe").fields
    assert (maize.crop, wheat.crop) == ("Maize", "Wheat")


def test_a_kind_placed_beside_the_plants_named_before_is_another_field(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Rows of capsicum heavy with glossy red fruit, plants about knee high and healthy, and "
        "the Jalapeño beds beside them still only flowering. Late August, shade cloth on poles "
        "over part of it, a pickup with crates."
    )
    capsicum, jalapeno = recipe(prompt).fields
    assert (capsicum.crop, capsicum.stage) == ("Pepper", "Maturation")
    assert capsicum.variety != "Jalapeno"
    assert (jalapeno.variety, jalapeno.stage) == ("Jalapeno", "Reproductive")
    assert named_relations(prompt) == {("next_to", "Jalapeno", ("Pepper",))}


def test_a_weak_variety_named_alone_past_the_field_said_again() -> None:
    (sonata,) = recipe(
        "Freshly planted Sonata runers on the ridges, only a few leaves each, in March with "
        "the hills still brown. A trailer of plant trays at the end of the field."
    ).fields
    assert (sonata.crop, sonata.variety) == ("Strawberry", "Sonata")
    assert (sonata.stage, sonata.season) == ("Vegetative", "Spring")


def test_an_order_past_a_bracket_naming_a_member_again(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Top to bottom on our hillside farm in Madeira: Gros Michel bananas (Big Mike, as "
        "granddad calls them), then a strip of Dwarf Cavendish, then the Hamlin oranges."
    )
    assert [(f.crop, f.variety) for f in recipe(prompt).fields] == [
        ("Banana", "Gros Michel"),
        ("Banana", "Cavendish"),
        ("Orange", "Hamlin"),
    ]
    assert {
        ("north_of", "Gros Michel", ("Cavendish",)),
        ("north_of", "Cavendish", ("Hamlin",)),
    } <= named_relations(prompt)


def test_vines_placed_past_scenery_are_a_vineyard_of_their_own() -> None:
    fields = recipe(
        "out the back door there's a bed of tomatoes with a bed of peppers right beside it, "
        "then a hawthorn hedge, and past the hedge the vines go up the slope"
    ).fields
    assert [f.crop for f in fields] == ["Tomato", "Pepper", "Grape"]
    carrots, vines = recipe("a bed of carrots, and behind the barn the vines").fields
    assert (carrots.crop, vines.crop) == ("Carrot", "Grape")
    # ... while vines said of the vineyard named are its own plants
    (riesling,) = recipe("a Riesling vineyard; behind the barn the vines have mildew").fields
    assert (riesling.variety, riesling.health) == ("Riesling", "Ill")


def test_fields_counted_then_each_said_on_a_side_of_it() -> None:
    bintje, carrots = recipe(
        "Two fields either side of the concrete farm track. Left of it is our Bintje, and you "
        "can see the dark blotches of late blight on the haulm; right of it the Nantes carrots "
        "look clean and green. Overcast, with rain coming in."
    ).fields
    assert (bintje.variety, bintje.health) == ("Bintje", "Ill")
    assert (carrots.variety, carrots.health) == ("Nantes", "Healthy")


def test_a_fronted_between_of_two_fields_named(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "An apple orchard and a vineyard. Between the orchard and the vines, a vegetable garden."
    )
    apples, vines, garden = recipe(prompt).fields
    assert (apples.crop, vines.crop, garden.category) == ("Apple", "Grape", "Vegetables")
    assert named_relations(prompt) == {("between", garden.crop, ("Apple", "Grape"))}
    assert named_relations("Between the wheat and the maize, a strip of carrots.") == {
        ("between", "Carrot", ("Wheat", "Maize"))
    }


def test_a_compass_letter_as_the_side_of_a_place(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "iceburg lettuce on the W side & savoy cabage on the E side, both healthy, early summer"
    )
    assert named_relations(prompt) == {("west_of", "Iceberg", ("Savoy",))}


def test_a_couple_said_without_of() -> None:
    fields = recipe("a couple diff veg plots n one strawberry patch").fields
    assert [f.category for f in fields] == ["Vegetables", "Vegetables", "Fruits"]
    assert len({f.crop for f in fields}) == 3
    # (not a couple of people)
    (wheat,) = recipe("a couple walking their dogs by a wheat field").fields
    assert wheat.crop == "Wheat"


def test_words_joined_by_and_to_words_said_of_both() -> None:
    winter, durum = recipe(
        "winter wheat in spring nxt 2 durum, both still green & young, march"
    ).fields
    assert (winter.variety, durum.variety) == ("Winter Wheat", "Durum")
    assert winter.stage == durum.stage == "Vegetative"


def test_the_top_field_is_a_zone_with_the_farms_others(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Field by field: the top field is Winter Wheat, 8 hectares; below it 5 ha of Dent "
        "maize; and at the bottom by the river, 2 ha of Nantes carrots."
    )
    assert {
        ("north_of", "Winter Wheat", ("Dent",)),
        ("north_of", "Dent", ("Nantes",)),
    } <= named_relations(prompt)
    assert named_relations("the upper block is Gala, the lower one has pears") == {
        ("north_of", "Gala", ("Pear",))
    }


def test_a_vegetable_garden_holds_no_wheat(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Layout from the farmhouse outward: a vegetable garden to the east, the apple orchard "
        "to the west, wheat north of the orchard and maize south of it."
    )
    garden, apples, wheat, maize = recipe(prompt).fields
    assert (garden.category, apples.crop, wheat.crop, maize.crop) == (
        "Vegetables",
        "Apple",
        "Wheat",
        "Maize",
    )
    assert {("north_of", "Wheat", ("Apple",)), ("south_of", "Maize", ("Apple",))} <= (
        named_relations(prompt)
    )


def test_the_plot_placed_by_a_pronoun_then_named() -> None:
    cherries, vines = recipe(
        "Regina cherries: 12 rows, 4.5 m between rows, a tree every 2.5 m. The vineyard north "
        "of it is Pinot Nero, rows 2.2 m apart running north-south."
    ).fields
    assert (cherries.variety, vines.variety) == ("Regina", "Pinot Noir")
    assert vines.agronomy.row_spacing_m == 2.2
    assert recipe("Regina cherries. The vineyard beside them is Pinot Nero.").relations[0].kind == (
        "next_to"
    )
    # ("the block north of it is ripe" names no crop: said of the cherries)
    (only,) = recipe("Regina cherries. The block north of it is ripe.").fields
    assert only.crop == "Cherry"


def test_it_is_a_plot_of_a_size_said_of_the_field_named() -> None:
    (durum,) = recipe(
        "Durum wheat, ears out and the awns catching the evening light; it's a 3 hectare field "
        "with power lines across the middle. Photo from June."
    ).fields
    assert (durum.variety, durum.stage) == ("Durum", "Reproductive")
    assert durum.geometry.area_m2 == 30_000


def test_fruit_in_bins_and_dropped_fruit_are_the_orchards_own() -> None:
    (apples,) = recipe(
        "Cripps Pink apples hanging red on the trees, hail net rolled up above the rows and "
        "some fruit already in bins. Shot at the end of October."
    ).fields
    assert (apples.variety, apples.stage) == ("Pink Lady", "Maturation")
    (oranges,) = recipe(
        "Orange trees with blotchy yellow mottling on the leaves and small lopsided fruit that "
        "stays green, lots of dropped fruit underneath. Dusty road along the edge and an "
        "irrigation pond."
    ).fields
    assert (oranges.crop, oranges.health) == ("Orange", "Ill")


def test_a_pronoun_placement_past_scenery_on_the_way(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "My photo shows a maize field with the tassels just out and, across a narrow ditch "
        "right next to it, carrots with feathery green tops. Pylons along the back and not a "
        "breath of wind."
    )
    assert named_relations(prompt) == {("next_to", "Carrot", ("Maize",))}


def test_a_side_said_of_a_misspelt_field(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "north feild is Jonagored apples, south feild is Conferance pears, both got scab this year"
    )
    assert named_relations(prompt) == {("north_of", "Jonagold", ("Conference",))}


def test_a_weak_variety_right_after_a_plots_label(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Plot 1 Iceberg, plot 2 Lollo Rosso, plot 3 Cos, plot 4 Butterhead. All lettuce, all "
        "ready for cutting, the plots side by side from left to right."
    )
    fields = recipe(prompt).fields
    assert [f.variety for f in fields] == ["Iceberg", "Lollo Rosso", "Romaine", "Butterhead"]
    assert {
        ("west_of", "Iceberg", ("Lollo Rosso",)),
        ("west_of", "Lollo Rosso", ("Romaine",)),
        ("west_of", "Romaine", ("Butterhead",)),
    } <= named_relations(prompt)


def test_a_test_field_heading_plots_of_one_crop() -> None:
    fields = recipe(
        "Plant-counting model test field, three wheat plots stacked north to south: Winter "
        "Wheat, then Spelt, then Durum. Each 10 m x 2 m, 12 rows at 15 cm, 150 plants per m2."
    ).fields
    assert [f.variety for f in fields] == ["Winter Wheat", "Spelt", "Durum"]
    assert all(f.row_count == 12 and f.agronomy.row_spacing_m == 0.15 for f in fields)
    # (a field of another crop before plots of a crop is a field of its own)
    assert [f.crop for f in recipe("a wheat field, two maize plots: Flint and Dent").fields] == [
        "Wheat",
        "Maize",
        "Maize",
    ]


def test_many_beds_of_a_crop_are_one_fields_beds() -> None:
    carrots, onions = recipe(
        "Carrot beds 1.6 m wide with 4 rows per bed at 120 plants/m2, 30 beds x 150 m; west of "
        "them 30 onion beds, also 1.6 m, 6 rows per bed."
    ).fields
    assert (carrots.bed_count, onions.bed_count) == (30, 30)
    assert onions.agronomy.row_spacing_m == 1.6 and onions.agronomy.rows_per_bed == 6
    (onions,) = recipe("30 onion beds.").fields
    assert onions.bed_count == 30


def test_beds_of_a_length_on_their_centres() -> None:
    (albion,) = recipe(
        "Albion strawberries, 6 beds of 40 m on 1.3 m centres, 2 rows each, 25 cm in-row, fruit "
        "ripening in August."
    ).fields
    assert (albion.bed_count, albion.agronomy.rows_per_bed) == (6, 2)
    assert albion.agronomy.row_spacing_m == 1.3
    assert albion.agronomy.in_row_spacing_m == 0.25


def test_rows_along_a_length_said_to_run_a_way() -> None:
    fields = recipe(
        "Vision test layout, carrots at the top, onions in the middle, lettuce at the bottom; "
        "each plot 4 m wide by 25 m long, rows along the length, which runs east-west."
    ).fields
    assert [f.row_bearing_deg for f in fields] == [90.0, 90.0, 90.0]


def test_a_field_in_between_said_last(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Row-crop sim: a 20 x 40 m tomato plot and a 20 x 40 m pepper plot, with a 10 x 40 m "
        "lettuce strip in between; rows lengthwise, N-S."
    )
    assert named_relations(prompt) == {("between", "Lettuce", ("Tomato", "Pepper"))}


def test_a_stated_count_that_does_not_fill_whole_rows_leaves_the_last_one_short() -> None:
    scene = recipe(
        "Bing cherries at harvest in June, 250 trees in 18 rows, 4.9 m between rows and 2.7 m "
        "between trees, rows NW-SE."
    )
    (bing,) = scene.fields
    assert bing.row_count == 18
    assert bing.nominal_plant_count == bing.geometry.plant_count == 250
    # every engine draws exactly those: the kernel stops at the 250th position
    (params,) = field_parameters(scene)
    assert len(place_field(dict(params, missing_rate=0.0))) == 250
    assert len(place_field_array(dict(params, missing_rate=0.0))[0]) == 250
    assert any("the last one short" in w for w in scene.warnings)
    # a count that fills whole rows leaves no limit
    (gala,) = recipe("300 Gala trees in 10 rows").fields
    assert gala.nominal_plant_count == 300 and gala.geometry.plant_count is None

"""Text of blind set g23 (issue 8): fillers of speech, "outdoor" fields, a plot after a
dash with its size next, "set out the same way", "right up against", "the near field",
fruit after a look said with "have", a field that is gone, "both north of", directed
rows after a heading's colon, a word for vines placed against other crops, "furthest
north", a crop's variety after "east of it is", terraces, vague counts said after the
fields, quarters said "top left", a kind heading one plot, a list counted again after a
colon, and a count "per block"."""

from __future__ import annotations

from collections.abc import Callable

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def crops(prompt: str) -> list[str]:
    return [f.crop for f in recipe(prompt).fields]


def test_fillers_of_speech_and_outdoor_fields() -> None:
    assert len(recipe("uhh fruit trees on the left and veg on the right").fields) == 2
    (peppers,) = recipe(
        "we only grow sweet peppers now - one outdoor field, roughly 60 by 120 m, next to the "
        "old dairy shed"
    ).fields
    assert (peppers.crop, peppers.geometry.size_m) == ("Pepper", (60.0, 120.0))


def test_set_out_the_same_way() -> None:
    _stuttgarter, sturon = recipe(
        "Onion ground: Stuttgarter Riesen on beds on 1.5 m centres, four rows per bed, rows "
        "30 cm apart, and Sturon alongside set out the same way."
    ).fields
    assert (sturon.agronomy.rows_per_bed, sturon.agronomy.row_spacing_m) == (4, 1.5)


def test_placements_of_g23(named_relations: Callable[[str], NamedRelations]) -> None:
    assert named_relations("dinkel right up against a field of durum, both ripe") == {
        ("next_to", "Spelt", ("Durum",))
    }
    # "the near field" says which field, no placement against another
    assert crops("Bibb lettuce in the near field and January King cabbage beyond it") == [
        "Lettuce",
        "Cabbage",
    ]
    both = named_relations("a corn field and a wheat field, both north of an orchard")
    assert {(kind, subject) for kind, subject, _ in both} == {
        ("north_of", "Maize"),
        ("north_of", "Wheat"),
    }
    assert named_relations(
        "Going from west to east the plots are: Chantenay carrots, Walla Walla onions, "
        "Iceberg lettuce, then Red Express cabbage."
    ) >= {
        ("west_of", "Chantenay", ("Walla Walla",)),
        ("west_of", "Walla Walla", ("Iceberg",)),
        ("west_of", "Iceberg", ("Red Express",)),
    }
    assert ("north_of", "Red Baron", ("Savoy",)) in named_relations(
        "From the top of the silo you can see three fields: Bintje potatoes nearest the farm "
        "on the south side, then a strip of Savoy cabbage "
        "north of them, and the Red Baron onions furthest north, up against the hedge."
    )


def test_fruit_after_a_look_said_with_have() -> None:
    (oranges,) = recipe(
        "Hamlin oranges in Florida in October. The fruit is still green-skinned, and a lot of "
        "the trees have blotchy yellow mottled leaves and small lopsided fruit."
    ).fields
    assert (oranges.variety, oranges.health) == ("Hamlin", "Ill")


def test_a_field_that_is_gone() -> None:
    assert crops(
        "The kitchen garden's gone, the whole place is one field of Jalapeños now, in flower"
    ) == ["Pepper"]
    # (leaves "gone brown" are a look)
    assert crops("tomato leaves gone brown") == ["Tomato"]


def test_vines_placed_against_fields_of_other_crops() -> None:
    assert crops("apple trees north of the carrots, and the vines south of the carrots") == [
        "Apple",
        "Carrot",
        "Grape",
    ]


def test_a_variety_after_a_placement_of_its_plot(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Pear block: 1,200 Conference trees, rows 3.5 m apart, trees 1 m apart in the row. "
        "The apple block east of it is Jonagored at the same spacing."
    )
    _pears, apples = recipe(prompt).fields
    assert (apples.variety, apples.agronomy.row_spacing_m) == ("Jonagold", 3.5)
    assert named_relations(prompt) == {("east_of", "Jonagold", ("Conference",))}


def test_terraces_and_vague_counts_said_after() -> None:
    assert crops("a citrus grove at the bottom, and above it terraces of vines") == [
        "Orange",
        "Grape",
    ]
    assert len(recipe("two terraces of vines").fields) == 2
    assert len(recipe("some fruit & veg fields, like 3 or 4, dont mind which").fields) == 3


def test_quarters_said_top_left() -> None:
    fields = recipe(
        "Sensor grid: four 25 x 25 m plots in a 2 x 2 layout. Top left wheat, top right "
        "maize, bottom left maize, bottom right wheat."
    ).fields
    assert [f.crop for f in fields] == ["Wheat", "Maize", "Maize", "Wheat"]


def test_a_kind_heading_one_plot() -> None:
    (cereal,) = recipe(
        "Any cereal will do: one plot drilled at 12.5 cm row spacing, 10 m x 50 m, for the "
        "NDVI camera."
    ).fields
    assert (cereal.category, cereal.geometry.size_m) == ("Cereals", (10.0, 50.0))


def test_a_list_counted_again_after_a_colon(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "Comice vs Durondeau: two adjacent pear blocks, 8 rows each, 3.5 m between rows."
    assert [f.variety for f in recipe(prompt).fields] == ["Doyenne du Comice", "Durondeau"]
    assert len(named_relations(prompt)) == 1


def test_a_count_per_block() -> None:
    fields = recipe(
        "Tree-fruit LiDAR benchmark: one block each of apples, pears and cherries, 150 trees "
        "per block, laid out west to east in that order."
    ).fields
    assert [f.nominal_plant_count for f in fields] == [150, 150, 150]


def test_a_variety_after_a_placement_of_plants_named_without_a_plot() -> None:
    fields = recipe(
        "The Golden Delicious trees run along the west side, and the cabbages east of them are "
        "Golden Acre."
    ).fields
    assert [f.variety for f in fields] == ["Golden Delicious", "Golden Acre"]

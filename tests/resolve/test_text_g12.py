"""Text of blind set g12 (issue 8): a row bearing in degrees (was read as a latitude),
counted beds of a variety, numbered lists, headings before a dash, clothing and events
that are no crop, views that turn left and right, corrections said casually, and cues
of ripening."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str | None, str, tuple[str | None, ...]]]:
    name = {f.id: f.variety or f.crop for f in scene.fields}
    return {(name[r.subject], r.kind, tuple(name[o] for o in r.objects)) for r in scene.relations}


def test_ridges_on_a_bearing_in_degrees() -> None:
    (field,) = recipe(
        "Carrot ridges 75 cm apart, two rows per ridge, 50 ridges, row length 80 m, seeded at 50 "
        "seeds per metre of row, ridges on a 100 degree bearing."
    ).fields
    assert "row_direction" in field.stated
    assert field.geometry.rotation_deg == pytest.approx(-100.0)


def test_counted_beds_of_a_variety_placed_against_another() -> None:
    scene = recipe(
        "Put 10 Sonata strawberry beds south of 10 Centenary beds, all beds on 1.5 m centres."
    )
    assert [f.variety for f in scene.fields] == ["Sonata", "Malling Centenary"]
    assert all(f._grid()[0] == 10 for f in scene.fields)
    assert relations(scene) == {("Sonata", "south_of", ("Malling Centenary",))}


def test_a_strip_said_to_be_there_between_two_sized_fields() -> None:
    scene = recipe(
        "Between the 3 ha wheat field and the 2 ha maize field there's a 1 ha strip of onions."
    )
    areas = [f.geometry.size_m[0] * f.geometry.size_m[1] for f in scene.fields]
    assert areas == pytest.approx([30_000, 20_000, 10_000], rel=0.001)
    assert ("Sturon", "between", ("Winter Wheat", "Dent")) in relations(scene)


@pytest.mark.parametrize(
    ("prompt", "varieties"),
    [
        (
            "Plot list for the allotment farm: 1) Roma tomatoes 2) San Marzano tomatoes 3) "
            "jalapeños 4) Padrón peppers, all in July.",
            ["Roma", "San Marzano", "Jalapeno", "Padron"],
        ),
        (
            "this is the veg garden at the school farm - a bed of peppers, a bed of tomatos and a "
            "bed of onions, kids in yellow hats weeding between them, sunny day",
            ["California Wonder", "Roma", "Sturon"],
        ),
        (
            "Field-day demo for the autonomous hoe: three 15 m x 40 m plots along the farm track "
            "- spuds at 75 cm rows, onions at 30 cm rows, cabbages at 75 cm rows.",
            ["Bintje", "Sturon", "Savoy"],
        ),
        ("kordia? no wait, bing cherries, ripe, july", ["Bing"]),
        (
            "Sadly, this is the Cabernet in the back block: yellow oily spots on the tops of the "
            "leaves and white down underneath, and it's on nearly every vine.",
            ["Cabernet Sauvignon"],
        ),
        (
            "Our little Lapins block, 120 trees, every one covered in ripe dark red cherries",
            ["Lapins"],
        ),
        (
            "Imperator carrots on the left side of the shot, harvest-ready; the harvester has "
            "lifted the first few beds and there are orange roots lying on the soil.",
            ["Imperator"],
        ),
        (
            "Weeding robot trial with two plots next to each other: Sturon onions in 12 beds, 1.8 "
            "m bed width, 4 rows per bed; and Nantes carrots on 40 ridges, 75 cm ridge spacing, 2 "
            "rows per ridge.",
            ["Sturon", "Nantes"],
        ),
    ],
)
def test_lists_headings_and_words_that_ask_for_no_field(prompt: str, varieties: list[str]) -> None:
    assert [f.variety for f in recipe(prompt).fields] == varieties


def test_no_relation_said_of_scenery() -> None:
    scene = recipe(
        "this is the veg garden at the school farm - a bed of peppers, a bed of tomatos and a bed "
        "of onions, kids in yellow hats weeding between them, sunny day"
    )
    assert scene.relations == ()


def test_looking_south_left_is_east() -> None:
    scene = recipe(
        "Looking south from the yard: Centenary strawberries on the left, which is the east side, "
        "and Sonata on the right, the west side, both loaded with ripe berries. Pickers in orange "
        "bibs working down the rows."
    )
    assert [f.variety for f in scene.fields] == ["Malling Centenary", "Sonata"]
    assert relations(scene) == {("Sonata", "west_of", ("Malling Centenary",))}


@pytest.mark.parametrize(
    ("prompt", "categories"),
    [
        (
            "Vegetables for the weeder: a 20 x 50 m cabbage plot with rows 75 cm apart, and east "
            "of it a carrot plot of the same size.",
            ["Vegetables", "Vegetables"],
        ),
        (
            "Fruit trees in the top field, grain in the bottom field, and a vegetable plot in "
            "between the two.",
            ["Fruits", "Cereals", "Vegetables"],
        ),
    ],
)
def test_a_category_heading_and_between_the_two(prompt: str, categories: list[str]) -> None:
    assert [f.category for f in recipe(prompt).fields] == categories


def test_the_crops_own_fruit_in_an_appositive_block() -> None:
    scene = recipe(
        "View over the Navel oranges, a 2 ha block with the fruit still small and green, and next "
        "to it a smaller block of Grand Nain bananas with purple flower bells hanging down."
    )
    oranges, bananas = scene.fields
    assert (oranges.variety, bananas.variety) == ("Navel", "Grand Nain")
    assert oranges.geometry.size_m[0] * oranges.geometry.size_m[1] == pytest.approx(20_000, 0.01)


def test_the_vines_placed_on_the_left() -> None:
    scene = recipe(
        "On the farm plan the vines are on the left and the orange grove is on the right, with "
        "the packing shed between them."
    )
    assert [f.crop for f in scene.fields] == ["Grape", "Orange"]


def test_a_season_said_for_the_scene_beats_a_cue() -> None:
    fields = recipe(
        "Bing cherries next to the Williams pears, white with blossom. Frosty blue April morning."
    ).fields
    assert [f.season for f in fields] == ["Spring", "Spring"]


@pytest.mark.parametrize(
    ("prompt", "stages"),
    [
        (
            "Left half of the picture is Pinot Noir with the bunches turning purple; right half "
            "is Chardonnay, still green.",
            ["Maturation", "Reproductive"],
        ),
        (
            "The dent corn, cobs drying on the stalks and the leaves gone brown, and across the "
            "lane the flint corn, still green with tassels showing.",
            ["Maturation", "Reproductive"],
        ),
    ],
)
def test_cues_of_ripening(prompt: str, stages: list[str]) -> None:
    assert [f.stage for f in recipe(prompt).fields] == stages


def test_a_month_opening_the_prompt() -> None:
    fields = recipe(
        "March on our farm in Sicily: the Moro blood oranges on the south terrace are ripe, and "
        "the Washington Navel trees north of them are already flowering."
    ).fields
    assert [f.season for f in fields] == ["Spring", "Spring"]
    assert [f.season for f in recipe("May the apples be ripe").fields] == ["Fall"]


def test_a_month_after_harvest_and_a_bearing_with_an_en_dash() -> None:
    (lettuce,) = recipe("butterhed lettuce🥬 ready 2 harvest sept, 30cm apart in the row").fields
    assert lettuce.season == "Fall"
    (maize,) = recipe(
        "Small maize plot for testing the stereo camera between rows: 8 rows at 30 in, 15 m "
        "long, NE–SW."
    ).fields
    assert "row_direction" in maize.stated
    assert abs(maize.geometry.rotation_deg) == pytest.approx(45.0)


def test_plants_poking_out_of_a_plot_of_no_crop_are_the_crop_just_named() -> None:
    scene = recipe(
        "The January King cabbages in the snow, purple-tinged leaves poking out of a white "
        "field, a fox track across the middle and the hedge behind all frosted."
    )
    assert [f.variety for f in scene.fields] == ["January King"]
    # a plot of no crop said on its own is still asked for
    assert len(recipe("onions next to a field").fields) == 2


def test_tillage_implements_and_worn_scenery_are_not_fields_or_cues() -> None:
    scene = recipe(
        "In the middle of the frame there are three different vegetable crops in strips and "
        "a tractor with a bed-former parked at the end."
    )
    assert len(scene.fields) == 3
    assert {f.category for f in scene.fields} == {"Vegetables"}
    vines = recipe(
        "Spelt nearest the camera and up on the hill the Pinot Nero vines in full leaf. "
        "A rusty old harvester by the track."
    ).fields
    assert [f.health for f in vines] == ["Healthy", "Healthy"]
    assert recipe("pinot noir vines, rusty leaves, an old tractor").fields[0].health == "Ill"


def test_a_zone_after_a_bracketed_variety_stays_with_its_crop() -> None:
    scene = recipe(
        "onions (stuttgarter) at the top, golden acre cabbage in the middle, danvers carrots "
        "at the bottom"
    )
    assert {
        ("Stuttgarter", "north_of", ("Golden Acre",)),
        ("Golden Acre", "north_of", ("Danvers",)),
    } <= relations(scene)


def test_a_closing_cue_about_the_fruit_of_fields_of_one_crop_is_said_of_all() -> None:
    scene = recipe("comice pears west of bartlett pears, late summer, fruit colouring up nicely")
    assert [f.stage for f in scene.fields] == ["Maturation", "Maturation"]
    # a relative clause stays with the field it follows
    blocks = recipe(
        "a Navel block and, south of it, a blood orange block whose trees have blotchy "
        "mottled leaves"
    ).fields
    assert [f.health for f in blocks] == ["Healthy", "Ill"]


@pytest.mark.parametrize(
    ("prompt", "kind"),
    [
        (
            "In the tomato tunnel: 8 rows of Beefsteak tomatoes. Outside, right beside the "
            "tunnel, 6 rows of California Wonder peppers.",
            "next_to",
        ),
        (
            "Beefsteak tomatoes in a tunnel. North of the tunnel, 6 rows of California Wonder "
            "peppers.",
            "north_of",
        ),
        ("Beefsteak tomatoes in the tunnel, peppers beside the tunnel.", "next_to"),
    ],
)
def test_a_field_placed_by_the_structure_another_grows_in(prompt: str, kind: str) -> None:
    assert relations(recipe(prompt)) == {("California Wonder", kind, ("Beefsteak",))}


def test_a_crop_word_in_a_machine_is_not_near_rows() -> None:
    scene = recipe(
        "Three 0.25 ha plots for a root-crop harvester sim, laid out north to south: onions, "
        "carrots, potatoes."
    )
    assert all("row_direction" not in f.stated for f in scene.fields)
    assert {
        ("Sturon", "north_of", ("Nantes",)),
        ("Nantes", "north_of", ("Bintje",)),
    } <= relations(scene)
    # a direction a few measures after the rows is still theirs
    (potato,) = recipe(
        "12 rows of Bintje potatoes, 75 cm apart, 60 m long, running east-west. Crop at flowering."
    ).fields
    assert "row_direction" in potato.stated


def test_the_only_total_of_one_field_is_its_size() -> None:
    (banana,) = recipe(
        "Banana test area, 1.5 ha in total. Double rows 1 m apart with 3.75 m alleys, 2.25 m "
        "between plants."
    ).fields
    assert banana.geometry.area_m2 == pytest.approx(15_000, rel=0.001)
    # a total of several fields is no field's size
    for prompt in ("two banana blocks, 1.5 ha in total", "wheat and maize, 2 ha in total"):
        assert all(
            f.geometry.area_m2 != pytest.approx(15_000, rel=0.01) for f in recipe(prompt).fields
        )
        assert all("size" not in f.stated for f in recipe(prompt).fields)

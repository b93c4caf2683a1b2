"""Text of blind set g13 (issue 8): row measures said as pairs and alleys, "single rows",
a crop named again with a plot of its own or after "the", a trailing direction after a
bracket, the order of a list "in that order", and a closing row direction said of fields
of one crop."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str | None, str, tuple[str | None, ...]]]:
    name = {f.id: f.variety or f.crop for f in scene.fields}
    return {(name[r.subject], r.kind, tuple(name[o] for o in r.objects)) for r in scene.relations}


def test_single_rows_are_how_a_crop_is_planted_not_a_count() -> None:
    scene = recipe(
        "Chantenay carrots and Red Baron onions next to each other, both in 20 m rows: carrots "
        "on 75 cm ridges with two rows per ridge, onions in single rows 30 cm apart with 10 "
        "plants per metre."
    )
    assert [f.variety for f in scene.fields] == ["Chantenay", "Red Baron"]
    onions = scene.fields[1]
    assert onions.agronomy.row_spacing_m == pytest.approx(0.3)
    assert onions.agronomy.in_row_spacing_m == pytest.approx(0.1)


@pytest.mark.parametrize(
    "prompt",
    [
        "Two plots for a tropical robotics demo: bananas on a 3 m square grid and chillies in "
        "1 m rows with plants every 40 cm, chilli plot west of the bananas.",
        "Two plots for an inter-row hoe: bananas on a 3 m square grid, and chillies in 1 m "
        "rows; chilli plot directly west of the bananas.",
    ],
)
def test_a_listed_crop_named_again_with_a_plot_and_placed_is_that_member(prompt: str) -> None:
    scene = recipe(prompt)
    assert [f.crop for f in scene.fields] == ["Banana", "Pepper"]
    assert {r.kind for r in scene.relations} == {"west_of"}


def test_a_second_definite_mention_of_a_clause_points_back() -> None:
    scene = recipe(
        "Occlusion test: a maize block (20 rows, 75 cm) immediately south of a tomato block "
        "(10 rows, 1.5 m), so the tall corn casts shadow on the tomatoes."
    )
    assert [f.crop for f in scene.fields] == ["Maize", "Tomato"]


def test_a_trailing_direction_after_a_bracket_places_the_field_before_it() -> None:
    scene = recipe(
        "a Cabernet Sauvignon vineyard (2.7 m rows, 1.2 m vines) to the south and a Fuji "
        "apple block (3.6 m rows, 1.0 m trees) to the north, both 0.4 ha."
    )
    assert relations(scene) == {("Cabernet Sauvignon", "south_of", ("Fuji",))}
    vines, apples = scene.fields
    assert (vines.agronomy.row_spacing_m, vines.agronomy.in_row_spacing_m) == (2.7, 1.2)
    assert (apples.agronomy.row_spacing_m, apples.agronomy.in_row_spacing_m) == (3.6, 1.0)


@pytest.mark.parametrize(
    ("prompt", "rows", "in_row"),
    [
        ("a Jonagold apple block (rows 3.2 m, trees 0.9 m)", 3.2, 0.9),
        ("a Riesling vineyard (2.5 m rows, 1.1 m vines)", 2.5, 1.1),
        ("a sweet cherry orchard: 4.5 m alleys, 2.5 m tree spacing", 4.5, 2.5),
    ],
)
def test_row_measures_said_as_a_pair_or_as_alleys(prompt: str, rows: float, in_row: float) -> None:
    (field,) = recipe(prompt).fields
    assert field.agronomy.row_spacing_m == pytest.approx(rows)
    assert field.agronomy.in_row_spacing_m == pytest.approx(in_row)


def test_alleys_between_double_rows_are_not_the_row_spacing() -> None:
    (banana,) = recipe(
        "a Grande Naine banana plantation: double rows 1 m apart with 3.75 m alleys between "
        "the pairs, 2.25 m between plants in a row"
    ).fields
    assert banana.agronomy.rows_per_bed == 2
    assert banana.agronomy.row_spacing_m == pytest.approx(4.75)


def test_laid_out_in_that_order_is_the_lists_order_not_the_rows() -> None:
    scene = recipe(
        "Red Express, January King and Golden Acre, each 10 rows x 50 m at 0.75 m x 0.4 m, "
        "laid out west to east in that order."
    )
    assert {
        ("Red Express", "west_of", ("January King",)),
        ("January King", "west_of", ("Golden Acre",)),
    } <= relations(scene)
    assert all("row_direction" not in f.stated for f in scene.fields)


def test_a_closing_row_direction_after_fields_of_one_crop_are_placed() -> None:
    scene = recipe(
        "Walla Walla and Stuttgarter Riesen onion plots, 0.3 m rows, 40 rows each, Stuttgarter "
        "plot east of the Walla Walla one, rows NE-SW"
    )
    assert [f.geometry.rotation_deg for f in scene.fields] == [-45.0, -45.0]
    # fields of different crops: the nearest one only
    apples, wheat = recipe("Gala west of wheat, rows NE-SW").fields
    assert "row_direction" not in apples.stated and "row_direction" in wheat.stated


@pytest.mark.parametrize(
    "prompt",
    [
        "Hamlin block in Florida, November: trees dripping with fruit turning from green to "
        "orange, a fruit trailer at the end of the row and palms behind.",
        "At the college plots: Beefsteak tomatoes on the right.",
    ],
)
def test_palms_and_colleges_are_scenery(prompt: str) -> None:
    assert len(recipe(prompt).fields) == 1


def test_a_palm_plantation_is_still_an_unknown_crop() -> None:
    from agrirecipe import UnknownCropError

    with pytest.raises(UnknownCropError, match="palm"):
        recipe("a palm plantation")


def test_the_short_name_of_a_variety_named_before() -> None:
    scene = recipe(
        "cherry tomatoes trained up strings on the left, Beefsteak tomatoes on the right; the "
        "beef ones have big fruit just turning red, the cherry ones are still in flower."
    )
    assert [(f.variety, f.stage) for f in scene.fields] == [
        ("Cherry", "Reproductive"),
        ("Beefsteak", "Maturation"),
    ]


def test_weather_on_plants_and_autumn_leaves_are_no_disease() -> None:
    cabbage, _red = recipe(
        "January King cabbages dusted with snow, heads solid and ready, and just north of them "
        "a block of Red Express"
    ).fields
    assert cabbage.health == "Healthy"
    assert recipe("apples dusted with mildew").fields[0].health == "Ill"
    (cherry,) = recipe(
        "the Regina cherry orchard in late October, white blossom among the yellowing leaves"
    ).fields
    assert cherry.health == "Healthy"
    # out of autumn, or on a crop that keeps no autumn colour, it is a disease
    assert recipe("cherry orchard in July, yellowing leaves").fields[0].health == "Ill"
    assert recipe("carrots in October, yellowing leaves").fields[0].health == "Ill"


def test_a_field_placed_behind_them_is_not_listed_with_them() -> None:
    apples, pears = recipe(
        "Jonagored apples in the front block with the hail nets pulled back, and behind them a "
        "row of old Durondeau pear trees, the leaves covered in little black spots."
    ).fields
    assert (apples.health, pears.health) == ("Healthy", "Ill")


def test_words_after_a_sentence_about_one_crops_plants_stay_with_it() -> None:
    cherries, pears = recipe(
        "the Kordia cherries east of the Comice pears; the cherry trees are draped in white "
        "netting with the fruit deep red and ripe, the pears still small and green."
    ).fields
    assert cherries.stage == "Maturation"
    assert pears.stage != "Maturation"


@pytest.mark.parametrize(
    ("prompt", "attribute", "value"),
    [
        ("Valencia grove in January, trees loaded with bright orange fruit", "stage", "Maturation"),
        ("a Chiquita banana farm with fat full bunches", "stage", "Maturation"),
        ("a vineyard, vines bare and pruned back to the wire", "season", "Winter"),
        ("a big potato field just coming through the soil", "stage", "Vegetative"),
    ],
)
def test_cues_of_g13(prompt: str, attribute: str, value: str) -> None:
    assert getattr(recipe(prompt).fields[0], attribute) == value


def test_directions_around_a_field_in_the_middle() -> None:
    scene = recipe(
        "To the north, the orchard, trees white with blossom; in the middle a field of young "
        "wheat; and to the south a big potato field."
    )
    name = {f.id: f.crop for f in scene.fields}
    said = {(name[r.subject], r.kind, tuple(name[o] for o in r.objects)) for r in scene.relations}
    assert {
        ("Wheat", "between", (scene.fields[0].crop, "Potato")),
        ("Potato", "south_of", ("Wheat",)),
    } <= said
    assert any(k == "north_of" and o == ("Wheat",) for _, k, o in said)


def test_a_capitalised_weak_variety_beside_a_variety_of_its_crop() -> None:
    scene = recipe(
        "Flint on the north side, Popcorn on the south side. Both maize blocks are tasseling."
    )
    assert relations(scene) == {("Flint", "north_of", ("Popcorn",))}


def test_a_lower_and_higher_count_of_fields_said_apart() -> None:
    assert len(recipe("some cereals, like 3 or 4 fields idk").fields) == 3
    assert len(recipe("some veggies maybe 2 or 3 fields").fields) == 2


def test_a_month_after_an_emoji() -> None:
    (tomato,) = recipe("beef tomatos w/ late blight 😩 sept").fields
    assert (tomato.health, tomato.season) == ("Ill", "Fall")


@pytest.mark.parametrize(
    "prompt",
    [
        "grape vines w/ the leaves all curled & spotty :(",
        "one field of cabbages left by the lane, with yellow V-shaped marks at the leaf edges",
    ],
)
def test_casual_and_farm_disease_cues(prompt: str) -> None:
    assert recipe(prompt).fields[0].health == "Ill"


def test_the_first_word_of_a_variety_named_before() -> None:
    pinot, chardonnay = recipe(
        "ok so pinot noir vines south of the chardonnay... the pinot has downy mildew rly bad, "
        "the chardonnay's fine. both at harvest"
    ).fields
    assert (pinot.health, chardonnay.health) == ("Ill", "Healthy")


def test_a_size_of_the_next_field_after_with() -> None:
    red, sturon = recipe(
        "1 ha of Red Baron onions with 1 ha of Sturon onions next to them, both ready to lift"
    ).fields
    assert red.geometry.area_m2 == pytest.approx(10_000, rel=0.001)
    assert sturon.geometry.area_m2 == pytest.approx(10_000, rel=0.001)
    # a block's own size before "with"
    apples, _cabbage = recipe(
        "a golden delicious block of 2 hectares with golden acre cabbages along its south side"
    ).fields
    assert apples.geometry.area_m2 == pytest.approx(20_000, rel=0.001)


def test_south_of_everything() -> None:
    scene = recipe(
        "Granny Smith apples north of the house, Comice pears west of the apples, and a field "
        "of Agria potatoes south of everything"
    )
    assert {
        ("Agria", "south_of", ("Doyenne du Comice",)),
        ("Agria", "south_of", ("Granny Smith",)),
    } <= relations(scene)


def test_a_numbered_list_after_a_colon() -> None:
    scene = recipe("plots are: 1) Chantenay carots 2) Stutgarter onions 3) January King cabage")
    assert [f.variety for f in scene.fields] == ["Chantenay", "Stuttgarter", "January King"]


def test_plots_told_apart_by_side_with_sizes_between() -> None:
    potatoes, carrots = recipe(
        "North plot, 50 x 120 m, Fontane potatoes; south plot, 40 x 120 m, Danvers carrots."
    ).fields
    assert potatoes.geometry.size_m == (50.0, 120.0)
    assert carrots.geometry.size_m == (40.0, 120.0)


def test_a_variety_with_an_article_after_a_relation_is_a_listed_member() -> None:
    scene = recipe(
        "Two wheat plots for spectral calibration: durum wheat north of a winter wheat plot. "
        "Both 50 x 20 m."
    )
    assert [f.variety for f in scene.fields] == ["Durum", "Winter Wheat"]
    assert relations(scene) == {("Durum", "north_of", ("Winter Wheat",))}


def test_listed_members_named_again_around_a_relation() -> None:
    scene = recipe(
        "Two fruit tree blocks: apples at 12 ft x 3 ft, cherries at 16 ft x 8 ft (row x tree), "
        "apples north of cherries, 10 rows each."
    )
    assert [f.crop for f in scene.fields] == ["Apple", "Cherry"]
    assert {r.kind for r in scene.relations} == {"north_of"}


def test_a_list_as_counted_plots() -> None:
    scene = recipe("onions, carrots and lettuce as three plots, all three with some disease")
    assert [f.crop for f in scene.fields] == ["Onion", "Carrot", "Lettuce"]


def test_a_bare_plot_noun_named_again_is_the_field_of_that_noun() -> None:
    banana, orange = recipe(
        "a banana plot at 3 x 3 m and an orange grove at 7 x 4 m next to it. Banana plot 50 x "
        "50 m, grove 100 x 60 m."
    ).fields
    assert banana.geometry.size_m == (50.0, 50.0)
    assert orange.geometry.size_m == (100.0, 60.0)

"""Text of blind set g14 (issue 8), first fixes: inches said "in" before a spacing word,
a counted plot of no crop whose members are named in the sentences after it, a field
named again past another, "in both" after "and a 6 m headland", an area said beside
row counts, spacings said of the nearest field, "Vines at 2.2 m row spacing" and
"along the east side of"."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_inches_said_in_before_a_spacing_word() -> None:
    (beds,) = recipe(
        "Albion strawberry beds on 60-inch centers, 2 rows/bed, 12 in plant spacing, 12 beds, "
        "rows 200 ft long running north-south."
    ).fields
    assert beds.agronomy.in_row_spacing_m == pytest.approx(0.3048)
    assert beds._grid()[0] == 12


def test_a_counted_plot_whose_members_are_named_in_later_sentences() -> None:
    scene = recipe(
        "Two blocks for drone flights. Block A: Gala apples, 8 rows, 3.5 m between rows, trees "
        "at 1 m, rows 60 m long. Block B, directly south of A: Conference pears, 6 rows at "
        "3.5 m with 1.25 m between trees."
    )
    assert [f.crop for f in scene.fields] == ["Apple", "Pear"]


def test_a_field_named_again_past_another_and_measures_in_both() -> None:
    potatoes, maize = recipe(
        "Robot navigation course: potatoes (20 rows at 75 cm) and maize (20 rows at 75 cm), "
        "80 m rows and a 6 m headland in both, maize east of potatoes."
    ).fields
    assert [r.kind for r in recipe("potatoes and maize, maize east of potatoes").relations] == [
        "east_of"
    ]
    for field in (potatoes, maize):
        assert "row_length" in field.stated and field.geometry.headland_m == 6.0


@pytest.mark.parametrize(
    "prompt",
    [
        "Potato ridges: 30 ridges on 75 cm centres, one row per ridge, 0.5 acre in total.",
        "half an acre of Russet Burbank potatoes in flower, 48 rows, 36-inch rows",
    ],
)
def test_an_area_said_beside_row_counts_is_the_whole_field(prompt: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.geometry.area_m2 == pytest.approx(2023.43, rel=0.005)


def test_spacings_after_a_list_go_to_the_nearest_field() -> None:
    banana, citrus = recipe(
        "a banana block planted 3 m x 3 m and a citrus block with rows 6 m apart and trees "
        "every 3 m, citrus north of the bananas"
    ).fields
    assert (citrus.agronomy.row_spacing_m, citrus.agronomy.in_row_spacing_m) == (6.0, 3.0)
    assert (banana.agronomy.row_spacing_m, banana.agronomy.in_row_spacing_m) == (3.0, 3.0)


def test_the_rows_spacing_said_of_the_plants() -> None:
    vines, apples = recipe(
        "Spätburgunder block west of a Royal Gala block. Vines at 2.2 m row spacing with 1 m "
        "between vines, apples on 3.4 m rows with a tree every 0.9 m."
    ).fields
    assert (vines.agronomy.row_spacing_m, vines.agronomy.in_row_spacing_m) == (2.2, 1.0)
    assert (apples.agronomy.row_spacing_m, apples.agronomy.in_row_spacing_m) == (3.4, 0.9)


def test_along_the_east_side_of() -> None:
    scene = recipe(
        "Golden Acre cabbage strip, 8 rows at 60 cm, along the east side of a Golden Delicious "
        "block of 12 rows at 3.5 m."
    )
    assert [r.kind for r in scene.relations] == ["east_of"]
    # "on the north side of it": of the hedge, not of a field
    hedge = recipe(
        "Two fields split by a hawthorn hedge, pears on the north side of it and cabbages on "
        "the south side."
    )
    assert len(hedge.fields) == 2


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        (
            "Vendimia in Chile, end of March: the Cabernet rows are heavy with ripe black grapes "
            "and a crew with yellow bins is picking.",
            ["Grape"],
        ),
        (
            "A Navel grove I photographed in Valencia province in January: trees loaded with "
            "ripe fruit.",
            ["Orange"],
        ),
        (
            "a field of flint corn with just a few leaves up, and beyond it spring wheat in ear. "
            "A hay wagon on the lane.",
            ["Maize", "Wheat"],
        ),
        (
            "strawberrys after all that rain, loads of rotten fruit with grey fuzz on it, straw "
            "between the rows",
            ["Strawberry"],
        ),
        (
            "Onions in neat rows with their green tops standing up, then suddenly a patch where "
            "everything has gone yellow and collapsed: downy mildew.",
            ["Onion"],
        ),
        (
            "Bananas from my trip to Tenerife! A plantation of banana plants behind an old stone "
            "wall, most of them in flower with big purple buds hanging down.",
            ["Banana"],
        ),
    ],
)
def test_photo_words_that_are_no_second_field(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_what_the_no_field_words_still_say() -> None:
    (strawberries,) = recipe("strawberries, loads of rotten fruit with grey fuzz on it").fields
    assert strawberries.health == "Ill"
    (onions,) = recipe(
        "Onions in neat rows, then a patch where everything has downy mildew."
    ).fields
    assert onions.health == "Ill"
    # a title with measures of its own is a field ("cabbage: 0.75 m rows ... A Red Express
    # plot to the west of it")
    assert (
        len(recipe("cabbage: 0.75 m rows, 64 rows. A Red Express plot to the west of it.").fields)
        == 2
    )
    # lots of a category after a field, not described, still asks for fields
    assert len(recipe("some apples and lots of fruit trees").fields) >= 2


def test_a_disease_on_the_fruit_is_the_fields() -> None:
    (strawberries,) = recipe(
        "The Malling Centenary strawberries in the walled garden have grey mould on the fruit. "
        "Mid-June."
    ).fields
    assert strawberries.health == "Ill"


def test_a_cue_of_its_own_beats_a_stage_lent_by_a_list() -> None:
    wheat, maize, _tomatoes = recipe(
        "In August the farm's got ripe wheat, maize in tassel and a patch of tomatoes."
    ).fields
    assert (wheat.stage, maize.stage) == ("Maturation", "Reproductive")


@pytest.mark.parametrize(
    ("prompt", "stages"),
    [
        (
            "a strawberry field on raised beds, and north of it a potato field where the plants "
            "have only just come through.",
            ["Reproductive", "Vegetative"],
        ),
        (
            "Over the fence in June: a field of flint corn with just a few leaves up.",
            ["Vegetative"],
        ),
        (
            "strawberries (sonata) + strawberries (albion), 20x50m each, flowering, june",
            ["Reproductive", "Reproductive"],
        ),
    ],
)
def test_g14_stage_cues(prompt: str, stages: list[str]) -> None:
    assert [f.stage for f in recipe(prompt).fields][-len(stages) :] == stages


def test_a_months_weather_says_the_month() -> None:
    scene = recipe(
        "From the terrace: blood oranges on the lower terrace, Valencia Late on the upper one, "
        "both heavy with fully coloured fruit. March sunshine and a stone farmhouse."
    )
    assert [(f.stage, f.season) for f in scene.fields] == [("Maturation", "Spring")] * 2
    # a lowercase "may" before rain is no month
    assert recipe("it may rain on the apples").fields[0].season != "Spring"


def test_a_list_counted_again_with_its_plots() -> None:
    scene = recipe("butterhead + lollo rosso + romaine, 3 lettuce plots, just emerged, april")
    assert [f.variety for f in scene.fields] == ["Butterhead", "Lollo Rosso", "Romaine"]


def test_a_plot_then_its_crop_after_a_copula() -> None:
    (vines,) = recipe(
        "The vineyard on the south slope is Pinot Noir. Mid-September, grapes ripening, and "
        "there's downy mildew on a good part of the lower leaves."
    ).fields
    assert (vines.variety, vines.health) == ("Pinot Noir", "Ill")


def test_grazing_is_no_grape() -> None:
    scene = recipe(
        "A ditch divides the lettuce from the onions: the onions are on the east side of the "
        "ditch, the lettuce on the west side, and the cows graze beyond the lettuce."
    )
    assert [f.crop for f in scene.fields] == ["Lettuce", "Onion"]


def test_the_sides_of_the_farm_are_zones() -> None:
    scene = recipe(
        "Granny Smith apples take up the west side of the farm, Valencia Late oranges the east "
        "side of the farm."
    )
    assert [r.kind for r in scene.relations] == ["west_of"]


def test_between_the_other_two() -> None:
    scene = recipe(
        "three strips: onions with the tops flopped over, then carrots, then lettuce, so the "
        "carrots are sandwiched between the other two."
    )
    between = [r for r in scene.relations if r.kind == "between"]
    assert len(between) == 1 and between[0].subject == scene.fields[1].id


def test_the_second_block_east_of_the_first() -> None:
    scene = recipe(
        "Two blocks of Romaine, each one 40 rows of 100 m with a 4 m headland round it; the "
        "second block is east of the first."
    )
    first, second = scene.fields
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("east_of", second.id, (first.id,))
    ]


def test_a_side_said_bare_after_a_side_of_the_farm() -> None:
    scene = recipe(
        "Granny Smith apples take up the west side of the farm, Valencia Late oranges the east "
        "side."
    )
    apples, oranges = scene.fields
    assert (apples.crop, oranges.crop) == ("Apple", "Orange")
    relations = [(r.kind, r.subject, r.objects) for r in scene.relations]
    assert relations == [("west_of", apples.id, (oranges.id,))]


@pytest.mark.parametrize(
    "prompt",
    [
        "banana farm, two blocks - Ladyfinger down near the river, Gros Michel up by the sheds",
        "two fields, wheat by the barn, maize near the river",
    ],
)
def test_members_of_a_count_placed_by_scenery(prompt: str) -> None:
    fields = recipe(prompt).fields
    # two fields, two crops or varieties: no third field of no crop
    assert len(fields) == 2
    assert len({(f.crop, f.variety) for f in fields}) == 2


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("two wheat and maize fields", ["Wheat", "Maize"]),
        ("3 apple and pear orchards", ["Apple", "Apple", "Pear"]),
        ("4 or 5 cereal fields", None),
    ],
)
def test_a_count_before_crops_sharing_one_plot_noun(prompt: str, crops: list[str] | None) -> None:
    fields = recipe(prompt).fields
    if crops is None:
        assert len(fields) == 4  # the lower of "4 or 5"
    else:
        assert [f.crop for f in fields] == crops


def test_a_vague_count_of_cereal_and_veg_fields_is_not_refused() -> None:
    fields = recipe("like 4 or 5 different cereal & veg fields, whatever u want").fields
    categories = [f.category for f in fields]
    assert len(fields) == 4
    assert categories.count("Cereals") == 2 and categories.count("Vegetables") == 2
    assert len({f.crop for f in fields}) == 4


def test_a_row_length_said_each_after_a_count_of_rows() -> None:
    tomatoes, peppers = recipe(
        "Tomato rows for the camera rig - 20 rows, 50 m each, 1.5 m between rows, density "
        "33,333 plants/ha, staked - with 10 rows of peppers at 0.9 m alongside."
    ).fields
    assert (tomatoes.agronomy.row_spacing_m, peppers.agronomy.row_spacing_m) == (1.5, 0.9)
    assert "row_length" not in peppers.stated
    assert tomatoes.geometry.size_m[1] > peppers.geometry.size_m[1] * 0.9


@pytest.mark.parametrize(
    "prompt",
    [
        "California Wonder peppers in front with blocky green fruit, and Roma tomatoes behind "
        "with curled, mottled leaves.",
        "on one side of the canal Grand Nain, on the other side Lady Finger with dark streaks "
        "on the leaves, black Sigatoka.",
    ],
)
def test_words_after_a_comma_go_on_with_the_last_members_own_with(prompt: str) -> None:
    first, second = recipe(prompt).fields
    assert (first.health, second.health) == ("Healthy", "Ill")


def test_a_trailing_cue_still_goes_to_a_bare_list() -> None:
    fields = recipe("bananas and oranges, ripe").fields
    assert [f.stage for f in fields] == ["Maturation", "Maturation"]

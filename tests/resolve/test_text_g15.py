"""Text of blind set g15 (issue 8): counted beds with a word before the crop, colours that
are crop words, typos of long names and doubled letters, "a field of those", crops said
as alternatives, numbered lists, headings before a colon, "N kinds of", bracketed
varieties of a counted list, scenery that places nothing, "both" of two, labels said
again, zones of a half and the rest, and row measures said "also"."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe._errors import UnknownCropError
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    crop = {f.id: f.variety or f.crop for f in scene.fields}
    return {(crop[r.subject], r.kind, tuple(crop[o] for o in r.objects)) for r in scene.relations}


def test_counted_beds_with_a_word_before_the_crop_are_one_field() -> None:
    (beds,) = recipe(
        "camera rig trial - 8 raised strawberry beds on 1.5 m centres, two rows per bed, "
        "30 cm between plants along the row."
    ).fields
    assert (beds.crop, beds.agronomy.rows_per_bed) == ("Strawberry", 2)
    assert beds.agronomy.row_spacing_m == pytest.approx(1.5)


@pytest.mark.parametrize(
    "prompt",
    [
        "Imperator carrots at harvest, the lifter pulling them up long and orange.",
        "Imperator carrots at harvest, the carrots are orange",
        "carrots, bright orange",
    ],
)
def test_a_colour_crop_word_said_of_a_field_is_its_colour(prompt: str) -> None:
    assert [f.crop for f in recipe(prompt).fields] == ["Carrot"]


def test_two_edits_in_a_long_name_and_a_doubled_letter_are_typos() -> None:
    (carrots,) = recipe("u know those chantaney carrots? a field of those, young, june").fields
    assert (carrots.variety, carrots.stage) == ("Chantenay", "Vegetative")
    red, sturon = recipe("Red Barron and Sturon onions, Sturon on the north side").fields
    assert (red.variety, sturon.variety) == ("Red Baron", "Sturon")


@pytest.mark.parametrize(
    "prompt", ["grain field, wheat or corn idc, 100 by 200 m", "a field of wheat or maize"]
)
def test_crops_said_as_alternatives_are_one_field(prompt: str) -> None:
    assert [f.crop for f in recipe(prompt).fields] == ["Wheat"]


def test_the_numbers_of_a_list_count_nothing() -> None:
    scene = recipe(
        "yield-mapping dataset, 2 plots: (1) wheat drilled at 15 cm, 1 ha, ready to combine; "
        "(2) a 1 ha maize plot directly south of it."
    )
    assert [f.crop for f in scene.fields] == ["Wheat", "Maize"]
    assert relations(scene) == {("Dent", "south_of", ("Winter Wheat",))}


def test_a_crop_heading_before_a_colon_is_the_fields_title() -> None:
    scene = recipe(
        "salad dataset: two lettuce plots, Cos on 16-inch rows and Lollo on 14-inch rows, 12 "
        "inches in the row for both, the Lollo west of the Cos"
    )
    assert [f.variety for f in scene.fields] == ["Romaine", "Lollo Rosso"]
    # a heading with measures of its own stays a field
    assert len(recipe("cabbage: 0.75 m rows, 64 rows. A Red Express plot west of it.").fields) == 2


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("orchard w 3 kinds of fruit tress, all diff pls", 3),
        ("an orchard with 3 varieties of apples", 3),
        ("a field with 2 types of lettuce", 2),
    ],
)
def test_kinds_counted_are_different_fields(prompt: str, count: int) -> None:
    fields = recipe(prompt).fields
    assert len(fields) == count
    assert len({(f.crop, f.variety) for f in fields}) == count


def test_an_orchard_with_trees_counted_is_one_field() -> None:
    (orchard,) = recipe("an orchard with 200 trees").fields
    assert orchard.nominal_plant_count >= 190


@pytest.mark.parametrize(
    ("prompt", "varieties"),
    [
        (
            "2 strawberry fields (sonata) & 1 of centenary",
            ["Sonata", "Sonata", "Malling Centenary"],
        ),
        (
            "ok so 2 fields pls: carrots (nantes) & cabbage (savoy) and the carrots go north of "
            "the cabbage thx",
            ["Nantes", "Savoy"],
        ),
        ("2 apple blocks (Gala, Fuji)", ["Gala", "Fuji"]),
    ],
)
def test_bracketed_varieties_of_a_counted_list(prompt: str, varieties: list[str]) -> None:
    assert [f.variety for f in recipe(prompt).fields] == varieties


@pytest.mark.parametrize(
    ("prompt", "kinds"),
    [
        (
            "Shot over the fence: a field of lettuce, then one of cabbages, then a corn field. "
            "There's an irrigation reel in the middle of the lettuce.",
            {"next_to", "between"},
        ),
        (
            "A ditch runs right through the middle of this photo. East of it is a field of "
            "sweetcorn, west of it a field of Iceberg lettuce.",
            {"west_of"},
        ),
        (
            "Chardonnay just west of the winery, and further west a field of Lapins cherries.",
            {"west_of"},
        ),
    ],
)
def test_scenery_places_no_field(prompt: str, kinds: set[str]) -> None:
    # (each was refused: the relations could not all hold)
    scene = recipe(prompt)
    assert {r.kind for r in scene.relations} == kinds


def test_a_pronoun_after_fields_named_before_still_places() -> None:
    scene = recipe(
        "The strawberry field and the potato field beside it: strawberries on beds, potato "
        "ridges about 90 cm apart."
    )
    assert relations(scene) == {("Bintje", "next_to", ("Elsanta",))}


def test_each_side_of_a_list_measured_apart() -> None:
    cherry, beef = recipe(
        "cherry tomatoes, 10 rows at 1.5 m, and beef tomatoes, 10 rows at 1.8 m, both 0.5 m "
        "in-row; the beef tomatoes south of the cherry tomatoes."
    ).fields
    assert (cherry.agronomy.row_spacing_m, beef.agronomy.row_spacing_m) == (1.5, 1.8)
    assert cherry.agronomy.in_row_spacing_m == beef.agronomy.in_row_spacing_m == 0.5
    # "both" before a measure after a list of fields still says it of both
    carrots, onions = recipe(
        "weeding robot test -> carrots vs onions, 100 m rows, both ridged at 75 cm"
    ).fields
    assert "row_length" in carrots.stated and "row_length" in onions.stated


def test_a_variety_list_grown_in_counted_plots() -> None:
    scene = recipe("Jonagold and Conference in two blocks")
    assert [f.variety for f in scene.fields] == ["Jonagold", "Conference"]


def test_the_middle_one_of_three_strips() -> None:
    scene = recipe(
        "The farm is three strips: onions on the north strip, cabbage in the middle one, "
        "lettuce on the south strip."
    )
    assert [f.crop for f in scene.fields] == ["Onion", "Cabbage", "Lettuce"]


def test_an_everyday_word_before_an_orchard_is_no_crop() -> None:
    (orchard,) = recipe(
        "the little home orchard beside the farmhouse, trees bare and dormant"
    ).fields
    assert orchard.category == "Fruits" and orchard.season == "Winter"
    with pytest.raises(UnknownCropError):
        recipe("render an office building with a rooftop terrace")


@pytest.mark.parametrize(
    ("prompt", "health"),
    [
        (
            "Crisphead lettuce in the front of the picture and Red Express cabbage behind, the "
            "cabbage leaves chewed full of holes by caterpillars.",
            ("Healthy", "Ill"),
        ),
    ],
)
def test_a_field_named_again_by_the_is_the_one_described(
    prompt: str, health: tuple[str, str]
) -> None:
    assert tuple(f.health for f in recipe(prompt).fields) == health


def test_short_names_of_varieties_said_before() -> None:
    beef, plum = recipe(
        "Beef tomatoes and plum tomatoes growing side by side. The beefs are still green, the "
        "plum ones already red and ripe."
    ).fields
    assert (beef.stage, plum.stage) == ("Reproductive", "Maturation")


def test_both_is_the_two_just_named() -> None:
    scene = recipe(
        "Three fields in the photo, taken in late April: a cherry orchard to the north, "
        "strawberries to the south and a potato field between them. Cherries and strawberries "
        "are both flowering, the potatoes were only just planted."
    )
    assert [f.stage for f in scene.fields] == ["Reproductive", "Reproductive", "Vegetative"]


def test_words_after_a_bracketed_variety_go_to_the_whole_list() -> None:
    red, walla = recipe(
        "red onions (red baron) n walla wallas side by side, ready to harvest in aug"
    ).fields
    assert red.stage == walla.stage == "Maturation"
    # a bracket of the member's own words ends the sharing
    fontane, agria = recipe("Fontane (2 ha) and Agria (3 ha) either side of the lane").fields
    assert fontane.geometry.size_m != agria.geometry.size_m


def test_a_label_said_again_is_its_field() -> None:
    fontane, agria = recipe(
        "Plot A: Fontane, plot B: Agria, each 16 rows x 75 cm x 50 m. Plot A shows late blight "
        "lesions, plot B is clean. B lies east of A."
    ).fields
    assert (fontane.health, agria.health) == ("Ill", "Healthy")


def test_half_the_farm_and_the_rest() -> None:
    scene = recipe("Half the farm is maize, the northern half, and the rest is wheat.")
    assert relations(scene) == {("Dent", "north_of", ("Winter Wheat",))}


def test_members_placed_on_either_side_with_their_own_measures() -> None:
    scene = recipe(
        "Two apple blocks either side of the farm track: Gala on the north side planted at "
        "3.5 m by 1 m, and Pink Lady on the south side with 12 ft between rows."
    )
    assert ("Gala", "north_of", ("Pink Lady",)) in relations(scene)


@pytest.mark.parametrize(
    ("prompt", "key", "value"),
    [
        (
            "field corn on 30-inch rows, 48 rows, 1,320 ft long, and next to it Russet potatoes "
            'on 36" rows, 24 rows of the same 1,320 ft length.',
            "row_length",
            402.336,
        ),
        (
            "Tomatoes: 10 rows 60 in apart, 24 in in-row, rows also 300 ft.",
            "row_spacing",
            1.524,
        ),
        (
            "Carrot strip: 6 rows 18 inches apart. Romaine strip right beside it: 6 rows, also "
            "18 inches, 12 inches between heads.",
            "row_spacing",
            0.4572,
        ),
    ],
)
def test_row_measures_said_the_engineers_way(prompt: str, key: str, value: float) -> None:
    last = recipe(prompt).fields[-1]
    if key == "row_length":
        _, per_row = last._grid()
        assert (per_row - 1) * last.agronomy.in_row_spacing_m == pytest.approx(value, rel=0.01)
    else:
        assert last.agronomy.row_spacing_m == pytest.approx(value)


def test_heads_counted_with_their_spacing() -> None:
    (cabbage,) = recipe(
        "Golden Acre cabbage, 2,400 heads at 70 x 45 cm, rows east-west, heads ready to cut."
    ).fields
    assert cabbage.nominal_plant_count == pytest.approx(2400, rel=0.01)

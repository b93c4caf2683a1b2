"""Farm, casual and photo text of blind set g5 (issue 8): thirds and paddocks as zones,
"top to bottom" lists, a view "looking east", scenery zones, demonyms, lower-case
"n" for "and", month abbreviations, and new visual cues."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in scene.relations}


def test_thirds_of_a_farm_are_zones() -> None:
    scene = recipe(
        "The farm's split by hedges into three: the west third is spuds, the middle third "
        "corn, and the east third strawberries."
    )
    west, middle, east = (f.id for f in scene.fields)
    assert {("west_of", west, (middle,)), ("west_of", middle, (east,))} <= relations(scene)


def test_compass_paddocks_are_placed() -> None:
    scene = recipe(
        "north paddock: Lapins cherrys, 1 ha. south paddock: Albion strawbery beds, half a hectare"
    )
    cherry, strawberry = (f.id for f in scene.fields)
    assert ("north_of", cherry, (strawberry,)) in relations(scene)


def test_top_to_bottom_lists_from_north_to_south() -> None:
    scene = recipe("Top to bottom the farm goes: vineyard, then grain, then greens.")
    vines, grain, greens = (f.id for f in scene.fields)
    assert {("north_of", vines, (grain,)), ("north_of", grain, (greens,))} <= relations(scene)


def test_looking_east_lists_from_the_viewer() -> None:
    scene = recipe(
        "Looking east from the barn roof: potatoes closest to me, then the wheat, then the "
        "maize right up against the woods."
    )
    potatoes, wheat, maize = (f.id for f in scene.fields)
    assert {("west_of", potatoes, (wheat,)), ("west_of", wheat, (maize,))} <= relations(scene)


def test_looking_north_leaves_placing_to_the_zones() -> None:
    scene = recipe(
        "Looking north from the yard: wheat at the far north end, potatoes in the middle, and "
        "strawberries closest to me at the south end."
    )
    wheat, potatoes, strawberries = (f.id for f in scene.fields)
    assert ("north_of", wheat, (potatoes,)) in relations(scene)
    assert ("north_of", potatoes, (strawberries,)) in relations(scene)


def test_a_zone_of_scenery_is_not_a_fields_zone() -> None:
    scene = recipe(
        "left side of the farm is leafy greens, rigth side is grain, and theres a duck pond "
        "in the middle"
    )
    greens, grain = (f.id for f in scene.fields)
    assert relations(scene) == {("west_of", greens, (grain,))}


@pytest.mark.parametrize(
    "prompt",
    [
        "can u make pinot nero on the left n chardonnay on the right, spring",
        "pinot nero on the left 'n' chardonnay on the right",
    ],
)
def test_lower_case_n_is_and(prompt: str) -> None:
    scene = recipe(prompt)
    assert [f.variety for f in scene.fields] == ["Pinot Noir", "Chardonnay"]
    assert ("west_of", scene.fields[0].id, (scene.fields[1].id,)) in relations(scene)


def test_capital_n_is_still_north() -> None:
    assert recipe("wheat, rows N-S").fields[0].row_bearing_deg == 0


def test_month_abbreviation_and_demonym() -> None:
    assert recipe("navel oranges, ripe, its dec so like xmas vibes").fields[0].season == "Winter"
    chile = generate(
        "On the Chilean farm the Bing cherries are ripe in December", resolver="hybrid"
    )
    assert chile.recipe.fields[0].season == "Summer"


def test_hay_shed_is_scenery() -> None:
    (field,) = recipe("Past the cattle grid and the hay shed there's our strawberry patch").fields
    assert field.crop == "Strawberry"


@pytest.mark.parametrize(
    ("prompt", "attribute", "value"),
    [
        ("a 3 hectare wheat field with the ears just coming out", "stage", "Reproductive"),
        ("Banana plants, each with a big purple flower bud hanging", "stage", "Reproductive"),
        ("a vineyard, first leaves just unfolding", "stage", "Vegetative"),
        ("Pear trees with blackened blossom clusters and a shepherd's crook", "health", "Ill"),
    ],
)
def test_new_visual_cues(prompt: str, attribute: str, value: str) -> None:
    assert getattr(recipe(prompt).fields[0], attribute) == value


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("cabbages and onions in 2 plots w/ a sprayer driving thru", ["Cabbage", "Onion"]),
        ("Sturon and Walla Walla onions in adjacent 6 x 50 m strips", ["Onion", "Onion"]),
        ("Durondeau and Bartlett pears in neighbouring blocks", ["Pear", "Pear"]),
    ],
)
def test_plots_a_list_is_grown_in_are_its_fields(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in recipe(prompt).fields] == crops


def test_measures_after_a_lists_plots_go_to_each() -> None:
    scene = recipe(
        "Sturon and Walla Walla onions in adjacent 6 x 50 m strips, rows 30 cm apart and "
        "8 cm in-row."
    )
    assert [f.agronomy.in_row_spacing_m for f in scene.fields] == [0.08, 0.08]
    assert [f.geometry.size_m for f in scene.fields] == [(6.0, 50.0), (6.0, 50.0)]


def test_both_fields_named_first_are_two() -> None:
    scene = recipe("Both cereal fields beside the grain dryer have yellow rust this summer.")
    assert len(scene.fields) == 2
    assert {f.health for f in scene.fields} == {"Ill"}


def test_a_weak_variety_placed_against_its_crop_is_that_crop() -> None:
    scene = recipe(
        "Sonata in 10 beds north of Malling Centenary in 10 beds. Bed centres 1.3 m, 2 rows "
        "per bed, 25 cm between plants."
    )
    assert [f.variety for f in scene.fields] == ["Sonata", "Malling Centenary"]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [1.3, 1.3]


def test_members_listed_without_commas() -> None:
    scene = recipe("onions (red baron) between 2 carrot fields, one nantes one chantenay")
    assert [f.variety for f in scene.fields] == ["Red Baron", "Nantes", "Chantenay"]


def test_the_other_after_a_size_is_the_next_member() -> None:
    scene = recipe("2 maize fields 75cm rows, 1 of them 5 ha the other 3 ha")
    assert [round(f.geometry.area_m2) for f in scene.fields] == [50_000, 30_000]


def test_slashed_fractions_and_weak_varieties_after_of() -> None:
    scene = recipe("1/2 acre of russets & a 100 ft by 200 ft plot of sturon onions south of it")
    potato, onion = scene.fields
    assert (potato.crop, potato.variety) == ("Potato", "Russet Burbank")
    assert potato.geometry.area_m2 == pytest.approx(4046.8564 / 2, rel=0.01)
    assert ("south_of", onion.id, (potato.id,)) in relations(scene)


def test_a_total_area_is_not_a_fields_size() -> None:
    scene = recipe("we farm about 4 ha in total - 2 ha of potatoes and the last 2 ha is onions")
    assert [f.crop for f in scene.fields] == ["Potato", "Onion"]
    assert [round(f.geometry.area_m2) for f in scene.fields] == [20_000, 20_000]


def test_words_about_one_crops_plants_go_to_that_crop() -> None:
    scene = recipe(
        "The Riesling vineyard runs along the north side of the Fuji orchard. Half the vines "
        "show downy mildew; the apples are colouring up nicely."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Grape", "Ill"), ("Apple", "Healthy")]


def test_bare_vines_are_still_vines() -> None:
    (field,) = recipe("Bare vines in the snow, every post capped with white").fields
    assert (field.crop, field.season) == ("Grape", "Winter")


@pytest.mark.parametrize(
    "prompt",
    [
        "In the polytunnel block there are Padrón peppers and jalapeños side by side, with the "
        "San Marzano tomatoes on the far side of the jalapeños.",
        "Padrón peppers next to jalapeños, and San Marzano tomatoes on the other side of the "
        "jalapeños.",
    ],
)
def test_the_far_side_of_a_named_field_is_beside_it(prompt: str) -> None:
    scene = recipe(prompt)
    _padron, jalapeno, tomato = (f.id for f in scene.fields)
    assert len(scene.fields) == 3
    assert ("next_to", tomato, (jalapeno,)) in relations(scene)


def test_what_a_field_has_is_another_field() -> None:
    scene = recipe("The cherry orchard has a plot of cherry tomatoes right next to it.")
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Cherry", scene.fields[0].variety),
        ("Tomato", "Cherry"),
    ]


def test_one_tree_of_the_named_fields_is_not_a_field() -> None:
    scene = recipe(
        "the Navel block with ripe fruit, and a picker's ladder leaning against one tree."
    )
    assert [f.crop for f in scene.fields] == ["Orange"]


def test_members_planted_one_strip_each_with_adjectives() -> None:
    scene = recipe(
        "Three pepper varieties in my photo, one strip each: California Wonder with big blocky "
        "green fruit, Jalapeños hanging dark and shiny, and Cayenne with long red pods."
    )
    assert [f.variety for f in scene.fields] == ["California Wonder", "Jalapeno", "Cayenne"]


def test_everywhere_after_one_field_is_that_fields() -> None:
    scene = recipe(
        "Field A - Russet potatoes, blight everywhere. Field B - Sturon onions, healthy. "
        "Field C - Iceberg lettuce, bolting."
    )
    assert [f.health for f in scene.fields] == ["Ill", "Healthy", "Healthy"]
    assert recipe("potatoes and onions, blight everywhere").fields[1].health == "Ill"


def test_separate_blocks_after_a_list_are_its_blocks() -> None:
    scene = recipe("i want jonagored apples AND fuji apples, 2 separate blocks, spring")
    assert [f.variety for f in scene.fields] == ["Jonagold", "Fuji"]


def test_a_field_of_it_is_the_crop_named() -> None:
    (field,) = recipe("all we really have is veg, one big field of it behind the barn").fields
    assert field.category == "Vegetables"


def test_the_block_one_field_is_planted_in_gives_its_size() -> None:
    (field,) = recipe("Pear trees at 3.5 x 1.2 m, in a 60 m x 80 m block, fire blight").fields
    assert (field.crop, field.health) == ("Pear", "Ill")
    assert field.geometry.size_m == (60.0, 80.0)


def test_a_crop_on_the_terraces_is_one_field() -> None:
    scene = recipe(
        "On the finca in Tenerife we grow Dwarf Cavendish bananas on the terraces below the "
        "house and Valencia Late oranges on the terraces up above."
    )
    assert [f.crop for f in scene.fields] == ["Banana", "Orange"]


def test_some_kind_of_root_crop_is_a_zone_field() -> None:
    scene = recipe(
        "so the farm splits into three bands: cherries across the top, some kind of root crop "
        "through the middle, and cereals down the bottom by the brook"
    )
    top, middle, _bottom = scene.fields
    assert middle.crop in ("Carrot", "Potato", "Onion")
    assert ("north_of", top.id, (middle.id,)) in relations(scene)


def test_the_half_being_the_northern_one() -> None:
    scene = recipe(
        "The orchard is half Comice and half Durondeau, the Comice half being the northern one."
    )
    comice, durondeau = scene.fields
    assert relations(scene) == {("north_of", comice.id, (durondeau.id,))}


def test_scenery_words_are_not_fuzzy_crops_or_stages() -> None:
    scene = recipe(
        "Wheat at the two-leaf stage, and the onion sets in the next field are barely up. "
        "Rooks picking about along the hedge."
    )
    wheat, onion = scene.fields
    assert ("next_to", onion.id, (wheat.id,)) in relations(scene)
    vines = recipe(
        "Pinot Noir vines, the bunches colouring up, grass in the alleys freshly mown"
    ).fields[0]
    assert vines.stage == "Maturation"


def test_the_first_leaves_just_out_are_vegetative() -> None:
    scene = recipe(
        "Fruit trees covered in blossom and, behind them, a vineyard with the first "
        "leaves just out."
    )
    assert [f.stage for f in scene.fields] == ["Reproductive", "Vegetative"]


def test_the_first_word_of_a_crop_named_stands_for_it() -> None:
    scene = recipe(
        "two staked tomato blocks, San Marzano and plum tomatoes (plum ones to the west)."
    )
    san_marzano, roma = scene.fields
    assert roma.variety == "Roma"
    assert ("west_of", roma.id, (san_marzano.id,)) in relations(scene)


def test_whole_patches_browned_off_describe_the_field() -> None:
    scene = recipe(
        "In the photo the carot tops are dotted with dark lesions ringed in yellow and whole "
        "patches have browned off; sprinkler line in the background, pale sky."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Carrot", "Ill")]


def test_a_listed_members_words_and_a_machine_are_not_fields() -> None:
    scene = recipe(
        "The church tower gives a view of three of our fields: Agria potatoes in flower nearest "
        "the village, Spelt furthest away and gone the colour of straw, and a strip of Sturon "
        "onions between the two. August, late afternoon, a combine already working in the spelt."
    )
    assert [f.variety for f in scene.fields] == ["Agria", "Spelt", "Sturon"]


def test_a_plot_word_before_a_list_of_its_crops_is_a_heading() -> None:
    scene = recipe("vineyard in NZ, cabernet on one block n chardonnay on the other, march")
    assert [f.variety for f in scene.fields] == ["Cabernet Sauvignon", "Chardonnay"]
    assert {f.season for f in scene.fields} == {"Fall"}

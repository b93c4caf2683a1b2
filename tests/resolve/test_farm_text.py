"""Farms and photographs described the way people write them (issue 8, blind sets g1 farm
and g1 photo): fields placed relative to each other with pointing words, scenery that
happens to be a plant, descriptions of the plants already named."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, UnknownCropError, generate
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


def test_that_after_a_relation_word_points_back() -> None:
    scene = recipe(
        "Behind the greenhouse there's a patch of cherry tomatoes, and north of that a row "
        "of Bing cherry trees."
    )
    assert relations(scene) == {("north_of", "Cherry", ("Tomato",))}
    assert relations(recipe("apples, and north of that pears")) == {
        ("north_of", "Pear", ("Apple",))
    }


def test_a_direction_with_a_plot_noun_places_the_field_before_it() -> None:
    scene = recipe(
        "Williams pears on the north block, Cavendish bananas in the big tunnel to the "
        "south of them."
    )
    assert [f.crop for f in scene.fields] == ["Pear", "Banana"]
    assert relations(scene) == {
        ("north_of", "Pear", ("Banana",)),
        ("south_of", "Banana", ("Pear",)),
    }


def test_grass_in_the_scenery_is_not_an_unknown_crop() -> None:
    scene = recipe(
        "Frosty January morning, hoarfrost on the bare branches of the cherry trees, the "
        "grass white underneath and the farmhouse chimney smoking at the back."
    )
    assert [(f.crop, f.season) for f in scene.fields] == [("Cherry", "Winter")]
    for asked in ("a grass field next to wheat", "grass and wheat"):
        with pytest.raises(UnknownCropError, match="grass"):
            recipe(asked)


def test_a_variety_name_before_a_plot_noun_names_the_field() -> None:
    (field,) = recipe("Russet field from the pivot road, plants in full flower").fields
    assert (field.crop, field.variety) == ("Potato", "Russet Burbank")
    (golden,) = recipe("a golden field of wheat").fields  # a colour, with its crop
    assert golden.crop == "Wheat"


def test_a_leading_direction_orders_the_list_after_it() -> None:
    scene = recipe(
        "Along the south fence, going west to east: San Marzano tomatoes first, then the "
        "Jalapenos, then a patch of California Wonder peppers."
    )
    assert [f.variety for f in scene.fields] == ["San Marzano", "Jalapeno", "California Wonder"]
    ids = [f.id for f in scene.fields]
    assert {(r.kind, r.subject, r.objects) for r in scene.relations} == {
        ("west_of", ids[0], (ids[1],)),
        ("west_of", ids[1], (ids[2],)),
        ("between", ids[1], (ids[0], ids[2])),
    }


def test_a_mixed_number_before_a_unit() -> None:
    scene = recipe("one and a half hectares of Conference pears and 2 and a quarter acres of wheat")
    areas = [round(f.geometry.size_m[0] * f.geometry.size_m[1]) for f in scene.fields]
    assert areas == [15000, round(2.25 * 4046.8564224)]


def test_fields_on_opposite_sides_of_a_landmark() -> None:
    scene = recipe(
        "East of the yard there's 2 ha of Gala apples and west of the yard we have one and a "
        "half hectares of Conference pears."
    )
    assert relations(scene) == {("east_of", "Apple", ("Pear",))}
    # one field placed by a building alone is placed by scenery: no relation from it
    lone = recipe("north of the barn an apple orchard, and wheat next to it")
    assert relations(lone) == {("next_to", "Wheat", ("Apple",))}


def test_a_verb_before_a_plot_noun_is_not_an_unknown_crop() -> None:
    scene = recipe(
        "From the farmhouse down to the river it goes vineyard, then a hawthorn hedge, then "
        "salad greens, then a strip of corn by the water."
    )
    assert [f.crop for f in scene.fields][::2] == ["Grape", "Maize"]
    assert scene.fields[1].crop in ("Lettuce", "Cabbage")


def test_descriptions_of_the_plants_are_not_fields() -> None:
    banana = recipe(
        "A banana plantation after the wet season - the leaves are covered in dark "
        "brown-black streaks, looks like Sigatoka, and a few plants have fallen over. "
        "Workers in hats carrying bunches to a trailer."
    )
    assert [(f.crop, f.health) for f in banana.fields] == [("Banana", "Ill")]
    tall = recipe(
        "Ladyfinger bananas with the bunches hanging and the purple flower bells still on "
        "the end, plants about three metres tall, a ute on the dirt track."
    )
    assert [(f.variety, f.stage) for f in tall.fields] == [("Lady Finger", "Reproductive")]
    fruit = recipe(
        "apple trees heavy with red fruit that's colouring up, and the tomatoes in front of "
        "the house with the last fruit ripening."
    )
    assert [(f.crop, f.stage) for f in fruit.fields] == [
        ("Apple", "Maturation"),
        ("Tomato", "Maturation"),
    ]
    # a counted or listed field of plants is still a field
    assert [f.crop for f in recipe("an apple orchard and some pear trees").fields] == [
        "Apple",
        "Pear",
    ]


def test_a_field_named_again_behind_scenery_is_the_same_field() -> None:
    scene = recipe(
        "Agria potatoes on 75 cm ridges beside a field of Red Baron onions. A sprayer is "
        "working in the potatoes and there's a water tower on the horizon."
    )
    assert [f.crop for f in scene.fields] == ["Potato", "Onion"]
    assert scene.fields[0].agronomy.row_spacing_m == pytest.approx(0.75)


def test_what_a_field_says_of_itself_wins_over_all() -> None:
    scene = recipe(
        "Savoy cabbages in the front of the shot, their outer leaves with V-shaped yellow "
        "lesions along the edges, and right next to them a field of Stuttgarter Riesen "
        "onions, all healthy."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Cabbage", "Ill"), ("Onion", "Healthy")]
    # "all over the ridges" is not "all fields"
    two = recipe(
        "spuds with white flowers all over the ridges, and a wheat field gone completely "
        "straw-coloured with the heads drooping"
    )
    assert [(f.crop, f.stage) for f in two.fields] == [
        ("Potato", "Reproductive"),
        ("Wheat", "Maturation"),
    ]


@pytest.mark.parametrize(
    ("prompt", "health"),
    [
        (
            "this lettuce: angular yellow patches on the outer leaves and white fluff underneath",
            "Ill",
        ),
        ("a capsicum plot, leaves dotted with dark spots and scabby patches on the fruit", "Ill"),
        ("tomato plants with dark water-soaked blotches on the leaves", "Ill"),
    ],
)
def test_signs_of_disease_read_as_ill(prompt: str, health: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.health == health


def test_two_fields_next_to_each_other() -> None:
    scene = recipe(
        "comice pears and bartlett pears next to each other, the bartletts r sick w/ fire blight"
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Doyenne du Comice", "Healthy"),
        ("Williams", "Ill"),
    ]
    ids = [f.id for f in scene.fields]
    assert {(r.kind, frozenset((r.subject, *r.objects))) for r in scene.relations} == {
        ("next_to", frozenset(ids))
    }


def test_casual_names_of_crops_and_filler_words() -> None:
    toms = recipe("roma tomatoes & jalapenos side by side, summer, the toms have blight rly bad")
    assert [(f.crop, f.health) for f in toms.fields] == [("Tomato", "Ill"), ("Pepper", "Healthy")]
    vibes = recipe(
        "savoy cabbage, january king cabbage + some chantenay carrots, 3 plots, all in nov, "
        "frosty morning vibes"
    )
    assert [f.crop for f in vibes.fields] == ["Cabbage", "Cabbage", "Carrot"]


def test_numbered_plots_are_labels_not_fields() -> None:
    scene = recipe(
        "Plot 1: Elsanta strawberries, 6 beds, two rows per bed, beds on 1.5 m centres. Plot "
        "2: Romaine lettuce next to it, just planted. Plot 3: Red Baron onions, right next to "
        "the lettuce."
    )
    assert [f.crop for f in scene.fields] == ["Strawberry", "Lettuce", "Onion"]
    assert scene.fields[0].agronomy.rows_per_bed == 2
    assert relations(scene) == {
        ("next_to", "Lettuce", ("Strawberry",)),
        ("next_to", "Onion", ("Lettuce",)),
    }


def test_a_capitalised_variety_name_in_a_list_is_its_crop() -> None:
    scene = recipe("west to east: Lollo, then Imperator carrots, then Stuttgarter Riesen onions")
    first = scene.fields[0]
    assert (first.crop, first.variety) == ("Lettuce", "Lollo Rosso")


def test_a_field_named_twice_is_one_object_of_a_pronoun() -> None:
    scene = recipe(
        "In the valley grove we've got Valencia oranges on the lower terraces and blood "
        "oranges (Moro) to the north of them, everything in flower in March."
    )
    assert [f.variety for f in scene.fields] == ["Valencia", "Moro"]
    ids = [f.id for f in scene.fields]
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("north_of", ids[1], (ids[0],))
    ]


def test_crops_counted_plant_by_plant_and_nothing_sick() -> None:
    (field,) = recipe("Past the pond is the Fontane field, 75 cm ridges, spuds every 33 cm").fields
    assert field.agronomy.in_row_spacing_m == pytest.approx(0.33)
    scene = recipe("crisphead lettuce and Cayenne chillies, each in its own bed, nothing sick")
    assert {f.health for f in scene.fields} == {"Healthy"}


def test_top_and_bottom_fields_with_one_between() -> None:
    scene = recipe(
        "top field is Russet potatos, bottom field Danvers carrots, and the onoins (Sturon) "
        "sit in between them"
    )
    assert [f.crop for f in scene.fields] == ["Potato", "Carrot", "Onion"]
    found = relations(scene)
    assert ("between", "Onion", ("Potato", "Carrot")) in found
    assert ("north_of", "Potato", ("Onion",)) in found


def test_a_label_defined_with_is_and_named_later_in_its_sentence() -> None:
    scene = recipe(
        "Block A is Cabernet, rows 2.5 m apart with a vine every 1.6 m. Block B, just south "
        "of A, is Pinot Noir on the same spacing."
    )
    assert [f.variety for f in scene.fields] == ["Cabernet Sauvignon", "Pinot Noir"]
    ids = [f.id for f in scene.fields]
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("south_of", ids[1], (ids[0],))
    ]
    assert scene.fields[1].agronomy.in_row_spacing_m == 1.6  # "the same spacing"


def test_next_door_and_ripening_fruit() -> None:
    scene = recipe(
        "My neighbour's tomato plants are wilting with dark water-soaked blotches on the "
        "leaves, while our peppers next door look perfectly fine."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Tomato", "Ill"), ("Pepper", "Healthy")]
    assert relations(scene) == {("next_to", "Pepper", ("Tomato",))}
    (bananas,) = recipe("Big Mike bananas, the bunches fat and yellowing, ready to be cut").fields
    assert (bananas.stage, bananas.health) == ("Maturation", "Healthy")
    (vines,) = recipe("a vineyard, the leaves yellowing").fields
    assert vines.health == "Ill"


def test_and_goes_on_describing_the_field_just_described() -> None:
    scene = recipe(
        "a grove of blood oranges south of a banana patch, the oranges colouring up, the "
        "bananas still small and just planted."
    )
    assert [(f.crop, f.stage) for f in scene.fields] == [
        ("Orange", "Maturation"),
        ("Banana", "Vegetative"),
    ]


def test_fields_one_after_another_with_then() -> None:
    scene = recipe(
        "From the farmhouse down to the river it goes vineyard, then a hawthorn hedge, then "
        "salad greens, then a strip of corn by the water."
    )
    vines, greens, corn = (f.id for f in scene.fields)
    found = {(r.kind, r.subject, r.objects) for r in scene.relations}
    assert ("between", greens, (vines, corn)) in found
    tour = recipe(
        "Going round clockwise from the gate you pass the Albion strawberries under their "
        "tunnels, then the Riesling vineyard, and right after it the Chardonnay."
    )
    straw, riesling, chardonnay = (f.id for f in tour.fields)
    pairs = {frozenset((r.subject, *r.objects)) for r in tour.relations if r.kind == "next_to"}
    assert pairs == {frozenset((straw, riesling)), frozenset((riesling, chardonnay))}


def test_a_farmyard_of_scenery_is_not_a_farm_of_fields() -> None:
    with pytest.raises(PromptError):
        recipe(
            "Calibration flight for the drone's RGB and thermal cameras over the farmyard: two "
            "tractors, a feed silo, the gravel track and targets laid out by the shed."
        )


def _relations(scene: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in scene.relations}


def test_a_zone_said_before_its_field_belongs_to_that_field() -> None:
    scene = recipe(
        "Bottom of the farm: popping corn, 5 acres. Above that: Walla Walla onions, 2 acres. "
        "At the top: Chantenay carrots, only just coming up."
    )
    corn, onions, carrots = (f.id for f in scene.fields)
    found = _relations(scene)
    assert ("north_of", onions, (corn,)) in found
    assert ("north_of", carrots, (onions,)) in found
    assert ("north_of", corn, (carrots,)) not in found


def test_a_field_placed_against_the_top_zone_lies_above_the_bottom_one() -> None:
    scene = recipe(
        "Royal Gala along the top hedge, Bartlett pears below them, and down at the bottom "
        "by the ditch a few rows of Granny."
    )
    gala, pears, granny = (f.id for f in scene.fields)
    found = _relations(scene)
    assert ("south_of", pears, (gala,)) in found
    assert ("north_of", pears, (granny,)) in found
    assert ("north_of", gala, (granny,)) in found


def test_between_closes_the_order_of_its_neighbours() -> None:
    scene = recipe(
        "top field is Russet potatos, bottom field Danvers carrots, and the onoins (Sturon) "
        "sit in between them"
    )
    potatoes, carrots, onions = (f.id for f in scene.fields)
    found = _relations(scene)
    assert ("between", onions, (potatoes, carrots)) in found
    assert ("north_of", potatoes, (carrots,)) in found


def test_a_direction_before_beyond_gives_it_its_side() -> None:
    scene = recipe(
        "The orchard is north of the house, it's all Conference pears, and further north "
        "again, beyond the orchard, there's about 3 ha of winter wheat."
    )
    pears, wheat = (f.id for f in scene.fields)
    assert _relations(scene) == {("north_of", wheat, (pears,))}
    beyond = recipe("a pear orchard and beyond it a wheat field")
    assert {r.kind for r in beyond.relations} == {"next_to"}


def test_the_middle_of_left_and_right_is_between_them() -> None:
    scene = recipe(
        "Three blocks visible from the barn roof: Fuji apples on the left, Kordia cherries in "
        "the middle between them and the Durondeau pears on the right, all in full blossom"
    )
    apples, cherries, pears = (f.id for f in scene.fields)
    found = _relations(scene)
    assert ("between", cherries, (apples, pears)) in found
    assert ("west_of", apples, (cherries,)) in found


def test_the_others_take_what_is_said_of_them() -> None:
    scene = recipe(
        "corn, wheat & carrots, 3 fields, make the corn biggest like 5 ha, the others 1 ha each"
    )
    areas = {f.crop: f.geometry.size_m[0] * f.geometry.size_m[1] for f in scene.fields}
    assert areas["Maize"] == pytest.approx(50_000, rel=0.01)
    assert areas["Wheat"] == pytest.approx(10_000, rel=0.01)
    assert areas["Carrot"] == pytest.approx(10_000, rel=0.01)


def test_a_weak_variety_heading_a_list_keeps_its_crop_when_merged() -> None:
    scene = recipe(
        "Market garden, west to east: Lollo, then Imperator carrots, then Stuttgarter Riesen "
        "onions, and a bed of Centenary strawberries at the far eastern end."
    )
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Lettuce", "Lollo Rosso"),
        ("Carrot", "Imperator"),
        ("Onion", "Stuttgarter"),
        ("Strawberry", "Malling Centenary"),
    ]


def test_a_plan_seen_from_above_is_a_viewpoint_not_a_relation() -> None:
    scene = recipe(
        "if you look at the farm plan from above: stone fruit along the top edge, root veg in "
        "the middle strip and grain across the bottom"
    )
    top, middle, bottom = (f.id for f in scene.fields)
    found = _relations(scene)
    assert ("north_of", top, (middle,)) in found and ("north_of", middle, (bottom,)) in found
    assert all(r.subject != middle or r.objects != (top,) for r in scene.relations)


def test_a_rusty_gate_does_not_make_the_plants_ill() -> None:
    scene = recipe(
        "In the picture there's a field of California Wonder peppers with mottled, curled "
        "leaves and a lot of plants wilting, and next to it beef tomatoes staked up on canes "
        "that look perfectly healthy. A blue water tank and a rusty gate in the foreground."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [("Pepper", "Ill"), ("Tomato", "Healthy")]
    assert recipe("a rusty wheat field").fields[0].health == "Ill"


@pytest.mark.parametrize(
    ("prompt", "season"),
    [
        (
            "Our farm near Cairns in Queensland, Australia is basically one 3 ha block of "
            "Grande Naine bananas. It's March and the bunches are ready to cut.",
            "Fall",
        ),
        ("Our vineyard in Chile: Pinot Noir and Chardonnay. It is May.", "Fall"),
        ("a wheat field; it was June", "Summer"),
    ],
)
def test_it_s_march_names_the_month(prompt: str, season: str) -> None:
    assert {f.season for f in recipe(prompt).fields} == {season}


def test_words_about_the_fruit_do_not_end_a_listing_of_members() -> None:
    scene = recipe(
        "Picture of the two apple blocks by the packhouse in October: Granny on the north side, "
        "fruit bright green and ready to pick, and Fuji to the south of it."
    )
    assert [f.variety for f in scene.fields] == ["Granny Smith", "Fuji"]
    granny, fuji = (f.id for f in scene.fields)
    assert ("south_of", fuji, (granny,)) in _relations(scene)


@pytest.mark.parametrize(
    ("prompt", "stage"),
    [
        (
            "we only grow lettuse on the farm, about 0.8 ha, and its starting to bolt",
            "Reproductive",
        ),
        ("in the photo the pasta wheat has full ears turning gold", "Maturation"),
    ],
)
def test_more_visual_cues_of_the_stage(prompt: str, stage: str) -> None:
    assert recipe(prompt).fields[0].stage == stage


def test_a_sized_plot_said_after_its_crop_is_that_crop_s_plot() -> None:
    scene = recipe(
        "All we have planted on our allotment farm is chillies, a 15 by 30 m patch, and some "
        "of the leaves have dark spots."
    )
    assert len(scene.fields) == 1
    chillies = scene.fields[0]
    assert chillies.crop == "Pepper" and chillies.geometry.size_m == (15.0, 30.0)
    two = recipe("carrots, a 20 by 40 m field, next to a potato field")
    carrots = two.fields[0]
    assert (carrots.crop, carrots.geometry.size_m) == ("Carrot", (20.0, 40.0))
    assert len(two.fields) == 2


def test_the_south_one_places_a_member_and_a_pathogen_genus_is_a_disease() -> None:
    scene = recipe(
        "Two carrot fields: Chantenay on the south one, and Imperator north of it, which has "
        "Alternaria on the leaves."
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Chantenay", "Healthy"),
        ("Imperator", "Ill"),
    ]
    chantenay, imperator = (f.id for f in scene.fields)
    assert ("north_of", imperator, (chantenay,)) in _relations(scene)


def test_between_the_two_groves_points_back_at_the_groves() -> None:
    scene = recipe(
        "Wide shot from the footpath: Washington Navel on one side, blood oranges on the other, "
        "and a strip of Jalapeños planted between the two groves. Irrigation pipes everywhere "
        "and the sierra behind."
    )
    assert [f.crop for f in scene.fields] == ["Orange", "Orange", "Pepper"]
    navel, blood, jalapenos = (f.id for f in scene.fields)
    assert ("between", jalapenos, (navel, blood)) in _relations(scene)


def test_two_fields_with_a_third_between_them_are_not_next_to_each_other() -> None:
    scene = recipe(
        "Out by the old well there are San Marzano and beef tomatoes, with a plot of cherry "
        "tomatoes in between them."
    )
    marzano, beef, cherry = (f.id for f in scene.fields)
    assert _relations(scene) == {("between", cherry, (marzano, beef))}


def test_plants_that_have_only_just_gone_in_are_young() -> None:
    scene = recipe(
        "In May the Sonata strawberries are flowering, and next to them the Albion plants have "
        "only just gone in."
    )
    assert [(f.variety, f.stage) for f in scene.fields] == [
        ("Sonata", "Reproductive"),
        ("Albion", "Vegetative"),
    ]


def test_a_definite_plural_heading_is_not_a_count_of_fields() -> None:
    scene = recipe(
        "Quick rundown of the plots. Plot 1: Conference pears, in full blossom, roughly "
        "1.2 ha. Plot 2: Elsanta strawberries, just planted. Plot 3: Savoy cabbage."
    )
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Pear", "Conference"),
        ("Strawberry", "Elsanta"),
        ("Cabbage", "Savoy"),
    ]


@pytest.mark.parametrize(
    "prompt",
    [
        "My allotment in one picture: a strawberry bed with runners everywhere, a patch of "
        "sweetcorn. My neighbour's shed in the corner.",
        "My plot: a strawberry bed and a patch of sweetcorn.",
    ],
)
def test_a_plot_heading_a_list_of_fields_is_not_another_field(prompt: str) -> None:
    assert sorted(f.crop for f in recipe(prompt).fields) == ["Maize", "Strawberry"]


def test_a_plot_before_a_colon_with_one_crop_is_that_crop_s_plot() -> None:
    assert [f.crop for f in recipe("a plot: carrots").fields] == ["Carrot"]


def test_a_member_s_own_cue_is_not_overwritten_by_the_next_member_s_stage() -> None:
    scene = recipe(
        "Inside the polytunnel you can see two crops: cherry tomatoes climbing their strings "
        "with the trusses already red, and Padron peppers along the other side, still only "
        "flowering."
    )
    stages = {f.crop: f.stage for f in scene.fields}
    assert stages == {"Tomato": "Maturation", "Pepper": "Reproductive"}


@pytest.mark.parametrize(
    "prompt",
    [
        "Took this on 20 April in the Jonagold block: every tree is white with blossom.",
        "Jonagold block, April 20, every tree white with blossom",
    ],
)
def test_a_day_of_the_month_is_a_date_not_a_count(prompt: str) -> None:
    scene = recipe(prompt)
    assert [(f.variety, f.season) for f in scene.fields] == [("Jonagold", "Spring")]


def test_a_count_after_a_month_still_counts_fields() -> None:
    assert len(recipe("in June 2 fields of wheat").fields) == 2


def test_a_capitalised_month_inside_a_sentence_is_the_month() -> None:
    scene = recipe("peppers and maize, still tiny. Cloudy May morning.")
    assert {f.season for f in scene.fields} == {"Spring"}
    assert {f.stage for f in scene.fields} == {"Vegetative"}
    assert recipe("May I have a ripe wheat field").fields[0].season != "Spring"


@pytest.mark.parametrize(
    "prompt",
    [
        "Durondeau pears, overcast, a ladder leaning against one of the pear trees.",
        "Conference pears and Kordia cherry trees. A tractor is working one of the pear alleys.",
    ],
)
def test_one_of_the_named_crop_s_plants_is_not_another_field(prompt: str) -> None:
    assert sorted(f.crop for f in recipe(prompt).fields) in (["Pear"], ["Cherry", "Pear"])
    assert len([f for f in recipe(prompt).fields if f.crop == "Pear"]) == 1


def test_one_of_a_crop_after_a_plural_still_adds_a_field() -> None:
    assert len(recipe("two apple orchards and one of cherries").fields) == 3


def test_fruit_of_a_crop_already_named_describes_it() -> None:
    scene = recipe(
        "Dawn in the Navel block, January: the trees are dark green and full of orange fruit "
        "ready for picking."
    )
    assert [(f.variety, f.stage) for f in scene.fields] == [("Navel", "Maturation")]


def test_fruit_after_a_with_list_describes_the_field_before() -> None:
    scene = recipe(
        "Yellow Delicious trees with scab spots on the leaves and corky fruit, and next to "
        "them Durondeau pears."
    )
    assert [f.crop for f in scene.fields] == ["Apple", "Pear"]
    assert recipe("apples and fruit").fields[1].crop != "Apple"  # a list member stays


def test_a_relative_clause_does_not_end_a_listing() -> None:
    scene = recipe(
        "Two blocks side by side, taken late August: Conference pears heavy with fruit that "
        "is just starting to turn yellow, and Kordia cherry trees that were picked weeks ago."
    )
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Pear", "Conference"),
        ("Cherry", "Kordia"),
    ]


@pytest.mark.parametrize(
    ("prompt", "key", "value"),
    [
        (
            "Granny Smith, 40 rows, rows 3.5 m apart with a tree about every metre",
            "in_row_spacing_m",
            1.0,
        ),
        ("Cayenne peppers, plants roughly 18 inches apart", "in_row_spacing_m", 0.4572),
        ("the wheat. The field has a headland about 6 m wide all round.", "headland_m", 6.0),
    ],
)
def test_lengths_said_roughly_are_read(prompt: str, key: str, value: float) -> None:
    field = recipe(prompt).fields[0]
    stated = field.geometry.headland_m if key == "headland_m" else field.agronomy.in_row_spacing_m
    assert stated == pytest.approx(value)


@pytest.mark.parametrize(
    "prompt",
    [
        "Market garden layout, left to right: lettuce first, then potatoes, then tomatoes.",
        "lettuce, then potatoes, then tomatoes going west to east",
        "Going east from the farmhouse you pass lettuce, then potatoes, then tomatoes.",
    ],
)
def test_a_row_in_the_order_named_towards_the_east(prompt: str) -> None:
    assert relations(recipe(prompt)) == {
        ("west_of", "Lettuce", ("Potato",)),
        ("west_of", "Potato", ("Tomato",)),
        ("between", "Potato", ("Lettuce", "Tomato")),
    }


def test_a_field_in_between_the_two_lies_between_them() -> None:
    scene = recipe(
        "San Marzano tomatoes, beefsteak tomatoes, and cherry tomatoes in between the two."
    )
    between = [r for r in scene.relations if r.kind == "between"]
    varieties = {f.id: f.variety for f in scene.fields}
    assert [(varieties[r.subject], {varieties[o] for o in r.objects}) for r in between] == [
        ("Cherry", {"San Marzano", "Beefsteak"})
    ]


def test_top_middle_and_bottom_terraces_are_zones() -> None:
    scene = recipe(
        "Top terrace Riesling, middle terrace Pinot Noir, bottom terrace Chardonnay, all three "
        "with their autumn leaves on."
    )
    varieties = {f.id: f.variety for f in scene.fields}
    north = {
        (varieties[r.subject], varieties[r.objects[0]])
        for r in scene.relations
        if r.kind == "north_of"
    }
    assert {("Riesling", "Pinot Noir"), ("Pinot Noir", "Chardonnay")} <= north
    assert {f.season for f in scene.fields} == {"Fall"}


def test_the_open_field_is_a_plot_not_an_unknown_crop() -> None:
    scene = recipe(
        "Our Belgian farm in February: Elsanta strawberries ripe and ready to pick in the open "
        "field, next to dormant Conference pears."
    )
    assert [f.crop for f in scene.fields] == ["Strawberry", "Pear"]


def test_beds_with_rows_on_each() -> None:
    field = recipe("the Elsanta field: six raised beds, two rows on each").fields[0]
    assert field.agronomy.rows_per_bed == 2


def test_a_weak_variety_name_before_words_about_its_fruit_heads_its_field() -> None:
    scene = recipe(
        "Two strawberry varieties side by side in the picture: Sonata with grey mould furring "
        "the fruit, and Albion clean and bright red."
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Sonata", "Ill"),
        ("Albion", "Healthy"),
    ]


def test_field_by_field_is_how_the_text_goes_not_a_field() -> None:
    scene = recipe(
        "The farm, field by field. Behind the farmhouse there's 3 ha of Conference pears in "
        "full blossom, and east of the pears a block of Jonagold apples."
    )
    assert [f.crop for f in scene.fields] == ["Pear", "Apple"]


def test_the_next_field_over_is_next_to_the_field_before() -> None:
    scene = recipe(
        "the Russet potatoes in Long Meadow have late blight, though the Walla Walla onions in "
        "the next field over look fine."
    )
    assert relations(scene) == {("next_to", "Onion", ("Potato",))}
    assert [f.health for f in scene.fields] == ["Ill", "Healthy"]


def test_when_a_crop_was_sown_is_not_the_season_shown() -> None:
    field = recipe("5 ha of spelt, sown last autumn, still young and green now in March").fields[0]
    assert (field.season, field.stage) == ("Spring", "Vegetative")


def test_zero_spacing_between_them_is_refused() -> None:
    with pytest.raises(PromptError, match="positive"):
        recipe("potato rows with zero spacing between them, ridges touching")


def test_fruit_held_by_scenery_is_not_a_field() -> None:
    scene = recipe(
        "Beefsteak tomatoes with late blight. September, a wheelbarrow full of split fruit."
    )
    assert [f.crop for f in scene.fields] == ["Tomato"]


def test_the_two_tomato_strips_are_the_tomato_fields_named() -> None:
    scene = recipe(
        "Trial strips in the photo: Roma tomatoes, then Padrón peppers, then cherry tomatoes, "
        "the peppers between the two tomato strips, everything in flower."
    )
    assert [f.variety for f in scene.fields] == ["Roma", "Padron", "Cherry"]
    assert relations(scene) == {("between", "Pepper", ("Tomato", "Tomato"))}


@pytest.mark.parametrize("thing", ["scarecrow", "bumblebee"])
def test_a_thing_in_a_named_field_is_not_another_field(thing: str) -> None:
    scene = recipe(f"fruit trees on the left, a veg plot on the right. A {thing} in the veg.")
    assert len(scene.fields) == 2


def test_strips_going_from_west_to_east_are_in_that_order() -> None:
    scene = recipe(
        "Three wheat strips, 12 m by 200 m each, drilled at 12.5, 15 and 20 cm row spacing "
        "going from west to east."
    )
    ids = [f.id for f in scene.fields]
    west = [(r.subject, r.objects) for r in scene.relations if r.kind == "west_of"]
    assert west == [(ids[0], (ids[1],)), (ids[1], (ids[2],))]
    assert [f.agronomy.row_spacing_m for f in scene.fields] == [0.125, 0.15, 0.2]


def test_the_northern_block_said_afterwards() -> None:
    scene = recipe("Two sweet cherry blocks, Kordia and Regina. Kordia is the northern block.")
    varieties = {f.id: f.variety for f in scene.fields}
    assert [(r.kind, varieties[r.subject], varieties[r.objects[0]]) for r in scene.relations] == [
        ("north_of", "Kordia", "Regina")
    ]


def test_a_field_with_one_on_each_side_lies_between_them() -> None:
    scene = recipe(
        "north field is wheat, south field is maize, and in between them a narrow strip of "
        "strawberries"
    )
    assert ("between", "Strawberry", ("Wheat", "Maize")) in relations(scene)


def test_words_after_beside_them_belong_to_the_field_placed() -> None:
    scene = recipe(
        "Fontane potatoes in the big field, and the Danvers carrots beside them have "
        "Alternaria, dark lesions with yellow halos all over the leaves."
    )
    assert [(f.crop, f.health) for f in scene.fields] == [
        ("Potato", "Healthy"),
        ("Carrot", "Ill"),
    ]


def test_a_correction_of_the_plot_word_keeps_the_crop() -> None:
    scene = recipe("the Valencia groove (sorry, grove), with Moro blood oranges right next to it")
    assert [(f.crop, f.variety) for f in scene.fields] == [
        ("Orange", "Valencia"),
        ("Orange", "Moro"),
    ]
    assert [f.crop for f in recipe("a wheat field, sorry, a plot").fields] == ["Wheat"]

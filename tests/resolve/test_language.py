"""The language of issue 3, prompt by prompt, through the whole pipeline (rules and hybrid).

Each case states what the prompt determines; attributes the prompt leaves
open are checked separately (tests/resolve/test_enrich.py).
"""

from __future__ import annotations

from collections import Counter
from typing import Any

import pytest

from agrirecipe.recipe import SceneRecipe
from agrirecipe.resolve import resolve

STRATEGIES = ["rules", "hybrid"]


def _fields(recipe: SceneRecipe) -> list[dict[str, Any]]:
    return [f.model_dump() for f in recipe.fields]


def _has(recipe: SceneRecipe, **expected: Any) -> bool:
    return any(all(f[k] == v for k, v in expected.items()) for f in _fields(recipe))


def _recipe(prompt: str, strategy: str, **options: Any) -> SceneRecipe:
    return resolve(prompt, resolver=strategy, **options).recipe


# --- one or many fields -----------------------------------------------------------


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_single_detailed_field(strategy: str) -> None:
    recipe = _recipe("Generate a healthy Pink Lady apple orchard in summer", strategy)
    assert len(recipe.fields) == 1
    field = recipe.fields[0]
    assert (field.crop, field.variety, field.season, field.health) == (
        "Apple",
        "Pink Lady",
        "Summer",
        "Healthy",
    )
    assert field.asset_path.endswith("SM_Apple_PinkLady_" + field.stage + "_Summer_Healthy")


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_an_orchard_next_to_two_fields_is_three_fields(strategy: str) -> None:
    recipe = _recipe("an apple orchard next to two carrot fields", strategy)
    assert Counter(f.crop for f in recipe.fields) == {"Apple": 1, "Carrot": 2}
    apple = next(f.id for f in recipe.fields if f.crop == "Apple")
    carrots = {f.id for f in recipe.fields if f.crop == "Carrot"}
    assert {(r.kind, r.subject, r.objects[0]) for r in recipe.relations} == {
        ("next_to", apple, c) for c in carrots
    }


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_a_count_with_an_attribute_for_all(strategy: str) -> None:
    recipe = _recipe("three tomato fields with blight", strategy)
    assert [(f.crop, f.health) for f in recipe.fields] == [("Tomato", "Ill")] * 3


@pytest.mark.parametrize(
    "prompt",
    [
        "Two orchards: one of Gala, one of Fuji",
        "two apple orchards, one Gala and the other Fuji",
        "two orchards - Gala and Fuji",
    ],
)
def test_members_of_a_plural_mention(prompt: str) -> None:
    recipe = _recipe(prompt, "rules")
    assert sorted((f.crop, f.variety) for f in recipe.fields) == [
        ("Apple", "Fuji"),
        ("Apple", "Gala"),
    ]


def test_listed_members_after_a_colon() -> None:
    recipe = _recipe("three fields: wheat, maize and potatoes", "rules")
    assert sorted(f.crop for f in recipe.fields) == ["Maize", "Potato", "Wheat"]


def test_ordinal_members() -> None:
    recipe = _recipe(
        "a farm with three fields. The first is Gala apples, the second Elsanta "
        "strawberries and the third Bintje potatoes",
        "rules",
    )
    assert sorted(f.variety for f in recipe.fields) == ["Bintje", "Elsanta", "Gala"]


# --- attributes stated once for all, or per field -------------------------------------


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_attributes_stated_for_all(strategy: str) -> None:
    recipe = _recipe("an apple orchard next to two carrot fields, all in autumn", strategy)
    assert {f.season for f in recipe.fields} == {"Fall"}
    assert all("season" in f.stated for f in recipe.fields)


def test_both_applies_to_both() -> None:
    recipe = _recipe("a pear orchard and a cherry orchard, both diseased", "rules")
    assert [f.health for f in recipe.fields] == ["Ill", "Ill"]


def test_per_field_attributes_stay_with_their_field() -> None:
    recipe = _recipe("ripe apples next to young carrots with blight, in autumn", "rules")
    apple = next(f for f in recipe.fields if f.crop == "Apple")
    carrot = next(f for f in recipe.fields if f.crop == "Carrot")
    assert (apple.stage, apple.health) == ("Maturation", "Healthy")
    assert (carrot.stage, carrot.health) == ("Vegetative", "Ill")
    assert apple.season == carrot.season == "Fall"


def test_a_trailing_attribute_covers_coordinated_fields() -> None:
    recipe = _recipe("bananas and oranges, ripe", "rules")
    assert [f.stage for f in recipe.fields] == ["Maturation", "Maturation"]


def test_a_later_mention_of_the_same_field_adds_to_it() -> None:
    recipe = _recipe(
        "a granny smith orchard when the apples are ripe in autumn. the trees have scab.",
        "rules",
    )
    assert len(recipe.fields) == 1
    field = recipe.fields[0]
    assert (field.variety, field.stage, field.season, field.health) == (
        "Granny Smith",
        "Maturation",
        "Fall",
        "Ill",
    )


def test_a_restated_variety_narrows_the_field() -> None:
    recipe = _recipe("a carrot field, nantes variety, plants still young, spring time", "rules")
    assert [(f.variety, f.stage, f.season) for f in recipe.fields] == [
        ("Nantes", "Vegetative", "Spring")
    ]


def test_a_correction_replaces_the_field_before_it() -> None:
    recipe = _recipe("cherry tomatoes? no, I mean cherry trees, Regina, in bloom", "rules")
    assert [(f.crop, f.variety, f.stage) for f in recipe.fields] == [
        ("Cherry", "Regina", "Reproductive")
    ]


# --- generic requests ------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_some_fruit_and_vegetable_fields(seed: int) -> None:
    recipe = _recipe("some fruit and vegetable fields", "rules", seed=seed)
    assert sorted(f.category for f in recipe.fields) == ["Fruits", "Vegetables"]
    assert all("crop" in f.inferred and "category" in f.stated for f in recipe.fields)


@pytest.mark.parametrize("seed", range(6))
def test_three_different_vegetables(seed: int) -> None:
    recipe = _recipe("a mixed farm with three different vegetables", "rules", seed=seed)
    assert [f.category for f in recipe.fields] == ["Vegetables"] * 3
    assert len({f.crop for f in recipe.fields}) == 3


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("three different fruit crops, one of them apples", None),
        ("two different fruits: Gala and Fuji", ["Apple", "Apple"]),
        ("three different vegetables: carrots, potatoes and tomatoes", None),
    ],
)
def test_different_crops_that_are_different(prompt: str, crops: list[str] | None) -> None:
    recipe = _recipe(prompt, "rules")
    if crops is None:  # different crops
        assert len({f.crop for f in recipe.fields}) == len(recipe.fields) == 3
    else:  # the same crop, told apart by the varieties named
        assert [f.crop for f in recipe.fields] == crops
        assert len({f.variety for f in recipe.fields}) == 2


@pytest.mark.parametrize("strategy", STRATEGIES)
@pytest.mark.parametrize("seed", range(3))
def test_different_fields_of_one_crop_get_different_varieties(strategy: str, seed: int) -> None:
    recipe = _recipe("three different potato fields, one of them Bintje", strategy, seed=seed)
    assert [f.crop for f in recipe.fields] == ["Potato"] * 3
    assert len({f.variety for f in recipe.fields}) == 3
    assert "Bintje" in {f.variety for f in recipe.fields}
    assert sum("variety" in f.inferred for f in recipe.fields) == 2
    apples = _recipe("two different apple orchards", strategy, seed=seed)
    assert len({f.variety for f in apples.fields}) == 2


def test_too_many_different_crops_is_an_error() -> None:
    from agrirecipe import PromptError

    with pytest.raises(PromptError, match="different cereals"):
        resolve("five different cereals", resolver="rules")


@pytest.mark.parametrize("seed", range(6))
def test_an_orchard_and_a_cereal_field(seed: int) -> None:
    recipe = _recipe("an orchard and a cereal field", "rules", seed=seed)
    orchard, cereal = recipe.fields
    assert orchard.crop in {"Apple", "Pear", "Cherry", "Orange"}
    assert cereal.category == "Cereals"


def test_a_vineyard_is_grapes() -> None:
    recipe = _recipe("a vineyard", "rules")
    assert recipe.fields[0].crop == "Grape"
    assert "crop" in recipe.fields[0].stated


def test_other_means_different_from_the_named_crop() -> None:
    for seed in range(5):
        recipe = _recipe("an apple orchard and two other orchards", "rules", seed=seed)
        assert len({f.crop for f in recipe.fields}) == 3


def test_generic_choice_follows_the_seed() -> None:
    crops = {
        tuple(f.crop for f in _recipe("three vegetable fields", "rules", seed=s).fields)
        for s in range(12)
    }
    assert len(crops) > 1  # the seed changes the choice...
    again = _recipe("three vegetable fields", "rules", seed=3)
    assert tuple(f.crop for f in again.fields) in crops  # ...and the same seed repeats it


def test_generic_choice_prefers_crops_plausible_in_the_season() -> None:
    for seed in range(10):
        recipe = _recipe("a vegetable field in winter", "rules", seed=seed)
        field = recipe.fields[0]
        assert field.crop not in {"Lettuce", "Tomato", "Pepper"}  # not grown outdoors in winter
        assert not recipe.warnings


# --- stage, season and health vocabulary -------------------------------------------------


@pytest.mark.parametrize(
    ("words", "stage"),
    [
        ("seedling", "Vegetative"),
        ("young", "Vegetative"),
        ("early stage", "Vegetative"),
        ("just planted", "Vegetative"),
        ("flowering", "Reproductive"),
        ("in bloom", "Reproductive"),
        ("blossoming", "Reproductive"),
        ("at fruit set", "Reproductive"),
        ("ripe", "Maturation"),
        ("harvest-ready", "Maturation"),
        ("at harvest", "Maturation"),
        ("mature", "Maturation"),
    ],
)
def test_stage_words(words: str, stage: str) -> None:
    recipe = _recipe(f"a Gala apple orchard, {words}", "rules")
    assert recipe.fields[0].stage == stage
    assert "stage" in recipe.fields[0].stated


def test_tasseling_maize() -> None:
    assert _recipe("sweetcorn tasselling in july", "rules").fields[0].stage == "Reproductive"


@pytest.mark.parametrize(
    "prompt",
    [
        "Fontane potatoes with late blight, canopy growing in summer",
        "winter wheat at stem elongation",
        "Butterhead lettuce at the rosette stage",
        "maize germinating in May",
    ],
)
def test_growth_stage_scale_words_are_vegetative(prompt: str) -> None:
    assert _recipe(prompt, "rules").fields[0].stage == "Vegetative"


@pytest.mark.parametrize(
    ("words", "season"),
    [
        ("in autumn", "Fall"),
        ("in the fall", "Fall"),
        ("in late summer", "Summer"),
        ("in mid-winter", "Winter"),
        ("in springtime", "Spring"),
        ("in March", "Spring"),
        ("in early June", "Summer"),
        ("in October", "Fall"),
        ("in December", "Winter"),
    ],
)
def test_season_words_and_months(words: str, season: str) -> None:
    assert _recipe(f"a wheat field {words}", "rules").fields[0].season == season


@pytest.mark.parametrize(
    ("place", "season", "hemisphere"),
    [
        ("in Chile", "Fall", "south"),
        ("in the southern hemisphere", "Fall", "south"),
        ("in New Zealand", "Fall", "south"),
        ("at 35°S", "Fall", "south"),
        ("in Belgium", "Spring", "north"),
    ],
)
def test_months_follow_the_hemisphere(place: str, season: str, hemisphere: str) -> None:
    recipe = _recipe(f"an apple orchard in April {place}", "rules")
    assert recipe.fields[0].season == season
    assert recipe.environment.hemisphere == hemisphere


def test_a_negative_latitude_argument_flips_months() -> None:
    recipe = _recipe("apples in July", "rules", latitude_deg=-33.9)
    assert recipe.fields[0].season == "Winter"
    assert recipe.environment.latitude_deg == -33.9


@pytest.mark.parametrize(
    ("words", "health"),
    [
        ("diseased", "Ill"),
        ("infected", "Ill"),
        ("blighted", "Ill"),
        ("with scab", "Ill"),
        ("sick", "Ill"),
        ("unhealthy", "Ill"),
        ("rotting", "Ill"),
        ("with fire blight", "Ill"),
        ("healthy", "Healthy"),
        ("vigorous", "Healthy"),
        ("with no disease", "Healthy"),
        ("free of scab", "Healthy"),
        ("disease-free", "Healthy"),
    ],
)
def test_health_words(words: str, health: str) -> None:
    recipe = _recipe(f"a Conference pear orchard, {words}", "rules")
    assert recipe.fields[0].health == health
    assert "health" in recipe.fields[0].stated


def test_disease_names_from_the_knowledge_base_mean_ill() -> None:
    recipe = _recipe("a cavendish banana plantation with black sigatoka", "rules")
    assert recipe.fields[0].health == "Ill"


# --- aliases, trade names, typos, accents, case ------------------------------------------


@pytest.mark.parametrize(
    ("prompt", "crop", "variety"),
    [
        ("Cripps Pink apples", "Apple", "Pink Lady"),
        ("Bartlett pears", "Pear", "Williams"),
        ("blood oranges", "Orange", "Moro"),
        ("a field of spuds", "Potato", None),
        ("sweetcorn", "Maize", "Sweet Corn"),
        ("Doyenné du Comice pears", "Pear", "Doyenne du Comice"),
        ("DOYENNE DU COMICE PEARS", "Pear", "Doyenne du Comice"),
        ("jalapeño peppers", "Pepper", "Jalapeno"),
        ("Spätburgunder vines", "Grape", "Pinot Noir"),
        ("a Pink Lday apple orchad", "Apple", "Pink Lady"),
        ("an appel orchard", "Apple", None),
        ("tomatos with blight", "Tomato", None),
        ("nantes carots", "Carrot", "Nantes"),
        ("golden delicous apples", "Apple", "Golden Delicious"),
        ("cabernet sauvingon vineyard", "Grape", "Cabernet Sauvignon"),
        ("strawbery field", "Strawberry", None),
    ],
)
@pytest.mark.parametrize("strategy", STRATEGIES)
def test_names_aliases_typos_accents(
    prompt: str, crop: str, variety: str | None, strategy: str
) -> None:
    recipe = _recipe(prompt, strategy)
    assert len(recipe.fields) == 1
    assert recipe.fields[0].crop == crop
    if variety is not None:
        assert recipe.fields[0].variety == variety


def test_a_typo_is_explained() -> None:
    resolution = resolve("an appel orchard", resolver="rules", explain=True)
    assert resolution.explanation is not None
    text = resolution.explanation.render()
    assert "appel" in text and "'apple'" in text and "fuzzy" in text


# --- words that belong to two places ---------------------------------------------------------


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_cherry_tomatoes_are_tomatoes(strategy: str) -> None:
    recipe = _recipe("a field of cherry tomatoes", strategy)
    assert [(f.crop, f.variety) for f in recipe.fields] == [("Tomato", "Cherry")]


def test_cherries_are_the_cherry_crop() -> None:
    assert _recipe("a cherry orchard", "rules").fields[0].crop == "Cherry"


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_winter_wheat_in_spring(strategy: str) -> None:
    field = _recipe("winter wheat in spring", strategy).fields[0]
    assert (field.crop, field.variety, field.season) == ("Wheat", "Winter Wheat", "Spring")


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_golden_acre_beside_golden_delicious(strategy: str) -> None:
    recipe = _recipe("Golden Acre cabbage beside Golden Delicious apples", strategy)
    assert [(f.crop, f.variety) for f in recipe.fields] == [
        ("Cabbage", "Golden Acre"),
        ("Apple", "Golden Delicious"),
    ]
    assert [r.kind for r in recipe.relations] == ["next_to"]


def test_a_weak_name_needs_its_crop() -> None:
    recipe = _recipe("a carrot field in golden autumn light", "rules")
    assert [(f.crop, f.variety) for f in recipe.fields] == [("Carrot", "Nantes")]
    assert _recipe("navel oranges", "rules").fields[0].variety == "Navel"


def test_shared_head_distributes() -> None:
    recipe = _recipe("navel and valencia orange groves, the navels have greening", "rules")
    assert sorted((f.variety, f.health) for f in recipe.fields) == [
        ("Navel", "Ill"),
        ("Valencia", "Healthy"),
    ]


# --- sizes and relations ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("prompt", "area_m2"),
    [
        ("a 2 ha orchard", 20_000.0),
        ("a 2-hectare apple orchard", 20_000.0),
        ("half a hectare of carrots", 5_000.0),
        ("1 acre of potatoes", 4_046.86),
        ("an onion field of 5000 m2", 5_000.0),
        ("an onion field of 5,000 m²", 5_000.0),
    ],
)
def test_areas(prompt: str, area_m2: float) -> None:
    field = _recipe(prompt, "rules").fields[0]
    assert field.geometry.area_m2 == pytest.approx(area_m2, rel=0.01)
    assert "size" in field.stated


@pytest.mark.parametrize(
    "prompt",
    [
        "a 50 by 100 m carrot field",
        "a carrot field of 50x100m",
        "a carrot field 50 m wide and 100 m long",
    ],
)
def test_rectangles(prompt: str) -> None:
    assert _recipe(prompt, "rules").fields[0].geometry.size_m == (50.0, 100.0)


def test_feet_are_converted() -> None:
    size = _recipe("a 100 by 200 ft lettuce patch", "rules").fields[0].geometry.size_m
    assert size == pytest.approx((30.48, 60.96))


@pytest.mark.parametrize(
    ("prompt", "kind"),
    [
        ("a wheat field north of an apple orchard", "north_of"),
        ("a wheat field to the south of an apple orchard", "south_of"),
        ("a wheat field east of an apple orchard", "east_of"),
        ("a wheat field west of an apple orchard", "west_of"),
        ("a wheat field next to an apple orchard", "next_to"),
        ("a wheat field beside an apple orchard", "next_to"),
        ("a wheat field adjacent to an apple orchard", "next_to"),
    ],
)
def test_relations(prompt: str, kind: str) -> None:
    recipe = _recipe(prompt, "rules")
    wheat = next(f for f in recipe.fields if f.crop == "Wheat")
    apple = next(f for f in recipe.fields if f.crop == "Apple")
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        (kind, wheat.id, (apple.id,))
    ]
    if kind == "north_of":
        assert wheat.geometry.origin_m[1] >= apple.geometry.origin_m[1] + apple.geometry.size_m[1]


def test_between() -> None:
    recipe = _recipe("a wheat field between an apple orchard and a pear orchard", "rules")
    wheat, apple, pear = recipe.fields
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        ("between", wheat.id, (apple.id, pear.id))
    ]


def test_between_two_members_of_one_mention() -> None:
    recipe = _recipe("elsanta strawberries between two fields of iceberg lettuce", "rules")
    lettuce = [f.id for f in recipe.fields if f.crop == "Lettuce"]
    assert [(r.kind, r.objects) for r in recipe.relations] == [("between", tuple(lettuce))]


def test_a_trailing_direction() -> None:
    recipe = _recipe("Fuji apples with a Red Baron onion field to the north", "rules")
    apple = next(f for f in recipe.fields if f.crop == "Apple")
    onion = next(f for f in recipe.fields if f.crop == "Onion")
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        ("north_of", onion.id, (apple.id,))
    ]


def test_a_relation_to_something_that_is_not_a_field_is_dropped_with_a_warning() -> None:
    recipe = _recipe("an apple orchard next to a parking lot", "rules")
    assert len(recipe.fields) == 1
    assert recipe.relations == ()
    assert any("parking lot" in w for w in recipe.warnings)


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_the_fields_of_one_mention_side_by_side_are_a_row(strategy: str) -> None:
    recipe = _recipe("Give me two different fruits side by side, summer", strategy)
    first, second = (f.id for f in recipe.fields)
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        ("next_to", second, (first,))
    ]
    three = _recipe("three carrot fields next to each other", strategy)
    ids = [f.id for f in three.fields]
    assert {(r.subject, r.objects[0]) for r in three.relations} == {
        (ids[1], ids[0]),
        (ids[2], ids[1]),
    }


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_the_fruit_of_named_fields_is_not_a_fruit_field(strategy: str) -> None:
    recipe = _recipe(
        "San Marzano and Roma tomatoes in January in the southern hemisphere, fruit ripe",
        strategy,
    )
    assert [(f.variety, f.stage, f.season) for f in recipe.fields] == [
        ("San Marzano", "Maturation", "Summer"),
        ("Roma", "Maturation", "Summer"),
    ]
    peppers = _recipe("jalapenos, fruits ready to pick", strategy)
    assert [(f.crop, f.stage) for f in peppers.fields] == [("Pepper", "Maturation")]
    # a field of fruit after another field is still a field of its own
    mixed = _recipe("a wheat field, some fruit, ripe", strategy)
    assert [f.category for f in mixed.fields] == ["Cereals", "Fruits"]
    trees = _recipe("a wheat field, fruit trees in bloom", strategy)
    assert trees.fields[0].crop == "Wheat"
    assert trees.fields[1].crop in {"Apple", "Pear", "Cherry", "Orange"}


def test_a_list_side_by_side_is_a_row() -> None:
    recipe = _recipe("potatoes, onions and cabbages side by side in September", "rules")
    potato, onion, cabbage = (f.id for f in recipe.fields)
    assert {(r.subject, r.objects[0]) for r in recipe.relations if r.kind == "next_to"} == {
        (potato, onion),
        (onion, cabbage),
    }
    # the middle one of three side by side lies between the other two
    assert [(r.subject, set(r.objects)) for r in recipe.relations if r.kind == "between"] == [
        (onion, {potato, cabbage})
    ]


@pytest.mark.parametrize(
    ("prompt", "kind"),
    [
        ("two fields of Fontane potatoes and between them a field of spelt", "between"),
        ("two potato fields and north of them a wheat field", "north_of"),
    ],
)
def test_a_pronoun_points_back(prompt: str, kind: str) -> None:
    recipe = _recipe(prompt, "rules")
    wheat = next(f.id for f in recipe.fields if f.crop == "Wheat")
    potatoes = {f.id for f in recipe.fields if f.crop == "Potato"}
    assert {r.kind for r in recipe.relations} == {kind}
    assert all(r.subject == wheat and set(r.objects) <= potatoes for r in recipe.relations)


def test_one_scene_one_season_when_only_stages_are_stated() -> None:
    recipe = _recipe("ripe cherries next to young carrots", "rules")
    assert len({f.season for f in recipe.fields}) == 1
    assert not recipe.warnings


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("carrot fields", 2),
        ("apple orchards and a carrot field", 3),
        ("apple trees", 1),
        ("tomato plants with blight", 1),
        ("Riesling and Pinot Noir vineyards", 2),
        ("some fruit and vegetable fields", 2),
        ("a banana plantation, mature plants", 1),
    ],
)
def test_plural_fields_and_plural_plants(prompt: str, count: int) -> None:
    assert len(_recipe(prompt, "rules").fields) == count


def test_a_season_said_once_holds_for_the_scene() -> None:
    recipe = _recipe("2 Gala apple orchards and 3 fields of Bintje potatoes in autumn", "rules")
    assert {(f.season, "season" in f.stated) for f in recipe.fields} == {("Fall", True)}


def test_between_them_after_both_are_named() -> None:
    recipe = _recipe("a couple of wheat fields and a maize field in between them", "rules")
    maize = next(f.id for f in recipe.fields if f.crop == "Maize")
    wheat = tuple(f.id for f in recipe.fields if f.crop == "Wheat")
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [("between", maize, wheat)]


def test_some_of_them_is_part_of_the_members() -> None:
    recipe = _recipe("four fields of different vegetables, some of them diseased", "rules")
    assert sorted(f.health for f in recipe.fields) == ["Healthy", "Healthy", "Ill", "Ill"]


@pytest.mark.parametrize(
    ("prompt", "count"),
    [("lots of grapes", 1), ("several vegetable fields", 3), ("a few vegetables", 3)],
)
def test_vague_amounts_count_fields_not_plants(prompt: str, count: int) -> None:
    assert len(_recipe(prompt, "rules").fields) == count


def test_a_listed_plural_is_shared() -> None:
    recipe = _recipe("orchards with apple, pear and cherry trees", "rules")
    assert [f.crop for f in recipe.fields] == ["Apple", "Pear", "Cherry"]


@pytest.mark.parametrize(
    ("prompt", "count"),
    [("carrots in 3 fields", 3), ("an orchard with 200 apple trees", 1)],
)
def test_numbers_count_fields_not_plants(prompt: str, count: int) -> None:
    assert len(_recipe(prompt, "rules").fields) == count


def test_plants_name_the_field_after_its_crop() -> None:
    recipe = _recipe("young lettuce plants (romaine)", "rules")
    assert [(f.id, f.variety) for f in recipe.fields] == [("lettuce_field_1", "Romaine")]


# --- a counted share of a plural mention ------------------------------------------


@pytest.mark.parametrize(
    "prompt",
    [
        "please make 4 fields of potatoes, two of them infected with late blight",
        "four potato fields, 2 of which are blighted",
        "four potato fields, two of them diseased and the others healthy",
    ],
)
def test_n_of_them_refines_exactly_n_members(prompt: str) -> None:
    recipe = _recipe(prompt, "rules")
    assert [f.crop for f in recipe.fields] == ["Potato"] * 4
    assert Counter(f.health for f in recipe.fields) == {"Ill": 2, "Healthy": 2}


def test_one_of_them_refines_one_member() -> None:
    intent = resolve("three tomato fields, one of them flowering", resolver="rules").intent
    assert [f.crop for f in intent.fields] == ["Tomato"] * 3
    assert [f.stage for f in intent.fields] == ["Reproductive", None, None]


def test_the_rest_keep_what_is_said_for_all() -> None:
    recipe = _recipe("five young carrot fields, three of which are diseased", "rules")
    assert Counter(f.health for f in recipe.fields) == {"Ill": 3, "Healthy": 2}
    assert {f.stage for f in recipe.fields} == {"Vegetative"}


# --- a colour names the variety whose name says it -----------------------------------


@pytest.mark.parametrize(
    ("prompt", "crop", "variety"),
    [
        (
            "a blossoming cherry orchard (Kordia) east of a field of red onions",
            "Onion",
            "Red Baron",
        ),
        ("a red cabbage field", "Cabbage", "Red Express"),
        ("a bed of red lettuce", "Lettuce", "Lollo Rosso"),
        ("a grove of red oranges", "Orange", "Moro"),
        ("yellow apples", "Apple", "Golden Delicious"),
    ],
)
def test_a_colour_selects_the_variety_named_for_it(prompt: str, crop: str, variety: str) -> None:
    assert _has(_recipe(prompt, "rules"), crop=crop, variety=variety)


def test_a_colour_no_variety_is_named_for_leaves_the_variety_open() -> None:
    intent = resolve("a field of red apples", resolver="rules").intent
    assert [(f.crop, f.variety) for f in intent.fields] == [("Apple", None)]


# --- fields placed by a trailing direction ----------------------------------------------


def _relations(recipe: SceneRecipe) -> set[tuple[str, str, tuple[str, ...]]]:
    crop = {f.id: f.crop for f in recipe.fields}
    return {(r.kind, crop[r.subject], tuple(crop[o] for o in r.objects)) for r in recipe.relations}


def test_opposite_placements_relate_to_each_other() -> None:
    recipe = _recipe("wheat to the north, maize to the south", "rules")
    assert _relations(recipe) == {("north_of", "Wheat", ("Maize",))}


def test_placements_around_a_field_between_them() -> None:
    recipe = _recipe(
        "A farm: wheat to the north, maize to the south and a strawberry patch between them",
        "rules",
    )
    assert _relations(recipe) == {
        ("north_of", "Wheat", ("Strawberry",)),
        ("south_of", "Maize", ("Strawberry",)),
        ("between", "Strawberry", ("Wheat", "Maize")),
        ("north_of", "Wheat", ("Maize",)),  # implied: the order is closed over "between"
    }


def test_placements_around_a_field_named_first() -> None:
    recipe = _recipe("an apple orchard, wheat to the north and maize to the south", "rules")
    assert _relations(recipe) == {
        ("north_of", "Wheat", ("Apple",)),
        ("south_of", "Maize", ("Apple",)),
        ("between", "Apple", ("Wheat", "Maize")),  # implied: one on each side
        ("north_of", "Wheat", ("Maize",)),  # implied: the order is closed over "between"
    }


def test_between_them_after_three_fields() -> None:
    recipe = _recipe("wheat, maize and a strawberry patch between them", "rules")
    assert _relations(recipe) == {("between", "Strawberry", ("Wheat", "Maize"))}


# --- generalisation fixes found by the blind held-out set 2 -----------------------------


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_a_variety_named_again_is_the_same_field(strategy: str) -> None:
    recipe = _recipe(
        "imperator and danvers carrots, 100 m x 25 m each, imperator north of danvers",
        strategy,
    )
    imperator, danvers = recipe.fields
    assert (imperator.variety, danvers.variety) == ("Imperator", "Danvers")
    assert [(r.kind, r.subject, r.objects) for r in recipe.relations] == [
        ("north_of", imperator.id, (danvers.id,))
    ]
    # a definite back-reference keeps the relation's direction
    named = _recipe("Gala and Fuji apples, the Gala north of the Fuji", strategy)
    gala, fuji = named.fields
    assert [(r.kind, r.subject, r.objects) for r in named.relations] == [
        ("north_of", gala.id, (fuji.id,))
    ]
    # the same variety on both sides of a relation is two fields
    twice = _recipe("Valencia oranges next to Valencia oranges", strategy)
    assert [f.variety for f in twice.fields] == ["Valencia", "Valencia"]
    assert len(twice.relations) == 1


def test_an_orchard_with_a_field_of_another_crop_is_two_fields() -> None:
    recipe = _recipe("a 2 ha orchard with a potato field to the west of it", "rules")
    orchard, potatoes = recipe.fields
    assert orchard.crop in {"Apple", "Pear", "Cherry", "Orange"}
    assert potatoes.crop == "Potato"
    assert orchard.geometry.size_m[0] * orchard.geometry.size_m[1] == pytest.approx(20000, 0.01)
    assert [(r.kind, r.subject) for r in recipe.relations] == [("west_of", potatoes.id)]


@pytest.mark.parametrize(
    ("prompt", "latitude"),
    [
        ("a Cripps Pink block ready to pick, march, hawke's bay NZ", -39.6),
        ("a Gala orchard in NZ in march", -41.0),
        ("Golden Delicious in South Tyrol in October", 46.6),
        ("blood oranges near Valencia in april", 39.5),
        ("give us a potato field", 50.8),  # "us" is not the United States
    ],
)
def test_places_and_their_abbreviations(prompt: str, latitude: float) -> None:
    recipe = _recipe(prompt, "rules")
    assert recipe.environment.latitude_deg == latitude
    if latitude < 0:
        assert recipe.fields[0].season == "Fall"  # March in the south


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "for the conference demo tomorrow: comice pears in blossom",
            [("Pear", "Doyenne du Comice")],
        ),
        ("a Conference orchard", [("Pear", "Conference")]),
        ("conference pears", [("Pear", "Conference")]),
    ],
)
def test_a_variety_that_is_an_everyday_word_needs_its_crop_or_plot(
    prompt: str, expected: list[tuple[str, str]]
) -> None:
    assert [(f.crop, f.variety) for f in _recipe(prompt, "rules").fields] == expected


def test_a_weak_month_alone_between_commas_is_a_month() -> None:
    recipe = _recipe("Agria potatoes north of a field of Elsanta strawberries, may", "rules")
    assert {f.season for f in recipe.fields} == {"Spring"}
    assert _recipe("apples. May I have them ripe?", "rules").fields[0].season == "Fall"


@pytest.mark.parametrize(
    ("prompt", "crop", "stage"),
    [
        (
            "san marzano tomatos with blight, fruit ripening on the vine, agust",
            "Tomato",
            "Maturation",
        ),
        ("Young strawberry plants on raised beds", "Strawberry", "Vegetative"),
        ("vine-ripened tomatoes", "Tomato", "Maturation"),
    ],
)
def test_where_the_fruit_hangs_is_not_a_field(prompt: str, crop: str, stage: str) -> None:
    recipe = _recipe(prompt, "rules")
    assert [(f.crop, f.stage) for f in recipe.fields] == [(crop, stage)]


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_fields_on_either_side_and_in_the_middle(strategy: str) -> None:
    flanked = _recipe(
        "ripe Durondeau and Williams pears on either side of a Jonagored block", strategy
    )
    durondeau, williams, jonagold = (f.id for f in flanked.fields)
    assert [(r.kind, r.subject, r.objects) for r in flanked.relations] == [
        ("between", jonagold, (durondeau, williams))
    ]
    each = _recipe("a vineyard with a strawberry field on each side, both of them ripe", strategy)
    assert [f.crop for f in each.fields] == ["Grape", "Strawberry", "Strawberry"]
    vineyard, first, second = (f.id for f in each.fields)
    assert [(r.kind, r.subject, r.objects) for r in each.relations] == [
        ("between", vineyard, (first, second))
    ]
    assert [f.stage for f in each.fields[1:]] == ["Maturation", "Maturation"]
    middle = _recipe(
        "walla walla onions, red express cabbage and beef tomatoes, put the tomatoes in the middle",
        strategy,
    )
    onions, cabbage, tomatoes = (f.id for f in middle.fields)
    assert [(r.kind, r.subject, r.objects) for r in middle.relations] == [
        ("between", tomatoes, (onions, cabbage))
    ]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        # a plural crop followed by its varieties lists its members
        (
            "two beds of lettuce, lolo rosso and bibb, both bolting; the bibb one has downy mildew",
            [("Lollo Rosso", "Healthy"), ("Butterhead", "Ill")],
        ),
        (
            "two wheat fields, a spring wheat one and a dinkel one",
            [("Spring Wheat", "Healthy"), ("Spelt", "Healthy")],
        ),
        # a definite back-reference finds a listed member
        (
            "three fields: russet potatoes, chantenay carrots and sturon onions, "
            "the carrots have some leaf blight",
            [("Russet Burbank", "Healthy"), ("Chantenay", "Ill"), ("Sturon", "Healthy")],
        ),
    ],
)
def test_members_named_after_a_plural(prompt: str, expected: list[tuple[str, str]]) -> None:
    assert [(f.variety, f.health) for f in _recipe(prompt, "rules").fields] == expected


def test_one_of_a_crop_after_a_full_plural_is_one_more_field() -> None:
    assert len(_recipe("three fields of sweet peppers and one of chillies", "rules").fields) == 4
    listed = _recipe("two apple orchards, one of Gala and one of Fuji", "rules")
    assert [f.variety for f in listed.fields] == ["Gala", "Fuji"]


@pytest.mark.parametrize(
    ("prompt", "stages"),
    [
        ("harvest-ready maize and wheat in january", ["Maturation", "Maturation"]),
        ("young carrots and potatoes", ["Vegetative", "Vegetative"]),
        ("young carrots and potatoes in bloom", ["Vegetative", "Reproductive"]),
    ],
)
def test_a_leading_stage_describes_a_list_of_bare_crops(prompt: str, stages: list[str]) -> None:
    assert [f.stage for f in _recipe(prompt, "rules").fields] == stages


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_adjacent_fields_and_borders(strategy: str) -> None:
    row = _recipe("Create three adjacent fields: wheat, maize, potatoes. Summer.", strategy)
    wheat, maize, potatoes = (f.id for f in row.fields)
    assert {(r.kind, r.subject, r.objects) for r in row.relations} == {
        ("next_to", maize, (wheat,)),
        ("next_to", potatoes, (maize,)),
    }
    bordered = _recipe("a pear orchard bordered on the east by a carrot field", strategy)
    pears, carrots = (f.id for f in bordered.fields)
    assert [(r.kind, r.subject, r.objects) for r in bordered.relations] == [
        ("west_of", pears, (carrots,))
    ]


def test_onions_drying_down_are_mature_not_dying() -> None:
    onions = _recipe("onions (red baron) drying down in the field, august", "rules").fields[0]
    assert (onions.variety, onions.stage, onions.health) == ("Red Baron", "Maturation", "Healthy")


# --- generalisation fixes found by the blind held-out set 3 -----------------------------


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        ("grains and veggies: two of each", ["Cereals", "Cereals", "Vegetables", "Vegetables"]),
        ("carrots and onions, two each", ["Vegetables"] * 4),
        ("a handful of grain fields, autumn", ["Cereals"] * 3),
    ],
)
def test_counts_said_for_a_list(prompt: str, expected: list[str]) -> None:
    assert [f.category for f in _recipe(prompt, "rules").fields] == expected


def test_each_a_different_crop_after_a_count() -> None:
    recipe = _recipe("five fields, each a different crop", "rules")
    assert len(recipe.fields) == 5 and len({f.crop for f in recipe.fields}) == 5


def test_both_after_the_last_field_describes_every_field() -> None:
    recipe = _recipe("cherry trees and apple trees both carrying ripe fruit in february", "rules")
    assert [(f.crop, f.stage, f.season) for f in recipe.fields] == [
        ("Cherry", "Maturation", "Winter"),
        ("Apple", "Maturation", "Winter"),
    ]


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_sides_and_the_middle_of_counted_fields(strategy: str) -> None:
    middle = _recipe("two potato fields and one carrot field, carrots in the middle", strategy)
    first, second, carrots = (f.id for f in middle.fields)
    assert [(r.kind, r.subject, r.objects) for r in middle.relations] == [
        ("between", carrots, (first, second))
    ]
    side = _recipe(
        "a golden delicious block of 2 hectares with golden acre cabbages along its south side",
        strategy,
    )
    apples, cabbage = (f.id for f in side.fields)
    assert [(r.kind, r.subject, r.objects) for r in side.relations] == [
        ("south_of", cabbage, (apples,))
    ]
    each = _recipe(
        "fontane and agria potatoes, one field each, agria on the west side, both with late blight",
        strategy,
    )
    assert [(f.variety, f.health) for f in each.fields] == [("Fontane", "Ill"), ("Agria", "Ill")]


def test_bolted_lettuce_is_reproductive() -> None:
    lettuce = _recipe("cos lettuce that has bolted in the summer heat", "rules").fields[0]
    assert (lettuce.variety, lettuce.stage) == ("Romaine", "Reproductive")


# --- generalisation fixes found by the blind held-out set 4 -----------------------------


def test_a_pronoun_that_ends_its_clause_points_back() -> None:
    recipe = _recipe(
        "ok so the main block is a hamlin orange grove. put valencia late oranges north of it, "
        "and a dwarf cavendish banana plot on its east side.",
        "rules",
    )
    hamlin, valencia, bananas = (f.id for f in recipe.fields)
    assert {(r.kind, r.subject, r.objects) for r in recipe.relations} == {
        ("north_of", valencia, (hamlin,)),
        ("east_of", bananas, (hamlin,)),
    }


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "a Roma tomato field and a Beefsteak tomato field, both ripe, the Roma one with blight",
            [("Roma", "Ill"), ("Beefsteak", "Healthy")],
        ),
        (
            "1.5 ha of Kordia cherries, ripe, early july - a fair bit of brown rot in the fruit",
            [("Kordia", "Ill")],
        ),
        (
            "durondeau pear trees and fuji apple trees covered in blossom in january, "
            "pears to the west, fire blight on the pears",
            [("Durondeau", "Ill"), ("Fuji", "Healthy")],
        ),
    ],
)
def test_back_references_to_named_fields(prompt: str, expected: list[tuple[str, str]]) -> None:
    assert [(f.variety, f.health) for f in _recipe(prompt, "rules").fields] == expected


def test_a_trailing_stage_after_two_bare_crops_describes_both() -> None:
    recipe = _recipe("apple and pear trees in full blossom in december", "rules")
    assert [f.stage for f in recipe.fields] == ["Reproductive", "Reproductive"]
    assert _recipe("young carrots and potatoes in bloom", "rules").fields[0].stage == "Vegetative"


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("can I get five fields: 2 of maize and 3 of wheat?", ["Maize"] * 2 + ["Wheat"] * 3),
        ("four orchards: two Gala and two Fuji", ["Apple"] * 4),
        ("we are testing a combine so basically a few cereal fields", ["Wheat", "Maize", "Maize"]),
    ],
)
def test_counted_members_and_amounts(prompt: str, crops: list[str]) -> None:
    assert [f.crop for f in _recipe(prompt, "rules").fields] == crops


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_placed_members_and_rows_in_order(strategy: str) -> None:
    placed = _recipe(
        "two carrot plots, imperator on the north side and danvers on the south side", strategy
    )
    imperator, danvers = placed.fields
    assert (imperator.variety, danvers.variety) == ("Imperator", "Danvers")
    assert ("north_of", imperator.id, (danvers.id,)) in {
        (r.kind, r.subject, r.objects) for r in placed.relations
    }
    row = _recipe(
        "three plots in a line, in this order: lollo rosso lettuce, red express cabbage, "
        "savoy cabbage",
        strategy,
    )
    first, middle, last = (f.id for f in row.fields)
    assert ("between", middle, (first, last)) in {
        (r.kind, r.subject, r.objects) for r in row.relations
    }


# --- fresh prompts tried by the developer after set 4 -----------------------------------


@pytest.mark.parametrize("strategy", STRATEGIES)
def test_halves_members_and_pronouns_in_relations(strategy: str) -> None:
    halves = _recipe("wheat in the north half and maize in the south half", strategy)
    wheat, maize = (f.id for f in halves.fields)
    assert [(r.kind, r.subject, r.objects) for r in halves.relations] == [
        ("north_of", wheat, (maize,))
    ]
    members = _recipe("two vineyards, chardonnay west of riesling, september", strategy)
    chardonnay, riesling = members.fields
    assert (chardonnay.variety, riesling.variety) == ("Chardonnay", "Riesling")
    assert [(r.kind, r.subject, r.objects) for r in members.relations] == [
        ("west_of", chardonnay.id, (riesling.id,))
    ]
    pronoun = _recipe("a cherry orchard and, to the south of it, two strawberry fields", strategy)
    cherry, first, _second = (f.id for f in pronoun.fields)
    assert {(r.kind, r.subject, r.objects) for r in pronoun.relations} >= {
        ("south_of", first, (cherry,))
    }


def test_still_green_is_not_ripe() -> None:
    recipe = _recipe(
        "Kordia and Regina cherries, the Regina block ripe, the Kordia block still green", "rules"
    )
    assert [(f.variety, f.stage) for f in recipe.fields] == [
        ("Kordia", "Reproductive"),
        ("Regina", "Maturation"),
    ]


# --- generalisation fixes found by the blind held-out set 5 -----------------------------


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        ("Kordia cherrys, ripe, in june... brown rot on a lot of the fruit", [("Cherry", "Ill")]),
        ("Elsanta strawberry beds in flower in May, no disease", [("Strawberry", "Healthy")]),
        (
            "grany smith apples and durondeau pears, two orchads, both in bloom, spring",
            [("Apple", "Healthy"), ("Pear", "Healthy")],
        ),
        (
            "cherry tomatoes beside a sweet cherry orchard, tomatoes sick, cherries healthy",
            [("Tomato", "Ill"), ("Cherry", "Healthy")],
        ),
    ],
)
def test_words_about_fields_already_named(prompt: str, expected: list[tuple[str, str]]) -> None:
    assert [(f.crop, f.health) for f in _recipe(prompt, "rules").fields] == expected


def test_no_two_the_same_crop() -> None:
    for seed in range(4):
        recipe = _recipe("give me 3 veg fields, no two the same crop", "rules", seed=seed)
        assert [f.category for f in recipe.fields] == ["Vegetables"] * 3
        assert len({f.crop for f in recipe.fields}) == 3

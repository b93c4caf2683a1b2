"""Requests as people write them (issue 8): visual cues, casual text, descriptions that
are not fields, scenery that is not a field."""

from __future__ import annotations

import pytest

from agrirecipe import PromptError, UnknownCropError, generate
from agrirecipe.resolve import FieldIntent, ResolveContext, Resolver, SceneIntent, resolve
from agrirecipe.resolve._casual import expand_casual


def fields(prompt: str, resolver: str = "hybrid") -> list[tuple[str, str, str, str]]:
    recipe = generate(prompt, resolver=resolver).recipe
    return [(f.crop, f.stage, f.season, f.health) for f in recipe.fields]


# --- visual cues --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("prompt", "attribute", "value"),
    [
        ("an apple orchard, trees white with blossom", "stage", "Reproductive"),
        ("a cherry orchard, petals falling", "stage", "Reproductive"),
        ("a wheat field, straw-coloured, heads drooping", "stage", "Maturation"),
        ("a plum tomato plot, fruit colouring up", "stage", "Maturation"),
        ("lettuce at the two-leaf stage", "stage", "Vegetative"),
        ("pear trees, hoarfrost on bare branches", "season", "Winter"),
        ("tomato plants with curled leaves and lesions", "health", "Ill"),
        ("a potato field, the plants wilted", "health", "Ill"),
        ("half the vines show mildew, a riesling vineyard", "health", "Ill"),
    ],
)
def test_a_visual_cue_sets_the_attribute(prompt: str, attribute: str, value: str) -> None:
    recipe = generate(prompt, resolver="hybrid").recipe
    assert len(recipe.fields) == 1, [f.crop for f in recipe.fields]
    assert getattr(recipe.fields[0], attribute) == value
    assert attribute in recipe.fields[0].stated


def test_a_winter_cue_needs_a_deciduous_crop() -> None:
    (field,) = generate("carrots in bare soil, hoarfrost", resolver="hybrid").recipe.fields
    assert field.season != "Winter" or "season" not in field.stated


def test_a_stated_word_wins_over_a_cue_with_a_warning() -> None:
    recipe = generate("a ripe apple orchard in summer, petals falling", resolver="hybrid").recipe
    assert recipe.fields[0].stage == "Maturation"
    assert any("petals" in w and "kept Maturation" in w for w in recipe.warnings)


# --- casual text ------------------------------------------------------------------------------


def test_texting_forms_are_words() -> None:
    assert expand_casual("apples nxt 2 pears b4 harvest thx").split() == [
        "apples",
        "next",
        "to",
        "pears",
        "before",
        "harvest",
    ]
    assert "+" in expand_casual("50+ trees")  # a number's plus is kept


@pytest.mark.parametrize(
    ("prompt", "crops"),
    [
        ("apples nxt 2 pears b4 harvest thx", ["Apple", "Pear"]),
        ("hamlin oranges + navel oranges, 2 ha each, winter", ["Orange", "Orange"]),
        ("tomatoes & peppers pls", ["Tomato", "Pepper"]),
        ("cherries (Kordia) next to pears (Conference)", ["Cherry", "Pear"]),
        ("groves of valencia and navel oranges", ["Orange", "Orange"]),
    ],
)
def test_casual_requests_make_the_fields_asked_for(prompt: str, crops: list[str]) -> None:
    assert [f[0] for f in fields(prompt)] == crops


# --- descriptions are not fields ---------------------------------------------------------------


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("a plum tomato plot, fruit colouring up", 1),
        ("half the vines show mildew, a riesling vineyard in august", 1),
        ("three orchards, each with a different fruit", 3),
        ("an apple orchard, the trees in full bloom", 1),
        ("apples and fruit trees", 2),  # a list member is a field
    ],
)
def test_a_description_attaches_to_its_field(prompt: str, count: int) -> None:
    assert len(fields(prompt)) == count


def test_each_with_a_different_fruit_makes_the_fields_different() -> None:
    crops = [f[0] for f in fields("three orchards, each with a different fruit")]
    assert len(set(crops)) == 3


def test_closing_words_about_the_plants_describe_every_field() -> None:
    result = fields("sonata strawberries next to albion strawberries, young plants, spring")
    assert [f[1] for f in result] == ["Vegetative", "Vegetative"]


# --- scenery and purpose are not fields, real unknown crops are refused -------------------------


@pytest.mark.parametrize(
    "prompt",
    [
        "a sprayer parked by the gate next to a wheat field",
        "an apple orchard with a hedge along the edge",
        "a barn behind the trees of a pear orchard",
        "a carrot field with a ditch, overcast sky",
        "maize for our weeding robot",
        "a test plot of lettuce for a LiDAR dataset",
        "drone survey of a vineyard",
        "a trial plot of potatoes",
    ],
)
def test_scenery_and_purpose_are_ignored(prompt: str) -> None:
    assert len(fields(prompt)) == 1


@pytest.mark.parametrize("prompt", ["an olive grove", "a rice paddy", "sunflowers"])
def test_real_crops_the_hierarchy_lacks_are_refused(prompt: str) -> None:
    with pytest.raises(UnknownCropError):
        generate(prompt, resolver="hybrid")


def test_scenery_alone_is_not_a_scene() -> None:
    with pytest.raises(PromptError):
        generate("a hedge and a gate", resolver="hybrid")


# --- intent validation: every field is traceable to the prompt's words --------------------------


class _Hallucinating(Resolver):
    """A strategy that adds a field nobody asked for (what a language model may do)."""

    name = "hallucinating"

    def resolve_intent(self, prompt: str, context: ResolveContext) -> SceneIntent:
        return SceneIntent(
            prompt=prompt,
            fields=(
                FieldIntent(text="a wheat field", crop="Wheat"),
                FieldIntent(text="banana plantation", crop="Banana"),
            ),
            resolver=self.name,
        )


def test_a_field_nobody_asked_for_fails_intent_validation() -> None:
    with pytest.raises(PromptError, match="not traceable") as caught:
        resolve("a wheat field", resolver=_Hallucinating())
    assert caught.value.stage == "validate"


def test_explain_lists_scenery_as_not_used() -> None:
    steps = resolve(
        "a sprayer parked by the gate next to a wheat field, overcast sky", explain=True
    ).intent.trace
    (step,) = [s for s in steps if s.subject == "not used"]
    assert "'sprayer'" in step.detail and "'gate'" in step.detail and "'sky'" in step.detail


# --- zones of a farm ----------------------------------------------------------------------------


def test_a_farm_described_by_zones_is_one_field_per_zone_in_order() -> None:
    recipe = generate(
        "stone fruit along the top, roots in the middle, grain at the bottom", resolver="hybrid"
    ).recipe
    crops = [f.crop for f in recipe.fields]
    assert crops[0] == "Cherry" and crops[1] in ("Carrot", "Potato", "Onion")
    assert crops[2] in ("Maize", "Wheat") and len(crops) == 3
    ids = [f.id for f in recipe.fields]
    pairs = {(r.kind, r.subject, r.objects) for r in recipe.relations}
    assert ("north_of", ids[0], (ids[1],)) in pairs and ("north_of", ids[1], (ids[2],)) in pairs
    ys = [f.geometry.origin_m[1] for f in recipe.fields]
    assert ys[0] > ys[1] > ys[2]


def test_left_and_right_are_west_and_east() -> None:
    recipe = generate("wheat on the left, maize on the right", resolver="hybrid").recipe
    (relation,) = recipe.relations
    assert relation.kind == "west_of" and relation.subject.startswith("wheat")


@pytest.mark.parametrize(
    "prompt", ["top quality apples", "a wheat field with tomatoes in the middle"]
)
def test_one_zone_word_alone_is_not_a_zoning(prompt: str) -> None:
    assert not any(
        r.kind in ("north_of", "west_of")
        for r in generate(prompt, resolver="hybrid").recipe.relations
    )


def test_a_category_that_no_plot_option_belongs_to_is_its_own_field() -> None:
    assert len(fields("an orchard, vegetables")) == 2


# --- from the blind casual set g1 -----------------------------------------------------------------


def test_a_negated_crop_is_not_a_field() -> None:
    with pytest.raises(PromptError):
        generate("just a red tractor parked by a barn at sunset, no crops or anything")
    assert [f[0] for f in fields("no apples, just pears")] == ["Pear"]


def test_same_size_copies_the_size_of_the_field_before() -> None:
    recipe = generate(
        "100 by 200 ft plot of butterhead lettuce & same size of romaine right nxt to it"
    ).recipe
    assert recipe.fields[0].geometry.size_m == recipe.fields[1].geometry.size_m


def test_a_second_field_named_by_place_is_not_one_more() -> None:
    assert len(fields("bell peppers red & ripe and some chillies in a 2nd field, thx")) == 2


def test_a_bunch_of_fields_is_a_few() -> None:
    assert len(fields("a bunch of fruit fields, 3 or 4 idk")) == 3


def test_inches_written_in_and_rows_counted_before_their_length() -> None:
    corn, _ = generate(
        "12 rows of sweetcorn, rows 30in apart & 80m long, nxt 2 a lil patch of jalapenos"
    ).recipe.fields
    assert corn.agronomy.row_spacing_m == pytest.approx(0.762) and corn.row_count == 12
    (maize,) = generate("maize, 80k plants/ha, 75cm rows, 10 rows 150m long").recipe.fields
    assert maize.row_count == 10 and maize.plants_per_ha == pytest.approx(80_000)


@pytest.mark.parametrize(
    ("prompt", "categories"),
    [
        ("6 fields in total, half vegetables half fruit", ["Vegetables"] * 3 + ["Fruits"] * 3),
        ("4 fields, a mix of fruit and vegetables", ["Fruits"] * 2 + ["Vegetables"] * 2),
    ],
)
def test_categories_after_counted_fields_share_them(prompt: str, categories: list[str]) -> None:
    recipe = generate(prompt).recipe
    assert [f.category for f in recipe.fields] == categories


def test_one_plant_described_is_not_a_field() -> None:
    result = fields(
        "Close-up of a tomato truss, fruit still green, one plant has wilted leaves, "
        "greenhouse in the background."
    )
    assert [f[0] for f in result] == ["Tomato"] and result[0][3] == "Ill"


def test_a_line_of_trees_in_the_scenery_is_not_a_row() -> None:
    recipe = generate(
        "Looking across a field of Bintje potatoes in flower, rows running away from me "
        "towards a line of poplars."
    ).recipe
    assert recipe.fields[0].row_count > 1


def test_a_members_own_closing_words_replace_what_a_list_lent_it() -> None:
    wheat, maize = fields(
        "Two fields in the photo: ripe wheat in front and maize behind it, still green."
    )
    assert wheat[1] == "Maturation" and maize[1] != "Maturation"
    assert [f[1] for f in fields("harvest-ready maize and wheat")] == ["Maturation"] * 2

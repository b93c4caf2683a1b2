"""Photo, casual and farm text of blind set g7 (issue 8): a plant's height says its stage
only when nothing else does, negated looks say nothing, damage "in patches" is no plot,
more cue words, one label opening a sentence, numbers that name a plot, and plural
names of weak varieties ("Russets")."""

from __future__ import annotations

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


@pytest.mark.parametrize(
    ("prompt", "stage"),
    [
        (
            "A potato field, plants about knee high with little white flowers all over them.",
            "Reproductive",
        ),
        ("knee high maize", "Vegetative"),
        ("Winter wheat in early May, knee-high and dark green, not in ear yet.", "Vegetative"),
        ("Rows of chillies, the plants hung with long thin red pods.", "Maturation"),
        ("Stuttgarter Riesen onions lifted and laid out to dry on the field.", "Maturation"),
        ("The wheat is just coming up green in rows.", "Vegetative"),
        ("cos lettuce at 2 leaf stage, april, its for the weeding robot test", "Vegetative"),
    ],
)
def test_stage_from_what_the_plants_look_like(prompt: str, stage: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.stage == stage


@pytest.mark.parametrize(
    "prompt",
    [
        "A Comice pear tree with the blossoms gone black and the shoot tips bent over like "
        "shepherd's crooks.",
        "Centenary strawberries, leaves spotted purple-brown.",
        "Our Bing cherries: blossoms turned brown and mushy and grey-tan powdery tufts.",
        "Agria spuds, July. The foliage is blackened and collapsed in patches and there's "
        "white fuzz under the leaves.",
    ],
)
def test_damage_described_in_words_makes_the_one_field_ill(prompt: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.health == "Ill"


def test_a_negated_look_says_nothing() -> None:
    (field,) = recipe("Carrots in June, no spots on the leaves, no wilting").fields
    assert field.health == "Healthy"


@pytest.mark.parametrize(
    "prompt",
    [
        "Field 4, the one over the ditch: Russet spuds, fully mature, September.",
        "Plot 2 - Red Baron onions, 25 rows at 30 cm",
        "Red Baron onions in plot 2, 25 rows",
    ],
)
def test_a_number_that_names_a_plot_asks_for_no_fields(prompt: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.crop in ("Potato", "Onion")


def test_two_labels_without_a_count_still_name_fields() -> None:
    scene = recipe("Block A: Gala apples. Block B, north of A: Conference pears.")
    gala, pears = scene.fields
    assert (gala.variety, pears.variety) == ("Gala", "Conference")
    assert [(r.kind, r.subject, r.objects) for r in scene.relations] == [
        ("north_of", pears.id, (gala.id,))
    ]


@pytest.mark.parametrize(
    ("prompt", "variety"),
    [
        ("Russets for the NDVI drone: 24 rows on 36-inch centers, July.", "Russet Burbank"),
        ("the Navels are ripe", "Navel"),
        ("Grannies in bloom", "Granny Smith"),
    ],
)
def test_the_plural_of_a_weak_variety_word_names_the_variety(prompt: str, variety: str) -> None:
    (field,) = recipe(prompt).fields
    assert field.variety == variety


def test_a_weak_variety_word_alone_stays_a_description() -> None:
    (field,) = recipe("russet apples in autumn").fields
    assert field.crop == "Apple"
    assert "variety" not in field.stated


def test_a_plot_word_inside_an_unknown_phrase_is_not_a_field() -> None:
    scene = recipe(
        "Two apple blocks on either side of a hawthorn hedge to compare planting systems for "
        "the LiDAR canopy model: one at 3 m x 0.5 m, the other at 4 m x 1.5 m."
    )
    assert [(f.crop, f.agronomy.row_spacing_m) for f in scene.fields] == [
        ("Apple", 3.0),
        ("Apple", 4.0),
    ]


def test_damage_in_patches_is_not_more_fields() -> None:
    scene = recipe("wheat with yellow rust in patches, and a maize field")
    assert [(f.crop, f.health) for f in scene.fields] == [("Wheat", "Ill"), ("Maize", "Healthy")]


@pytest.mark.parametrize(
    "prompt",
    [
        "Apple trees in full pink-white blossom. Frost on the grass and the pruning crew's van "
        "by the gate.",
        "1 ha of maize and 1 ha of wheat, the two blocks adjacent with only a 6 m grass track "
        "separating them.",
    ],
)
def test_grass_that_is_ground_or_a_track_is_scenery(prompt: str) -> None:
    assert all(f.crop != "Grass" for f in recipe(prompt).fields)


def test_all_before_a_plain_word_stresses_it_and_shares_nothing() -> None:
    wheat, maize = recipe(
        "Shot across our wheat in May, all green and even, drilled at 12.5 cm with the rows "
        "running east to west. Beside it is a field of flint corn that has only just emerged."
    ).fields
    assert wheat.agronomy.row_spacing_m == 0.125
    assert "row_spacing" not in maize.stated
    both = recipe("wheat and maize, all in flower").fields
    assert [f.stage for f in both] == ["Reproductive", "Reproductive"]


def test_fruit_a_member_is_bent_with_is_its_own_and_the_list_goes_on() -> None:
    scene = recipe(
        "Two blocks next to each other in this shot. Conference pears on one side, branches "
        "bent with fruit that's clearly ready to pick, and Kordia cherries on the other, whose "
        "leaves are riddled with holes from some pest."
    )
    assert [(f.variety, f.stage, f.health) for f in scene.fields] == [
        ("Conference", "Maturation", "Healthy"),
        ("Kordia", scene.fields[1].stage, "Ill"),
    ]


def test_a_count_said_after_a_guess_is_the_plant_count() -> None:
    (field,) = recipe(
        "orange trees, hundreds of them - 400 actually - on the hill behind our house"
    ).fields
    assert field.crop == "Orange"
    assert field.nominal_plant_count == 400


def test_damage_patches_and_a_row_of_windbreak_trees_are_no_fields() -> None:
    (field,) = recipe(
        "Took this one last October at the back of the farm: Granny Smith trees loaded with "
        "big green apples ready to pick, but lots of them have brown corky scab patches on the "
        "skin. Grey sky, a tractor with a bin trailer in the alley and a row of poplars behind."
    ).fields
    assert (field.variety, field.stage, field.health) == ("Granny Smith", "Maturation", "Ill")
    assert "rows" not in field.stated
    (row,) = recipe("a row of Gala apple trees").fields
    assert row.row_count == 1

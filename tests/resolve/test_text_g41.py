"""Text of blind set g41 (issue 8): fixes after its blind run ("eight 100 m rows at 3.5 m",
"3 m wide x 120 m", "20 rows x 30 in", labels with no mark, "put the blighted plot south of
the healthy one", a crop a model is trained on, "along its eastern edge", bolting and
banana bracts and a forage harvester as cues, a member said with "the", a field beside the
structure another grows in, list marks in brackets mid-sentence, "over the hedge to the
south", "(the plum ones)", sizes said in turn, "one has greening... the hamlin one")."""

from __future__ import annotations

import pytest

from agrirecipe import generate


def _relations(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in generate(prompt).recipe.relations}


def test_a_count_of_rows_said_before_their_length_and_spacing() -> None:
    fields = generate(
        "three apple blocks, west to east Jonagold, Gala, Fuji. each block eight 100 m rows at "
        "3.5 m, trees 1 m apart."
    ).recipe.fields
    assert [f.variety for f in fields] == ["Jonagold", "Gala", "Fuji"]
    for field in fields:
        assert field.row_count == 8
        assert field.agronomy.row_spacing_m == pytest.approx(3.5)
        assert field.row_length_m == pytest.approx(100.0, rel=0.01)


@pytest.mark.parametrize("said", ["3 m wide x 120 m", "3 m wide by 120 m", "120 m long by 3 m"])
def test_one_side_named_then_the_other_bare(said: str) -> None:
    (strip,) = generate(f"a durum wheat strip, {said}").recipe.fields
    assert strip.geometry.size_m == pytest.approx((3.0, 120.0))


def test_rows_times_inches() -> None:
    (corn,) = generate("corn plot, 20 rows x 30 in, 100 m long").recipe.fields
    assert corn.row_count == 20
    assert corn.agronomy.row_spacing_m == pytest.approx(0.762)


def test_labels_with_no_mark_placed_against_each_other() -> None:
    scene = generate(
        "Three plots for an RTK rover test. Plot A carrots; plot B onions, north of A; plot C "
        "lettuce, east of A. All plots 10 x 20 m."
    ).recipe
    carrots, onions, lettuce = (f.id for f in scene.fields)
    assert [f.crop for f in scene.fields] == ["Carrot", "Onion", "Lettuce"]
    assert {(r.kind, r.subject, r.objects) for r in scene.relations} == {
        ("north_of", onions, (carrots,)),
        ("east_of", lettuce, (carrots,)),
    }


def test_members_named_again_by_their_look() -> None:
    scene = generate(
        "LiDAR + multispectral test: two potato plots, 0.75 m rows, one healthy and one with "
        "late blight; put the blighted plot south of the healthy one."
    ).recipe
    healthy, blighted = scene.fields
    assert (healthy.health, blighted.health) == ("Healthy", "Ill")
    assert {(r.kind, r.subject, r.objects) for r in scene.relations} == {
        ("south_of", blighted.id, (healthy.id,))
    }


def test_the_crop_a_model_is_trained_on_is_no_field() -> None:
    fields = generate(
        "Spätburgunder vineyard, 2.2 m between rows, 1 m between vines, 3000 vines, "
        "harvest-ready in September; we're training a grape-bunch counting CNN on it."
    ).recipe.fields
    assert [f.variety for f in fields] == ["Pinot Noir"]


def test_along_its_eastern_edge() -> None:
    assert _relations("A maize field. Along its eastern edge a 40 x 80 m wheat field.") == {
        ("east_of", "wheat_field_1", ("maize_field_1",))
    }


@pytest.mark.parametrize(
    ("prompt", "stage"),
    [
        ("the lettuce in this pic has started to bolt", "Reproductive"),
        (
            "Gros Michel bananas with purple flower bracts hanging at the end of each bunch",
            "Reproductive",
        ),
        ("a maize field with the forage harvester just starting on it", "Maturation"),
    ],
)
def test_cues_of_bolting_flowering_and_harvest(prompt: str, stage: str) -> None:
    (field,) = generate(prompt).recipe.fields
    assert field.stage == stage


def test_a_member_said_with_the_but_named_nowhere_before() -> None:
    scene = generate(
        "Two blocks side by side in this shot, Conference pears covered in white blossom and "
        "the Kordia cherries, also in bloom, with the hail nets still rolled up."
    ).recipe
    assert [f.crop for f in scene.fields] == ["Pear", "Cherry"]


def test_a_field_beside_the_structure_another_grows_in() -> None:
    assert _relations(
        "Centenary strawberries in the tunnels, ripe and being picked, and right beside the "
        "tunnels an orchard of Bing cherries."
    ) == {("next_to", "cherry_orchard_1", ("strawberry_field_1",))}


def test_list_marks_in_brackets_inside_a_sentence() -> None:
    fields = generate(
        "plots are (a) Albion strawberries, ripe (b) California Wonder peppers, flowering "
        "(c) Beefsteak tomatoes, young plants"
    ).recipe.fields
    assert [(f.crop, f.stage) for f in fields] == [
        ("Strawberry", "Maturation"),
        ("Pepper", "Reproductive"),
        ("Tomato", "Vegetative"),
    ]


def test_over_the_hedge_to_the_south_with_its_other_side_said() -> None:
    assert _relations(
        "Over the hedge to the south the cherry trees are white with blossom, and north of the "
        "hedge the carrots are at the two-leaf stage."
    ) == {("south_of", "cherry_orchard_1", ("carrot_field_1",))}


def test_a_kind_in_brackets_said_with_ones_and_sizes_in_turn() -> None:
    scene = generate("roma toms (the plum ones) north of cayenne chillies, 20x40m & 30x50m").recipe
    tomatoes, chillies = scene.fields
    assert (tomatoes.variety, chillies.variety) == ("Roma", "Cayenne")
    assert tomatoes.geometry.size_m == pytest.approx((20.0, 40.0))
    assert chillies.geometry.size_m == pytest.approx((30.0, 50.0))


def test_a_look_said_of_one_then_which_one() -> None:
    hamlin, valencia = generate(
        "hamlin & valencia oranges, 2 groves, one has greening... the hamlin one"
    ).recipe.fields
    assert (hamlin.variety, hamlin.health, valencia.health) == ("Hamlin", "Ill", "Healthy")
    # (not "one has late blight, the other one is clean": the other one is the other)
    blighted, clean = generate(
        "Two potatoe fields separated by a farm track - one has late blight, the other one is "
        "clean."
    ).recipe.fields
    assert (blighted.health, clean.health) == ("Ill", "Healthy")

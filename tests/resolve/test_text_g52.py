"""Text of blind set g52 (issue 8): each miss of its blind run fixed as the general
mechanism (a "then" list of counted members; a year after its month; plants trained or
guarded; rows of a crop named again; a row crop named by its rows' spacing in inches;
members named by their rows' direction; a crop picture beside a variety name ...)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import PromptError, generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def _fields(prompt: str) -> list[dict[str, object]]:
    recipe = generate(prompt).recipe
    return [
        {
            "crop": f.crop,
            "variety": f.variety,
            "stage": f.stage,
            "area": round(f.geometry.size_m[0] * f.geometry.size_m[1]),
            "headland": f.geometry.headland_m,
            "row_spacing": f.agronomy.row_spacing_m,
        }
        for f in recipe.fields
    ]


@pytest.mark.parametrize(
    "prompt",
    [
        "Three fields in the photo: cabbages nearest to us, then a wheat field golden and "
        "ready, and past that a field of potatoes, still green.",
        "three fields: cabbages, then a wheat field, then a field of potatoes.",
    ],
)
def test_counted_members_named_in_turn_lie_in_that_order(
    prompt: str, crop_relations: Callable[[str], NamedRelations]
) -> None:
    assert ("between", "Wheat", ("Cabbage", "Potato")) in crop_relations(prompt)


def test_a_field_placed_between_two_of_a_then_list_keeps_only_that_place(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "three fields in a row: onions, then carrots running down to the canal, and a strip "
        "of lettuce between the onions and the carrots."
    )
    assert relations == {("between", "Lettuce", ("Onion", "Carrot"))}


@pytest.mark.parametrize(
    ("prompt", "season"),
    [
        (
            "That's the Spätburgunder block in January 2026: bare vines and a dusting of snow.",
            "Winter",
        ),
        ("Gala apples in spring 2024", "Spring"),
    ],
)
def test_a_year_after_its_month_or_season_counts_no_fields(prompt: str, season: str) -> None:
    recipe = generate(prompt).recipe
    assert len(recipe.fields) == 1
    assert recipe.fields[0].season == season


def test_what_young_trees_are_staked_and_guarded_with_is_scenery() -> None:
    fields = _fields(
        "Our new Golden Delicious planting, just planted this spring: the whips are only waist "
        "high, with bamboo canes and tree guards, and the wind machine standing at the end."
    )
    assert [(f["crop"], f["variety"]) for f in fields] == [("Apple", "Golden Delicious")]


@pytest.mark.parametrize("training", ["Two trellised blocks", "Two staked blocks"])
def test_how_plants_are_held_up_is_no_crop_or_variety(training: str) -> None:
    fields = _fields(f"{training} side by side: Chardonnay, 12 rows, and Pinot Noir, 10 rows.")
    assert [f["variety"] for f in fields] == ["Chardonnay", "Pinot Noir"]
    assert [f["variety"] for f in _fields("Staked tomatoes: 10 rows, 1.5 m apart.")] == ["Roma"]


def test_a_count_of_fields_then_a_new_field_placed_against_the_first_lists_both(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two fields in this one, a field of young maize at the four-leaf stage next to a "
        "wheat field whose ears have just come out, and a hawthorn hedge dividing them."
    )
    fields = _fields(prompt)
    assert [(f["crop"], f["stage"]) for f in fields] == [
        ("Maize", "Vegetative"),
        ("Wheat", "Reproductive"),
    ]
    assert crop_relations(prompt) == {("next_to", "Maize", ("Wheat",))}


@pytest.mark.parametrize(
    ("prompt", "stages"),
    [
        (
            "chilli plants heavy with ripe red chillies in front, and a big field of corn "
            "behind them just starting to tassel.",
            ["Maturation", "Reproductive"],
        ),
        ("Beef tomatoes in the greenhouse, huge ribbed fruit turning deep red.", ["Maturation"]),
    ],
)
def test_looks_said_with_a_colour_shade_or_a_beginning_give_the_stage(
    prompt: str, stages: list[str]
) -> None:
    assert [f["stage"] for f in _fields(prompt)] == stages


def test_side_by_side_with_scenery_between_them_is_still_side_by_side(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "the cabbage and the lettuce fields side by side with the tractor between them"
    assert crop_relations(prompt) == {("next_to", "Lettuce", ("Cabbage",))}
    assert not any("between" in w for w in generate(prompt).recipe.warnings)


def test_the_sky_over_the_farm_is_only_scenery() -> None:
    with pytest.raises(PromptError, match="only scenery"):
        generate("The sky over the farm this evening, pink clouds and swallows on the wires.")
    assert len(generate("a farm in summer").recipe.fields) == 3


def test_a_crops_rows_named_again_are_that_fields_rows() -> None:
    fields = _fields(
        "two 20 x 100 m plots next to each other: wheat drilled at 12.5 cm row spacing, and "
        "maize in 75 cm rows. Drill rows and maize rows all running east-west."
    )
    assert [f["crop"] for f in fields] == ["Wheat", "Maize"]


def test_the_same_row_length_said_again_with_also() -> None:
    recipe = generate(
        "Carrots: 30 ridges at 75 cm centres, 2 rows on each ridge, 100 m long. Cabbage: 40 "
        "rows 75 cm apart with heads every 45 cm, also 100 m."
    ).recipe
    assert [f.row_length_m for f in recipe.fields] == [pytest.approx(100), pytest.approx(100)]


@pytest.mark.parametrize(
    ("prompt", "spacing"),
    [
        ("30-inch corn, 16 rows, 500 ft rows", 0.762),
        ("a 20-row block of 30-inch sweetcorn", 0.762),
        ("20 rows of 36-inch potatoes", 0.9144),
    ],
)
def test_a_row_crop_named_by_its_rows_spacing_in_inches(prompt: str, spacing: float) -> None:
    [field] = _fields(prompt)
    assert field["row_spacing"] == pytest.approx(spacing)


def test_a_kind_of_crop_a_camera_is_for_is_no_field() -> None:
    fields = _fields(
        "Nantes carrots on 75 cm ridges, 24 ridges 80 m long. Need it for a root-crop yield camera."
    )
    assert [f["crop"] for f in fields] == ["Carrot"]


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "two identical maize plots, 16 rows at 75 cm, one with rows east-west and one with "
            "rows north-south, the E-W one to the south.",
            ("south_of", 90.0, 0.0),
        ),
        (
            "two 1 ha vineyards at 2.5 x 1.5 m, one planted north-south, the other east-west; "
            "the north-south one lies east of the east-west one.",
            ("east_of", 0.0, 90.0),
        ),
    ],
)
def test_a_member_named_by_its_rows_direction(
    prompt: str, expected: tuple[str, float, float]
) -> None:
    recipe = generate(prompt).recipe
    bearing = {f.id: f.row_bearing_deg for f in recipe.fields}
    [relation] = recipe.relations
    assert (relation.kind, bearing[relation.subject], bearing[relation.objects[0]]) == expected


def test_a_side_in_brackets_after_uphill_is_the_relation(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Spätburgunder and Riesling terraces, 20 rows of each, Riesling uphill (north) of "
        "the Spätburgunder."
    )
    assert relations == {("north_of", "Grape", ("Grape",))}


def test_a_crop_picture_beside_a_variety_that_is_an_everyday_word_names_its_crop() -> None:
    fields = _fields("🍓 sonata + iceberg 🥬 lettuce, adjacent, may")
    assert [(f["crop"], f["variety"]) for f in fields] == [
        ("Strawberry", "Sonata"),
        ("Lettuce", "Iceberg"),
    ]
    # (a picture beside the crop's own word repeats it: one field)
    assert len(_fields("sonata 🍓 strawberries")) == 1


def test_a_headland_round_each_field_is_each_ones() -> None:
    fields = _fields("a carrot field & a cabbage field w/ a 5m headland round each")
    assert [f["headland"] for f in fields] == [5.0, 5.0]
    # (a headland on each side is one field's, not a field on each side)
    assert len(_fields("a carrot field and a cabbage field with a 5 m headland on each side")) == 2


def test_a_negative_spacing_said_after_like_is_refused() -> None:
    with pytest.raises(PromptError, match="positive"):
        generate("grapes w/ negative row spacing, like -2m")


def test_a_field_placed_past_a_plot_named_again_with_a_size(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Behind the house there's a 100 ft by 200 ft vegetable garden, and north of the "
        "garden a 10-acre corn field."
    )
    assert len(relations) == 1
    [(kind, subject, _)] = relations
    assert (kind, subject) == ("north_of", "Maize")


def test_where_one_field_ends_the_next_begins(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Where the orchard ends the maize begins, and the maize runs right up to the potato field."
    )
    assert ("next_to", "Maize", ("Potato",)) in relations
    others = relations - {("next_to", "Maize", ("Potato",))}
    assert any(kind == "next_to" and subject == "Maize" for kind, subject, _ in others)


@pytest.mark.parametrize(
    ("prompt", "area"),
    [("Fifteen hectares of Dent corn", 150_000), ("seventeen hectares of wheat", 170_000)],
)
def test_numbers_thirteen_to_nineteen_said_in_words(prompt: str, area: int) -> None:
    [field] = _fields(prompt)
    assert field["area"] == pytest.approx(area, rel=1e-3)


def test_the_back_forty_is_one_field() -> None:
    assert len(_fields("The back forty is all corn this year and it has only just emerged.")) == 1


def test_scenery_in_the_middle_of_a_field_places_no_field() -> None:
    recipe = generate(
        "Three lettuces in this shot: Cos nearest, then crisphead, then Butterhead at the far "
        "end, all ready to cut. The harvest rig with its conveyor is in the middle of the Cos."
    ).recipe
    variety = {f.id: f.variety for f in recipe.fields}
    middles = [r for r in recipe.relations if r.kind == "between"]
    assert [variety[r.subject] for r in middles] == ["Iceberg"]

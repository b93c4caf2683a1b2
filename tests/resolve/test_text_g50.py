"""Text of blind set g50 (issue 8): each miss of its blind run fixed as the general
mechanism (a relation that goes on with "and" and no subject of its own; a field with no
crop in it, ploughed or fallow, as scenery)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


@pytest.mark.parametrize(
    "prompt",
    [
        "A potato field east of a carrot field and west of a cabbage field.",
        "Sensor-test farm: a potato field (rows 75 cm, in-row 35 cm) east of a carrot field "
        "(75 cm ridges, two rows each) and west of a cabbage field (rows 60 cm, in-row 40 cm).",
    ],
)
def test_a_relation_going_on_with_and_keeps_its_subject(
    prompt: str, crop_relations: Callable[[str], NamedRelations]
) -> None:
    relations = crop_relations(prompt)
    assert {("east_of", "Potato", ("Carrot",)), ("west_of", "Potato", ("Cabbage",))} <= relations
    assert ("west_of", "Carrot", ("Cabbage",)) not in relations


def test_a_relation_said_of_a_field_named_after_and_is_that_fields(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations("wheat north of the maize and potatoes south of it")
    assert ("north_of", "Wheat", ("Maize",)) in relations
    assert not any(subject == "Wheat" and kind == "south_of" for kind, subject, _ in relations)


@pytest.mark.parametrize(
    "ground",
    ["a big bare ploughed field with a tractor working it", "a fallow field", "a plowed field"],
)
def test_a_field_with_no_crop_in_it_is_scenery(ground: str) -> None:
    recipe = generate(
        f"A potato field in flower, a carrot field next to it and beyond that {ground}."
    )
    assert [f.crop for f in recipe.recipe.fields] == ["Potato", "Carrot"]


@pytest.mark.parametrize("plot", ["a vineyard", "an orchard"])
def test_a_plot_of_a_crop_the_field_cannot_hold_is_a_field_of_its_own(
    plot: str, crop_relations: Callable[[str], NamedRelations]
) -> None:
    relations = crop_relations(f"{plot} with a block of carrots to the north of it")
    assert any(kind == "north_of" and subject == "Carrot" for kind, subject, _ in relations)


def test_a_plot_of_the_fields_own_crop_after_with_is_still_its_block() -> None:
    recipe = generate("an orchard with a block of Gala and a block of Fuji").recipe
    assert [f.variety for f in recipe.fields] == ["Gala", "Fuji"]


def test_a_fence_on_a_side_of_the_farm_places_the_field_along_it(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "Jonagored along the east fence and Cripps Pink along the west fence."
    )
    assert ("west_of", "Apple", ("Apple",)) in relations


def test_the_season_before_is_not_the_fields() -> None:
    recipe = generate(
        "our Royal Gala trees flowering in December after the mild autumn, pink blossom"
    ).recipe
    assert (recipe.fields[0].stage, recipe.fields[0].season) == ("Reproductive", "Winter")


@pytest.mark.parametrize(
    "prompt",
    [
        "fruit trees at 5 m spacing",
        "fruit-tree rows at 5 m spacing between two maize strips sown in 75 cm rows",
    ],
)
def test_the_plants_word_a_spacing_takes_still_says_the_plot(prompt: str) -> None:
    trees = generate(prompt).recipe.fields[0]
    assert trees.crop in ("Apple", "Pear", "Cherry", "Orange")


# Leftovers of g50, fixed after it moved into the development set.


def _fields(prompt: str) -> list[dict[str, object]]:
    return [
        {
            "crop": f.crop,
            "variety": f.variety,
            "health": f.health,
            "area": round(f.geometry.size_m[0] * f.geometry.size_m[1]),
            "row_spacing": f.agronomy.row_spacing_m,
            "in_row": f.agronomy.in_row_spacing_m,
        }
        for f in generate(prompt).recipe.fields
    ]


@pytest.mark.parametrize(
    "prompt",
    [
        "A wheat field with a field of spuds to the east, both ill: the wheat has rust and "
        "the potatoes have blight.",
        "A wheat field with a field of spuds to the east, both a bit sorry for themselves: "
        "the wheat has rust pustules on the leaves and the potato leaves are blotched brown.",
    ],
)
def test_fields_described_again_after_a_colon_keep_their_relation(
    prompt: str, crop_relations: Callable[[str], NamedRelations]
) -> None:
    assert crop_relations(prompt) == {("east_of", "Potato", ("Wheat",))}
    assert [f["health"] for f in _fields(prompt)] == ["Ill", "Ill"]


def test_sorry_for_itself_is_a_poorly_look_not_a_correction() -> None:
    fields = _fields("a potato field next to a carrot field looking sorry for itself")
    assert [(f["crop"], f["health"]) for f in fields] == [
        ("Potato", "Healthy"),
        ("Carrot", "Ill"),
    ]


def test_between_the_two_with_a_look_after_it_is_still_between_them(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "winter wheat just up; a block of maize, dry and brown; and a cabbage field in "
        "between the two with fat blue-green heads."
    )
    assert relations == {("between", "Cabbage", ("Wheat", "Maize"))}


def test_measures_each_member_says_before_in_each_stay_its_own() -> None:
    fields = _fields(
        "Two Gala blocks: one with rows 3 m apart and trees every 0.6 m, the other with "
        "rows 4 m apart and trees every 1.5 m, 10 rows in each."
    )
    assert [(f["row_spacing"], f["in_row"]) for f in fields] == [(3.0, 0.6), (4.0, 1.5)]


@pytest.mark.parametrize(
    ("prompt", "crops", "area"),
    [
        (
            "Split a 1-acre test field into four quarter-acre plots - lettuce, cabbage, onions "
            "and carrots - with all rows running east-west.",
            ["Lettuce", "Cabbage", "Onion", "Carrot"],
            1012,
        ),
        (
            "a 1 ha field split into four plots: lettuce, cabbage, onions and carrots",
            ["Lettuce", "Cabbage", "Onion", "Carrot"],
            2500,
        ),
        (
            "a 1 ha field split into lettuce, cabbage, onions and carrots",
            ["Lettuce", "Cabbage", "Onion", "Carrot"],
            2500,
        ),
        ("a 2 ha wheat field divided into four plots", ["Wheat"] * 4, 5000),
        (
            "3 ha split equally between Royal Gala and Granny, the Granny block to the south",
            ["Apple", "Apple"],
            15000,
        ),
    ],
)
def test_an_area_split_into_parts_is_shared_out(prompt: str, crops: list[str], area: int) -> None:
    fields = _fields(prompt)
    assert [f["crop"] for f in fields] == crops
    assert all(abs(f["area"] - area) <= area * 0.01 for f in fields)


def test_a_group_opening_a_list_after_a_patch_is_its_first_member(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "we keep a veg patch: greens by the gate, peppers at the far end, and the tomatoes "
        "between the greens and the peppers."
    )
    crops = sorted(str(f["crop"]) for f in _fields(prompt))
    assert len(crops) == 3 and {"Pepper", "Tomato"} < set(crops)
    assert any(
        kind == "between" and subject == "Tomato" for kind, subject, _ in crop_relations(prompt)
    )


def test_a_structure_in_a_fields_name_is_a_landmark_that_field_holds(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    relations = crop_relations(
        "The polytunnel field is planted with Albion strawberries and the outdoor Sonata field "
        "lies south of the tunnels."
    )
    assert relations == {("south_of", "Strawberry", ("Strawberry",))}
    recipe = generate(
        "The polytunnel field is planted with Albion strawberries and the outdoor Sonata field "
        "lies south of the tunnels."
    ).recipe
    variety = {f.id: f.variety for f in recipe.fields}
    [relation] = recipe.relations
    assert (variety[relation.subject], variety[relation.objects[0]]) == ("Sonata", "Albion")


def test_a_crop_only_a_few_weeks_in_is_young() -> None:
    recipe = generate(
        "The Iceberg lettuce has bolted, tall stalks shooting up out of the heads, and the "
        "Butterhead next to it is still small and fresh, only a few weeks in."
    ).recipe
    assert [(f.variety, f.stage) for f in recipe.fields] == [
        ("Iceberg", "Reproductive"),
        ("Butterhead", "Vegetative"),
    ]


@pytest.mark.parametrize(
    "prompt",
    [
        "San Marzano field in August with long red fruit hanging in clusters, and the Roma "
        "field beside it hit hard by blight, black stems and rotting fruit.",
        "A Gala block in flower, and the Fuji block next to it badly scabbed, black spots "
        "and cracked fruit.",
    ],
)
def test_words_after_a_field_placed_by_a_pronoun_are_its_own(prompt: str) -> None:
    assert [f["health"] for f in _fields(prompt)] == ["Healthy", "Ill"]


def test_a_colour_naming_a_fields_own_variety_after_with_is_its_fruit(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "The Gala block hanging with ripe striped red fruit, and the Golden Delicious block "
        "beyond it with pale yellow apples, also ready."
    )
    assert [(f["variety"]) for f in _fields(prompt)] == ["Gala", "Golden Delicious"]
    assert crop_relations(prompt) == {("next_to", "Apple", ("Apple",))}


def test_a_variety_named_again_after_with_is_still_the_member() -> None:
    recipe = generate(
        "Cabbage variety block: Savoy, Red Express and January King, each 10 rows at 75 cm, "
        "with Red Express between the other two."
    ).recipe
    variety = {f.id: f.variety for f in recipe.fields}
    [relation] = recipe.relations
    assert variety[relation.subject] == "Red Express"
    assert sorted(variety[o] for o in relation.objects) == ["January King", "Savoy"]


def test_a_list_after_a_count_and_restated_after_a_colon_is_the_counted_fields(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Two plots for camera calibration, carrots on the west and onions on the east: "
        "Nantes carrots on 75 cm ridges, and Sturon onions in rows 30 cm apart, 10 cm in-row."
    )
    fields = _fields(prompt)
    assert [(f["crop"], f["variety"]) for f in fields] == [
        ("Carrot", "Nantes"),
        ("Onion", "Sturon"),
    ]
    assert (fields[1]["row_spacing"], fields[1]["in_row"]) == (0.3, 0.1)
    assert ("west_of", "Carrot", ("Onion",)) in crop_relations(prompt)


@pytest.mark.parametrize(
    ("prompt", "count"),
    [
        ("some veggies: a field of carrots & whatever else u want, at least 3 fields total", 3),
        ("some veg: a field of carrots, 4 fields in total", 4),
    ],
)
def test_a_group_heading_a_list_is_the_fields_a_total_leaves(prompt: str, count: int) -> None:
    fields = generate(prompt).recipe.fields
    assert len(fields) == count
    assert sum(f.crop == "Carrot" for f in fields) == 1
    assert all(f.category == "Vegetables" for f in fields)

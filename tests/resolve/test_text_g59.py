"""Text of blind set g59 (issue 8): its misses fixed as general mechanisms (a colour after
"came out"; settings written as key=value; "place the second plot east of the first"; the
plots said again after a list; "three adjacent blocks of A, B and C"; "rows along 160
degrees", "row bearing 075", "1 m vine pitch"; "separate fields" after a list; a variety
named again by its first word; a salad picture and "af"; a placement corrected with "i
mean"; "and so does the tomato field"; a field at one end of a directed row)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from agrirecipe import generate
from agrirecipe.recipe import SceneRecipe

#: The fixture crop_relations' answer (tests/resolve/conftest.py).
NamedRelations = set[tuple[str, str, tuple[str, ...]]]


def recipe(prompt: str) -> SceneRecipe:
    return generate(prompt, resolver="hybrid").recipe


def test_a_colour_something_came_out_is_no_crop() -> None:
    (wheat,) = recipe(
        "The wheat in the photo has yellow-orange stripes of pustules on nearly every leaf, "
        "rust all over it, and my boots came out orange from walking through."
    ).fields
    assert (wheat.crop, wheat.health) == ("Wheat", "Ill")
    # (an orange named as a crop is still one)
    assert [f.crop for f in recipe("apples and orange with lettuce").fields] == [
        "Apple",
        "Orange",
        "Lettuce",
    ]


def test_settings_written_as_key_values(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "crop=lettuce var=Iceberg rows=30 row_spacing=0.35m in_row=0.30m | crop=lettuce "
        "var=Lollo Rosso rows=30 row_spacing=0.35m in_row=0.30m | place the second plot east "
        "of the first"
    )
    iceberg, lollo = recipe(prompt).fields
    assert (iceberg.variety, lollo.variety) == ("Iceberg", "Lollo Rosso")
    for field in (iceberg, lollo):
        assert field.row_count == 30
        assert field.agronomy.row_spacing_m == pytest.approx(0.35)
        assert field.agronomy.in_row_spacing_m == pytest.approx(0.3)
    assert named_relations(prompt) == {("east_of", "Lollo Rosso", ("Iceberg",))}
    # (a sum is no setting: "12 rows x 30 trees = 360 trees")
    (oranges,) = recipe(
        "Valencia oranges, 7.2 m rows, 3.8 m between trees, 12 rows x 30 trees = 360 trees"
    ).fields
    assert oranges.row_count == 12


def test_the_plots_said_again_after_a_list_are_no_member() -> None:
    scene = recipe(
        "Variety strips for the hyperspectral camera: Agria, Fontane and Russet Burbank, 6 rows "
        "each at 75 cm, rows 50 m long, strips in that order from west to east. Late blight is "
        "showing on the Fontane."
    )
    assert [(f.variety, f.health) for f in scene.fields] == [
        ("Agria", "Healthy"),
        ("Fontane", "Ill"),
        ("Russet Burbank", "Healthy"),
    ]
    assert all(f.row_count == 6 for f in scene.fields)


def test_adjacent_blocks_of_a_list_of_varieties(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = (
        "Orchard digital twin: three adjacent blocks of Jonagored, Fuji and Pink Lady apples, "
        "12 rows each, rows 3.5 m apart with trees at 1 m, rows running north-south. The Fuji "
        "block is between the other two."
    )
    scene = recipe(prompt)
    assert [f.variety for f in scene.fields] == ["Jonagold", "Fuji", "Pink Lady"]
    assert all(f.row_count == 12 for f in scene.fields)
    assert ("between", "Fuji", ("Jonagold", "Pink Lady")) in named_relations(prompt)


@pytest.mark.parametrize(
    ("prompt", "bearing"),
    [
        ("Dent corn: 32 rows, 30 in spacing, 20 ft headlands, row bearing 075, tasselling.", 75),
        (
            "Riesling for the vine-pruning perception stack: 36 rows, 2 m row pitch, 1 m vine "
            "pitch, rows 120 m long, 8 m headlands, rows along 160 degrees, leafless in January.",
            160,
        ),
    ],
)
def test_row_bearings_said_bare_or_along(prompt: str, bearing: float) -> None:
    (field,) = recipe(prompt).fields
    assert field.row_bearing_deg == pytest.approx(bearing)
    if field.crop == "Grape":
        assert field.agronomy.in_row_spacing_m == pytest.approx(1.0)


def test_separate_fields_after_a_list_are_the_lists() -> None:
    scene = recipe("flint corn & popping corn, separate fields")
    assert [f.variety for f in scene.fields] == ["Flint", "Popcorn"]


def test_a_variety_named_again_by_its_first_word(
    named_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "pinot nero & cabernet, 1ha each, pinot north"
    assert named_relations(prompt) == {("north_of", "Pinot Noir", ("Cabernet Sauvignon",))}


def test_a_salad_picture_names_lettuce() -> None:
    (lollo,) = recipe("lollo 🥗 sick af, mildew all over, sept").fields
    assert (lollo.variety, lollo.health, lollo.season) == ("Lollo Rosso", "Ill", "Fall")


def test_a_placement_corrected_with_i_mean(
    crop_relations: Callable[[str], NamedRelations],
) -> None:
    prompt = "california wonder peppers b4 the onions (sturon)... i mean west of them lol"
    assert crop_relations(prompt) == {("west_of", "Pepper", ("Onion",))}


def test_so_does_the_next_field() -> None:
    scene = recipe("Both of our potato fields have late blight, and so does the tomato field.")
    assert [(f.crop, f.health) for f in scene.fields] == [
        ("Potato", "Ill"),
        ("Potato", "Ill"),
        ("Tomato", "Ill"),
    ]


def id_relations(prompt: str) -> set[tuple[str, str, tuple[str, ...]]]:
    return {(r.kind, r.subject, r.objects) for r in recipe(prompt).relations}


def test_a_field_at_one_end_of_a_directed_row() -> None:
    south = id_relations(
        "Three wheat fields in a line running north to south, with a maize field at the "
        "southern end."
    )
    assert {r for r in south if "maize_field_1" in (r[1], *r[2])} == {
        ("north_of", "wheat_field_3", ("maize_field_1",))
    }
    north = id_relations(
        "Three wheat fields in a line running north to south, with a maize field at the "
        "northern end."
    )
    assert {r for r in north if "maize_field_1" in (r[1], *r[2])} == {
        ("north_of", "maize_field_1", ("wheat_field_1",))
    }
    east = id_relations(
        "Potatoes, carrots and onions from west to east, and strawberries at the east end"
    )
    assert ("west_of", "onion_field_1", ("strawberry_field_1",)) in east
    # (scenery at the end places nothing; an end zone on the other axis is no row end)
    barn = id_relations("Three wheat fields running north to south and a barn at the south end")
    assert len(barn) == 3
    across = id_relations(
        "Three wheat fields running north to south, with a maize field at the east end"
    )
    assert not any("maize_field_1" in (r[1], *r[2]) for r in across)

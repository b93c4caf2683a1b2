"""Field geometry stated in rows and spacings (issue 8): read, carried, checked, laid out."""

from __future__ import annotations

import math

import pytest

from agrirecipe import PromptError, generate
from agrirecipe.resolve._geometry import find_geometry
from agrirecipe.resolve._lexicon import tokenize


def read(prompt: str) -> dict[str, float]:
    return {m.key: m.value for m in find_geometry(tokenize(prompt))}


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "10 rows of maize, 80 m long, 76 cm apart",
            {"rows": 10, "row_length_m": 80, "row_spacing_m": 0.76},
        ),
        ("38-inch rows of corn", {"row_spacing_m": 0.9652}),
        ("30 in rows", {"row_spacing_m": 0.762}),
        ("a plant every 20 cm", {"in_row_spacing_m": 0.2}),
        ("5 plants per metre", {"in_row_spacing_m": 0.2}),
        ("80,000 plants/ha", {"plants_per_ha": 80_000}),
        ("9 plants per m²", {"plants_per_ha": 90_000}),
        ("two rows per bed on 1.5 m beds", {"rows_per_bed": 2, "bed_width_m": 1.5}),
        ("a 5 m headland", {"headland_m": 5}),
        ("rows running east-west", {"row_bearing_deg": 90}),
        ("north-south rows", {"row_bearing_deg": 0}),
        ("rows NE-SW", {"row_bearing_deg": 45}),
        ("rows at 30°", {"row_bearing_deg": 30}),
        (
            "rows 100 m long, 3.5 m apart, trees 1 m apart",
            {"row_length_m": 100, "row_spacing_m": 3.5, "in_row_spacing_m": 1.0},
        ),
        ("200 Gala apple trees", {"plant_count": 200}),
        ("12 raised beds", {"beds": 12}),
        # measures written after another one, the way engineers list them
        ("rows 45 cm apart, running east-west", {"row_spacing_m": 0.45, "row_bearing_deg": 90}),
        ("rows north–south", {"row_bearing_deg": 0}),
        ("rows NNE-SSW", {"row_bearing_deg": 22.5}),
        ("rows 100 m long at 67.5°", {"row_length_m": 100, "row_bearing_deg": 67.5}),
        ("rows 20 degrees from north", {"row_bearing_deg": 20}),
        ("20 rows at 5 m", {"rows": 20, "row_spacing_m": 5}),
        ("8 rows each at 76 cm", {"rows": 8, "row_spacing_m": 0.76}),
        ("12 rows spaced 30 cm", {"rows": 12, "row_spacing_m": 0.3}),
        ("onion rows 30 cm", {"row_spacing_m": 0.3}),
        ("wheat drilled at 15 cm", {"row_spacing_m": 0.15}),
        ("8 in between seeds", {"in_row_spacing_m": 0.2032}),
        ("one plant per 10 cm", {"in_row_spacing_m": 0.1}),
        ("seed tubers every 33 cm", {"in_row_spacing_m": 0.33}),
        ("6 beds on 1.52 m centres", {"beds": 6, "bed_width_m": 1.52}),
        ("15 beds of 1.4 m", {"beds": 15, "bed_width_m": 1.4}),
        ("2 rows per 75 cm ridge", {"rows_per_bed": 2, "bed_width_m": 0.75}),
        ("on 3 m square spacing", {"row_spacing_m": 3, "in_row_spacing_m": 3}),
        ("a 3 m x 3 m square grid", {"row_spacing_m": 3, "in_row_spacing_m": 3}),
        (
            "400 plants at 2 m by 2 m",
            {"plant_count": 400, "row_spacing_m": 2, "in_row_spacing_m": 2},
        ),
        ("100 Ladyfinger plants", {"plant_count": 100}),
        (
            "40 rows at 2.5 m with vines 1 m apart",
            {"rows": 40, "row_spacing_m": 2.5, "in_row_spacing_m": 1},
        ),
    ],
)
def test_stated_geometry_is_read(prompt: str, expected: dict[str, float]) -> None:
    found = read(prompt)
    assert set(found) == set(expected), found
    for key, value in expected.items():
        assert math.isclose(found[key], value, rel_tol=1e-9), (key, found[key])


@pytest.mark.parametrize(
    "prompt",
    [
        "a 2 ha field of wheat",
        "two apple orchards",
        "a 50 by 100 m carrot field",
        "three fields of maize",
        "a tree",
        "apple trees in bloom",
        "two bed systems of strawberries",
    ],
)
def test_sizes_and_counts_of_fields_are_not_geometry(prompt: str) -> None:
    assert read(prompt) == {}


@pytest.mark.parametrize("prompt", ["rows 0 cm apart", "0 rows of maize", "-3 rows of wheat"])
def test_zero_or_negative_geometry_is_a_prompt_error(prompt: str) -> None:
    with pytest.raises(PromptError):
        generate(prompt, resolver="rules")


def test_ten_rows_of_maize_is_one_field_of_exactly_ten_rows() -> None:
    scene = generate("10 rows of maize, 80 m long, 76 cm apart", resolver="rules")
    (spec,) = scene.recipe.fields
    assert spec.row_count == 10
    assert math.isclose(spec.row_length_m, 80.0, rel_tol=0.01)
    assert spec.agronomy.row_spacing_m == 0.76
    assert {"rows", "row_length", "row_spacing"} <= set(spec.stated)
    # plants.csv follows: 10 distinct rows 0.76 m apart (jitter is 2 cm).
    plants = scene.layout.field(spec.id)
    xs = sorted({round(float(x) / 0.76) for x in plants.xyz[:, 0]})
    assert len(xs) == 10
    assert plants.nominal_plant_count == 10 * (math.floor(80 / 0.15 + 1e-9) + 1)


def test_row_direction_turns_the_field() -> None:
    scene = generate("6 rows of Gala apples 50 m long, rows running east-west", resolver="rules")
    (spec,) = scene.recipe.fields
    assert spec.row_bearing_deg == 90.0
    xyz = scene.layout.field(spec.id).xyz
    xs, ys = xyz[:, 0], xyz[:, 1]
    # Rows run east-west: the planted block is long in x and narrow in y.
    assert max(xs) - min(xs) > 45 and max(ys) - min(ys) < 6 * 3.4


def test_density_sets_the_in_row_spacing() -> None:
    spec = generate("a maize field at 80,000 plants/ha", resolver="rules").recipe.fields[0]
    assert math.isclose(spec.plants_per_ha, 80_000, rel_tol=1e-6)
    assert "density" in spec.stated


def test_tree_count_is_planted_exactly() -> None:
    spec = generate("an orchard of 200 Gala apple trees", resolver="rules").recipe.fields[0]
    assert spec.nominal_plant_count == 200
    assert "plant_count" in spec.stated


def test_outside_the_sourced_range_is_kept_with_a_warning() -> None:
    recipe = generate("grapes with rows 4 m apart", resolver="rules").recipe
    assert recipe.fields[0].agronomy.row_spacing_m == 4.0
    assert any("2.5-3 m" in w and "kept as asked" in w for w in recipe.warnings)


def test_rows_closer_than_the_plant_is_wide_are_refused() -> None:
    with pytest.raises(PromptError, match="closer than apple plants are wide"):
        generate("apple trees with rows 20 cm apart", resolver="rules")


def test_density_and_spacing_that_disagree_are_refused() -> None:
    with pytest.raises(PromptError, match="plants/ha"):
        generate("maize rows 75 cm apart, a plant every 15 cm, 50,000 plants/ha", resolver="rules")


@pytest.mark.parametrize(
    ("prompt", "expected"),
    [
        (
            "5 rows x 30 trees of Gala, 3.5 m x 1 m spacing",
            {"rows": 5, "plants_per_row": 30, "row_spacing_m": 3.5, "in_row_spacing_m": 1.0},
        ),
        ("planted at 3 x 1.5 m", {"row_spacing_m": 3.0, "in_row_spacing_m": 1.5}),
        ("8 rows of cabbage, 40 m each", {"rows": 8, "row_length_m": 40}),
        ("a 100 m long row of tomatoes", {"row_length_m": 100, "rows": 1}),
        ("one row of lettuce", {"rows": 1}),
        ("three plots in a row of maize", {}),
    ],
)
def test_grids_and_single_rows_are_read(prompt: str, expected: dict[str, float]) -> None:
    assert read(prompt) == pytest.approx(expected)


def test_a_grid_of_trees_is_planted_exactly() -> None:
    scene = generate("orchard test site: 5 rows x 30 trees of Gala, 3.5 m x 1 m", resolver="rules")
    (spec,) = scene.recipe.fields
    assert (spec.row_count, spec.nominal_plant_count) == (5, 150)


def test_a_row_direction_in_degrees_is_not_a_latitude() -> None:
    """It once raised "latitude 160 is not on Earth"."""
    recipe = generate(
        "vines in 2.5 m rows, rows at 160 degrees from north", resolver="hybrid"
    ).recipe
    assert recipe.fields[0].row_bearing_deg == pytest.approx(160)


def test_a_measure_is_never_a_count_of_fields() -> None:
    """ "drilled at 15 cm" and "20 ridges at 75 cm centres" once made 15 and 20 fields."""
    for prompt in (
        "maize in 30-inch rows, and wheat drilled at 15 cm just north of the maize",
        "Chantenay carrots on 20 ridges at 75 cm centres, two rows per ridge",
        "14 rows at 1.5 m of plum tomatoes with 45 cm in-row",
    ):
        assert len(generate(prompt, resolver="hybrid").recipe.fields) <= 2, prompt

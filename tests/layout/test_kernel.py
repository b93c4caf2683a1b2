"""The placement kernel: standard library only, and identical to the library's numpy path."""

from __future__ import annotations

import ast
import hashlib
import json
import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from agrirecipe.layout import (
    field_parameters,
    field_seed,
    kernel_source,
    layout_scene,
    place_field,
    place_field_array,
    plant_grid,
)
from agrirecipe.recipe import Agronomy, FieldGeometry, FieldSpec, Placement, SceneRecipe

RecipeFactory = Callable[..., SceneRecipe]

STDLIB_ALLOWED = {"math", "random", "collections.abc", "typing"}


def kernel_namespace() -> dict[str, Any]:
    namespace: dict[str, Any] = {"__name__": "engine_script"}
    exec(compile(kernel_source(), "<inlined kernel>", "exec"), namespace)
    return namespace


def as_matrix(plants: list[tuple[float, ...]]) -> np.ndarray:
    return np.array(plants, dtype=np.float64).reshape(-1, 6)


def array_matrix(params: dict[str, Any]) -> np.ndarray:
    xyz, yaw, scale, height = place_field_array(params)
    return np.column_stack([xyz, yaw, scale, height])


def test_kernel_source_uses_only_the_standard_library() -> None:
    tree = ast.parse(kernel_source())
    imported: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            imported.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            assert node.module is not None and node.level == 0
            assert node.module != "__future__", "cannot be inlined mid-script"
            imported.add(node.module)
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
            assert node.func.id not in {"hash", "__import__", "eval", "exec", "open"}
    assert imported <= STDLIB_ALLOWED, imported - STDLIB_ALLOWED
    assert "agrirecipe" not in {name.split(".")[0] for name in imported}


def test_inlined_kernel_matches_the_library_exactly(make_recipe: RecipeFactory) -> None:
    recipe = make_recipe(
        ["Apple", "Strawberry", "Potato", "Grape", "Banana", "Pepper", "Wheat", "Maize"],
        seed=7,
        size_factor=0.4,
    )
    namespace = kernel_namespace()
    layout = layout_scene(recipe)
    for plants, params in zip(layout.fields, field_parameters(recipe), strict=True):
        # The engine script receives the parameters as JSON text.
        engine_params = json.loads(json.dumps(params))
        from_engine = as_matrix(namespace["place_field"](engine_params))
        from_library = np.column_stack([plants.xyz, plants.yaw_rad, plants.scale, plants.height_m])
        assert from_engine.shape == from_library.shape
        assert plants.plant_count > 0
        assert np.array_equal(from_engine, from_library), plants.field_id  # bit for bit
        assert from_engine.tobytes() == from_library.tobytes()


def test_field_parameters_are_json_and_complete(make_recipe: RecipeFactory) -> None:
    recipe = make_recipe(["Apple", "Carrot"], size_factor=0.3)
    params = field_parameters(recipe)
    assert [p["id"] for p in params] == ["f0", "f1"]
    assert json.loads(json.dumps(params)) == params
    assert params[0]["seed"] != params[1]["seed"]
    for p in params:
        assert isinstance(p["seed"], int) and 0 <= p["seed"] < 2**64


def test_field_seed_is_stable_and_distinct() -> None:
    # A fixed value: the seed must not depend on the process (no salted hash()).
    assert field_seed(0, "orchard") == field_seed(0, "orchard")
    assert field_seed(0, "orchard") != field_seed(1, "orchard")
    assert field_seed(0, "orchard") != field_seed(0, "orchard2")
    # Pinned: a change here silently moves every plant of every existing recipe.
    assert field_seed(0, "f0") == 0x72CFFF15089DF3B3
    assert field_seed(42, "f0") == int.from_bytes(
        hashlib.sha256(b"agrirecipe/layout/42/f0").digest()[:8], "big"
    )


# --- kernel against hand-made fields over many shapes and spacings -----------------------------


def make_spec(
    *,
    width: float,
    length: float,
    headland: float,
    row_spacing: float,
    in_row: float,
    rows_per_bed: int,
    bed_row_spacing: float,
    rotation: float,
    placement: Placement,
    pattern: str,
    planted: tuple[float, float] | None = None,
    plant_count: int | None = None,
) -> FieldSpec:
    agronomy = Agronomy(
        planting_pattern=pattern,  # type: ignore[arg-type]
        growth_form="row_crop",
        row_spacing_m=row_spacing,
        rows_per_bed=rows_per_bed,
        bed_row_spacing_m=bed_row_spacing,
        in_row_spacing_m=in_row,
        plant_height_m=0.5,
        max_height_m=0.5,
        canopy_width_m=0.05,
        kc_mid=1.0,
        leaf_habit="annual",
        foliage="leafy",
        foliage_rgb=(0.2, 0.5, 0.2),
    )
    return FieldSpec(
        id="test_field",
        label="test",
        category="Vegetables",
        crop="Test",
        variety="Test",
        stage="Vegetative",
        season="Summer",
        health="Healthy",
        asset_path="/Game/Test/SM_Test.SM_Test",
        agronomy=agronomy,
        geometry=FieldGeometry(
            origin_m=(13.5, -7.25),
            size_m=(width, length),
            rotation_deg=rotation,
            headland_m=headland,
            planted_m=planted,
            plant_count=plant_count,
        ),
        placement=placement,
    )


@st.composite
def field_specs(draw: st.DrawFn) -> FieldSpec:
    rows_per_bed = draw(st.integers(1, 4))
    row_spacing = draw(st.floats(0.1, 5.0))
    bed_row_spacing = 0.0
    if rows_per_bed > 1:
        bed_row_spacing = draw(st.floats(0.01, 0.99)) * row_spacing / (rows_per_bed - 1)
    headland = draw(st.floats(0.0, 5.0))
    bed_span = bed_row_spacing * (rows_per_bed - 1)
    width = 2 * headland + bed_span + draw(st.floats(0.06, 30.0))
    length = 2 * headland + draw(st.floats(0.06, 30.0))
    in_row = draw(st.floats(max(0.03, length / 500), 3.0))
    row_spacing = max(row_spacing, width / 300)
    if rows_per_bed > 1:
        bed_row_spacing = min(bed_row_spacing, 0.99 * row_spacing / (rows_per_bed - 1))
    stride = draw(st.sampled_from([1, 1, 2, 5, 10]))
    return make_spec(
        width=width,
        length=length,
        headland=headland,
        row_spacing=row_spacing,
        in_row=in_row,
        rows_per_bed=rows_per_bed,
        bed_row_spacing=bed_row_spacing,
        rotation=draw(st.sampled_from([0.0, 30.0, -90.0, 135.5, 180.0])),
        # a stated count that leaves the last row short ("250 trees in 18 rows"), or none
        plant_count=draw(st.none() | st.integers(1, 5000)) if stride == 1 else None,
        placement=Placement(
            jitter_m=draw(st.floats(0.0, 0.2)),
            missing_rate=draw(st.sampled_from([0.0, 0.05, 0.3])),
            size_variation=draw(st.floats(0.0, 0.9)),
            yaw_variation_deg=draw(st.floats(0.0, 180.0)),
            # (a dense field thinned to fit the plant cap: every N-th plant drawn)
            plants_per_instance=stride,
        ),
        pattern=draw(
            st.sampled_from(["rows", "drilled_rows", "ridges", "double_rows_on_beds", "tree_rows"])
        ),
        # a planted block smaller than the field ("10 rows in a 25 x 60 m plot"), or none
        planted=draw(
            st.none()
            | st.tuples(
                st.floats(bed_span + 0.06, max(bed_span + 0.06, width - 2 * headland)),
                st.floats(0.06, max(0.06, length - 2 * headland)),
            )
        ),
    )


def recipe_of(spec: FieldSpec, seed: int) -> SceneRecipe:
    from agrirecipe.enrich import build_environment

    return SceneRecipe(
        prompt="t", seed=seed, environment=build_environment("Summer"), fields=(spec,)
    )


@settings(max_examples=60, deadline=None)
@given(field_specs(), st.integers(0, 2**63 - 1))
def test_kernel_and_numpy_path_agree_on_any_field(spec: FieldSpec, seed: int) -> None:
    (params,) = field_parameters(recipe_of(spec, seed))
    kernel = as_matrix(place_field(params))
    assert np.array_equal(kernel, array_matrix(params))


@settings(max_examples=60, deadline=None)
@given(field_specs())
def test_nominal_grid_matches_the_recipe_count(spec: FieldSpec) -> None:
    (params,) = field_parameters(recipe_of(spec, 0))
    beds, rows_per_bed, per_row, _, _ = plant_grid(params)
    limit = spec.geometry.plant_count
    grid = beds * rows_per_bed * per_row
    assert (grid if limit is None else min(grid, limit)) == spec.drawn_plant_count()
    without_gaps = dict(params, missing_rate=0.0)
    assert len(place_field(without_gaps)) == spec.drawn_plant_count()
    if spec.placement.plants_per_instance == 1:
        assert spec.drawn_plant_count() == spec.nominal_plant_count


@settings(max_examples=60, deadline=None)
@given(field_specs(), st.integers(0, 1000))
def test_plants_stay_inside_the_field_minus_headland(spec: FieldSpec, seed: int) -> None:
    (params,) = field_parameters(recipe_of(spec, seed))
    xyz, yaw, scale, height = place_field_array(params)
    geometry, placement = spec.geometry, spec.placement
    # Back into field-local coordinates.
    angle = math.radians(geometry.rotation_deg)
    dx, dy = xyz[:, 0] - geometry.origin_m[0], xyz[:, 1] - geometry.origin_m[1]
    local_x = dx * math.cos(angle) + dy * math.sin(angle)
    local_y = -dx * math.sin(angle) + dy * math.cos(angle)
    slack = placement.jitter_m + 1e-6
    width, length = geometry.size_m
    h = geometry.headland_m
    assert (local_x >= h - slack).all() and (local_x <= width - h + slack).all()
    assert (local_y >= h - slack).all() and (local_y <= length - h + slack).all()
    if geometry.planted_m is not None:  # and inside the planted block, centred
        block_w, block_l = geometry.usable_m()
        assert (np.abs(local_x - width / 2) <= block_w / 2 + slack).all()
        assert (np.abs(local_y - length / 2) <= block_l / 2 + slack).all()
    assert (xyz[:, 2] == 0.0).all()
    yaw_limit = math.radians(placement.yaw_variation_deg) + 1e-9
    assert (np.abs(yaw - angle) <= yaw_limit).all()
    assert (scale >= 0.1).all()
    assert np.array_equal(height, spec.agronomy.plant_height_m * scale)


def test_rows_are_centred_and_spaced_by_the_agronomy() -> None:
    spec = make_spec(
        width=10.0,
        length=6.0,
        headland=1.0,
        row_spacing=1.5,
        in_row=0.5,
        rows_per_bed=2,
        bed_row_spacing=0.3,
        rotation=0.0,
        placement=Placement(yaw_variation_deg=0.0),
        pattern="double_rows_on_beds",
    )
    (params,) = field_parameters(recipe_of(spec, 0))
    xyz, yaw, scale, _ = place_field_array(params)
    local_x = np.unique(np.round(xyz[:, 0] - 13.5, 9))
    # Usable 8 m minus the 0.3 m bed span leaves room for floor(7.7 / 1.5) + 1 = 6 beds;
    # they occupy 5 * 1.5 + 0.3 = 7.8 m, centred in the usable 8 m -> first row at 1.1 m.
    expected = sorted(1.1 + bed * 1.5 + row * 0.3 for bed in range(6) for row in range(2))
    assert np.allclose(local_x, expected)
    local_y = np.unique(np.round(xyz[:, 1] + 7.25, 9))
    assert np.allclose(local_y, [1.0 + 0.5 * i for i in range(9)])  # 4 m usable, 9 positions
    assert (yaw == 0.0).all() and (scale == 1.0).all()


def test_missing_fraction_is_near_the_missing_rate() -> None:
    placement = Placement(missing_rate=0.08, jitter_m=0.01)
    spec = make_spec(
        width=60.0,
        length=60.0,
        headland=2.0,
        row_spacing=0.5,
        in_row=0.1,
        rows_per_bed=1,
        bed_row_spacing=0.0,
        rotation=0.0,
        placement=placement,
        pattern="rows",
    )
    for seed in (0, 1, 2):
        (params,) = field_parameters(recipe_of(spec, seed))
        present = len(place_field_array(params)[1])
        nominal = spec.nominal_plant_count
        missing = 1 - present / nominal
        sigma = math.sqrt(0.08 * 0.92 / nominal)
        assert abs(missing - 0.08) < 5 * sigma, (seed, missing)


def test_scale_noise_has_the_requested_spread() -> None:
    spec = make_spec(
        width=40.0,
        length=40.0,
        headland=0.0,
        row_spacing=0.5,
        in_row=0.2,
        rows_per_bed=1,
        bed_row_spacing=0.0,
        rotation=0.0,
        placement=Placement(size_variation=0.1, yaw_variation_deg=90.0),
        pattern="rows",
    )
    (params,) = field_parameters(recipe_of(spec, 3))
    _, yaw, scale, _ = place_field_array(params)
    assert abs(scale.mean() - 1.0) < 0.005
    assert abs(scale.std() - 0.1) < 0.005
    assert yaw.min() < -1.5 and yaw.max() > 1.5 and np.abs(yaw).max() <= math.pi / 2


def test_seed_changes_the_plants_and_only_the_seed(make_recipe: RecipeFactory) -> None:
    first = layout_scene(make_recipe(["Tomato"], seed=1, size_factor=0.3)).fields[0]
    again = layout_scene(make_recipe(["Tomato"], seed=1, size_factor=0.3)).fields[0]
    other = layout_scene(make_recipe(["Tomato"], seed=2, size_factor=0.3)).fields[0]
    assert np.array_equal(first.xyz, again.xyz) and np.array_equal(first.scale, again.scale)
    assert not np.array_equal(first.scale, other.scale)


def test_unknown_pattern_is_refused_by_the_kernel() -> None:
    params = {"pattern": "spiral", "size_m": [10, 10], "headland_m": 0}
    params |= {"row_spacing_m": 1, "rows_per_bed": 1, "bed_row_spacing_m": 0, "in_row_spacing_m": 1}
    with pytest.raises(ValueError, match="spiral"):
        plant_grid(params)


@settings(max_examples=40, deadline=None)
@given(field_specs(), st.integers(0, 1000))
def test_a_field_keeps_its_first_plant_whatever_the_missing_rate(
    spec: FieldSpec, seed: int
) -> None:
    (params,) = field_parameters(recipe_of(spec, seed))
    all_missing = dict(params, missing_rate=1.0)
    kernel = place_field(all_missing)
    assert len(kernel) == 1  # only the first position survives
    assert np.array_equal(as_matrix(kernel), array_matrix(all_missing))
    assert len(place_field(params)) >= 1

"""Scene geometry over recipes of one to ten fields built from the real knowledge base."""

from __future__ import annotations

import hashlib
import itertools
import math
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from agrirecipe.hierarchy import Hierarchy
from agrirecipe.layout import Layout, layout_scene
from agrirecipe.recipe import Relation, SceneRecipe, dump_recipe

RecipeFactory = Callable[..., SceneRecipe]


def layout_digest(layout: Layout) -> str:
    digest = hashlib.sha256()
    for plants in layout.fields:
        digest.update(plants.field_id.encode())
        for array in (plants.xyz, plants.yaw_rad, plants.scale, plants.height_m):
            digest.update(np.ascontiguousarray(array).tobytes())
    return digest.hexdigest()


def local_coordinates(plants_xyz: np.ndarray, origin: tuple[float, float], rotation_deg: float):  # type: ignore[no-untyped-def]
    angle = math.radians(rotation_deg)
    dx, dy = plants_xyz[:, 0] - origin[0], plants_xyz[:, 1] - origin[1]
    return dx * math.cos(angle) + dy * math.sin(angle), -dx * math.sin(angle) + dy * math.cos(angle)


def check_scene(recipe: SceneRecipe) -> Layout:
    layout = layout_scene(recipe)
    assert [p.field_id for p in layout.fields] == [f.id for f in recipe.fields]
    # Fields never overlap (axis-aligned: rotation is 0 from the packer).
    for a, b in itertools.combinations(recipe.fields, 2):
        (ax, ay), (aw, al) = a.geometry.origin_m, a.geometry.size_m
        (bx, by), (bw, bl) = b.geometry.origin_m, b.geometry.size_m
        assert ax + aw <= bx or bx + bw <= ax or ay + al <= by or by + bl <= ay, (a.id, b.id)
    missing_total = nominal_total = 0
    expected_missing = 0.0
    variance = 0.0
    for plants in layout.fields:
        spec = plants.spec
        geometry, agronomy = spec.geometry, spec.agronomy
        assert plants.plant_count > 0, f"{spec.id} is empty"
        assert plants.plant_count <= spec.nominal_plant_count
        # The nominal count is the spacing grid over the usable rectangle.
        width, length = geometry.size_m
        span = agronomy.bed_row_spacing_m * (agronomy.rows_per_bed - 1)
        beds = (
            math.floor((width - 2 * geometry.headland_m - span) / agronomy.row_spacing_m + 1e-9) + 1
        )
        per_row = (
            math.floor((length - 2 * geometry.headland_m) / agronomy.in_row_spacing_m + 1e-9) + 1
        )
        assert spec.nominal_plant_count == beds * agronomy.rows_per_bed * per_row
        # Every plant inside the field minus its headland, up to the jitter.
        local_x, local_y = local_coordinates(plants.xyz, geometry.origin_m, geometry.rotation_deg)
        slack = spec.placement.jitter_m + 1e-6
        h = geometry.headland_m
        assert local_x.min() >= h - slack and local_x.max() <= width - h + slack
        assert local_y.min() >= h - slack and local_y.max() <= length - h + slack
        assert np.allclose(plants.height_m, agronomy.plant_height_m * plants.scale)
        rate = spec.placement.missing_rate
        nominal = spec.nominal_plant_count
        missing_total += nominal - plants.plant_count
        nominal_total += nominal
        expected_missing += rate * nominal
        variance += rate * (1 - rate) * nominal
    # Missing plants: the scene total is within 5 standard deviations of the rate.
    assert abs(missing_total - expected_missing) <= 5 * math.sqrt(variance) + 1
    return layout


@st.composite
def scenes(draw: st.DrawFn, crops: list[str]) -> dict[str, object]:
    count = draw(st.integers(1, 10))
    chosen = draw(st.lists(st.sampled_from(crops), min_size=count, max_size=count))
    factors = draw(st.lists(st.floats(0.05, 0.3), min_size=count, max_size=count))
    cells = draw(
        st.lists(
            st.tuples(st.integers(0, 3), st.integers(0, 3)),
            min_size=count,
            max_size=count,
            unique=True,
        )
    )
    true_relations = []
    for i, j in itertools.permutations(range(count), 2):
        (ci, ri), (cj, rj) = cells[i], cells[j]
        if ci == cj and ri > rj:
            true_relations.append(Relation(kind="north_of", subject=f"f{i}", objects=(f"f{j}",)))
        if ri == rj and ci == cj + 1:
            true_relations.append(Relation(kind="next_to", subject=f"f{i}", objects=(f"f{j}",)))
        if ri == rj and ci < cj:
            true_relations.append(Relation(kind="west_of", subject=f"f{i}", objects=(f"f{j}",)))
    for i, j, k in itertools.permutations(range(count), 3):
        (ci, ri), (cj, rj), (ck, rk) = cells[i], cells[j], cells[k]
        if ci == cj == ck and rj < ri < rk:
            true_relations.append(
                Relation(kind="between", subject=f"f{i}", objects=(f"f{j}", f"f{k}"))
            )
    relations = (
        draw(st.lists(st.sampled_from(true_relations), max_size=4, unique=True))
        if true_relations
        else []
    )
    return {
        "crops": chosen,
        "size_factor": factors,
        "relations": relations,
        "seed": draw(st.integers(0, 2**63 - 1)),
        "season": draw(st.sampled_from(["Spring", "Summer", "Fall", "Winter"])),
    }


def test_geometry_over_one_to_ten_fields(hierarchy: Hierarchy, make_recipe: RecipeFactory) -> None:
    crops = list(hierarchy.crops)

    @settings(
        max_examples=40,
        deadline=None,
        suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
    )
    @given(scenes(crops))
    def run(scene: dict[str, object]) -> None:
        recipe = make_recipe(**scene)
        check_scene(recipe)

    run()


def test_every_crop_and_pattern(hierarchy: Hierarchy, make_recipe: RecipeFactory) -> None:
    # Every crop of the hierarchy at half its default field size, in one scene.
    recipe = make_recipe(list(hierarchy.crops), size_factor=0.5, seed=3)
    layout = check_scene(recipe)
    patterns = {plants.spec.agronomy.planting_pattern for plants in layout.fields}
    assert patterns == {
        "tree_rows",
        "trellis_rows",
        "rows",
        "drilled_rows",
        "double_rows_on_beds",
        "ridges",
    }


def test_layout_is_identical_in_another_process(make_recipe: RecipeFactory, tmp_path: Path) -> None:
    recipe = make_recipe(["Apple", "Carrot", "Strawberry"], seed=11, size_factor=0.3)
    recipe_file = tmp_path / "recipe.json"
    recipe_file.write_text(dump_recipe(recipe), encoding="utf-8")
    here = layout_digest(layout_scene(recipe))
    program = (
        "import sys, hashlib, numpy as np\n"
        "from agrirecipe.recipe import load_recipe\n"
        "from agrirecipe.layout import layout_scene\n"
        "layout = layout_scene(load_recipe(sys.argv[1]))\n"
        "d = hashlib.sha256()\n"
        "for p in layout.fields:\n"
        "    d.update(p.field_id.encode())\n"
        "    for a in (p.xyz, p.yaw_rad, p.scale, p.height_m):\n"
        "        d.update(np.ascontiguousarray(a).tobytes())\n"
        "print(d.hexdigest())\n"
    )
    for hash_seed in ("1", "2"):
        result = subprocess.run(
            [sys.executable, "-c", program, str(recipe_file)],
            capture_output=True,
            text=True,
            check=True,
            env={**os.environ, "PYTHONHASHSEED": hash_seed},
        )
        assert result.stdout.strip() == here


def test_layout_arrays_are_read_only(make_recipe: RecipeFactory) -> None:
    plants = layout_scene(make_recipe(["Lettuce"], size_factor=0.2)).fields[0]
    assert not plants.xyz.flags.writeable and not plants.scale.flags.writeable
    assert plants.xyz.dtype == np.float64 and plants.xyz.shape == (plants.plant_count, 3)

"""Generated scripts executed in real bpy: instances, placement, proxies, light and camera."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from blender_recipes import HOSTILE, mixed_recipe, single_field_recipe
from blender_runner import build_in_bpy, run_in_bpy

from agrirecipe import Scene
from agrirecipe.backends.blender import BlenderBackend
from agrirecipe.layout import layout_scene
from agrirecipe.plants import plant_variants
from agrirecipe.recipe import SceneRecipe

pytestmark = pytest.mark.slow

# Instance transforms are float32: a few micrometres at the tens of metres used here.
POSITION_TOLERANCE_M = 1e-4


@pytest.fixture(scope="module")
def recipe() -> SceneRecipe:
    return mixed_recipe()


@pytest.fixture(scope="module")
def built(recipe: SceneRecipe, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    """The mixed recipe built once in bpy with proxy plants, described by the probe."""
    return build_in_bpy(recipe, tmp_path_factory.mktemp("mixed"), ["--plants", "proxies"])


def test_every_field_instances_exactly_the_layout_plants(
    recipe: SceneRecipe, built: dict[str, Any]
) -> None:
    layout = layout_scene(recipe)
    assert built["field_order"] == [spec.id for spec in recipe.fields]
    for plants in layout.fields:
        described = built["fields"][plants.field_id]
        assert plants.plant_count > 0
        assert described["points"] == plants.plant_count
        assert described["instances"]["count"] == plants.plant_count
        assert f"agrirecipe: {plants.field_id}: {plants.plant_count:,} plants" in built["log"]


def test_instance_transforms_equal_the_layout(recipe: SceneRecipe, built: dict[str, Any]) -> None:
    for plants in layout_scene(recipe).fields:
        instances = built["fields"][plants.field_id]["instances"]
        xyz = np.array(instances["xyz"])
        np.testing.assert_allclose(xyz, plants.xyz, rtol=0, atol=POSITION_TOLERANCE_M)
        turn = np.angle(np.exp(1j * (np.array(instances["yaw"]) - plants.yaw_rad)))
        np.testing.assert_allclose(turn, 0.0, atol=1e-5)
        np.testing.assert_allclose(instances["scale"], plants.scale, rtol=1e-5)
        np.testing.assert_allclose(instances["scale_z"], plants.scale, rtol=1e-5)
        assert {"yaw", "scale", "height_m"} <= set(instances["attributes"])


def test_instances_stay_inside_their_field(recipe: SceneRecipe, built: dict[str, Any]) -> None:
    for spec in recipe.fields:
        geometry, jitter = spec.geometry, spec.placement.jitter_m
        xyz = np.array(built["fields"][spec.id]["instances"]["xyz"])
        angle = math.radians(geometry.rotation_deg)
        dx, dy = xyz[:, 0] - geometry.origin_m[0], xyz[:, 1] - geometry.origin_m[1]
        across = dx * math.cos(angle) + dy * math.sin(angle)
        along = -dx * math.sin(angle) + dy * math.cos(angle)
        slack = jitter + POSITION_TOLERANCE_M
        width, length = geometry.size_m
        assert across.min() >= geometry.headland_m - slack
        assert across.max() <= width - geometry.headland_m + slack
        assert along.min() >= geometry.headland_m - slack
        assert along.max() <= length - geometry.headland_m + slack
        np.testing.assert_allclose(xyz[:, 2], 0.0, atol=POSITION_TOLERANCE_M)


def test_objects_are_named_by_field_and_carry_the_recipe(
    recipe: SceneRecipe, built: dict[str, Any]
) -> None:
    for spec in recipe.fields:
        described = built["fields"][spec.id]
        objects = described["objects"]
        assert spec.id in objects
        assert set(objects) - {spec.id, f"{spec.id}_soil"} <= {
            f"{spec.id}_mulch",
            f"{spec.id}_track",
        }
        assert f"{spec.id}_soil" in objects
        # plastic mulch only where the crop is grown on it
        assert (f"{spec.id}_mulch" in objects) == (spec.crop in ("Strawberry", "Tomato"))
        assert described["modifiers"] == [["NODES", "agrirecipe_plants"]]
        assert {"yaw", "scale", "height_m"} <= set(described["point_attributes"])
        properties = described["properties"]
        assert properties["agrirecipe_label"] == spec.label
        assert properties["agrirecipe_asset_path"] == spec.asset_path
        assert (properties["agrirecipe_crop"], properties["agrirecipe_stage"]) == (
            spec.crop,
            spec.stage,
        )
        # the soil covers the field rectangle, its crests and bed tops at the plants' z = 0
        soil = np.array(described["soil_corners"])
        turn = math.radians(spec.geometry.rotation_deg)
        dx, dy = soil[:, 0] - spec.geometry.origin_m[0], soil[:, 1] - spec.geometry.origin_m[1]
        across = dx * math.cos(turn) + dy * math.sin(turn)
        along = -dx * math.sin(turn) + dy * math.cos(turn)
        width, length = spec.geometry.size_m
        np.testing.assert_allclose([across.min(), across.max()], [0.0, width], atol=1e-4)
        np.testing.assert_allclose([along.min(), along.max()], [0.0, length], atol=1e-4)
        assert soil[:, 2].max() == pytest.approx(0.0, abs=1e-6)
    assert {"agrirecipe_ground", "agrirecipe_sun", "agrirecipe_camera"} <= set(built["objects"])


def test_plants_pick_among_their_own_proxy_variants(built: dict[str, Any]) -> None:
    for field_id, described in built["fields"].items():
        instances = described["instances"]
        proxies = [proxy["name"] for proxy in described["proxies"]]
        assert len(proxies) == 3
        assert sorted(instances["references"]) == proxies
        if instances["count"] >= 30:
            assert all(count > 0 for count in instances["reference_counts"]), field_id
    assert built["proxies_excluded"] is True  # originals never render at the origin


def test_proxies_follow_growth_form_season_and_health(
    recipe: SceneRecipe, built: dict[str, Any]
) -> None:
    fields = built["fields"]
    winter = fields["apple_winter"]["proxies"][0]
    assert set(winter["parts"]) == {"trunk", "branch"}
    assert list(winter["materials"]) == ["apple_winter_bark"]
    summer = fields["apple_summer"]["proxies"][0]
    assert {"canopy", "fruit"} <= set(summer["parts"])
    summer_spec = recipe.field("apple_summer")
    assert summer["materials"]["apple_summer_foliage"] == pytest.approx(
        summer_spec.agronomy.foliage_rgb
    )
    assert summer_spec.agronomy.fruit_rgb is not None
    assert summer["materials"]["apple_summer_fruit"] == pytest.approx(
        summer_spec.agronomy.fruit_rgb
    )
    ill = fields["carrots"]["proxies"][0]
    assert ill["materials"]["carrots_foliage"] == pytest.approx(
        recipe.field("carrots").agronomy.foliage_rgb
    )
    signatures = {
        (tuple(sorted(f["proxies"][0]["parts"])), f["proxies"][0]["faces"]) for f in fields.values()
    }
    assert len(signatures) == len(fields)  # every field's proxy is its own


def test_proxies_are_sized_like_the_plants(recipe: SceneRecipe, built: dict[str, Any]) -> None:
    for spec in recipe.fields:
        for proxy in built["fields"][spec.id]["proxies"]:
            min_x, _, min_z, max_x, _, max_z = proxy["bounds"]
            # Standing on the ground: nothing floats, nothing sinks.
            height = spec.agronomy.plant_height_m
            assert -0.02 * height <= min_z <= 0.05 * height, spec.id
            assert max_z == pytest.approx(height, rel=0.1), spec.id
            if spec.agronomy.growth_form in ("tree", "bush", "leafy_head"):
                assert max_x - min_x == pytest.approx(spec.agronomy.canopy_width_m, rel=0.35)


def test_sun_shines_from_the_recipe_sun(recipe: SceneRecipe, built: dict[str, Any]) -> None:
    sun = recipe.environment.sun
    elevation, azimuth = math.radians(sun.elevation_deg), math.radians(sun.azimuth_deg)
    toward_sun = np.array(
        [
            math.sin(azimuth) * math.cos(elevation),  # +X is east
            math.cos(azimuth) * math.cos(elevation),  # +Y is north
            math.sin(elevation),
        ]
    )
    np.testing.assert_allclose(built["sun_direction"], -toward_sun, atol=1e-5)


def test_camera_frames_every_field(built: dict[str, Any]) -> None:
    for field_id, described in built["fields"].items():
        for x, y, depth in described["corners_in_view"]:
            assert 0.0 <= x <= 1.0 and 0.0 <= y <= 1.0, field_id
            assert depth > 0.0
    assert built["camera"]["forward"][2] < -0.3  # an oblique view, looking down
    assert built["camera"]["location"][2] > 0.0


def test_default_render_settings_are_cpu_cycles(built: dict[str, Any]) -> None:
    assert built["render"] == {
        "engine": "CYCLES",
        "resolution": [960, 540],
        "device": "CPU",
        "samples": 16,
    }
    assert built["world_strength"] > 0.0


def test_hostile_label_is_kept_as_text_and_options_override_settings(tmp_path: Path) -> None:
    recipe = single_field_recipe(label=HOSTILE, prompt=HOSTILE)
    built = build_in_bpy(
        recipe,
        tmp_path,
        ["--resolution", "320x180", "--samples", "3", "--engine", "workbench"],
    )
    assert built["fields"]["plot"]["properties"]["agrirecipe_label"] == HOSTILE
    assert not (tmp_path / "PWNED").exists()
    assert built["render"]["engine"] == "BLENDER_WORKBENCH"
    assert built["render"]["resolution"] == [320, 180]
    assert built["fields"]["plot"]["instances"]["count"] == layout_scene(recipe).plant_count


@pytest.fixture(scope="module")
def built_meshes(
    recipe: SceneRecipe, tmp_path_factory: pytest.TempPathFactory
) -> tuple[dict[str, Any], Path]:
    """The mixed recipe built in bpy with the plant library's meshes (the default)."""
    folder = tmp_path_factory.mktemp("meshes")
    return build_in_bpy(recipe, folder), folder


def test_plants_are_the_library_meshes_imported_from_assets(
    recipe: SceneRecipe, built_meshes: tuple[dict[str, Any], Path]
) -> None:
    built, folder = built_meshes
    layout = layout_scene(recipe)
    for plants in layout.fields:
        spec = plants.spec
        described = built["fields"][spec.id]
        assert described["properties"]["agrirecipe_plants"] == "meshes"
        meshes = described["proxies"]
        assert [m["name"] for m in meshes] == [f"{spec.id}_plant_{v}" for v in range(3)]
        for mesh in meshes:
            assert mesh["role"] == "plant"
            assert (folder / mesh["mesh_file"]).is_file()  # written beside the script
            min_x, _, min_z, max_x, _, max_z = mesh["bounds"]
            height = spec.agronomy.plant_height_m
            assert max_z == pytest.approx(height, rel=0.05)  # glTF's Y up is Z up again
            assert 0.0 <= min_z <= max(0.02 * height, 0.01)
            assert max_x - min_x <= 1.05 * spec.agronomy.canopy_width_m
        instances = described["instances"]
        assert instances["count"] == plants.plant_count
        xyz = np.array(instances["xyz"])
        np.testing.assert_allclose(xyz, plants.xyz, rtol=0, atol=POSITION_TOLERANCE_M)


def test_each_plant_shows_the_variant_plants_csv_names(
    recipe: SceneRecipe, built_meshes: tuple[dict[str, Any], Path]
) -> None:
    built, _ = built_meshes
    for plants in layout_scene(recipe).fields:
        instances = built["fields"][plants.field_id]["instances"]
        names = instances["references"]
        shown = [int(names[i].rsplit("_", 1)[1]) for i in instances["reference_index"]]
        assert shown == plant_variants(plants.plant_count, 3).tolist()


def test_a_missing_mesh_file_falls_back_to_proxies(tmp_path: Path) -> None:
    recipe = single_field_recipe()
    BlenderBackend().write(Scene(recipe), tmp_path)
    for mesh in (tmp_path / "assets").rglob("*_v1.glb"):
        mesh.unlink()
    built = run_in_bpy(tmp_path / "blender_build.py", tmp_path / "probe.json")
    described = built["fields"]["plot"]
    assert described["properties"]["agrirecipe_plants"] == "proxies"
    assert "is missing; drawing proxies" in built["log"]
    assert described["instances"]["count"] == layout_scene(recipe).plant_count


def test_ground_view_camera_looks_along_the_rows(tmp_path: Path) -> None:
    recipe = single_field_recipe("Maize", size_m=(12.0, 20.0))
    built = build_in_bpy(recipe, tmp_path, ["--plants", "proxies", "--view", "ground"])
    camera = built["camera"]
    forward = np.array(camera["forward"])
    # field rotation 0: the rows run north (+Y); the camera looks along them, a little down
    assert forward[1] > 0.99 and abs(forward[0]) < 1e-6 and -0.2 < forward[2] < 0.0
    x, y, z = camera["location"]
    assert 0.0 < x < 12.0 and 0.0 <= y < 1.0 and z == pytest.approx(1.4)

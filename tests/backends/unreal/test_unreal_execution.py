"""Generated Unreal scripts, executed against the recording fake, build exactly the layout."""

from __future__ import annotations

import csv
import functools
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from fake_unreal import Recording, run_script
from unreal_recipes import growth_form_recipe, two_field_recipe

from agrirecipe import Scene
from agrirecipe.backends.unreal import UnrealBackend, default_scene_name
from agrirecipe.layout import FieldPlants
from agrirecipe.recipe import FieldSpec, SceneRecipe

_BASIC_SHAPE_MATERIAL = "/Engine/BasicShapes/BasicShapeMaterial.BasicShapeMaterial"
_EXPECTED_SHAPE = {
    "tree": "/Engine/BasicShapes/Cone.Cone",
    "vine": "/Engine/BasicShapes/Cylinder.Cylinder",
    "bush": "/Engine/BasicShapes/Sphere.Sphere",
    "row_crop": "/Engine/BasicShapes/Cone.Cone",
    "leafy_head": "/Engine/BasicShapes/Sphere.Sphere",
    "cereal": "/Engine/BasicShapes/Cylinder.Cylinder",
}


@functools.cache
def _scene() -> Scene:
    return Scene(two_field_recipe())


def _asset_paths(recipe: SceneRecipe) -> frozenset[str]:
    return frozenset(spec.asset_path for spec in recipe.fields)


# A folder without plant meshes: fields fall back to project assets or basic shapes.
_NO_MESHES = "/nonexistent/agrirecipe-assets"


def _run(
    scene: Scene,
    backend: UnrealBackend | None = None,
    assets_root: str | Path = _NO_MESHES,
    **fake: Any,
) -> tuple[dict[str, Any], Recording]:
    script = (backend or UnrealBackend()).script(scene)
    assert script.count("\nASSETS_ROOT = None\n") == 1
    script = script.replace("\nASSETS_ROOT = None\n", f"\nASSETS_ROOT = {str(assets_root)!r}\n")
    namespace, recording = run_script(script, **fake)
    return namespace["AGRIRECIPE_RESULT"], recording


def _field_actor(recording: Recording, spec: FieldSpec) -> Any:
    matches = [actor for actor in recording.actors_of("Actor") if actor._label == spec.label]
    assert len(matches) == 1
    return matches[0]


def _instances_cm(actor: Any) -> dict[str, np.ndarray]:
    """World transforms of an actor's instances: location (n, 3) cm, rotator (n, 3), scale."""
    component = actor._root
    origin = actor._location
    location = np.array(
        [
            (t._location.x + origin.x, t._location.y + origin.y, t._location.z + origin.z)
            for t in component._instances
        ]
    ).reshape(-1, 3)
    rotation = np.array(
        [(t._rotation.roll, t._rotation.pitch, t._rotation.yaw) for t in component._instances]
    ).reshape(-1, 3)
    scale = np.array([(t._scale.x, t._scale.y, t._scale.z) for t in component._instances]).reshape(
        -1, 3
    )
    return {"location": location, "rotation": rotation, "scale": scale}


def _wrapped_degrees(difference: np.ndarray) -> np.ndarray:
    return (difference + 180.0) % 360.0 - 180.0


def _assert_same_plants(actor: Any, plants: FieldPlants, *, placeholder: bool) -> None:
    got = _instances_cm(actor)
    assert got["location"].shape[0] == plants.plant_count
    expected_location = np.column_stack(
        (plants.xyz[:, 0] * 100.0, -plants.xyz[:, 1] * 100.0, plants.xyz[:, 2] * 100.0)
    )
    if placeholder:
        # Basic shapes are centred on their pivot: lifted by half the plant's height.
        expected_location[:, 2] += plants.height_m * 50.0
    np.testing.assert_allclose(got["location"], expected_location, rtol=0, atol=1e-6)
    assert np.all(got["rotation"][:, :2] == 0.0), "plants only turn about the vertical"
    yaw_error = _wrapped_degrees(got["rotation"][:, 2] - (-np.degrees(plants.yaw_rad)))
    np.testing.assert_allclose(yaw_error, 0.0, atol=1e-9)
    if placeholder:
        width = plants.spec.agronomy.canopy_width_m * plants.scale
        expected_scale = np.column_stack((width, width, plants.height_m))
    else:
        expected_scale = np.column_stack((plants.scale, plants.scale, plants.scale))
    np.testing.assert_allclose(got["scale"], expected_scale, rtol=1e-12, atol=0)


def test_project_assets_place_exactly_the_layout_plants() -> None:
    scene = _scene()
    result, recording = _run(scene, project_assets=_asset_paths(scene.recipe))
    assert result["cancelled"] is False
    assert recording.warnings() == []
    for plants in scene.layout.fields:
        actor = _field_actor(recording, plants.spec)
        assert actor._root._mesh._path == plants.spec.asset_path
        assert actor._root._materials == {}, "real assets keep their own materials"
        _assert_same_plants(actor, plants, placeholder=False)
        assert result["fields"][plants.field_id] == plants.plant_count
    assert result["instances"] == scene.layout.plant_count


def test_instances_match_plants_csv(tmp_path: Path) -> None:
    scene = _scene()
    scene.write(tmp_path, backends=["annotations"])
    with (tmp_path / "plants.csv").open(newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    _, recording = _run(scene, project_assets=_asset_paths(scene.recipe))
    for spec in scene.recipe.fields:
        expected = [row for row in rows if row["field_id"] == spec.id]
        got = _instances_cm(_field_actor(recording, spec))
        assert len(expected) == got["location"].shape[0] > 0
        column = {
            name: np.array([float(row[name]) for row in expected])
            for name in ("x_m", "y_m", "z_m", "yaw_deg", "scale")
        }
        # plants.csv rounds positions to 0.1 mm, yaw to 0.001 degree, scale to 1e-5.
        np.testing.assert_allclose(got["location"][:, 0], column["x_m"] * 100.0, atol=0.0051)
        np.testing.assert_allclose(got["location"][:, 1], -column["y_m"] * 100.0, atol=0.0051)
        np.testing.assert_allclose(got["location"][:, 2], column["z_m"] * 100.0, atol=0.0051)
        yaw_error = _wrapped_degrees(got["rotation"][:, 2] + column["yaw_deg"])
        np.testing.assert_allclose(yaw_error, 0.0, atol=0.00051)
        for axis in range(3):
            np.testing.assert_allclose(got["scale"][:, axis], column["scale"], atol=0.0000051)


def test_missing_assets_fall_back_to_tinted_basic_shapes_with_a_warning() -> None:
    scene = Scene(growth_form_recipe())
    result, recording = _run(scene)
    assert result["cancelled"] is False
    warnings = recording.warnings()
    assert len(warnings) == len(scene.recipe.fields)
    for plants in scene.layout.fields:
        spec = plants.spec
        assert sum(spec.asset_path in warning for warning in warnings) == 1
        actor = _field_actor(recording, spec)
        shape = _EXPECTED_SHAPE[spec.agronomy.growth_form]
        assert actor._root._mesh._path == shape
        material = actor._root._materials[0]
        assert material._parent._path == _BASIC_SHAPE_MATERIAL
        colour = material._vectors["Color"]
        assert (colour.r, colour.g, colour.b) == pytest.approx(spec.agronomy.foliage_rgb)
        _assert_same_plants(actor, plants, placeholder=True)
    assert recording.errors() == []


def test_only_the_missing_asset_is_replaced() -> None:
    scene = _scene()
    apples, carrots = scene.recipe.fields
    _, recording = _run(scene, project_assets=frozenset({apples.asset_path}))
    assert _field_actor(recording, apples)._root._mesh._path == apples.asset_path
    assert _field_actor(recording, carrots)._root._mesh._path == _EXPECTED_SHAPE["row_crop"]
    warnings = recording.warnings()
    assert len(warnings) == 1 and carrots.asset_path in warnings[0]
    # Plants of a placeholder field are as many as the layout's, too.
    assert len(_field_actor(recording, carrots)._root._instances) == (
        scene.layout.field("carrots").plant_count
    )


def test_one_labelled_foldered_actor_per_field_with_one_instanced_component() -> None:
    scene = _scene()
    _, recording = _run(scene)
    folder = f"Agrirecipe/{default_scene_name(scene.recipe)}"
    field_actors = recording.actors_of("Actor")
    assert len(field_actors) == len(scene.recipe.fields)
    for spec in scene.recipe.fields:
        actor = _field_actor(recording, spec)
        assert actor._folder == f"{folder}/{spec.id}"
        assert len(actor._components) == 1
        assert type(actor._root).__name__ == "InstancedStaticMeshComponent"
        assert actor._root._collision._name == "NO_COLLISION"
        # The actor sits at the field origin (set after its root existed).
        x, y = spec.geometry.origin_m
        assert (actor._location.x, actor._location.y, actor._location.z) == pytest.approx(
            (x * 100.0, -y * 100.0, 0.0)
        )
    ignored = [event for event in recording.events if event.kind == "location_ignored"]
    assert ignored == []
    environment = {
        type(a).__name__: a for a in recording.actors if a._folder.endswith("Environment")
    }
    assert set(environment) == {"DirectionalLight", "SkyAtmosphere", "SkyLight"}
    assert all(a._folder == f"{folder}/Environment" for a in environment.values())
    assert environment["SkyLight"]._root._real_time_capture is True


def test_instances_are_added_in_chunks() -> None:
    scene = _scene()
    _, recording = _run(scene, UnrealBackend(chunk_size=1000))
    carrots = _field_actor(recording, scene.recipe.field("carrots"))
    count = scene.layout.field("carrots").plant_count
    assert count > 3000
    calls = carrots._root._add_calls
    assert calls[:-1] == [1000] * (len(calls) - 1)
    assert 0 < calls[-1] <= 1000 and sum(calls) == count
    adds = [e for e in recording.events if e.kind == "add_instances"]
    assert all(event.details[1] is True for event in adds), "instances are given in world space"


def test_the_whole_build_is_one_transaction_inside_one_cancellable_slow_task() -> None:
    scene = _scene()
    _, recording = _run(scene, UnrealBackend(save_level=True))
    assert len(recording.transactions) == 1
    assert len(recording.slow_tasks) == 1
    kinds = [event.kind for event in recording.events]
    assert kinds[:2] == ["transaction_begin", "slow_task_begin"]
    end = kinds.index("transaction_end")
    assert kinds[end - 1] == "slow_task_end"
    for event in recording.events[2 : end - 1]:
        assert (event.transaction_depth, event.slow_task_depth) == (1, 1), event
    # Only the level save comes after the undo step closed.
    assert kinds[end + 1 :] == ["save_level"]
    task = recording.slow_tasks[0]
    assert task._dialog == (True, False)
    done = sum(work for work, _ in task._frames)
    assert 0 < done <= task._work
    assert done == pytest.approx(
        task._work - scene.recipe.nominal_plant_count + scene.layout.plant_count
    )


def test_level_is_saved_only_when_asked() -> None:
    _, recording = _run(_scene())
    assert "save_level" not in [event.kind for event in recording.events]


def test_cancelling_stops_cleanly_and_keeps_one_undo_step() -> None:
    scene = _scene()
    # Frames: sun, apples set-up, apples plants (1 chunk), apples ground, carrots set-up,
    # then the first carrot chunk asks should_cancel after 5 frames: cancelled.
    result, recording = _run(
        scene, UnrealBackend(chunk_size=500, save_level=True), cancel_after_frames=5
    )
    assert result["cancelled"] is True
    apples = scene.layout.field("apples").plant_count
    assert apples <= 500
    assert result["fields"] == {"apples": apples, "carrots": 0}
    carrots = _field_actor(recording, scene.recipe.field("carrots"))
    assert carrots._root._instances == []
    kinds = [event.kind for event in recording.events]
    assert kinds.count("transaction_end") == 1 and kinds.count("slow_task_end") == 1
    assert recording.transaction_depth == 0 and recording.slow_task_depth == 0
    assert "save_level" not in kinds, "a cancelled build is not saved"
    # The carrot field's ground was not laid after the cancel.
    assert [a._label for a in recording.actors_of("StaticMeshActor")] == ["apple orchard ground"]
    assert any("cancelled" in warning for warning in recording.warnings())
    assert recording.errors() == []


def test_cancelling_before_the_first_field_builds_no_field() -> None:
    result, recording = _run(_scene(), cancel_after_frames=1)
    assert result == {"fields": {}, "instances": 0, "cancelled": True}
    assert recording.actors_of("Actor") == []
    assert recording.transaction_depth == 0


def test_ground_planes_cover_their_fields() -> None:
    scene = _scene()
    _, recording = _run(scene, project_assets=_asset_paths(scene.recipe))
    grounds = {actor._label: actor for actor in recording.actors_of("StaticMeshActor")}
    assert len(grounds) == len(scene.recipe.fields)
    for plants in scene.layout.fields:
        spec = plants.spec
        ground = grounds[f"{spec.label} ground"]
        assert ground._root._mesh._path == "/Engine/BasicShapes/Plane.Plane"
        soil = ground._root._materials[0]._vectors["Color"]
        assert soil.r > soil.g > soil.b, "soil brown"
        width, length = spec.geometry.size_m
        assert (ground._scale.x, ground._scale.y, ground._scale.z) == pytest.approx(
            (width, length, 1.0)
        )
        yaw = ground._rotation.yaw if ground._rotation is not None else 0.0
        assert yaw == pytest.approx(-spec.geometry.rotation_deg)
        # Every plant, taken into the plane's own frame (Unreal's yaw rotates +X
        # toward +Y), lies on the 100 cm plane scaled to the field.
        location = _instances_cm(_field_actor(recording, spec))["location"]
        dx = location[:, 0] - ground._location.x
        dy = location[:, 1] - ground._location.y
        turn = math.radians(yaw)
        u = dx * math.cos(turn) + dy * math.sin(turn)
        v = -dx * math.sin(turn) + dy * math.cos(turn)
        # Plants stay inside the headland, give or take their positional jitter.
        margin_cm = (spec.geometry.headland_m - spec.placement.jitter_m) * 100.0 - 1e-6
        assert np.all(np.abs(u) <= 50.0 * width - margin_cm)
        assert np.all(np.abs(v) <= 50.0 * length - margin_cm)
        assert np.abs(u).max() > 50.0 * width - 2.0 * spec.geometry.headland_m * 100.0


@pytest.mark.parametrize(
    ("season", "latitude"),
    [("Summer", 50.8), ("Winter", 50.8), ("Spring", 10.0), ("Summer", -33.9), ("Fall", -45.0)],
)
def test_sun_light_shines_from_the_recipe_sun(season: Any, latitude: float) -> None:
    scene = Scene(two_field_recipe(season=season, latitude_deg=latitude))
    _, recording = _run(scene)
    (light,) = recording.actors_of("DirectionalLight")
    assert light._root._atmosphere_sun is True
    rotation = light._rotation
    assert rotation is not None and rotation.roll == 0.0
    pitch, yaw = math.radians(rotation.pitch), math.radians(rotation.yaw)
    # A directional light shines along its forward vector, in Unreal axes...
    forward_unreal = (
        math.cos(pitch) * math.cos(yaw),
        math.cos(pitch) * math.sin(yaw),
        math.sin(pitch),
    )
    # ...which is (x, -y, z) in the recipe's east-north-up axes.
    forward = (forward_unreal[0], -forward_unreal[1], forward_unreal[2])
    sun = scene.recipe.environment.sun
    elevation, azimuth = math.radians(sun.elevation_deg), math.radians(sun.azimuth_deg)
    towards_sun = (
        math.cos(elevation) * math.sin(azimuth),  # east
        math.cos(elevation) * math.cos(azimuth),  # north
        math.sin(elevation),
    )
    assert forward == pytest.approx(tuple(-c for c in towards_sun), abs=1e-9)
    if sun.elevation_deg > 0:
        assert forward[2] < 0, "a sun above the horizon shines downward"


# --- the plant library's meshes, imported from assets/ beside the script ---


def _component_instances(actor: Any) -> list[list[Any]]:
    """Each instanced component's transforms, in the order the components were added."""
    return [component._instances for component in actor._components]


def test_plant_meshes_are_imported_once_and_instanced_per_variant(tmp_path: Path) -> None:
    scene = _scene()
    scene.write(tmp_path, backends=["unreal", "annotations"])
    result, recording = _run(scene, assets_root=tmp_path)
    assert recording.warnings() == [] and recording.errors() == []
    with (tmp_path / "plants.csv").open(newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    imports = [t for t in recording.import_tasks if Path(t["filename"]).parent.name != "ground"]
    assert len(imports) == 3 * len(scene.recipe.fields)  # each variant once, then reused
    for task in imports:
        assert Path(task["filename"]).is_file()
        assert task["automated"] is True and task["save"] is True
    for plants in scene.layout.fields:
        spec = plants.spec
        folder = spec.asset_path.rpartition("/")[0]
        actor = _field_actor(recording, spec)
        components = actor._components
        assert len(components) == 3
        stems = [f"{spec.asset_path.rsplit('.', 1)[-1]}_v{v}" for v in range(3)]
        assert [c._mesh._path for c in components] == [f"{folder}/{s}.{s}" for s in stems]
        assert all(c._materials == {} for c in components), "meshes keep their own materials"
        variant = np.array([int(r["variant"]) for r in rows if r["field_id"] == spec.id])
        per_component = _component_instances(actor)
        assert [len(chunk) for chunk in per_component] == [
            int((variant == v).sum()) for v in range(3)
        ]
        # Every plant is placed once, on the component of its plants.csv variant.
        origin = actor._location
        expected = plants.xyz * np.array([100.0, -100.0, 100.0])
        for v, instances in enumerate(per_component):
            got = np.array(
                [
                    (t._location.x + origin.x, t._location.y + origin.y, t._location.z)
                    for t in instances
                ]
            ).reshape(-1, 3)
            np.testing.assert_allclose(got, expected[variant == v], atol=1e-6)
            scales = np.array([t._scale.x for t in instances])
            np.testing.assert_allclose(scales, plants.scale[variant == v], rtol=1e-12)
        assert result["fields"][spec.id] == plants.plant_count


def test_a_project_asset_wins_over_the_plant_meshes(tmp_path: Path) -> None:
    scene = _scene()
    apples, carrots = scene.recipe.fields
    scene.write(tmp_path, backends=["unreal"])
    _, recording = _run(scene, assets_root=tmp_path, project_assets=frozenset({apples.asset_path}))
    apple_actor = _field_actor(recording, apples)
    assert [c._mesh._path for c in apple_actor._components] == [apples.asset_path]
    imported = {
        task["filename"]
        for task in recording.import_tasks
        if Path(task["filename"]).parent.name != "ground"
    }
    assert imported and all("Carrot" in name for name in imported)
    assert len(_field_actor(recording, carrots)._components) == 3
    assert recording.warnings() == []


def test_a_second_run_reuses_the_imported_meshes(tmp_path: Path) -> None:
    scene = _scene()
    scene.write(tmp_path, backends=["unreal"])
    _, first = _run(scene, assets_root=tmp_path)
    imported = frozenset(path for path, kind in first.imported.items() if kind == "StaticMesh")
    _, second = _run(scene, assets_root=tmp_path, project_assets=imported)
    assert second.import_tasks == []
    assert second.warnings() == []


def test_ridged_fields_get_their_surface_mesh_at_the_field_origin(tmp_path: Path) -> None:
    from agrirecipe.layout import field_parameters
    from agrirecipe.plants import ground_mesh, has_relief

    scene = _scene()
    scene.write(tmp_path, backends=["unreal"])
    _, recording = _run(scene, assets_root=tmp_path)
    parameters = {str(p["id"]): p for p in field_parameters(scene.recipe)}
    grounds = {a._label: a for a in recording.actors_of("StaticMeshActor")}
    ridged = [s for s in scene.recipe.fields if has_relief(s, parameters[s.id])]
    assert ridged, "the test scene has a ridged field"
    for spec in scene.recipe.fields:
        actor = grounds[f"{spec.label} ground"]
        mesh = actor.static_mesh_component._mesh
        if spec in ridged:
            name = f"SM_Ground_{spec.id}"
            assert mesh._path.startswith("/Game/Agriculture/Ground/")
            assert mesh._path.endswith(f"/{name}.{name}")
            x, y = spec.geometry.origin_m
            location = actor._location
            assert (location.x, location.y, location.z) == pytest.approx((x * 100, -y * 100, 0))
            assert actor._scale is None  # imported in centimetres: no scaling
            task = next(t for t in recording.import_tasks if t["destination_name"] == name)
            glb = Path(task["filename"])
            assert glb == tmp_path / "assets" / "ground" / f"{spec.id}.glb"
            surface = ground_mesh(spec, parameters[spec.id])
            assert surface.triangle_count > 2  # a track or ridges, not one quad
            lowest, highest = surface.bounds
            assert highest[2] == pytest.approx(0.0, abs=0.01)  # crests at the plants' z = 0
            if spec.agronomy.planting_pattern == "ridges":
                assert lowest[2] < -0.05  # the carrots' furrows
        else:
            assert mesh._path.startswith("/Engine/BasicShapes/Plane")

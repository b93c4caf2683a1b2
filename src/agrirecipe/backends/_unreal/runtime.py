# ---------------------------------------------------------------------------
# agrirecipe Unreal Engine 5 runtime: builds the scene described by SCENE_JSON.
#
# This code runs inside the Unreal Editor's Python, never in the library: the
# Unreal backend inlines it verbatim into every generated unreal_build.py,
# after the placement kernel, so the engine computes the plant positions
# itself (the script stays proportional to fields, not plants). It uses only
# the standard library and the `unreal` module, and only API names that the
# tests check against the UE 5.6 API stub.
#
# Conventions (see agrirecipe.backends.unreal):
# - the recipe is right-handed, Z up, metres; Unreal is left-handed, Z up,
#   centimetres: (x, y, z) m -> (100 x, -100 y, 100 z) cm and a yaw of a
#   radians -> yaw = -degrees(a);
# - engine basic shapes are 100 cm with their pivot at the centre, so a
#   scale of 1.0 is one metre and a placeholder is lifted by half its height;
# - annotations evaluated at definition time stay valid on Python 3.9 (the
#   interpreter of UE 5.0-5.3), hence no `X | Y` outside quotes.
# ---------------------------------------------------------------------------
import json
import math
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import Any

import unreal

PlantSource = Callable[[dict[str, Any]], Iterable[tuple[float, float, float, float, float, float]]]
# Knuth's multiplicative hash: agrirecipe.plants.plant_variant, the same formula.
PLANT_VARIANT_HASH = 0x9E3779B1


def plant_variant(index: int, variants: int) -> int:
    """The shape variant of a field's ``index``-th plant (``plants.csv``'s ``variant``)."""
    return (((index * PLANT_VARIANT_HASH) & 0xFFFFFFFF) >> 16) % variants


def assets_root(configured: "str | None") -> str:
    """The folder holding ``assets/``: the setting, else this script's folder, else the cwd."""
    if configured:
        return configured
    script = globals().get("__file__")
    return str(Path(script).resolve().parent if script else Path.cwd())


def build_scene(scene: dict[str, Any], plants: PlantSource) -> dict[str, Any]:
    """Build every field, its ground and the light as one undo step.

    ``plants(kernel_parameters)`` yields ``(x, y, z, yaw_rad, scale, height_m)``
    per plant (the inlined placement kernel). Returns a summary: instances
    placed per field and whether the user cancelled.
    """
    header = scene["scene"]
    editor_actors = unreal.get_editor_subsystem(unreal.EditorActorSubsystem)
    subobjects = unreal.get_engine_subsystem(unreal.SubobjectDataSubsystem)
    meshes: dict[str, Any] = {}
    summary: dict[str, Any] = {"fields": {}, "instances": 0, "cancelled": False}
    unreal.log(header["log_start"])
    # One undo step for the whole scene; the slow task shows progress and a Cancel button.
    transaction = unreal.ScopedEditorTransaction(header["transaction"])
    progress = unreal.ScopedSlowTask(float(header["work"]), header["title"])
    with transaction, progress as task:
        task.make_dialog(True)
        task.enter_progress_frame(1.0, header["environment_progress"])
        build_environment(editor_actors, scene["environment"])
        for field in scene["fields"]:
            if task.should_cancel():
                summary["cancelled"] = True
                break
            placed, cancelled = build_field(
                editor_actors, subobjects, task, scene["engine"], field, plants, meshes
            )
            summary["fields"][field["id"]] = placed
            summary["instances"] += placed
            if cancelled:
                summary["cancelled"] = True
                break
    if summary["cancelled"]:
        built = len(summary["fields"])
        unreal.log_warning(
            f"{header['log_cancelled']} ({summary['instances']} plants in {built} of "
            f"{len(scene['fields'])} fields were placed; Edit > Undo removes them)"
        )
    else:
        unreal.log(f"{header['log_done']} ({summary['instances']} plants placed)")
    return summary


def build_field(
    editor_actors: unreal.EditorActorSubsystem,
    subobjects: unreal.SubobjectDataSubsystem,
    task: unreal.ScopedSlowTask,
    engine: dict[str, Any],
    field: dict[str, Any],
    plants: PlantSource,
    meshes: dict[str, Any],
) -> tuple[int, bool]:
    """One field: an actor holding an instanced static mesh, its plants, its ground.

    Returns ``(instances placed, cancelled)``.
    """
    task.enter_progress_frame(1.0, field["progress_setup"])
    # A user's own asset pack wins; then the plant library's meshes written beside
    # this script (imported once into the project); then an engine basic shape.
    mesh = load_project_mesh(field["asset_path"], meshes)
    variant_meshes = [mesh]
    placeholder_canopy_m = None
    mesh_scale = [1.0, 1.0, 1.0]
    if mesh is None and field["plant_meshes"] is not None:
        imported = import_plant_meshes(field["plant_meshes"], engine["assets_root"], meshes)
        if imported is not None:
            variant_meshes = imported
            mesh_scale = field["plant_meshes"]["scale"]
    if variant_meshes[0] is None:
        # Without any mesh a user still gets a visible, correctly laid-out scene:
        # an engine basic shape sized like the plant, tinted like its foliage.
        unreal.log_warning(field["log_missing_asset"])
        variant_meshes = [load_engine_asset(field["fallback_mesh"], meshes)]
        placeholder_canopy_m = float(field["canopy_width_m"])

    actor = spawn(
        editor_actors,
        unreal.Actor,
        field["location_cm"],
        unreal.Rotator(roll=0.0, pitch=0.0, yaw=0.0),
        field["label"],
        field["folder"],
    )
    # One instanced-mesh component per shape variant; the first becomes the root.
    components = []
    for variant_mesh in variant_meshes:
        component = add_instanced_mesh_component(subobjects, actor)
        component.set_collision_enabled(unreal.CollisionEnabled.NO_COLLISION)
        if variant_mesh is not None:
            component.set_static_mesh(variant_mesh)
        if placeholder_canopy_m is not None:
            tint(component, engine, field["foliage_rgb"], meshes)
        components.append(component)
    # A plain Actor has no root until a component becomes it; only now does moving
    # the actor stick. Instances are then given in world space.
    actor.set_actor_location(to_vector(field["location_cm"]), False, True)

    variants = len(components)
    placed = 0
    cancelled = False
    chunks: list[list[Any]] = [[] for _ in components]
    pending = 0
    chunk_size = int(engine["chunk_size"])
    for index, plant in enumerate(plants(field["kernel"])):
        transform = plant_transform(plant, placeholder_canopy_m, mesh_scale)
        chunks[plant_variant(index, variants)].append(transform)
        pending += 1
        if pending >= chunk_size:
            if task.should_cancel():
                cancelled = True
                break
            placed += flush_instances(task, components, chunks, field["progress_plants"])
            pending = 0
    if pending and not cancelled:
        placed += flush_instances(task, components, chunks, field["progress_plants"])
    if not cancelled:
        task.enter_progress_frame(1.0, field["progress_ground"])
        if not build_ground_mesh(editor_actors, engine, field["ground"], field["folder"], meshes):
            build_ground(editor_actors, engine, field["ground"], field["folder"], meshes)
    return placed, cancelled


def flush_instances(
    task: unreal.ScopedSlowTask, components: list[Any], chunks: list[list[Any]], progress: str
) -> int:
    """Add each variant's pending transforms to its component; return how many were added."""
    added = sum(len(chunk) for chunk in chunks)
    task.enter_progress_frame(float(added), progress)
    for variant, chunk in enumerate(chunks):
        if chunk:
            component = unreal.InstancedStaticMeshComponent.cast(components[variant])
            component.add_instances(chunk, False, world_space=True)
            del chunk[:]
    return added


def import_plant_meshes(
    plan: dict[str, Any], root: "str | None", meshes: dict[str, Any]
) -> "list[Any] | None":
    """The static meshes of a field's shape variants, imported from ``assets/`` if needed.

    Each ``.glb`` is imported once (AssetImportTask; glTF's metres and Y up become
    centimetres and Z up) into the catalogue's content folder and reused on the
    next run. Returns None, with a warning, when a file is missing or fails.
    """
    loaded = []
    for relative, name in zip(plan["files"], plan["names"]):  # noqa: B905 - Python 3.9
        mesh = project_or_imported_mesh(relative, plan["destination_path"], name, root, meshes)
        if mesh is None:
            return None
        loaded.append(mesh)
    return loaded


def project_or_imported_mesh(
    relative: str, destination_path: str, name: str, root: "str | None", meshes: dict[str, Any]
) -> Any:
    """The project's static mesh ``destination_path/name``, else the one imported (once)
    from ``relative`` under the folder holding ``assets/``; None when neither exists."""
    object_path = f"{destination_path}/{name}.{name}"
    if object_path not in meshes:
        filename = str(Path(assets_root(root)).joinpath(*relative.split("/")))
        meshes[object_path] = load_project_mesh(object_path, meshes) or import_glb(
            filename, destination_path, name
        )
    return meshes[object_path]


def import_glb(filename: str, destination_path: str, name: str) -> Any:
    """Import one glTF binary as a static mesh; None (with a warning) when it fails."""
    if not Path(filename).is_file():
        return None  # the field's fallback warning says where the meshes are expected
    task = unreal.AssetImportTask()
    task.set_editor_property("filename", filename)
    task.set_editor_property("destination_path", destination_path)
    task.set_editor_property("destination_name", name)
    task.set_editor_property("automated", True)
    task.set_editor_property("replace_existing", True)
    task.set_editor_property("save", True)
    unreal.AssetToolsHelpers.get_asset_tools().import_asset_tasks([task])
    for path in task.get_editor_property("imported_object_paths"):
        asset = unreal.EditorAssetLibrary.load_asset(path)
        if isinstance(asset, unreal.StaticMesh):
            unreal.log(f"agrirecipe: imported {filename} as {path}")
            return asset
    unreal.log_warning(f"agrirecipe: {filename} did not import as a static mesh")
    return None


def plant_transform(
    plant: tuple[float, float, float, float, float, float],
    placeholder_canopy_m: "float | None",
    mesh_scale: "list[float] | None" = None,
) -> unreal.Transform:
    """The world transform (cm, left-handed) of one kernel plant."""
    x, y, z, yaw_rad, scale, height_m = plant
    rotation = unreal.Rotator(roll=0.0, pitch=0.0, yaw=-math.degrees(yaw_rad))
    if placeholder_canopy_m is None:
        # Meshes (the plant library's, imported in centimetres, or the user's own).
        location = unreal.Vector(x * 100.0, -y * 100.0, z * 100.0)
        sx, sy, sz = mesh_scale or (1.0, 1.0, 1.0)
        size = unreal.Vector(scale * sx, scale * sy, scale * sz)
    else:
        # Basic shapes are 1 m at scale 1 and centred on their pivot.
        width_m = placeholder_canopy_m * scale
        location = unreal.Vector(x * 100.0, -y * 100.0, (z + height_m / 2.0) * 100.0)
        size = unreal.Vector(width_m, width_m, height_m)
    return unreal.Transform(location=location, rotation=rotation, scale=size)


def add_instanced_mesh_component(
    subobjects: unreal.SubobjectDataSubsystem, actor: unreal.Actor
) -> unreal.InstancedStaticMeshComponent:
    """Add an InstancedStaticMeshComponent to a spawned actor (it becomes the root)."""
    root = subobjects.k2_gather_subobject_data_for_instance(actor)[0]
    handle, failure = subobjects.add_new_subobject(
        unreal.AddNewSubobjectParams(
            parent_handle=root,
            new_class=unreal.InstancedStaticMeshComponent,
            blueprint_context=None,
        )
    )
    if not failure.is_empty():
        raise RuntimeError(f"agrirecipe: could not add an instanced mesh component: {failure}")
    created = unreal.SubobjectDataBlueprintFunctionLibrary.get_object(
        unreal.SubobjectDataBlueprintFunctionLibrary.get_data(handle)
    )
    return unreal.InstancedStaticMeshComponent.cast(created)


def load_project_mesh(path: str, meshes: dict[str, Any]) -> Any:
    """The static mesh at a project asset path, or None when it is missing or not a mesh."""
    if path not in meshes:
        mesh = None
        if unreal.EditorAssetLibrary.does_asset_exist(path):
            asset = unreal.EditorAssetLibrary.load_asset(path)
            if isinstance(asset, unreal.StaticMesh):
                mesh = asset
        meshes[path] = mesh
    return meshes[path]


def load_engine_asset(path: str, meshes: dict[str, Any]) -> Any:
    """An engine content asset (basic shape, basic material), cached; None if it fails to load."""
    if path not in meshes:
        asset = unreal.load_asset(path)
        if asset is None:
            unreal.log_error(f"agrirecipe: engine asset {path} could not be loaded")
        meshes[path] = asset
    return meshes[path]


def tint(
    component: unreal.StaticMeshComponent,
    engine: dict[str, Any],
    rgb: list[float],
    meshes: dict[str, Any],
) -> None:
    """Colour a basic-shape mesh through the engine's BasicShapeMaterial colour parameter."""
    material = load_engine_asset(engine["basic_shape_material"], meshes)
    if not isinstance(material, unreal.MaterialInterface):
        return
    instance = component.create_dynamic_material_instance(0, material)
    instance.set_vector_parameter_value(
        engine["colour_parameter"], unreal.LinearColor(r=rgb[0], g=rgb[1], b=rgb[2], a=1.0)
    )


def build_ground_mesh(
    editor_actors: unreal.EditorActorSubsystem,
    engine: dict[str, Any],
    ground: dict[str, Any],
    folder: str,
    meshes: dict[str, Any],
) -> bool:
    """The field's surface (ridges, beds, mulch, track) from ``assets/ground/``, imported
    once; False when the field has none or it cannot be imported (the plane is used)."""
    plan = ground.get("mesh")
    if plan is None:
        return False
    mesh = project_or_imported_mesh(
        plan["file"], plan["destination_path"], plan["name"], engine["assets_root"], meshes
    )
    if mesh is None:
        # the plants' warning already says where assets/ is expected
        unreal.log(f"agrirecipe: no ground mesh {plan['file']}; a flat plane is used")
        return False
    actor = unreal.StaticMeshActor.cast(
        spawn(
            editor_actors,
            unreal.StaticMeshActor,
            plan["origin_cm"],
            unreal.Rotator(roll=0.0, pitch=0.0, yaw=float(ground["yaw_deg"])),
            ground["label"],
            folder,
        )
    )
    actor.static_mesh_component.set_static_mesh(mesh)
    return True


def build_ground(
    editor_actors: unreal.EditorActorSubsystem,
    engine: dict[str, Any],
    ground: dict[str, Any],
    folder: str,
    meshes: dict[str, Any],
) -> None:
    """A soil-coloured plane under a field (the 100 cm engine plane, scaled to the field)."""
    actor = unreal.StaticMeshActor.cast(
        spawn(
            editor_actors,
            unreal.StaticMeshActor,
            ground["location_cm"],
            unreal.Rotator(roll=0.0, pitch=0.0, yaw=float(ground["yaw_deg"])),
            ground["label"],
            folder,
        )
    )
    actor.set_actor_scale3d(to_vector(ground["scale"]))
    component = actor.static_mesh_component
    plane = load_engine_asset(engine["ground_mesh"], meshes)
    if plane is not None:
        component.set_static_mesh(plane)
    tint(component, engine, engine["soil_rgb"], meshes)


def build_environment(
    editor_actors: unreal.EditorActorSubsystem, environment: dict[str, Any]
) -> None:
    """The sun as a DirectionalLight (and optionally a sky atmosphere and sky light)."""
    sun = environment["sun"]
    folder = environment["folder"]
    light = unreal.DirectionalLight.cast(
        spawn(
            editor_actors,
            unreal.DirectionalLight,
            sun["location_cm"],
            unreal.Rotator(roll=0.0, pitch=float(sun["pitch_deg"]), yaw=float(sun["yaw_deg"])),
            sun["label"],
            folder,
        )
    )
    unreal.DirectionalLightComponent.cast(light.light_component).set_atmosphere_sun_light(True)
    if environment["sky"]:
        level = unreal.Rotator(roll=0.0, pitch=0.0, yaw=0.0)
        label = environment["sky_atmosphere_label"]
        spawn(editor_actors, unreal.SkyAtmosphere, sun["location_cm"], level, label, folder)
        label = environment["sky_light_label"]
        sky_light = unreal.SkyLight.cast(
            spawn(editor_actors, unreal.SkyLight, sun["location_cm"], level, label, folder)
        )
        sky_light.light_component.set_real_time_capture(True)


def spawn(
    editor_actors: unreal.EditorActorSubsystem,
    actor_class: type,
    location_cm: list[float],
    rotation: unreal.Rotator,
    label: str,
    folder: str,
) -> unreal.Actor:
    """Spawn an actor in the editor world, labelled and put in an outliner folder."""
    actor = editor_actors.spawn_actor_from_class(actor_class, to_vector(location_cm), rotation)
    actor.set_actor_label(label)
    actor.set_folder_path(folder)
    return actor


def to_vector(values: list[float]) -> unreal.Vector:
    """An unreal.Vector from three numbers (already in Unreal's frame and units)."""
    return unreal.Vector(float(values[0]), float(values[1]), float(values[2]))


def save_current_level() -> bool:
    """Save the level the scene was built into (headless runs would lose it otherwise)."""
    return bool(unreal.get_editor_subsystem(unreal.LevelEditorSubsystem).save_current_level())


def run(scene_json: str, plants: PlantSource, assets: "str | None" = None) -> dict[str, Any]:
    """Parse the scene description, build it, and save the level when it asks to.

    ``assets`` is the folder holding the plant library's ``assets/`` (None: the
    folder of this script).
    """
    scene = json.loads(scene_json)
    scene["engine"]["assets_root"] = assets
    summary = build_scene(scene, plants)
    saving = scene["scene"]["save_level"] and not summary["cancelled"]
    if saving and not save_current_level():
        unreal.log_error("agrirecipe: the level could not be saved")
    return summary

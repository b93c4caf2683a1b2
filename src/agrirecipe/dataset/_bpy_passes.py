# agrirecipe dataset passes (runs inside Blender).
#
# The library never imports this file: agrirecipe.dataset appends its source,
# verbatim, to a generated blender_build.py (after the Blender backend's scene
# builder), followed by one call of `render_dataset_views(AGRIRECIPE_REPORT, JOB, SCENE)`.
# It uses only bpy, the standard library and names the builder defines
# (`plants_node_group`, `look_rotation`, `fit_view`, `scene_bounds`, `srgb_to_linear`;
# imported below for type checkers only). Rules as for the builder: no
# `from __future__`, no agrirecipe import at run time.
"""Render an agrirecipe scene's dataset views: RGB, then an exact label pass per camera."""

import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import bpy

if TYPE_CHECKING:  # defined by the scene builder, earlier in the same generated script
    from agrirecipe.backends._blender.scene_builder import (
        fit_view,
        look_rotation,
        plants_node_group,
        scene_bounds,
        srgb_to_linear,
    )

#: Value AOVs of the label render (read back from its multilayer EXR).
LABEL_AOVS = ("agr_field", "agr_plant", "agr_ground")
#: ``agr_ground`` values: the object index of ground objects.
GROUND_SOIL, GROUND_OTHER = 1, 2
#: ``agr_field`` of weeds (crops hold their field's index + 1).
WEED_FIELD = -1.0
_LABEL_MATERIAL = "agrirecipe_dataset_labels"


def _instancer_attribute(nodes: Any, name: str) -> Any:
    node = nodes.new("ShaderNodeAttribute")
    node.attribute_type = "INSTANCER"
    node.attribute_name = name
    return node


def label_material() -> Any:
    """The override material of the label render: black diffuse, and three value AOVs.

    ``agr_field``/``agr_plant`` are the instance attributes the dataset adds to
    every field's points (so to every plant instance); ``agr_ground`` is the
    object's pass index (soil 1, other ground 2, else 0).
    """
    material = bpy.data.materials.new(_LABEL_MATERIAL)
    if material.node_tree is None:  # Blender 4.x creates materials without nodes
        material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    # A black diffuse surface: the camera ray stops at it. (A shader without a closure,
    # such as a zero-strength emission, lets the ray pass on and sums the AOVs of
    # every surface behind.)
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    links.new(diffuse.outputs[0], output.inputs["Surface"])
    info = nodes.new("ShaderNodeObjectInfo")
    sources = {
        "agr_field": _instancer_attribute(nodes, "agr_field").outputs["Fac"],
        "agr_plant": _instancer_attribute(nodes, "agr_plant").outputs["Fac"],
        "agr_ground": info.outputs["Object Index"],
    }
    for name, socket in sources.items():
        aov = nodes.new("ShaderNodeOutputAOV")
        aov.aov_name = name
        links.new(socket, aov.inputs["Value"])
    return material


def tag_plants(scene_data: dict[str, Any]) -> None:
    """Give every plant instance its field (index + 1) and its index in the field."""
    for index, field in enumerate(scene_data["fields"]):
        points = bpy.data.objects[field["id"]]
        mesh = points.data
        count = len(mesh.vertices)
        field_values = mesh.attributes.new("agr_field", "FLOAT", "POINT")
        field_values.data.foreach_set("value", [float(index + 1)] * count)
        plant_values = mesh.attributes.new("agr_plant", "FLOAT", "POINT")
        plant_values.data.foreach_set("value", [float(i) for i in range(count)])
        mesh.update()


def tag_ground(scene_data: dict[str, Any]) -> list[Any]:
    """Pass indices of the ground (field soil 1, the grass base 2); returns the soil
    materials (the ones wet soil darkens)."""
    field_ids = {field["id"] for field in scene_data["fields"]}
    materials: list[Any] = []
    for obj in bpy.data.objects:
        if obj.type != "MESH" or obj.name in field_ids:
            continue
        if obj.name == "agrirecipe_ground":
            obj.pass_index = GROUND_OTHER
        elif obj.get("agrirecipe_field_id") is not None:
            obj.pass_index = GROUND_SOIL
            materials.extend(slot.material for slot in obj.material_slots if slot.material)
    return materials


def weed_mesh(name: str, leaves: int, phase: float) -> Any:
    """A weed rosette 1 unit across (scaled per plant): ``leaves`` blades rising from its centre."""
    verts: list[tuple[float, float, float]] = []
    faces: list[tuple[int, ...]] = []
    for leaf in range(leaves):
        angle = phase + 2 * math.pi * leaf / leaves
        ca, sa = math.cos(angle), math.sin(angle)
        rise = 0.35 + 0.5 * ((leaf * 7) % leaves) / leaves
        base = len(verts)
        for along, half_width, height in ((0.0, 0.0, 0.0), (0.45, 0.16, 0.6), (1.0, 0.0, 1.0)):
            for side in (-1.0, 1.0) if half_width else (0.0,):
                x = along * 0.5
                y = side * half_width * 0.5
                verts.append((x * ca - y * sa, x * sa + y * ca, height * rise * 0.5))
        faces.append((base, base + 1, base + 3, base + 2))
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    return mesh


def build_weeds(weeds: dict[str, Any], parent: Any, root: Any) -> int:
    """The weeds of one variant: a point cloud instancing a few procedural rosettes."""
    count = len(weeds["x"])
    if count == 0:
        return 0
    collection = bpy.data.collections.new("agrirecipe_weed_shapes")
    parent.children.link(collection)
    material = bpy.data.materials.new("agrirecipe_weed")
    if material.node_tree is None:  # Blender 4.x creates materials without nodes
        material.use_nodes = True
    colour = srgb_to_linear(weeds["rgb"])
    material.diffuse_color = colour
    bsdf = material.node_tree.nodes.get("Principled BSDF")
    if bsdf is not None:
        bsdf.inputs["Base Color"].default_value = colour
        bsdf.inputs["Roughness"].default_value = 0.7
    for variant, leaves in enumerate(weeds["leaves"]):
        mesh = weed_mesh(f"agrirecipe_weed_v{variant}", int(leaves), 0.7 * variant)
        mesh.materials.append(material)
        shape = bpy.data.objects.new(f"agrirecipe_weed_v{variant}", mesh)
        collection.objects.link(shape)
    mesh = bpy.data.meshes.new("agrirecipe_weeds_points")
    mesh.vertices.add(count)
    coordinates = [c for xyz in zip(weeds["x"], weeds["y"], weeds["z"], strict=True) for c in xyz]
    mesh.vertices.foreach_set("co", coordinates)
    columns = {
        "yaw": weeds["yaw"],
        "scale": weeds["size_m"],
        "agr_field": [WEED_FIELD] * count,
        "agr_plant": [float(i) for i in range(count)],
    }
    for name, values in columns.items():
        mesh.attributes.new(name, "FLOAT", "POINT").data.foreach_set("value", values)
    chosen = mesh.attributes.new("variant", "INT", "POINT")
    chosen.data.foreach_set("value", [int(v) for v in weeds["variant"]])
    mesh.update()
    points = bpy.data.objects.new("agrirecipe_weeds", mesh)
    root.objects.link(points)
    modifier = points.modifiers.new("agrirecipe_weeds", "NODES")
    group = plants_node_group()
    modifier.node_group = group
    for item in group.interface.items_tree:
        if getattr(item, "in_out", None) == "INPUT" and item.name == "Proxies":
            modifier[item.identifier] = collection
    return count


def apply_conditions(scene: Any, conditions: dict[str, Any], soils: Sequence[Any]) -> None:
    """Sun direction and strength, sky, and wet soil for one variant."""
    sun = bpy.data.objects.get("agrirecipe_sun")
    if sun is not None:
        elevation = max(float(conditions["sun_elevation_deg"]), 2.0)
        sun.rotation_euler = look_rotation(float(conditions["sun_azimuth_deg"]) + 180.0, -elevation)
        sun.data.energy *= float(conditions["sun_factor"])
    world = scene.world
    if world is not None and world.node_tree is not None:
        background = next(
            (n for n in world.node_tree.nodes if n.bl_idname == "ShaderNodeBackground"), None
        )
        if background is not None:
            background.inputs["Color"].default_value = srgb_to_linear(conditions["sky_rgb"])
            background.inputs["Strength"].default_value *= float(conditions["sky_factor"])
    if conditions["wet_soil"]:
        for material in {m.name: m for m in soils}.values():
            bsdf = material.node_tree.nodes.get("Principled BSDF") if material.node_tree else None
            if bsdf is None:
                continue
            colour = bsdf.inputs["Base Color"].default_value
            bsdf.inputs["Base Color"].default_value = (
                colour[0] * 0.55,
                colour[1] * 0.55,
                colour[2] * 0.55,
                1.0,
            )
            bsdf.inputs["Roughness"].default_value = 0.35


def place_camera(scene: Any, scene_data: dict[str, Any], view: dict[str, Any]) -> Any:
    """The camera of one view: a given pose, or the overview fitted to every field."""
    width, height = scene.render.resolution_x, scene.render.resolution_y
    data = bpy.data.cameras.new(f"agrirecipe_dataset_{view['name']}")
    data.sensor_width = float(view["sensor_width_mm"])
    data.clip_start = float(view["clip_start_m"])
    data.clip_end = float(view["clip_end_m"])
    bearing, pitch = float(view["bearing_deg"]), float(view["pitch_deg"])
    if view["kind"] == "overview":
        data.sensor_fit = "AUTO"
        data.lens = float(view["lens_mm"])
        min_x, min_y, max_x, max_y, top = scene_bounds(scene_data["fields"])
        corners = [(x, y, z) for x in (min_x, max_x) for y in (min_y, max_y) for z in (0.0, top)]
        target = ((min_x + max_x) / 2, (min_y + max_y) / 2, 0.0)
        back_bearing, elevation = math.radians(bearing + 180.0), math.radians(-pitch)
        backward = (
            math.sin(back_bearing) * math.cos(elevation),
            math.cos(back_bearing) * math.cos(elevation),
            math.sin(elevation),
        )
        aspect = width / height
        half_wide = data.sensor_width / 2.0 / data.lens / float(view["margin"])
        tan_x, tan_y = (
            (half_wide, half_wide / aspect) if aspect >= 1 else (half_wide * aspect, half_wide)
        )
        distance, data.shift_x, data.shift_y = fit_view(corners, target, backward, tan_x, tan_y)
        location = tuple(t + b * distance for t, b in zip(target, backward, strict=True))
        data.clip_end = max(data.clip_end, 3.0 * distance)
    else:
        data.sensor_fit = "HORIZONTAL"
        data.lens = float(view["lens_mm"])
        location = tuple(float(v) for v in view["location_m"])
    camera = bpy.data.objects.new(f"agrirecipe_dataset_{view['name']}", data)
    camera.location = location
    camera.rotation_euler = look_rotation(bearing, pitch)
    scene.collection.objects.link(camera)
    scene.camera = camera
    bpy.context.view_layer.update()
    return camera


def camera_record(scene: Any, camera: Any) -> dict[str, Any]:
    """Intrinsics K (pixels) and the world-to-camera matrix (OpenCV axes: x right, y down,
    z forward) of the camera as Blender renders it."""
    width, height = scene.render.resolution_x, scene.render.resolution_y
    data = camera.data
    # AUTO: the sensor width spans the wider side; the dataset's own cameras fit it to the width.
    reference = max(width, height) if data.sensor_fit == "AUTO" else width
    focal_px = data.lens / data.sensor_width * reference
    shift_unit = reference
    cx = width / 2.0 - data.shift_x * shift_unit
    cy = height / 2.0 + data.shift_y * shift_unit
    world = camera.matrix_world
    rotation = [[world[r][c] for c in range(3)] for r in range(3)]
    centre = [world[r][3] for r in range(3)]
    flip = (1.0, -1.0, -1.0)
    # OpenCV rotation: rows are the camera axes in world coordinates (Blender's y and z flipped).
    r_cv = [[flip[a] * rotation[c][a] for c in range(3)] for a in range(3)]
    t_cv = [-sum(r_cv[a][c] * centre[c] for c in range(3)) for a in range(3)]
    extrinsic = [[*r_cv[a], t_cv[a]] for a in range(3)] + [[0.0, 0.0, 0.0, 1.0]]
    return {
        "K": [[focal_px, 0.0, cx], [0.0, focal_px, cy], [0.0, 0.0, 1.0]],
        "world_to_camera": extrinsic,
        "location_m": centre,
        "lens_mm": data.lens,
        "sensor_width_mm": data.sensor_width,
        "sensor_fit": data.sensor_fit,
        "shift": [data.shift_x, data.shift_y],
    }


def rgb_mode(scene: Any, job: dict[str, Any], layer: Any) -> None:
    """Settings of the colour render: path traced, filtered, the job's samples."""
    cycles = scene.cycles
    cycles.samples = int(job["samples"])
    cycles.use_denoising = bool(job["denoise"])
    cycles.max_bounces = 4
    cycles.filter_width = 1.5
    cycles.pixel_filter_type = "BLACKMAN_HARRIS"
    layer.material_override = None
    if hasattr(scene.render.image_settings, "media_type"):
        scene.render.image_settings.media_type = "IMAGE"
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.color_depth = "8"


def label_mode(scene: Any, layer: Any, material: Any) -> None:
    """Settings of the label render: one unfiltered ray through each pixel centre, so every
    pixel holds exactly one surface's values (no blending across edges)."""
    cycles = scene.cycles
    cycles.samples = 1
    cycles.use_denoising = False
    cycles.max_bounces = 0
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 0.01
    layer.material_override = material
    settings = scene.render.image_settings
    if hasattr(settings, "media_type"):  # Blender 5: multilayer EXR is a media type
        settings.media_type = "MULTI_LAYER_IMAGE"
    settings.file_format = "OPEN_EXR_MULTILAYER"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"


#: GPU back-ends Cycles may offer, in order of preference.
GPU_KINDS = ("OPTIX", "CUDA", "HIP", "ONEAPI", "METAL")


def choose_device(scene: Any, requested: str) -> str:
    """Render on a GPU when ``requested`` is ``"gpu"`` and Cycles finds one, else the CPU;
    returns what was chosen (``"CPU"``, ``"OPTIX"``, ``"CUDA"``...)."""
    scene.cycles.device = "CPU"
    if requested != "gpu":
        return "CPU"
    addon = bpy.context.preferences.addons.get("cycles")
    if addon is None:
        return "CPU"
    preferences = addon.preferences
    for kind in GPU_KINDS:
        try:
            preferences.compute_device_type = kind
        except TypeError:  # not built into this Blender
            continue
        preferences.get_devices()
        gpus = [device for device in preferences.devices if device.type == kind]
        if gpus:
            for device in preferences.devices:
                device.use = device.type == kind
            scene.cycles.device = "GPU"
            return kind
    return "CPU"


def render_to(scene: Any, path: str) -> None:
    """Render with the scene camera to ``path`` (format from the image settings)."""
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True, scene=scene.name)


def render_dataset_views(
    report: dict[str, Any], job: dict[str, Any], scene_data: dict[str, Any]
) -> None:
    """Weeds, conditions, then per view an RGB PNG, a label EXR and ``cameras.json``."""
    scene = report["scene"]
    tag_plants(scene_data)
    soils = tag_ground(scene_data)
    root = bpy.data.collections["agrirecipe"]
    shapes = bpy.data.collections["agrirecipe_proxies"]
    build_weeds(job["weeds"], shapes, root)
    apply_conditions(scene, job["conditions"], soils)
    render = scene.render
    render.resolution_x, render.resolution_y = (int(v) for v in job["resolution"])
    render.threads_mode = "FIXED"
    render.threads = int(job["threads"])
    render.use_persistent_data = True
    scene.cycles.seed = int(job["cycles_seed"])
    scene.cycles.use_animated_seed = False
    device = choose_device(scene, str(job.get("device", "cpu")))
    layer = scene.view_layers[0]
    layer.use_pass_z = True
    for name in LABEL_AOVS:
        if name not in layer.aovs:
            aov = layer.aovs.add()
            aov.name, aov.type = name, "VALUE"
    material = label_material()
    out = Path(job["output_dir"])
    records = []
    for view in job["views"]:
        camera = place_camera(scene, scene_data, view)
        rgb_mode(scene, job, layer)
        render_to(scene, str(out / f"{view['name']}.rgb.png"))
        label_mode(scene, layer, material)
        render_to(scene, str(out / f"{view['name']}.labels.exr"))
        records.append({"name": view["name"], **camera_record(scene, camera)})
    (out / "cameras.json").write_text(json.dumps(records, indent=1), encoding="utf-8")
    (out / "device.txt").write_text(device, encoding="utf-8")

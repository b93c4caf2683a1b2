"""Run a generated ``blender_build.py`` in real bpy and describe the built scene as JSON.

Usage (in a child process, so every test scene gets a fresh Blender)::

    python blender_probe.py SCRIPT OUTPUT_JSON [ARGS...]

The script runs exactly as ``python blender_build.py ARGS...`` would (as
``__main__``); then the evaluated depsgraph is read: per field the Geometry
Nodes instances (count, transforms, referenced proxies), the proxies and their
materials, the sun, the camera and the render settings.
"""

from __future__ import annotations

import json
import runpy
import sys
from pathlib import Path
from typing import Any

import bpy
import numpy as np
from bpy_extras.object_utils import world_to_camera_view
from mathutils import Vector


def _instances(obj: Any, depsgraph: Any) -> dict[str, Any]:
    geometry = obj.evaluated_get(depsgraph).evaluated_geometry()
    cloud = geometry.instances_pointcloud()
    if cloud is None:
        return {"count": 0, "xyz": [], "yaw": [], "scale": [], "references": [], "attributes": []}
    count = len(cloud.points)
    flat = np.empty(count * 16, dtype=np.float32)
    cloud.attributes["instance_transform"].data.foreach_get("value", flat)
    # Blender stores 4x4 matrices column by column: row k of this array is column k.
    columns = flat.reshape(count, 4, 4).astype(np.float64)
    variants = np.empty(count, dtype=np.int32)
    cloud.attributes[".reference_index"].data.foreach_get("value", variants)
    references = []
    for reference in geometry.instance_references():
        name = getattr(reference, "name", None)
        references.append(name if name is not None else repr(reference))
    return {
        "count": count,
        "xyz": columns[:, 3, :3].tolist(),
        "yaw": np.arctan2(columns[:, 0, 1], columns[:, 0, 0]).tolist(),
        "scale": np.linalg.norm(columns[:, 0, :3], axis=1).tolist(),
        "scale_z": np.linalg.norm(columns[:, 2, :3], axis=1).tolist(),
        "references": references,
        "reference_counts": np.bincount(variants, minlength=len(references)).tolist(),
        "reference_index": variants.tolist(),
        "attributes": sorted(a.name for a in cloud.attributes if not a.name.startswith(".")),
    }


def _proxies(collection: Any) -> list[dict[str, Any]]:
    proxies = []
    for obj in sorted(collection.objects, key=lambda o: o.name):
        mesh = obj.data
        zs = [v.co.z for v in mesh.vertices]
        xs = [v.co.x for v in mesh.vertices]
        ys = [v.co.y for v in mesh.vertices]
        used_slots = {polygon.material_index for polygon in mesh.polygons}
        proxies.append(
            {
                "name": obj.name,
                "role": obj.get("agrirecipe_role"),
                "mesh_file": obj.get("agrirecipe_mesh_file"),
                "parts": list(obj.get("agrirecipe_parts", [])),
                "materials": {
                    mesh.materials[slot].name: list(mesh.materials[slot].get("agrirecipe_srgb", []))
                    for slot in sorted(used_slots)
                },
                "faces": len(mesh.polygons),
                "bounds": [min(xs), min(ys), min(zs), max(xs), max(ys), max(zs)],
            }
        )
    return proxies


def _world_strength(scene: Any) -> float:
    background = scene.world.node_tree.nodes["Background"]
    return float(background.inputs["Strength"].default_value)


def describe() -> dict[str, Any]:
    """The built scene as plain data."""
    scene = bpy.context.scene
    depsgraph = bpy.context.evaluated_depsgraph_get()
    camera = scene.camera
    fields: dict[str, Any] = {}
    for collection in bpy.data.collections["agrirecipe"].children:
        field_id = collection.name
        obj = bpy.data.objects[field_id]
        soil = bpy.data.objects[f"{field_id}_soil"]
        corners = [soil.matrix_world @ v.co for v in soil.data.vertices]
        fields[field_id] = {
            "objects": sorted(o.name for o in collection.objects),
            "points": len(obj.data.vertices),
            "point_attributes": sorted(
                a.name for a in obj.data.attributes if not a.name.startswith(".")
            ),
            "modifiers": [(m.type, m.node_group.name) for m in obj.modifiers],
            "properties": {
                key: obj[key]
                for key in obj.keys()  # noqa: SIM118 - bpy objects are not iterable
                if key.startswith("agrirecipe_")
            },
            "instances": _instances(obj, depsgraph),
            "soil_corners": [list(c) for c in corners],
            "corners_in_view": [
                list(world_to_camera_view(scene, camera, corner)) for corner in corners
            ],
            "proxies": _proxies(bpy.data.collections[f"{field_id}_proxies"]),
        }
    sun = bpy.data.objects["agrirecipe_sun"]
    sun_direction = sun.matrix_world.to_3x3() @ Vector((0.0, 0.0, -1.0))
    proxy_layer = scene.view_layers[0].layer_collection.children["agrirecipe_proxies"]
    return {
        "fields": fields,
        "field_order": [c.name for c in bpy.data.collections["agrirecipe"].children],
        "objects": sorted(o.name for o in scene.objects),
        "proxies_excluded": proxy_layer.exclude,
        "sun_direction": list(sun_direction),
        "sun_energy": sun.data.energy,
        "camera": {
            "name": camera.name,
            "location": list(camera.location),
            "forward": list(camera.matrix_world.to_3x3() @ Vector((0.0, 0.0, -1.0))),
        },
        "render": {
            "engine": scene.render.engine,
            "resolution": [scene.render.resolution_x, scene.render.resolution_y],
            "device": scene.cycles.device,
            "samples": scene.cycles.samples,
        },
        "world_strength": _world_strength(scene),
    }


def main() -> None:
    script, output, *args = sys.argv[1:]
    sys.argv = [script, *args]
    runpy.run_path(script, run_name="__main__")
    Path(output).write_text(json.dumps(describe()), encoding="utf-8")


if __name__ == "__main__":
    main()

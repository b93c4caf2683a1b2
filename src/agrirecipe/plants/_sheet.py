"""A contact sheet of the plant library: every crop at each stage, season and health.

One row per crop (its first variety, or the one asked for) and one column per
(stage, season, health) of the catalogue, each cell the variant-0 mesh scaled to
fit, rendered headless in Blender (Workbench: studio light, material colours,
shadows, one anti-aliasing pass, so hundreds of plants render in seconds on a
CPU's software OpenGL; the meshes are read from their .glb files directly) and labelled with
Pillow. Blender runs in a child Python process, so the caller's own ``bpy`` state
is untouched and a Blender crash is a :class:`~agrirecipe.BackendError`.
"""

from __future__ import annotations

import json
import tempfile
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from agrirecipe._errors import BackendError, ConfigurationError
from agrirecipe._files import atomic_path
from agrirecipe.backends.blender import run_bpy_child
from agrirecipe.hierarchy import AssetKey
from agrirecipe.knowledge import KnowledgeBase, default_knowledge_base
from agrirecipe.plants._library import asset_glb, plant_spec

if TYPE_CHECKING:
    from PIL import ImageFont

__all__ = ["contact_sheet", "sheet_keys"]

_LABEL_PX = 220
_HEADER_PX = 70

# The Blender side: import each mesh into its cell, light, frame, render. Plain data in,
# no agrirecipe import (it runs in a child process with only bpy).
_BLENDER = r"""
import json, math, struct, sys
import bpy
import numpy as np

def read_glb(path):
    # The meshes' own glTF binary, read directly: the importer operator slows down
    # with every object already in the scene, and hundreds are imported here.
    data = open(path, "rb").read()
    length, _ = struct.unpack_from("<II", data, 12)
    document = json.loads(data[20:20 + length])
    binary = data[20 + length + 8:]
    def accessor(index, dtype, width):
        acc = document["accessors"][index]
        view = document["bufferViews"][acc["bufferView"]]
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        return np.frombuffer(
            binary, dtype=dtype, count=acc["count"] * width, offset=start
        ).reshape(-1, width)
    parts = []
    for primitive in document["meshes"][0]["primitives"]:
        points = accessor(primitive["attributes"]["POSITION"], "<f4", 3)
        kind = document["accessors"][primitive["indices"]]["componentType"]
        index_type = "<u2" if kind == 5123 else "<u4"
        triangles = accessor(primitive["indices"], index_type, 1).reshape(-1, 3)
        material = document["materials"][primitive["material"]]
        rgb = material["pbrMetallicRoughness"]["baseColorFactor"][:3]
        # glTF is Y up: (x, y, z) was written as (x, z, -y)
        points = np.stack([points[:, 0], -points[:, 2], points[:, 1]], axis=1)
        parts.append((points, triangles.astype(np.int64), material["name"], rgb))
    return parts

job = json.loads(open(sys.argv[1], encoding="utf-8").read())
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
cell = 1.0
materials = {}
for item in job["cells"]:
    size = max(item["height_m"], item["width_m"], 1e-3)
    factor = 0.85 * cell / size
    turn = math.radians(item["turn_deg"])
    tilt = math.radians(18.0)
    for points, triangles, name, rgb in read_glb(item["file"]):
        # turned about Z, tipped towards the camera, scaled into the cell
        x = points[:, 0] * math.cos(turn) - points[:, 1] * math.sin(turn)
        y = points[:, 0] * math.sin(turn) + points[:, 1] * math.cos(turn)
        z = points[:, 2]
        y, z = y * math.cos(tilt) - z * math.sin(tilt), y * math.sin(tilt) + z * math.cos(tilt)
        placed = np.stack(
            [x * factor + item["column"] * cell, y * factor,
             z * factor - item["row"] * cell - 0.45 * cell],
            axis=1,
        ).astype(np.float32)
        mesh = bpy.data.meshes.new(name)
        mesh.vertices.add(len(placed))
        mesh.vertices.foreach_set("co", placed.ravel())
        mesh.loops.add(triangles.size)
        mesh.loops.foreach_set("vertex_index", triangles.ravel().astype(np.int32))
        mesh.polygons.add(len(triangles))
        mesh.polygons.foreach_set("loop_start", np.arange(0, triangles.size, 3, dtype=np.int32))
        mesh.update(calc_edges=True)
        key = (name, tuple(round(c, 4) for c in rgb))
        if key not in materials:
            material = bpy.data.materials.new(name)
            material.diffuse_color = (rgb[0], rgb[1], rgb[2], 1.0)
            materials[key] = material
        mesh.materials.append(materials[key])
        obj = bpy.data.objects.new(name, mesh)
        scene.collection.objects.link(obj)
columns, rows = job["columns"], job["rows"]
camera_data = bpy.data.cameras.new("sheet")
camera_data.type = "ORTHO"
# the orthographic scale spans the image's longer side; the cells are square
camera_data.ortho_scale = max(columns, rows) * cell
camera = bpy.data.objects.new("sheet", camera_data)
scene.collection.objects.link(camera)
camera.location = ((columns - 1) * cell / 2.0, -50.0, -(rows - 1) * cell / 2.0)
camera.rotation_euler = (math.radians(90.0), 0.0, 0.0)
scene.camera = camera
scene.render.engine = "BLENDER_WORKBENCH"
shading = scene.display.shading
shading.light = "STUDIO"
shading.color_type = "MATERIAL"
shading.show_shadows = True
shading.show_cavity = True
shading.background_type = "WORLD"
scene.display.render_aa = "FXAA"
scene.render.resolution_x = job["width_px"]
scene.render.resolution_y = job["height_px"]
scene.world = bpy.data.worlds.new("sheet")
scene.world.color = (0.85, 0.85, 0.8)
scene.view_settings.view_transform = "Standard"
scene.render.filepath = job["output"]
bpy.ops.render.render(write_still=True)
"""


def sheet_keys(
    knowledge: KnowledgeBase, crops: Sequence[str] | None = None, variety: str | None = None
) -> list[list[AssetKey]]:
    """Per crop (catalogue order), its keys for the sheet: one variety, every state."""
    hierarchy = knowledge.hierarchy
    for crop in crops or ():
        hierarchy.crop(crop)  # an unknown crop: the hierarchy's error, listing the known ones
    rows: dict[str, list[AssetKey]] = {}
    chosen: dict[str, str] = {}
    for key in hierarchy.assets():
        if crops and key.crop not in crops:
            continue
        if variety is not None and key.variety != variety:
            continue
        chosen.setdefault(key.crop, key.variety)
        if key.variety == chosen[key.crop]:
            rows.setdefault(key.crop, []).append(key)
    if not rows:
        raise ConfigurationError(
            f"no catalogue asset matches variety {variety!r}"
            + (f" of {', '.join(crops)}" if crops else ""),
            stage="plants",
            hint="agrirecipe assets list --crop CROP shows the varieties",
        )
    return list(rows.values())


def contact_sheet(
    output: str | Path,
    *,
    knowledge: KnowledgeBase | None = None,
    crops: Sequence[str] | None = None,
    variety: str | None = None,
    cell_px: int = 150,
    timeout_s: float = 900.0,
) -> Path:
    """Render the contact sheet to ``output`` (a PNG); return its path."""
    from PIL import Image, ImageDraw

    target = Path(output)
    if target.suffix.lower() != ".png":
        raise ConfigurationError(
            f"contact sheet {str(target)!r} is not a .png file", stage="plants", hint="sheet.png"
        )
    if not 40 <= cell_px <= 1000:
        raise ConfigurationError(f"cell_px must be 40-1000, got {cell_px}", stage="plants")
    kb = knowledge or default_knowledge_base()
    rows = sheet_keys(kb, crops, variety)
    states = sorted(
        {(k.stage, k.season, k.health) for row in rows for k in row},
        key=lambda s: (_order("stage", s[0]), _order("season", s[1]), s[2] != "Healthy"),
    )
    column_of = {state: index for index, state in enumerate(states)}
    with tempfile.TemporaryDirectory(prefix="agrirecipe-sheet-") as folder:
        cells = []
        for row, keys in enumerate(rows):
            for key in keys:
                spec = plant_spec(kb, key)
                path = kb.hierarchy.asset_path(key)
                _, data, _ = asset_glb(spec, key, path, 0)
                file = Path(folder) / f"{row}_{column_of[(key.stage, key.season, key.health)]}.glb"
                file.write_bytes(data)
                cells.append(
                    {
                        "file": str(file),
                        "row": row,
                        "column": column_of[(key.stage, key.season, key.health)],
                        "height_m": spec.height_m,
                        "width_m": max(
                            spec.width_m, spec.in_row_m if spec.archetype == "vine" else 0
                        ),
                        # a trellis is seen along its wires, other plants a little turned
                        "turn_deg": 90.0 if spec.archetype == "vine" else 25.0,
                    }
                )
        raw = Path(folder) / "sheet.png"
        job = {
            "cells": cells,
            "columns": len(states),
            "rows": len(rows),
            "width_px": cell_px * len(states),
            "height_px": cell_px * len(rows),
            "output": str(raw),
        }
        (Path(folder) / "job.json").write_text(json.dumps(job), encoding="utf-8")
        script = Path(folder) / "sheet_blender.py"
        script.write_text(_BLENDER, encoding="utf-8")
        run_bpy_child(script, [str(Path(folder) / "job.json")], timeout_s=timeout_s)
        if not raw.is_file():
            raise BackendError("Blender finished but wrote no contact sheet", stage="render")
        render = Image.open(raw).convert("RGB")
        sheet = Image.new(
            "RGB", (render.width + _LABEL_PX, render.height + _HEADER_PX), (255, 255, 255)
        )
        sheet.paste(render, (_LABEL_PX, _HEADER_PX))
    draw = ImageDraw.Draw(sheet)
    font = _font(18)
    small = _font(13)
    for row, keys in enumerate(rows):
        y = _HEADER_PX + row * cell_px + cell_px // 2
        draw.text((10, y - 20), keys[0].crop, fill=(20, 20, 20), font=font)
        draw.text((10, y + 4), keys[0].variety, fill=(90, 90, 90), font=small)
    for (stage, season, health), column in column_of.items():
        x = _LABEL_PX + column * cell_px + 6
        draw.text((x, 6), stage, fill=(20, 20, 20), font=small)
        draw.text((x, 24), season, fill=(60, 60, 60), font=small)
        draw.text(
            (x, 42),
            health,
            fill=(150, 40, 30) if health != "Healthy" else (40, 110, 40),
            font=small,
        )
    with atomic_path(target, suffix=".png") as temporary:
        sheet.save(temporary, format="PNG")
    return target


def _order(attribute: str, value: str) -> int:
    values = {
        "stage": ("Vegetative", "Reproductive", "Maturation"),
        "season": ("Spring", "Summer", "Fall", "Winter"),
    }[attribute]
    return values.index(value) if value in values else len(values)


def _font(size: int) -> ImageFont.FreeTypeFont | ImageFont.ImageFont:
    from PIL import ImageFont

    try:
        return ImageFont.truetype("DejaVuSans.ttf", size)
    except OSError:
        return ImageFont.load_default(size)

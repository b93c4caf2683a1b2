"""A field's soil surface as a glTF binary, for engines that import meshes (Unreal).

Blender and USD build the surface themselves (``layout/_ground.py``); Unreal imports
it like the plants: ``assets/ground/<field id>.glb``, in the field's own frame
(origin at its south-west corner, before its turn), with a material per part
(soil, plastic mulch, headland track) in the colours of ``layout/data/ground.yaml``.
Flat fields without mulch or track need no mesh: the engine's plane does.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from agrirecipe._files import write_atomic
from agrirecipe.plants._gltf import glb_bytes
from agrirecipe.plants._library import GENERATOR
from agrirecipe.plants._mesh import Material, PlantMesh, Primitive
from agrirecipe.plants._scene import unchanged
from agrirecipe.recipe import FieldSpec, SceneRecipe

__all__ = ["GROUND_FOLDER", "ground_file", "ground_mesh", "has_relief", "write_ground_assets"]

#: Folder of the ground meshes inside ``assets/``.
GROUND_FOLDER = "ground"
_ROUGHNESS = {"soil": 0.95, "mulch": 0.35, "track": 0.9}


def ground_file(field_id: str) -> str:
    """The ground mesh's path relative to ``assets/``."""
    return f"{GROUND_FOLDER}/{field_id}.glb"


def has_relief(spec: FieldSpec, params: dict[str, Any]) -> bool:
    """Whether the field's surface is more than a flat soil rectangle."""
    from agrirecipe.layout import ground_spec

    ground = ground_spec(spec, params)
    return ground["relief"] != "flat" or bool(ground["mulch"]) or float(ground["track_m"]) > 0


def _vertex_normals(points: NDArray[np.float32], triangles: NDArray[np.uint32]) -> NDArray[Any]:
    """Area-weighted vertex normals (up where a vertex has no face)."""
    corners = points[triangles]
    faces = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normals = np.zeros_like(points, dtype=np.float64)
    for k in range(3):
        np.add.at(normals, triangles[:, k], faces)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    normals = np.where(length > 0, normals / np.maximum(length, 1e-12), [0.0, 0.0, 1.0])
    return normals.astype(np.float32)


def ground_mesh(spec: FieldSpec, params: dict[str, Any]) -> PlantMesh:
    """The field's surface parts as one mesh, a primitive per part, in the field frame."""
    from agrirecipe.layout import field_ground, ground_colours

    colours = ground_colours()
    primitives = []
    for part in field_ground(spec, params):
        points = np.asarray(part["points"], dtype=np.float32).reshape(-1, 3)
        triangles = np.asarray(part["triangles"], dtype=np.uint32).reshape(-1, 3)
        name = str(part["part"])
        primitives.append(
            Primitive(
                material=Material(
                    name=f"ground_{name}",
                    rgb=colours[name],
                    roughness=_ROUGHNESS.get(name, 0.9),
                    double_sided=True,
                ),
                positions=points,
                normals=_vertex_normals(points, triangles),
                uvs=np.ascontiguousarray(points[:, :2]),  # one texture repeat per metre
                triangles=triangles,
            )
        )
    return PlantMesh(primitives=tuple(primitives))


def write_ground_assets(recipe: SceneRecipe, directory: str | Path) -> list[Path]:
    """Write ``assets/ground/<field id>.glb`` for every field with relief, mulch or a
    track; a file already there with the same bytes is kept. Returns the files."""
    from agrirecipe.layout import field_parameters

    folder = Path(directory) / "assets"
    written: list[Path] = []
    parameters = {str(p["id"]): p for p in field_parameters(recipe)}
    for spec in recipe.fields:
        params = parameters[spec.id]
        if not has_relief(spec, params):
            continue
        data = glb_bytes(
            ground_mesh(spec, params),
            name=f"SM_Ground_{spec.id}",
            generator=GENERATOR,
            extras={"field_id": spec.id, "frame": "field: origin at its south-west corner"},
        )
        target = folder / ground_file(spec.id)
        if not unchanged(target, data):
            write_atomic(target, data)
        written.append(target)
    return written

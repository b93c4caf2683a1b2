"""Writing a plant as glTF 2.0 binary (``.glb``): one mesh, one primitive per material.

Written by hand (the format is a JSON chunk and a binary chunk) so that the same
mesh always gives the same bytes: keys sorted, no timestamps, buffers aligned to 4
bytes. glTF is Y-up; the scene is Z-up, so (x, y, z) is written as (x, z, -y),
which every glTF reader (Blender, three.js, trimesh, Unreal's Interchange) turns
back. Colours are given in sRGB and written as linear ``baseColorFactor``.
"""

from __future__ import annotations

import json
import struct
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from agrirecipe._files import write_atomic
from agrirecipe.plants._mesh import PlantMesh

__all__ = ["glb_bytes", "linear_rgb", "write_glb"]

_FLOAT, _UINT16, _UINT32 = 5126, 5123, 5125
_ARRAY_BUFFER, _ELEMENT_ARRAY_BUFFER = 34962, 34963
_TRIANGLES = 4
_MAGIC, _JSON, _BIN = 0x46546C67, 0x4E4F534A, 0x004E4942


def _linear(channel: float) -> float:
    """sRGB -> linear (IEC 61966-2-1)."""
    if channel <= 0.04045:
        return channel / 12.92
    return float(((channel + 0.055) / 1.055) ** 2.4)


def linear_rgb(rgb: tuple[float, float, float]) -> tuple[float, float, float]:
    """An sRGB colour (0-1) in linear light, as glTF and UsdPreviewSurface expect."""
    return (_linear(rgb[0]), _linear(rgb[1]), _linear(rgb[2]))


def _y_up(vectors: NDArray[np.float32]) -> NDArray[np.float32]:
    return np.ascontiguousarray(np.stack([vectors[:, 0], vectors[:, 2], -vectors[:, 1]], axis=1))


def glb_bytes(mesh: PlantMesh, *, name: str, generator: str, extras: dict[str, object]) -> bytes:
    """The ``.glb`` file of ``mesh`` (``extras`` go into the mesh's glTF ``extras``)."""
    binary = bytearray()
    views: list[dict[str, object]] = []
    accessors: list[dict[str, object]] = []

    def add(data: bytes, target: int) -> int:
        while len(binary) % 4:
            binary.append(0)
        views.append(
            {"buffer": 0, "byteOffset": len(binary), "byteLength": len(data), "target": target}
        )
        binary.extend(data)
        return len(views) - 1

    def attribute(values: NDArray[np.float32], kind: str, bounds: bool = False) -> int:
        view = add(np.ascontiguousarray(values, dtype="<f4").tobytes(), _ARRAY_BUFFER)
        accessor: dict[str, object] = {
            "bufferView": view,
            "componentType": _FLOAT,
            "count": len(values),
            "type": kind,
        }
        if bounds:
            accessor["min"] = [float(v) for v in values.min(axis=0)]
            accessor["max"] = [float(v) for v in values.max(axis=0)]
        accessors.append(accessor)
        return len(accessors) - 1

    materials: list[dict[str, object]] = []
    primitives: list[dict[str, object]] = []
    for primitive in mesh.primitives:
        material = primitive.material
        materials.append(
            {
                "name": material.name,
                "doubleSided": material.double_sided,
                "pbrMetallicRoughness": {
                    "baseColorFactor": [round(_linear(c), 6) for c in material.rgb] + [1.0],
                    "metallicFactor": 0.0,
                    "roughnessFactor": material.roughness,
                },
            }
        )
        positions = _y_up(primitive.positions)
        normals = _y_up(primitive.normals)
        uvs = np.ascontiguousarray(primitive.uvs)
        small = len(positions) < 65536
        indices = primitive.triangles.reshape(-1).astype("<u2" if small else "<u4")
        index_view = add(indices.tobytes(), _ELEMENT_ARRAY_BUFFER)
        accessors.append(
            {
                "bufferView": index_view,
                "componentType": _UINT16 if small else _UINT32,
                "count": len(indices),
                "type": "SCALAR",
            }
        )
        index_accessor = len(accessors) - 1
        primitives.append(
            {
                "attributes": {
                    "POSITION": attribute(positions, "VEC3", bounds=True),
                    "NORMAL": attribute(normals, "VEC3"),
                    "TEXCOORD_0": attribute(uvs, "VEC2"),
                },
                "indices": index_accessor,
                "material": len(materials) - 1,
                "mode": _TRIANGLES,
            }
        )
    while len(binary) % 4:
        binary.append(0)
    document = {
        "asset": {"version": "2.0", "generator": generator},
        "scene": 0,
        "scenes": [{"name": name, "nodes": [0]}],
        "nodes": [{"name": name, "mesh": 0}],
        "meshes": [{"name": name, "primitives": primitives, "extras": extras}],
        "materials": materials,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary)}],
    }
    text = json.dumps(document, sort_keys=True, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(binary)
    return b"".join(
        [
            struct.pack("<III", _MAGIC, 2, total),
            struct.pack("<II", len(text), _JSON),
            text,
            struct.pack("<II", len(binary), _BIN),
            bytes(binary),
        ]
    )


def write_glb(
    path: Path, mesh: PlantMesh, *, name: str, generator: str, extras: dict[str, object]
) -> int:
    """Write ``mesh`` to ``path`` atomically; return the number of bytes written."""
    data = glb_bytes(mesh, name=name, generator=generator, extras=extras)
    write_atomic(path, data)
    return len(data)

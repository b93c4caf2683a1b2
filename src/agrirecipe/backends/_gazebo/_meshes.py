"""Plant meshes merged per row group, written as binary STL (one file per material).

Gazebo draws a visual per mesh file, so a field of 100,000 plants cannot be
100,000 visuals. The plants of a field are merged instead: consecutive rows are
grouped into *chunks* of at most ``max_chunk_triangles`` triangles per material
(a row longer than that is cut along its length), and each chunk is one mesh per
material of the plant (leaf, stem, fruit...), coloured by the SDF visual's
``<material>``.

Binary STL is the one mesh format that Gazebo Classic (9+) and gz-sim both read
and that numpy writes without formatting text: 50 bytes per triangle, flat
normals, no materials (the SDF supplies them). Vertices are single-precision,
in the field's own frame (the model's pose), so they stay exact to well under a
millimetre over a kilometre. Double-sided materials (thin leaf blades) are either
flagged for the SDF material's ``<double_sided>`` (gz-sim) or written twice, the
second copy with its winding reversed (Gazebo Classic culls back faces and has no
per-visual switch for it).

All transforms are numpy broadcasts over (plants, corners): no Python loop per
plant or per vertex.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from agrirecipe._files import atomic_path
from agrirecipe.plants import PlantMesh

__all__ = [
    "STL_RECORD",
    "Chunk",
    "Template",
    "chunk_bounds",
    "merged_chunk",
    "plant_rows",
    "stl_records",
    "template",
    "templates",
    "write_chunk_meshes",
    "write_stl",
]

#: One binary STL facet: normal, three corners, an attribute word (50 bytes).
STL_RECORD = np.dtype([("normal", "<f4", (3,)), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])
_STL_HEADER = b"agrirecipe gazebo backend: binary STL, metres, Z up".ljust(80, b" ")


@dataclass(frozen=True, slots=True)
class Template:
    """One material of one shape variant, as triangle corners in the plant's frame.

    ``corners`` is (triangles, 3, 3) float64 with the asset's scale applied,
    ``normals`` the (triangles, 3) unit facet normals. ``double_sided``: the material
    shows both faces; when its reversed copy was added to the triangles, False.
    """

    material: str
    rgb: tuple[float, float, float]
    corners: NDArray[np.float64]
    normals: NDArray[np.float64]
    double_sided: bool = False


@dataclass(frozen=True, slots=True)
class Chunk:
    """Plants ``start`` to ``stop`` (exclusive) of a field, rows ``first_row`` to ``last_row``."""

    index: int
    start: int
    stop: int
    first_row: int
    last_row: int


def _facet_normals(corners: NDArray[np.float64]) -> NDArray[np.float64]:
    normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    return np.asarray(normals / np.where(length > 1e-20, length, 1.0), dtype=np.float64)


def template(
    material: str,
    rgb: tuple[float, float, float],
    corners: NDArray[np.float64],
    *,
    double_sided: bool = False,
    duplicate: bool = False,
) -> Template:
    """A template from (triangles, 3, 3) corners. A double-sided one gets a reversed copy of
    its triangles with ``duplicate``, else it is flagged for the SDF material."""
    if double_sided and duplicate:
        corners = np.concatenate([corners, corners[:, ::-1]])
    name = re.sub(r"[^A-Za-z0-9_]", "_", material) or "material"
    return Template(name, rgb, corners, _facet_normals(corners), double_sided and not duplicate)


def templates(
    mesh: PlantMesh, scale: tuple[float, float, float], *, duplicate: bool = False
) -> dict[str, Template]:
    """Per material name, the variant's triangles scaled by ``scale`` (x, y, z); see
    :func:`template` for ``duplicate``."""
    factors = np.asarray(scale, dtype=np.float64)
    found: dict[str, Template] = {}
    for primitive in mesh.primitives:
        positions = primitive.positions.astype(np.float64) * factors
        made = template(
            primitive.material.name,
            primitive.material.rgb,
            positions[primitive.triangles.astype(np.int64)],
            double_sided=primitive.material.double_sided,
            duplicate=duplicate,
        )
        found[made.material] = made
    return found


def plant_rows(local_x: NDArray[np.float64], row_x: NDArray[np.float64]) -> NDArray[np.int64]:
    """The row of each plant: the nearest nominal row line to its field-local x.

    Jitter is far smaller than half the distance between rows, so the nearest
    line is the row the kernel planted it in.
    """
    if len(row_x) == 1:
        return np.zeros(len(local_x), dtype=np.int64)
    order = np.argsort(row_x, kind="stable")
    ordered = row_x[order]
    middles = (ordered[1:] + ordered[:-1]) / 2.0
    return np.asarray(order[np.searchsorted(middles, local_x)], dtype=np.int64)


def chunk_bounds(
    rows: NDArray[np.int64], triangles: NDArray[np.int64], max_chunk_triangles: int
) -> list[Chunk]:
    """Cut a field's plants (in kernel order, ``rows`` non-decreasing) into chunks.

    ``triangles`` is each plant's largest per-material triangle count. Whole rows
    are grouped while a chunk stays within ``max_chunk_triangles``; a row that is
    larger on its own is cut along its length.
    """
    count = len(rows)
    if count == 0:
        return []
    cumulative = np.concatenate([[0], np.cumsum(triangles)])
    row_starts = np.flatnonzero(np.diff(rows, prepend=-1) != 0)
    row_ends = np.append(row_starts[1:], count)
    chunks: list[Chunk] = []
    start = 0
    for row_start, row_end in zip(row_starts.tolist(), row_ends.tolist(), strict=True):
        if cumulative[row_end] - cumulative[start] <= max_chunk_triangles:
            continue  # the row fits in the open chunk
        if row_start > start:  # close the chunk before this row
            chunks.append(_chunk(len(chunks), start, row_start, rows))
            start = row_start
        while cumulative[row_end] - cumulative[start] > max_chunk_triangles:
            limit = cumulative[start] + max_chunk_triangles
            stop = max(int(np.searchsorted(cumulative, limit, side="right")) - 1, start + 1)
            chunks.append(_chunk(len(chunks), start, stop, rows))
            start = stop
    if start < count:
        chunks.append(_chunk(len(chunks), start, count, rows))
    return chunks


def _chunk(index: int, start: int, stop: int, rows: NDArray[np.int64]) -> Chunk:
    return Chunk(index, start, stop, int(rows[start]), int(rows[stop - 1]))


def write_stl(path: Path, records: NDArray[np.void]) -> Path:
    """Write :data:`STL_RECORD` ``records`` as a binary STL file, atomically."""
    with atomic_path(path, suffix=".stl") as temporary, temporary.open("wb") as stream:
        stream.write(_STL_HEADER)
        stream.write(np.uint32(len(records)).tobytes())
        records.tofile(stream)
    return path


def stl_records(corners: NDArray[np.float64], normals: NDArray[np.float64]) -> NDArray[np.void]:
    """(n, 3, 3) ``corners`` and (n, 3) ``normals`` as :data:`STL_RECORD` facets."""
    records = np.zeros(len(corners), dtype=STL_RECORD)
    records["corners"] = corners
    records["normal"] = normals
    return records


def _place(
    out: NDArray[np.void],
    template: Template,
    xy: NDArray[np.float32],
    z: NDArray[np.float32],
    cos: NDArray[np.float32],
    sin: NDArray[np.float32],
    scale: NDArray[np.float32],
) -> None:
    """Fill ``out`` with the template at every plant: scaled, turned about Z, moved.

    Single precision throughout: the result is stored as float32 anyway, and field
    frames keep coordinates within a kilometre (0.1 mm steps).
    """
    count, triangles = len(cos), len(template.corners)
    shape = (count, triangles, 3)
    base = template.corners.astype(np.float32)[None]  # (1, t, 3, 3)
    c, s, k = cos[:, None, None], sin[:, None, None], scale[:, None, None]
    corners = out["corners"].reshape(count, triangles, 3, 3)
    px, py = base[..., 0] * k, base[..., 1] * k
    corners[..., 0] = c * px - s * py + xy[:, 0, None, None]
    corners[..., 1] = s * px + c * py + xy[:, 1, None, None]
    corners[..., 2] = base[..., 2] * k + z[:, None, None]
    normal = template.normals.astype(np.float32)[None]  # (1, t, 3)
    normals = out["normal"].reshape(shape)
    c2, s2 = cos[:, None], sin[:, None]
    normals[..., 0] = c2 * normal[..., 0] - s2 * normal[..., 1]
    normals[..., 1] = s2 * normal[..., 0] + c2 * normal[..., 1]
    normals[..., 2] = normal[..., 2]


def merged_chunk(
    variants: list[dict[str, Template]],
    plant_variant: NDArray[np.int32],
    xy: NDArray[np.float64],
    z: NDArray[np.float64],
    yaw: NDArray[np.float64],
    scale: NDArray[np.float64],
) -> Iterator[tuple[str, tuple[float, float, float], NDArray[np.void]]]:
    """Per material (in first-variant order): the STL facets of these plants, merged.

    Plants are merged variant by variant, each in its order in the field.
    """
    xy32, z32, scale32 = (a.astype(np.float32) for a in (xy, z, scale))
    cos, sin = np.cos(yaw).astype(np.float32), np.sin(yaw).astype(np.float32)
    chosen = [np.flatnonzero(plant_variant == number) for number in range(len(variants))]
    names = list(dict.fromkeys(name for variant in variants for name in variant))
    for name in names:
        parts = [
            (variant[name], plants)
            for variant, plants in zip(variants, chosen, strict=True)
            if name in variant and len(plants)
        ]
        if not parts:
            continue
        total = sum(len(t.corners) * len(plants) for t, plants in parts)
        records = np.empty(total, dtype=STL_RECORD)
        records["attribute"] = 0
        offset = 0
        for template, plants in parts:
            size = len(template.corners) * len(plants)
            _place(
                records[offset : offset + size],
                template,
                xy32[plants],
                z32[plants],
                cos[plants],
                sin[plants],
                scale32[plants],
            )
            offset += size
        yield name, parts[0][0].rgb, records


def write_chunk_meshes(
    folder: Path,
    stem: str,
    variants: list[dict[str, Template]],
    plant_variant: NDArray[np.int32],
    xy: NDArray[np.float64],
    z: NDArray[np.float64],
    yaw: NDArray[np.float64],
    scale: NDArray[np.float64],
) -> list[tuple[str, tuple[float, float, float], Path, int]]:
    """Write ``<stem>_<material>.stl`` per material; return (material, rgb, path, triangles)."""
    written = []
    for name, rgb, records in merged_chunk(variants, plant_variant, xy, z, yaw, scale):
        path = write_stl(folder / f"{stem}_{name}.stl", records)
        written.append((name, rgb, path, len(records)))
    return written

"""Triangle meshes for plants: a few vectorised primitives and a builder that merges them.

Coordinates are the scene's: metres, Z up, the plant's base at the origin, its row
along +Y. Every primitive returns a :class:`Part` (positions, normals, UVs and
triangles); the builder collects parts per material and merges them into a
:class:`PlantMesh` of one primitive per material. Many copies of one part (leaves,
berries, blossom) are placed at once with :func:`instances`, so a tree of thousands
of leaves costs a few array operations, not a Python loop per leaf.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "Material",
    "MeshBuilder",
    "Part",
    "PlantMesh",
    "Primitive",
    "blade",
    "ellipsoid",
    "frames_along",
    "instances",
    "tube",
]

Floats = NDArray[np.float64]


@dataclass(frozen=True, slots=True)
class Material:
    """A PBR material: base colour (sRGB, 0-1), roughness, and whether both faces show."""

    name: str
    rgb: tuple[float, float, float]
    roughness: float = 0.8
    double_sided: bool = False


@dataclass(frozen=True, slots=True)
class Part:
    """Mesh data of one primitive before merging."""

    positions: Floats
    normals: Floats
    uvs: Floats
    triangles: NDArray[np.int64]

    @property
    def empty(self) -> bool:
        """No triangles."""
        return len(self.triangles) == 0


@dataclass(frozen=True, slots=True)
class Primitive:
    """One material's merged geometry (float32 arrays, uint32 triangle indices)."""

    material: Material
    positions: NDArray[np.float32]
    normals: NDArray[np.float32]
    uvs: NDArray[np.float32]
    triangles: NDArray[np.uint32]


@dataclass(frozen=True, slots=True)
class PlantMesh:
    """A plant: one primitive per material."""

    primitives: tuple[Primitive, ...]

    @property
    def triangle_count(self) -> int:
        """Triangles over all primitives."""
        return sum(len(p.triangles) for p in self.primitives)

    @property
    def bounds(self) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
        """(min xyz, max xyz) over all vertices."""
        points = np.concatenate([p.positions for p in self.primitives])
        low, high = points.min(axis=0), points.max(axis=0)
        return (
            (float(low[0]), float(low[1]), float(low[2])),
            (float(high[0]), float(high[1]), float(high[2])),
        )


@dataclass
class MeshBuilder:
    """Collects parts per material, in the order materials are first used."""

    _parts: dict[str, list[Part]] = field(default_factory=dict)
    _materials: dict[str, Material] = field(default_factory=dict)

    def add(self, material: Material, part: Part) -> None:
        """Add geometry drawn with ``material`` (empty parts are skipped)."""
        if part.empty:
            return
        known = self._materials.setdefault(material.name, material)
        if known != material:
            raise ValueError(f"two materials named {material.name!r}")
        self._parts.setdefault(material.name, []).append(part)

    def build(self, scale: tuple[float, float, float] = (1.0, 1.0, 1.0)) -> PlantMesh:
        """The merged mesh, scaled per axis (normals follow the inverse transpose)."""
        factors = np.asarray(scale, dtype=np.float64)
        primitives: list[Primitive] = []
        for name, parts in self._parts.items():
            offsets = np.cumsum([0] + [len(p.positions) for p in parts[:-1]])
            positions = np.concatenate([p.positions for p in parts]) * factors
            positions[:, 2] = np.maximum(positions[:, 2], 0.0)  # leaves lie on the soil, not in it
            normals = np.concatenate([p.normals for p in parts]) / factors
            normals = _unit(normals)
            uvs = np.concatenate([p.uvs for p in parts])
            triangles = np.concatenate(
                [p.triangles + o for p, o in zip(parts, offsets, strict=True)]
            )
            primitives.append(
                Primitive(
                    material=self._materials[name],
                    positions=positions.astype(np.float32),
                    normals=normals.astype(np.float32),
                    uvs=uvs.astype(np.float32),
                    triangles=triangles.astype(np.uint32),
                )
            )
        return PlantMesh(tuple(primitives))

    def extent(self) -> tuple[Floats, Floats]:
        """(min, max) of every position added so far."""
        points = np.concatenate([p.positions for parts in self._parts.values() for p in parts])
        return points.min(axis=0), points.max(axis=0)


def _unit(vectors: Floats) -> Floats:
    length = np.linalg.norm(vectors, axis=-1, keepdims=True)
    return np.asarray(vectors / np.where(length > 1e-12, length, 1.0), dtype=np.float64)


def frames_along(points: Floats) -> tuple[Floats, Floats, Floats]:
    """Tangent, normal and binormal at each point of a polyline (parallel transport)."""
    points = np.asarray(points, dtype=np.float64)
    tangents = np.gradient(points, axis=0)
    tangents = _unit(tangents)
    reference = np.array([0.0, 0.0, 1.0])
    if abs(float(tangents[0] @ reference)) > 0.9:
        reference = np.array([1.0, 0.0, 0.0])
    normal = _unit(np.cross(tangents[0], reference)[None, :])[0]
    normals = np.empty_like(points)
    for index, tangent in enumerate(tangents):
        normal = normal - tangent * float(normal @ tangent)
        length = float(np.linalg.norm(normal))
        if length < 1e-9:  # tangent turned onto the normal: take any perpendicular
            normal = _unit(np.cross(tangent, [1.0, 0.0, 0.0])[None, :])[0]
        else:
            normal = normal / length
        normals[index] = normal
    binormals = np.cross(tangents, normals)
    return tangents, normals, binormals


def tube(points: Sequence[Any] | Floats, radii: Sequence[float] | Floats, sides: int) -> Part:
    """A tube along a polyline (stems, trunks, branches, onion leaves), open at its ends.

    ``radii`` is one radius per point; a zero radius closes the tube to a tip.
    """
    path = np.asarray(points, dtype=np.float64)
    radius = np.asarray(radii, dtype=np.float64)
    _, normals, binormals = frames_along(path)
    angles = np.linspace(0.0, 2.0 * np.pi, sides, endpoint=False)
    cos, sin = np.cos(angles)[None, :, None], np.sin(angles)[None, :, None]
    directions = cos * normals[:, None, :] + sin * binormals[:, None, :]  # (n, sides, 3)
    positions = path[:, None, :] + directions * radius[:, None, None]
    count = len(path)
    ring = np.arange(sides)
    following = (ring + 1) % sides
    rows = np.arange(count - 1)[:, None] * sides
    a, b = rows + ring, rows + following
    c, d = a + sides, b + sides
    triangles = np.concatenate(
        [np.stack([a, b, d], axis=-1), np.stack([a, d, c], axis=-1)], axis=1
    ).reshape(-1, 3)
    u = np.broadcast_to(ring / sides, (count, sides))
    v = np.broadcast_to(np.linspace(0.0, 1.0, count)[:, None], (count, sides))
    part = Part(
        positions=positions.reshape(-1, 3),
        normals=directions.reshape(-1, 3),
        uvs=np.stack([u, v], axis=-1).reshape(-1, 2),
        triangles=triangles.astype(np.int64),
    )
    return _drop_degenerate(part)


def ellipsoid(radii: Sequence[float], rows: int, columns: int) -> Part:
    """A closed ellipsoid centred on the origin (fruit, heads, berries, canopies)."""
    rx, ry, rz = (float(r) for r in radii)
    theta = np.linspace(0.0, np.pi, rows + 1)[:, None]  # from the top pole down
    phi = np.linspace(0.0, 2.0 * np.pi, columns + 1)[None, :]
    unit = np.stack(
        [
            np.sin(theta) * np.cos(phi),
            np.sin(theta) * np.sin(phi),
            np.broadcast_to(np.cos(theta), (rows + 1, columns + 1)),
        ],
        axis=-1,
    )
    positions = unit * np.array([rx, ry, rz])
    normals = _unit(unit / np.array([rx * rx, ry * ry, rz * rz]))
    width = columns + 1
    r = np.arange(rows)[:, None]
    c = np.arange(columns)[None, :]
    a = r * width + c
    b, d = a + 1, a + width + 1
    cc = a + width
    upper = np.stack([a, cc, d], axis=-1)
    lower = np.stack([a, d, b], axis=-1)
    triangles = np.concatenate([upper.reshape(-1, 3), lower.reshape(-1, 3)])
    u = np.broadcast_to(phi / (2.0 * np.pi), (rows + 1, columns + 1))
    v = np.broadcast_to(theta / np.pi, (rows + 1, columns + 1))
    part = Part(
        positions=positions.reshape(-1, 3),
        normals=normals.reshape(-1, 3),
        uvs=np.stack([u, v], axis=-1).reshape(-1, 2),
        triangles=triangles.astype(np.int64),
    )
    return _drop_degenerate(part)


def blade(
    length: float,
    width: float,
    *,
    segments: int,
    bend: float = 0.0,
    cup: float = 0.0,
    taper: float = 1.0,
    base_width: float = 0.25,
    split: int = 1,
) -> Part:
    """A leaf blade in its own frame: base at the origin, growing along +Z, face to +X.

    ``bend`` arches the tip down towards +X (1 = the tip at the base's height),
    ``cup`` folds the sides up, ``taper`` shapes the outline (1 = lanceolate).
    ``split`` cuts the blade across into strips with gaps (a torn banana leaf).
    """
    t = np.linspace(0.0, 1.0, segments + 1)
    outline = np.sin(np.pi * np.clip(t, 0.0, 1.0) ** taper) + base_width * (1.0 - t)
    outline = outline / outline.max() * (width / 2.0)
    outline[-1] = 0.0 if taper >= 1.0 else outline[-1]
    angle = bend * (np.pi / 2.0) * t**1.5
    step = length / segments
    spine = np.zeros((segments + 1, 3))
    direction = np.stack([np.sin(angle), np.zeros_like(t), np.cos(angle)], axis=-1)
    spine[1:] = np.cumsum(direction[:-1] * step, axis=0)
    side = np.array([0.0, 1.0, 0.0])
    face = _unit(np.cross(direction, side))  # leaf normal, towards +X for an upright leaf
    across = np.array([-1.0, 0.0, 1.0])  # left edge, midrib, right edge
    lift = cup * np.abs(across)[None, :, None] * outline[:, None, None] * face[:, None, :]
    positions = spine[:, None, :] + across[None, :, None] * outline[:, None, None] * side + lift
    normals = np.broadcast_to(face[:, None, :], positions.shape)
    rows = np.arange(segments)
    if split > 1:  # keep rows in bands, dropping one row between bands
        rows = rows[(rows % max(2, segments // split)) != max(1, segments // split) - 1]
    a = rows[:, None] * 3 + np.array([0, 1])[None, :]
    b, c, d = a + 1, a + 3, a + 4
    triangles = np.concatenate(
        [np.stack([a, c, d], axis=-1), np.stack([a, d, b], axis=-1)], axis=1
    ).reshape(-1, 3)
    u = np.broadcast_to((across + 1.0) / 2.0, (segments + 1, 3))
    v = np.broadcast_to(t[:, None], (segments + 1, 3))
    part = Part(
        positions=positions.reshape(-1, 3),
        normals=np.ascontiguousarray(normals).reshape(-1, 3),
        uvs=np.stack([u, v], axis=-1).reshape(-1, 2),
        triangles=triangles.astype(np.int64),
    )
    return _drop_degenerate(part)


def instances(template: Part, matrices: Floats) -> Part:
    """Copies of ``template`` placed by 4 x 4 affine ``matrices`` (rotation and scale)."""
    matrices = np.asarray(matrices, dtype=np.float64).reshape(-1, 4, 4)
    count = len(matrices)
    if count == 0 or template.empty:
        return Part(np.zeros((0, 3)), np.zeros((0, 3)), np.zeros((0, 2)), np.zeros((0, 3), int))
    linear = matrices[:, :3, :3]
    positions = np.einsum("kij,nj->kni", linear, template.positions) + matrices[:, None, :3, 3]
    normal_matrices = np.linalg.inv(linear).transpose(0, 2, 1)
    normals = _unit(np.einsum("kij,nj->kni", normal_matrices, template.normals))
    offsets = (np.arange(count) * len(template.positions))[:, None, None]
    triangles = template.triangles[None, :, :] + offsets
    return Part(
        positions=positions.reshape(-1, 3),
        normals=normals.reshape(-1, 3),
        uvs=np.broadcast_to(template.uvs, (count, *template.uvs.shape)).reshape(-1, 2),
        triangles=triangles.reshape(-1, 3),
    )


def _drop_degenerate(part: Part) -> Part:
    """Remove triangles of (near) zero area: tips where a tube closes, blade points."""
    p = part.positions[part.triangles]
    area = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=-1)
    keep = area > 1e-14
    if keep.all():
        return part
    return Part(part.positions, part.normals, part.uvs, part.triangles[keep])

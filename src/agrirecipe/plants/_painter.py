"""What a plant is drawn from (:class:`PlantSpec`) and the :class:`Painter` that shape
programs draw with: its materials, and helpers that place many leaves, flowers or
fruit at once (oriented copies of one template)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from agrirecipe.plants._mesh import (
    Material,
    MeshBuilder,
    Part,
    blade,
    ellipsoid,
    instances,
)

__all__ = ["GOLDEN", "Floats", "Painter", "PlantSpec", "branch", "compass", "mix", "orient", "unit"]

Floats = NDArray[np.float64]
Rng = np.random.Generator
GOLDEN = np.pi * (3.0 - np.sqrt(5.0))


@dataclass(frozen=True, slots=True)
class PlantSpec:
    """Everything a shape program needs about one plant asset."""

    archetype: str
    height_m: float
    width_m: float
    in_row_m: float
    foliage: str
    stage: str
    leaf_rgb: tuple[float, float, float]
    ill_rgb: tuple[float, float, float] | None
    flower_rgb: tuple[float, float, float] | None
    fruit_rgb: tuple[float, float, float] | None
    mature_rgb: tuple[float, float, float] | None
    params: dict[str, Any]
    colours: dict[str, tuple[float, float, float]]
    ill_share: float

    @property
    def ill(self) -> bool:
        """Whether the plant shows a disease."""
        return self.ill_rgb is not None

    @property
    def ripe(self) -> bool:
        """Fruit at its ripe colour (maturation), not green."""
        return self.stage == "Maturation"


# --- placing many copies ------------------------------------------------------------------------


def unit(v: Floats) -> Floats:
    return np.asarray(v / np.maximum(np.linalg.norm(v, axis=-1, keepdims=True), 1e-12), np.float64)


def orient(positions: Floats, directions: Floats, rolls: Floats, scales: Floats) -> Floats:
    """Matrices taking a template grown along +Z (face -X) to ``positions``, pointing
    along ``directions``, turned by ``rolls`` about them, scaled by ``scales`` (k, 3)."""
    z = unit(np.asarray(directions, dtype=np.float64))
    helper = np.where(np.abs(z[:, 2:3]) > 0.95, [[1.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])
    x = unit(np.cross(helper, z))
    y = np.cross(z, x)
    cos, sin = np.cos(rolls)[:, None], np.sin(rolls)[:, None]
    x, y = x * cos + y * sin, y * cos - x * sin
    matrices = np.zeros((len(z), 4, 4))
    matrices[:, :3, 0] = x * scales[:, 0:1]
    matrices[:, :3, 1] = y * scales[:, 1:2]
    matrices[:, :3, 2] = z * scales[:, 2:3]
    matrices[:, :3, 3] = positions
    matrices[:, 3, 3] = 1.0
    return matrices


def compass(azimuth: Floats, elevation: Floats) -> Floats:
    """Unit vectors from azimuths and elevations above the horizontal (radians)."""
    return np.stack(
        [
            np.cos(elevation) * np.cos(azimuth),
            np.cos(elevation) * np.sin(azimuth),
            np.sin(elevation),
        ],
        axis=-1,
    )


class Painter:
    """Materials of one plant and helpers that add many leaves, flowers or fruit."""

    def __init__(self, spec: PlantSpec, rng: Rng) -> None:
        self.spec, self.rng, self.builder = spec, rng, MeshBuilder()
        colours = spec.colours
        self.bark = Material("bark", colours["bark"], 0.95)
        self.stem = Material("stem", mix(colours["stem"], spec.leaf_rgb, 0.5), 0.85)
        self.stake = Material("stake", colours["stake"], 0.9)
        self.wire = Material("wire", colours["wire"], 0.4)
        self.leaf = Material("leaf", spec.leaf_rgb, 0.75, double_sided=True)
        self.sick = (
            Material("leaf_ill", spec.ill_rgb, 0.85, double_sided=True) if spec.ill_rgb else None
        )
        self.flower = Material("flower", spec.flower_rgb or (0.95, 0.95, 0.92), 0.7, True)
        fruit = spec.fruit_rgb or (0.8, 0.2, 0.1)
        self.fruit = Material("fruit", fruit if spec.ripe else mix(fruit, spec.leaf_rgb, 0.75), 0.5)

    def leaves(
        self,
        positions: Floats,
        directions: Floats,
        size: tuple[float, float],
        *,
        segments: int = 2,
        bend: float = 0.2,
        cup: float = 0.0,
        split: int = 1,
        taper: float = 1.0,
        jitter: float = 0.25,
    ) -> None:
        """Leaf blades at ``positions`` along ``directions``; an ill plant's share sick."""
        count = len(positions)
        if count == 0:
            return
        rng, spec = self.rng, self.spec
        droop = 0.35 if spec.ill else 0.0
        template = blade(
            1.0,
            size[1] / size[0],
            segments=segments,
            bend=min(1.0, bend + droop),
            cup=cup,
            split=split,
            taper=taper,
        )
        lengths = size[0] * (1.0 + jitter * (rng.random(count) - 0.5))
        scales = np.stack([lengths, lengths, lengths], axis=-1)
        rolls = rng.uniform(-0.6, 0.6, count)
        matrices = orient(positions, directions, rolls, scales)
        sick = (
            rng.random(count) < spec.ill_share if self.sick is not None else np.zeros(count, bool)
        )
        self.builder.add(self.leaf, instances(template, matrices[~sick]))
        if self.sick is not None:
            self.builder.add(self.sick, instances(template, matrices[sick]))

    def spheres(
        self,
        material: Material,
        centres: Floats,
        radius: float,
        elongation: float,
        detail: tuple[int, int] = (4, 6),
        hang: bool = True,
    ) -> None:
        """Fruit, berries, heads and buds: ellipsoids at ``centres`` (long axis down)."""
        if len(centres) == 0:
            return
        template = ellipsoid((radius, radius, radius * elongation), *detail)
        if hang:
            template = Part(
                template.positions - [0.0, 0.0, radius * elongation],
                template.normals,
                template.uvs,
                template.triangles,
            )
        count = len(centres)
        scale = 1.0 + 0.25 * (self.rng.random(count) - 0.5)
        tilt = compass(self.rng.uniform(0, 2 * np.pi, count), np.full(count, 1.35))
        matrices = orient(
            centres, tilt, self.rng.uniform(0, 6.28, count), np.stack([scale] * 3, -1)
        )
        self.builder.add(material, instances(template, matrices))

    def blossoms(self, centres: Floats, radius: float) -> None:
        """Flat five-sided flowers facing up and out."""
        if len(centres) == 0:
            return
        template = ellipsoid((radius, radius, radius * 0.3), 2, 5)
        up = unit(centres * [1.0, 1.0, 0.0] + [0.0, 0.0, 1.0])
        matrices = orient(
            centres, up, self.rng.uniform(0, 6.28, len(centres)), np.ones((len(centres), 3))
        )
        self.builder.add(self.flower, instances(template, matrices))


def mix(
    a: tuple[float, float, float], b: tuple[float, float, float], t: float
) -> tuple[float, float, float]:
    return (a[0] * t + b[0] * (1 - t), a[1] * t + b[1] * (1 - t), a[2] * t + b[2] * (1 - t))


def branch(start: Floats, direction: Floats, length: float, rng: Rng, steps: int = 4) -> Floats:
    """A gently curving polyline (a branch bends up towards the light)."""
    points = [np.asarray(start, dtype=np.float64)]
    heading = unit(np.asarray(direction, dtype=np.float64))
    for _ in range(steps):
        heading = unit(heading + np.array([0.0, 0.0, 0.18]) + rng.normal(0.0, 0.12, 3))
        points.append(points[-1] + heading * length / steps)
    return np.array(points)

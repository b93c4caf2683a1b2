"""What the 3D view draws: fields, their plant meshes and a compact plant table.

The browser never reads ``plants.csv``: :func:`view_plants` sends each shown
plant as six little-endian float32 numbers ``x, y, z, yaw, scale, variant``
(scene metres, Z up; yaw in radians; ``variant`` indexes the field's ``.glb``
files), fields in recipe order, the count per field in :func:`scene_view`'s
``shown``. Above ``limit`` plants a seeded sample of each field is sent (the
same sample every time for the same recipe) and the page says so.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:
    from agrirecipe._scene import Scene
    from agrirecipe.knowledge import KnowledgeBase
    from agrirecipe.layout import FieldPlants, Layout

__all__ = ["RECORD_FLOATS", "sample_indices", "scene_view", "view_plants"]

#: float32 numbers per plant in :func:`view_plants`.
RECORD_FLOATS = 6
_EYE_HEIGHT_M = 1.6


def _quotas(counts: list[int], limit: int) -> list[int]:
    total = sum(counts)
    if total <= limit:
        return counts
    return [min(count, max(1 if count else 0, count * limit // total)) for count in counts]


def sample_indices(layout: Layout, limit: int) -> list[NDArray[np.int64]]:
    """Per field, the indices of the plants shown (all, or a seeded sample when above ``limit``)."""
    counts = [plants.plant_count for plants in layout.fields]
    chosen = []
    for index, (count, quota) in enumerate(zip(counts, _quotas(counts, limit), strict=True)):
        if quota >= count:
            chosen.append(np.arange(count, dtype=np.int64))
        else:
            rng = np.random.default_rng([layout.recipe.seed, index])
            chosen.append(np.sort(rng.choice(count, size=quota, replace=False)).astype(np.int64))
    return chosen


def _hex(rgb: tuple[float, float, float]) -> str:
    return "#" + "".join(f"{round(max(0.0, min(1.0, c)) * 255):02x}" for c in rgb)


def _walk(plants: FieldPlants) -> dict[str, Any] | None:
    """A path along the alley beside the field's first row, in scene metres."""
    if plants.plant_count == 0:
        return None
    spec = plants.spec
    ox, oy = spec.geometry.origin_m
    turn = math.radians(spec.geometry.rotation_deg)
    cos_t, sin_t = math.cos(turn), math.sin(turn)
    dx, dy = plants.xyz[:, 0] - ox, plants.xyz[:, 1] - oy
    across = dx * cos_t + dy * sin_t
    along = -dx * sin_t + dy * cos_t
    agronomy = spec.agronomy
    spacing = agronomy.bed_row_spacing_m if agronomy.rows_per_bed > 1 else agronomy.row_spacing_m
    first = across < across.min() + spacing / 2
    alley = float(across.min() + spacing / 2)
    start, end = float(along[first].min()), float(along[first].max())

    def world(u: float, v: float) -> list[float]:
        return [round(ox + u * cos_t - v * sin_t, 3), round(oy + u * sin_t + v * cos_t, 3)]

    return {
        "field_id": spec.id,
        "start": world(alley, start),
        "end": world(alley, end),
        "eye_m": _EYE_HEIGHT_M,
    }


def scene_view(scene: Scene, knowledge: KnowledgeBase, limit: int) -> dict[str, Any]:
    """The view's description: per field its outline, meshes, scale and plants shown."""
    from agrirecipe.backends.annotations import field_colours
    from agrirecipe.plants import field_assets

    layout = scene.layout
    recipe = scene.recipe
    assets = field_assets(recipe, knowledge=knowledge)
    shown = [len(indices) for indices in sample_indices(layout, limit)]
    colours = field_colours(len(layout.fields))
    fields = []
    for plants, count, colour in zip(layout.fields, shown, colours, strict=True):
        spec = plants.spec
        asset = assets.get(spec.id)
        fields.append(
            {
                "id": spec.id,
                "label": spec.label,
                "crop": spec.crop,
                "variety": spec.variety,
                "growth_form": spec.agronomy.growth_form,
                "colour": "#{:02x}{:02x}{:02x}".format(*colour),
                "foliage": _hex(spec.agronomy.foliage_rgb),
                "corners": [list(c) for c in spec.geometry.corners_m()],
                "plant_count": plants.plant_count,
                "shown": count,
                "height_m": spec.agronomy.plant_height_m,
                "canopy_m": spec.agronomy.canopy_width_m,
                "files": list(asset.files) if asset is not None else [],
                "scale": list(asset.scale) if asset is not None else [1.0, 1.0, 1.0],
                "mesh_height_m": asset.height_m
                if asset is not None
                else spec.agronomy.plant_height_m,
                "mesh_width_m": asset.width_m
                if asset is not None
                else spec.agronomy.canopy_width_m,
            }
        )
    corners = [c for f in recipe.fields for c in f.geometry.corners_m()]
    total, drawn = layout.plant_count, sum(shown)
    first = next((plants for plants in layout.fields if plants.plant_count), None)
    return {
        "fields": fields,
        "total_plants": total,
        "shown_plants": drawn,
        "sampled": drawn < total,
        "limit": limit,
        "record_floats": RECORD_FLOATS,
        "bounds": [
            min(x for x, _ in corners),
            min(y for _, y in corners),
            max(x for x, _ in corners),
            max(y for _, y in corners),
        ],
        "walk": _walk(first) if first is not None else None,
    }


def view_plants(scene: Scene, limit: int) -> bytes:
    """The shown plants as float32 records (x, y, z, yaw, scale, variant), fields in order."""
    from agrirecipe.plants import SCENE_VARIANTS, plant_variants

    layout = scene.layout
    parts = []
    for plants, indices in zip(layout.fields, sample_indices(layout, limit), strict=True):
        records = np.empty((len(indices), RECORD_FLOATS), dtype="<f4")
        records[:, 0:3] = plants.xyz[indices]
        records[:, 3] = plants.yaw_rad[indices]
        records[:, 4] = plants.scale[indices]
        records[:, 5] = plant_variants(plants.plant_count, SCENE_VARIANTS)[indices]
        parts.append(records.tobytes())
    return b"".join(parts)

"""Recipes for the Blender backend tests, built the way the resolver builds them."""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence

from agrirecipe.enrich import build_environment, build_field
from agrirecipe.hierarchy import Hierarchy, default_hierarchy
from agrirecipe.knowledge import KnowledgeBase, default_knowledge_base
from agrirecipe.layout import FieldRequest, pack_fields
from agrirecipe.recipe import (
    FieldGeometry,
    FieldSpec,
    HealthState,
    SceneRecipe,
    Season,
    Stage,
)

__all__ = [
    "HOSTILE",
    "MIXED_FIELDS",
    "field",
    "mixed_recipe",
    "packed_recipe",
    "single_field_recipe",
]

#: A label (or prompt) that would run code if it ever reached a script unescaped.
HOSTILE = (
    'x"""\'\'\'\n__import__("os").system("touch PWNED")\n'
    "# \\ \\n \x00 é 漢 \u2028 {SCENE} %s ' \" ) ] }"
)

#: (field id, crop, stage, season, health, width m, length m, headland m) of :func:`mixed_recipe`:
#: one crop per growth form, an orchard in summer and one in winter, an ill carrot field.
MIXED_FIELDS: tuple[tuple[str, str, Stage, Season, HealthState, float, float, float], ...] = (
    ("apple_summer", "Apple", "Maturation", "Summer", "Healthy", 14.0, 16.0, 2.0),
    ("apple_winter", "Apple", "Vegetative", "Winter", "Healthy", 12.0, 12.0, 2.0),
    ("grapes", "Grape", "Maturation", "Summer", "Healthy", 12.0, 14.0, 1.5),
    ("tomatoes", "Tomato", "Maturation", "Summer", "Healthy", 8.0, 8.0, 1.0),
    ("carrots", "Carrot", "Vegetative", "Summer", "Ill", 4.0, 5.0, 0.5),
    ("lettuce", "Lettuce", "Vegetative", "Summer", "Healthy", 5.0, 5.0, 0.5),
    ("wheat", "Wheat", "Maturation", "Summer", "Healthy", 3.0, 3.0, 0.5),
)


@functools.cache
def _sources() -> tuple[Hierarchy, KnowledgeBase]:
    return default_hierarchy(), default_knowledge_base()


def field(
    field_id: str,
    crop: str,
    geometry: FieldGeometry,
    *,
    stage: Stage | None = None,
    season: Season = "Summer",
    health: HealthState = "Healthy",
    label: str | None = None,
    variety: str | None = None,
) -> FieldSpec:
    """A complete field of ``crop`` (default variety, typical stage unless given)."""
    hierarchy, knowledge = _sources()
    variety = variety or knowledge.default_variety(crop)
    return build_field(
        hierarchy=hierarchy,
        knowledge=knowledge,
        field_id=field_id,
        label=label or f"{variety} {crop}",
        crop=crop,
        variety=variety,
        stage=stage or knowledge.typical_stage(crop, season, variety),
        season=season,
        health=health,
        geometry=geometry,
    )


def mixed_recipe(*, seed: int = 3, rotate_first_deg: float = 25.0) -> SceneRecipe:
    """The :data:`MIXED_FIELDS`, packed; the first field is rotated and moved east of the rest."""
    requests = [
        FieldRequest(field_id, width, length, headland)
        for field_id, _, _, _, _, width, length, headland in MIXED_FIELDS
    ]
    geometry = pack_fields(requests)
    east = max(g.origin_m[0] + g.size_m[0] for g in geometry.values())
    fields = []
    for index, (field_id, crop, stage, season, health, *_) in enumerate(MIXED_FIELDS):
        placed = geometry[field_id]
        if index == 0:
            # Rotated fields exercise the kernel's rotation and the bounds check.
            placed = placed.model_copy(
                update={"origin_m": (east + 30.0, 5.0), "rotation_deg": rotate_first_deg}
            )
        fields.append(field(field_id, crop, placed, stage=stage, season=season, health=health))
    return SceneRecipe(
        prompt="one plot per growth form, an orchard in winter, ill carrots",
        seed=seed,
        environment=build_environment("Summer"),
        fields=tuple(fields),
    )


def single_field_recipe(
    crop: str = "Lettuce",
    *,
    size_m: tuple[float, float] = (4.0, 4.0),
    label: str | None = None,
    prompt: str = "a small field",
    season: Season = "Summer",
    seed: int = 0,
) -> SceneRecipe:
    """One small field at the origin."""
    geometry = FieldGeometry(origin_m=(0.0, 0.0), size_m=size_m, headland_m=0.5)
    spec = field("plot", crop, geometry, season=season, label=label)
    return SceneRecipe(
        prompt=prompt, seed=seed, environment=build_environment(season), fields=(spec,)
    )


def packed_recipe(crops: Sequence[str], total_plants: int, *, seed: int = 0) -> SceneRecipe:
    """Square fields of ``crops`` packed side by side, holding about ``total_plants`` in all."""
    hierarchy, knowledge = _sources()
    share = total_plants / len(crops)
    requests = []
    for index, crop in enumerate(crops):
        variety = knowledge.default_variety(crop)
        key = hierarchy.key(
            crop, variety, knowledge.typical_stage(crop, "Summer", variety), "Summer", "Healthy"
        )
        agronomy = knowledge.agronomy(key)
        area_per_plant = agronomy.row_spacing_m * agronomy.in_row_spacing_m / agronomy.rows_per_bed
        side = math.sqrt(share * area_per_plant)
        requests.append(FieldRequest(f"f{index}_{crop.lower()}", side + 2.0, side + 2.0, 1.0))
    geometry = pack_fields(requests)
    fields = tuple(
        field(request.id, crop, geometry[request.id])
        for crop, request in zip(crops, requests, strict=True)
    )
    return SceneRecipe(
        prompt=f"{len(crops)} fields, about {total_plants} plants",
        seed=seed,
        environment=build_environment("Summer"),
        fields=fields,
    )

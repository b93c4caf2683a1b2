"""Recipes for the Unreal backend tests, built the way the resolver builds them."""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence

from agrirecipe.enrich import build_environment, build_field
from agrirecipe.hierarchy import Hierarchy, default_hierarchy
from agrirecipe.knowledge import KnowledgeBase, default_knowledge_base
from agrirecipe.layout import FieldRequest, pack_fields
from agrirecipe.recipe import FieldGeometry, FieldSpec, SceneRecipe, Season

__all__ = [
    "GROWTH_FORM_CROPS",
    "MIXED_CROPS",
    "growth_form_recipe",
    "mixed_crops",
    "packed_recipe",
    "two_field_recipe",
]

#: One crop per growth form (every placeholder shape gets exercised).
GROWTH_FORM_CROPS = ("Apple", "Grape", "Tomato", "Carrot", "Lettuce", "Wheat")
#: Crops of many-field scenes, every planting pattern among the first ten.
MIXED_CROPS = (
    "Wheat",
    "Maize",
    "Carrot",
    "Onion",
    "Lettuce",
    "Potato",
    "Strawberry",
    "Cabbage",
    "Apple",
    "Grape",
    "Tomato",
    "Pepper",
)


def mixed_crops(count: int) -> list[str]:
    """``count`` crops for a many-field scene (MIXED_CROPS, repeated as needed)."""
    return [MIXED_CROPS[index % len(MIXED_CROPS)] for index in range(count)]


@functools.cache
def _sources() -> tuple[Hierarchy, KnowledgeBase]:
    return default_hierarchy(), default_knowledge_base()


def _field(
    crop: str,
    field_id: str,
    label: str,
    geometry: FieldGeometry,
    season: Season = "Summer",
) -> FieldSpec:
    hierarchy, knowledge = _sources()
    variety = knowledge.default_variety(crop)
    return build_field(
        hierarchy=hierarchy,
        knowledge=knowledge,
        field_id=field_id,
        label=label,
        crop=crop,
        variety=variety,
        stage=knowledge.typical_stage(crop, season, variety),
        season=season,
        health="Healthy",
        geometry=geometry,
    )


def two_field_recipe(
    *,
    prompt: str = "a healthy apple orchard next to young carrots",
    apple_label: str = "apple orchard",
    carrot_label: str = "carrots",
    seed: int = 7,
    season: Season = "Summer",
    latitude_deg: float = 50.8,
) -> SceneRecipe:
    """An orchard rotated 20 degrees away from the origin, and a carrot field east of it."""
    apples = _field(
        "Apple",
        "apples",
        apple_label,
        FieldGeometry(
            origin_m=(12.0, -8.0), size_m=(30.0, 40.0), rotation_deg=20.0, headland_m=4.0
        ),
        season,
    )
    carrots = _field(
        "Carrot",
        "carrots",
        carrot_label,
        FieldGeometry(origin_m=(60.0, 5.0), size_m=(8.0, 10.0), headland_m=1.0),
        season,
    )
    return SceneRecipe(
        prompt=prompt,
        seed=seed,
        environment=build_environment(season, latitude_deg),
        fields=(apples, carrots),
    )


def growth_form_recipe(season: Season = "Summer") -> SceneRecipe:
    """Small fields of one crop per growth form, packed without overlap."""
    requests = [FieldRequest(crop.lower(), 10.0, 10.0, 1.0) for crop in GROWTH_FORM_CROPS]
    geometry = pack_fields(requests)
    fields = tuple(
        _field(crop, crop.lower(), f"{crop} plot", geometry[crop.lower()], season)
        for crop in GROWTH_FORM_CROPS
    )
    return SceneRecipe(
        prompt="one small plot of each growth form",
        seed=11,
        environment=build_environment(season),
        fields=fields,
    )


def packed_recipe(crops: Sequence[str], total_plants: int, *, seed: int = 0) -> SceneRecipe:
    """Fields of ``crops`` packed side by side, sized so the scene holds about ``total_plants``.

    Each field is square-ish and gets an equal share of the plants, from its
    crop's spacing.
    """
    _, knowledge = _sources()
    share = total_plants / len(crops)
    requests = []
    for index, crop in enumerate(crops):
        agronomy = knowledge.agronomy(
            _sources()[0].key(
                crop,
                knowledge.default_variety(crop),
                knowledge.typical_stage(crop, "Summer"),
                "Summer",
                "Healthy",
            )
        )
        area_per_plant = agronomy.row_spacing_m * agronomy.in_row_spacing_m / agronomy.rows_per_bed
        side = math.sqrt(share * area_per_plant)
        headland = 1.0
        requests.append(
            FieldRequest(
                f"f{index}_{crop.lower()}", side + 2 * headland, side + 2 * headland, headland
            )
        )
    geometry = pack_fields(requests)
    fields = tuple(
        _field(crop, request.id, f"{crop} field {index}", geometry[request.id])
        for index, (crop, request) in enumerate(zip(crops, requests, strict=True))
    )
    return SceneRecipe(
        prompt=f"{len(crops)} fields, about {total_plants} plants",
        seed=seed,
        environment=build_environment("Summer"),
        fields=fields,
    )

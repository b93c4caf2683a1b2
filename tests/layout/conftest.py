"""Recipes for layout tests, built the way the resolver builds them: packer + ``build_field``.

The ``hierarchy`` and ``knowledge`` fixtures come from ``tests/conftest.py``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import pytest

from agrirecipe.enrich import build_environment, build_field
from agrirecipe.hierarchy import Hierarchy
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.layout import FieldRequest, pack_fields
from agrirecipe.recipe import Placement, Relation, SceneRecipe, Season

RecipeFactory = Callable[..., SceneRecipe]


def request_for(
    knowledge: KnowledgeBase, crop: str, field_id: str, size_factor: float = 1.0
) -> FieldRequest:
    """A field of ``crop`` at ``size_factor`` times its default size, never too small to plant."""
    width, length = knowledge.default_field_size_m(crop)
    headland = knowledge.default_headland_m(crop)
    planting = knowledge.crop_file(crop).planting
    canopy = knowledge.crop_file(crop).canopy_width_m.value
    bed_span = planting.bed_row_spacing_m.value * (planting.rows_per_bed - 1)
    least = 2 * headland + max(canopy, bed_span) + 0.5
    return FieldRequest(
        id=field_id,
        width_m=max(width * size_factor, least),
        length_m=max(length * size_factor, least),
        headland_m=headland,
    )


def build_recipe(
    hierarchy: Hierarchy,
    knowledge: KnowledgeBase,
    crops: Sequence[str],
    *,
    seed: int = 0,
    relations: Sequence[Relation] = (),
    size_factor: float | Sequence[float] = 1.0,
    season: Season = "Summer",
    placement: Placement | None = None,
) -> SceneRecipe:
    """A complete recipe with one field per crop (ids ``f0``, ``f1``, ...)."""
    factors = (
        [float(size_factor)] * len(crops)
        if isinstance(size_factor, int | float)
        else list(size_factor)
    )
    requests = [
        request_for(knowledge, crop, f"f{index}", factors[index])
        for index, crop in enumerate(crops)
    ]
    geometry = pack_fields(requests, relations)
    fields = []
    for index, crop in enumerate(crops):
        field_id = f"f{index}"
        fields.append(
            build_field(
                hierarchy=hierarchy,
                knowledge=knowledge,
                field_id=field_id,
                label=f"{crop} field",
                crop=crop,
                variety=knowledge.default_variety(crop),
                stage=knowledge.typical_stage(crop, season),
                season=season,
                health="Ill" if index % 3 == 2 else "Healthy",
                geometry=geometry[field_id],
                placement=placement,
            )
        )
    return SceneRecipe(
        prompt="test: " + ", ".join(crops),
        seed=seed,
        environment=build_environment(season),
        fields=tuple(fields),
        relations=tuple(relations),
    )


@pytest.fixture(scope="session")
def make_recipe(hierarchy: Hierarchy, knowledge: KnowledgeBase) -> RecipeFactory:
    """``make_recipe(["Apple", "Carrot"], seed=..., relations=..., size_factor=...)``."""

    def factory(crops: Sequence[str], **options: object) -> SceneRecipe:
        return build_recipe(hierarchy, knowledge, crops, **options)  # type: ignore[arg-type]

    return factory

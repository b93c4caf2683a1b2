"""Builders shared by the evaluation tests (a module with a unique name: ``conftest`` is
ambiguous when several test folders have one)."""

from __future__ import annotations

from typing import Any

from agrirecipe.evaluation import BenchmarkPrompt, PredictedField, PredictedScene
from agrirecipe.evaluation._benchmark import _apply_defaults, _check_names
from agrirecipe.hierarchy import default_hierarchy

__all__ = ["field", "make_prompt", "scene"]


def make_prompt(**spec: Any) -> BenchmarkPrompt:
    """A benchmark prompt checked and completed exactly as the loader does it."""
    spec.setdefault("id", "t-1")
    spec.setdefault("prompt", "test prompt")
    item = BenchmarkPrompt.model_validate(spec)
    hierarchy = default_hierarchy()
    fields = tuple(
        _apply_defaults(_check_names(f, hierarchy, "test"), {"health": "Healthy"})
        for f in item.fields
    )
    extra = item.extra_field
    if extra is not None:
        extra = _apply_defaults(_check_names(extra, hierarchy, "test"), {"health": "Healthy"})
    return item.model_copy(update={"fields": fields, "extra_field": extra})


def field(
    crop: str,
    variety: str,
    stage: str = "Vegetative",
    season: str = "Summer",
    health: str = "Healthy",
    *,
    field_id: str | None = None,
    size_m: tuple[float, float] | None = (60.0, 100.0),
    stated: tuple[str, ...] = ("crop", "variety", "stage", "season", "health"),
    inferred: tuple[str, ...] = (),
) -> PredictedField:
    """A predicted field; the category comes from the hierarchy."""
    category = default_hierarchy().crops[crop].category
    return PredictedField(
        id=field_id or f"{crop.lower()}_{variety.lower().replace(' ', '_')}",
        category=category,
        crop=crop,
        variety=variety,
        stage=stage,
        season=season,
        health=health,
        size_m=size_m,
        stated=stated,
        inferred=inferred,
    )


def scene(*fields: PredictedField, **options: Any) -> PredictedScene:
    """A predicted scene of ``fields`` (northern hemisphere unless told otherwise)."""
    options.setdefault("hemisphere", "north")
    return PredictedScene(fields=fields, **options)

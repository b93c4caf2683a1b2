"""Vary a recipe's stage, season and health where its prompt left them open.

Only attributes a field lists as ``inferred`` (the prompt did not say them) are
drawn; stated ones are kept. The season is scene-wide (it sets the sun), so it
is drawn once and applied to every field whose season was inferred, and only
when no field stated one. Geometry, spacing and placement stay, so the plants
stand where they would have; heights, foliage and meshes follow the new stage,
season and health from the knowledge base.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, cast, get_args

import numpy as np

from agrirecipe._errors import ConfigurationError
from agrirecipe.recipe import HealthState, SceneRecipe, Season, Stage

__all__ = ["VARIABLE_ATTRIBUTES", "check_attributes", "vary_recipe"]

#: Attributes a dataset variant may draw where the prompt left them open.
VARIABLE_ATTRIBUTES = ("stage", "season", "health")
_CHOICES: dict[str, tuple[str, ...]] = {
    "stage": get_args(Stage),
    "season": get_args(Season),
    "health": get_args(HealthState),
}
# Stated spacing is kept (the same field, another day).
_KEPT_AGRONOMY = ("row_spacing_m", "in_row_spacing_m", "rows_per_bed", "bed_row_spacing_m")


def check_attributes(attributes: Sequence[str]) -> tuple[str, ...]:
    """``attributes`` validated against :data:`VARIABLE_ATTRIBUTES` (order kept, no repeats)."""
    unknown = [a for a in attributes if a not in VARIABLE_ATTRIBUTES]
    if unknown:
        raise ConfigurationError(
            f"cannot vary {', '.join(map(repr, unknown))}",
            stage="dataset",
            hint="attributes: " + ", ".join(VARIABLE_ATTRIBUTES),
        )
    return tuple(dict.fromkeys(attributes))


def vary_recipe(
    recipe: SceneRecipe, attributes: Sequence[str], rng: np.random.Generator
) -> tuple[SceneRecipe, dict[str, Any]]:
    """A copy of ``recipe`` with ``attributes`` drawn where inferred, and what was drawn
    (``{"season": ..., "fields": {field id: {attribute: value}}}``)."""
    from agrirecipe.enrich import build_environment, build_field
    from agrirecipe.hierarchy import default_hierarchy
    from agrirecipe.knowledge import default_knowledge_base

    attributes = check_attributes(attributes)
    drawn: dict[str, Any] = {"fields": {}}
    if not attributes:
        return recipe, drawn
    season = recipe.environment.season
    environment = recipe.environment
    if "season" in attributes and all("season" in f.inferred for f in recipe.fields):
        season = cast(Season, _CHOICES["season"][int(rng.integers(4))])
        environment = build_environment(season, recipe.environment.latitude_deg)
        drawn["season"] = season
    hierarchy, knowledge = default_hierarchy(), default_knowledge_base()
    fields = []
    for spec in recipe.fields:
        values: dict[str, str] = {"stage": spec.stage, "season": spec.season, "health": spec.health}
        changed: dict[str, str] = {}
        for attribute in attributes:
            if attribute == "season":
                if "season" in drawn and "season" in spec.inferred:
                    values["season"] = changed["season"] = season
                continue
            if attribute in spec.inferred:
                choices = _CHOICES[attribute]
                values[attribute] = changed[attribute] = choices[int(rng.integers(len(choices)))]
        if not changed:
            fields.append(spec)
            continue
        drawn["fields"][spec.id] = changed
        fields.append(
            build_field(
                hierarchy=hierarchy,
                knowledge=knowledge,
                field_id=spec.id,
                label=spec.label,
                crop=spec.crop,
                variety=spec.variety,
                stage=cast(Stage, values["stage"]),
                season=cast(Season, values["season"]),
                health=cast(HealthState, values["health"]),
                geometry=spec.geometry,
                placement=spec.placement,
                stated=spec.stated,
                inferred=spec.inferred,
                agronomy_update={k: getattr(spec.agronomy, k) for k in _KEPT_AGRONOMY},
            )
        )
    varied = SceneRecipe.model_validate(
        {
            **recipe.model_dump(),
            "environment": environment.model_dump(),
            "fields": [f.model_dump() for f in fields],
        }
    )
    return varied, drawn

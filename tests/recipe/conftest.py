"""Recipes for the recipe tests, built the way the resolver builds them (``build_field``)."""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from typing import Any

import pytest

from agrirecipe import RecipeValidationError
from agrirecipe.enrich import build_environment, build_field
from agrirecipe.hierarchy import Hierarchy
from agrirecipe.knowledge import KnowledgeBase
from agrirecipe.recipe import (
    AttributeName,
    FieldGeometry,
    FieldSpec,
    Relation,
    SceneRecipe,
    dump_recipe,
    parse_recipe,
)


@pytest.fixture(scope="session")
def make_field(hierarchy: Hierarchy, knowledge: KnowledgeBase) -> Callable[..., FieldSpec]:
    """A complete field: attributes resolved, everything else from the knowledge base."""

    def make(
        field_id: str = "apples",
        *,
        crop: str = "Apple",
        variety: str = "Pink Lady",
        stage: str = "Reproductive",
        season: str = "Summer",
        health: str = "Healthy",
        origin_m: tuple[float, float] = (0.0, 0.0),
        size_m: tuple[float, float] | None = None,
        rotation_deg: float = 0.0,
        headland_m: float | None = None,
        stated: Sequence[AttributeName] = ("crop", "variety"),
        inferred: Sequence[AttributeName] = ("category", "stage", "season", "health"),
    ) -> FieldSpec:
        geometry = FieldGeometry(
            origin_m=origin_m,
            size_m=size_m or knowledge.default_field_size_m(crop, variety),
            rotation_deg=rotation_deg,
            headland_m=(
                knowledge.default_headland_m(crop, variety) if headland_m is None else headland_m
            ),
        )
        return build_field(
            hierarchy=hierarchy,
            knowledge=knowledge,
            field_id=field_id,
            label=f"{variety} {crop.lower()}",
            crop=crop,
            variety=variety,
            stage=stage,  # type: ignore[arg-type]
            season=season,  # type: ignore[arg-type]
            health=health,  # type: ignore[arg-type]
            geometry=geometry,
            stated=stated,
            inferred=inferred,
        )

    return make


@pytest.fixture(scope="session")
def make_recipe(make_field: Callable[..., FieldSpec]) -> Callable[..., SceneRecipe]:
    """A recipe of the given fields (one apple orchard by default)."""

    def make(
        *fields: FieldSpec,
        relations: Sequence[Relation] = (),
        prompt: str = "a healthy Pink Lady apple orchard in summer",
        seed: int = 0,
        latitude_deg: float = 50.8,
    ) -> SceneRecipe:
        return SceneRecipe(
            prompt=prompt,
            seed=seed,
            environment=build_environment("Summer", latitude_deg),
            fields=fields or (make_field(),),
            relations=tuple(relations),
        )

    return make


def _recipe_data(recipe: SceneRecipe) -> dict[str, Any]:
    data: dict[str, Any] = json.loads(dump_recipe(recipe))
    return data


def _problems_of(data: dict[str, Any], **options: Any) -> dict[str, str]:
    with pytest.raises(RecipeValidationError) as caught:
        parse_recipe(json.dumps(data), **options)
    problems = dict(caught.value.problems)
    assert len(problems) == len(caught.value.problems), "one message per path"
    for path, message in caught.value.problems:
        assert f"{path}: {message}" in str(caught.value), "every problem is in the message"
    return problems


@pytest.fixture(scope="session")
def two_orchards(
    make_field: Callable[..., FieldSpec], make_recipe: Callable[..., SceneRecipe]
) -> SceneRecipe:
    """Orchards 'a' and 'b' side by side, 10 m apart (1,335 trees each)."""
    return make_recipe(make_field("a"), make_field("b", origin_m=(70.0, 0.0)))


@pytest.fixture(scope="session")
def recipe_data() -> Callable[[SceneRecipe], dict[str, Any]]:
    """The recipe as decoded JSON, ready to be broken by a test."""
    return _recipe_data


@pytest.fixture(scope="session")
def problems_of() -> Callable[..., dict[str, str]]:
    """Parse broken recipe data (``parse_recipe`` options as keywords); return {path: message}.

    Fails unless parsing raises :class:`RecipeValidationError` whose message lists
    every problem.
    """
    return _problems_of

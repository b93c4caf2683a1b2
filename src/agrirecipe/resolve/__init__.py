"""Prompt -> recipe: decompose, normalise, retrieve, validate, enrich.

:func:`resolve` is what :func:`agrirecipe.generate` calls. A strategy
(:class:`Resolver`, chosen by name: "rules", "embedding", "llm", "hybrid",
"auto") turns the prompt into a :class:`SceneIntent`; the shared pipeline
turns that into a validated :class:`~agrirecipe.recipe.SceneRecipe`.
"""

from agrirecipe.resolve._explain import Explanation
from agrirecipe.resolve._intent import (
    Candidate,
    FieldIntent,
    Hemisphere,
    RelationIntent,
    ResolveContext,
    Resolver,
    RowSpec,
    SceneIntent,
    SizeIntent,
    TraceStep,
)
from agrirecipe.resolve._pipeline import MAX_PROMPT_CHARS, Resolution, build_recipe, resolve
from agrirecipe.resolve._registry import (
    BUILTIN_RESOLVERS,
    available_resolvers,
    get_resolver,
    register_resolver,
    resolve_resolver_name,
)

__all__ = [
    "BUILTIN_RESOLVERS",
    "MAX_PROMPT_CHARS",
    "Candidate",
    "Explanation",
    "FieldIntent",
    "Hemisphere",
    "RelationIntent",
    "Resolution",
    "ResolveContext",
    "Resolver",
    "RowSpec",
    "SceneIntent",
    "SizeIntent",
    "TraceStep",
    "available_resolvers",
    "build_recipe",
    "get_resolver",
    "register_resolver",
    "resolve",
    "resolve_resolver_name",
]

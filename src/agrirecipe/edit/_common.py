"""What every kind of edit shares: the resolver context, reading words, finding the
fields named, and validating the edited recipe."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pydantic import ValidationError

from agrirecipe._errors import PromptError
from agrirecipe.edit._words import Instruction, matching_fields, unmatched
from agrirecipe.recipe import FieldSpec, SceneRecipe

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase
    from agrirecipe.resolve._intent import FieldIntent, ResolveContext, SceneIntent

__all__ = [
    "describe",
    "edit_context",
    "read_words",
    "targets_of",
    "validated",
    "warnings_without",
]


def edit_context(
    recipe: SceneRecipe,
    hierarchy: Hierarchy | str | Path | None,
    knowledge: KnowledgeBase | str | Path | None,
    max_plants: int,
) -> ResolveContext:
    from agrirecipe.knowledge import KnowledgeBase
    from agrirecipe.resolve._intent import ResolveContext
    from agrirecipe.resolve._pipeline import _hierarchy, _knowledge

    if hierarchy is None and isinstance(knowledge, KnowledgeBase):
        hierarchy = knowledge.hierarchy
    tree = _hierarchy(hierarchy)
    return ResolveContext(
        hierarchy=tree,
        knowledge=_knowledge(knowledge, tree),
        seed=recipe.seed,
        latitude_deg=recipe.environment.latitude_deg,
        max_plants=max_plants,
    )


def read_words(text: str, context: ResolveContext, resolver: str) -> SceneIntent | None:
    """What the words ask for, read like a prompt; None when they name no field."""
    from agrirecipe.resolve import get_resolver

    if not text.strip():
        return None
    try:
        return get_resolver(resolver).resolve_intent(text, context)
    except PromptError as exc:
        if "no crop or field found" in exc.message:
            return None
        raise


def validated(recipe: SceneRecipe, data: dict[str, Any], context: ResolveContext) -> SceneRecipe:
    """The edited recipe, validated like any other (overlaps and the plant cap included)."""
    from agrirecipe.recipe import check_recipe

    try:
        new = SceneRecipe.model_validate(
            {**recipe.model_dump(), **data}, context={"max_plants": context.max_plants}
        )
    except ValidationError as exc:
        error = exc.errors()[0]
        where = ".".join(str(part) for part in error["loc"])
        message = str(error["msg"]).removeprefix("Value error, ")
        raise PromptError(
            f"the edited scene is not valid: {message}",
            stage="edit",
            path=where or None,
            hint="make a smaller change, or remove the field in the way first",
        ) from exc
    problems = check_recipe(new, context.hierarchy)
    if problems:
        path, message = problems[0]
        raise PromptError(f"the edited scene is not valid: {message}", stage="edit", path=path)
    return new


def targets_of(
    recipe: SceneRecipe, words: Instruction, intent: SceneIntent | None
) -> list[FieldSpec]:
    """The fields the instruction names: by id or label, by crop or kind, or all of them."""
    chosen = set(words.named)
    if intent is not None:
        for field in intent.fields:
            found = matching_fields(field, recipe)
            if found:
                chosen.update(f.id for f in found)
            elif field.crop is not None or field.crop_options or field.category is not None:
                raise unmatched(describe(field), recipe)
    if not chosen and words.everything:
        chosen = {f.id for f in recipe.fields}
    return [f for f in recipe.fields if f.id in chosen]


def describe(field: FieldIntent) -> str:
    noun = field.noun or "field"
    if field.crop is not None:
        name = f"{field.variety} {field.crop}" if field.variety else field.crop
        return f"{name.lower()} {noun}"
    return f"{field.category.lower()} {noun}" if field.category else noun


def warnings_without(recipe: SceneRecipe, field_ids: Iterable[str]) -> tuple[str, ...]:
    """The recipe's warnings but those about the given fields ("<id>: ...")."""
    prefixes = tuple(f"{field_id}:" for field_id in field_ids)
    return tuple(w for w in recipe.warnings if not w.startswith(prefixes))

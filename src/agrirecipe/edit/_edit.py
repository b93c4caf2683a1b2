"""``edit_recipe``: change one thing about a scene by words, leaving everything else as it was.

An instruction adds fields ("add a wheat field south of the orchard"),
removes them ("remove the carrots") or changes the fields it names ("make the
pears ill", "the carrots in autumn", "rows 50 cm apart"). Its words are read
by the same resolver as a prompt. Fields the instruction does not touch are
copied unchanged, so their ids, attributes, geometry and (the layout being
seeded by recipe seed and field id) every plant position stay byte-identical.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from agrirecipe._errors import PromptError
from agrirecipe.edit._change import change_fields
from agrirecipe.edit._common import (
    edit_context,
    read_words,
    targets_of,
    validated,
    warnings_without,
)
from agrirecipe.edit._diff import diff_recipes
from agrirecipe.edit._grow import add_fields, replace_fields
from agrirecipe.edit._words import Instruction, fields_list, read_instruction
from agrirecipe.recipe import DEFAULT_MAX_PLANTS, SceneRecipe

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy
    from agrirecipe.knowledge import KnowledgeBase
    from agrirecipe.resolve._intent import ResolveContext

__all__ = ["MAX_INSTRUCTION_CHARS", "EditResult", "edit_recipe"]

MAX_INSTRUCTION_CHARS = 1000


@dataclass(frozen=True, slots=True)
class EditResult:
    """The edited recipe and what changed, one line per change."""

    recipe: SceneRecipe
    changes: tuple[str, ...]
    #: Ids of the fields added, removed or changed.
    touched: tuple[str, ...]


def edit_recipe(
    recipe: SceneRecipe,
    instruction: str,
    *,
    hierarchy: Hierarchy | str | Path | None = None,
    knowledge: KnowledgeBase | str | Path | None = None,
    resolver: str = "auto",
    max_plants: int = DEFAULT_MAX_PLANTS,
) -> EditResult:
    """Apply one instruction in words to ``recipe``; return the new recipe and the diff.

    Raises :class:`~agrirecipe.PromptError` (stage ``"edit"``) when the
    instruction names no field of the scene, is ambiguous ("make it ill" with
    three fields), or asks for nothing; its hint lists the scene's fields.
    """
    if not isinstance(instruction, str) or not instruction.strip():
        raise PromptError(
            "the edit instruction is empty",
            stage="edit",
            hint="say what to change, e.g. 'make the pears ill', 'remove the carrots', "
            "'add a wheat field south of the orchard', 'rows 50 cm apart'",
        )
    if len(instruction) > MAX_INSTRUCTION_CHARS:
        raise PromptError(
            f"the edit instruction is {len(instruction):,} characters long; an edit reads at "
            f"most {MAX_INSTRUCTION_CHARS:,}",
            stage="edit",
            hint="make one change at a time",
        )
    context = edit_context(recipe, hierarchy, knowledge, max_plants)
    words = read_instruction(instruction, recipe)
    if words.action == "remove":
        new = remove_fields(recipe, words, context, resolver)
    elif words.action == "add":
        new = add_fields(recipe, words, context, resolver)
    elif words.action == "replace":
        new = replace_fields(recipe, words, context, resolver)
    else:
        new = change_fields(recipe, words, context, resolver)
    changes = diff_recipes(recipe, new)
    if not changes:
        raise PromptError(
            f"{instruction!r} changes nothing in the scene",
            stage="edit",
            hint="the fields are already like that: " + fields_list(recipe),
        )
    old = {f.id: f for f in recipe.fields}
    fresh = {f.id: f for f in new.fields}
    touched = tuple(
        sorted(
            {i for i in old if i not in fresh or fresh[i] != old[i]}
            | {i for i in fresh if i not in old}
        )
    )
    return EditResult(recipe=new, changes=changes, touched=touched)


def remove_fields(
    recipe: SceneRecipe, words: Instruction, context: ResolveContext, resolver: str
) -> SceneRecipe:
    intent = read_words(words.rest, context, resolver)
    targets = targets_of(recipe, words, intent)
    if not targets:
        raise PromptError(
            f"{words.text!r} names no field of the scene to remove",
            stage="edit",
            hint="name it by crop, kind or id; the fields are: " + fields_list(recipe),
        )
    gone = {f.id for f in targets}
    if len(gone) == len(recipe.fields):
        raise PromptError(
            "an edit cannot remove every field: a scene holds at least one",
            stage="edit",
            hint="generate a new scene instead",
        )
    fields = tuple(f for f in recipe.fields if f.id not in gone)
    relations = tuple(
        r for r in recipe.relations if r.subject not in gone and not gone & set(r.objects)
    )
    warnings = warnings_without(recipe, gone)
    return validated(
        recipe,
        {"fields": fields, "relations": relations, "warnings": warnings},
        context,
    )

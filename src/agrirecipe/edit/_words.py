"""Reading an edit instruction: what it does (add, remove, change) and which fields it names."""

from __future__ import annotations

import functools
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import yaml

from agrirecipe._errors import PromptError
from agrirecipe.recipe import FieldSpec, SceneRecipe
from agrirecipe.resolve._intent import FieldIntent

__all__ = ["Instruction", "fields_list", "matching_fields", "read_instruction", "unmatched"]

Action = Literal["add", "remove", "change", "replace"]
_DATA = Path(__file__).resolve().parent / "data" / "edit.yaml"


@functools.cache
def _words() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load(_DATA.read_text(encoding="utf-8"))
    return data


def _alternatives(phrases: Sequence[str]) -> str:
    """A regex alternation of ``phrases``, longest first."""
    return "|".join(re.escape(p) for p in sorted(phrases, key=len, reverse=True))


def _phrase_pattern(phrases: Sequence[str]) -> re.Pattern[str]:
    return re.compile(rf"^(?:{_alternatives(phrases)})\b[\s,:]*", re.I)


@dataclass(frozen=True, slots=True)
class Instruction:
    """An instruction split into its action, the fields it names by id or label, and the rest."""

    text: str
    action: Action
    rest: str
    named: tuple[str, ...]
    everything: bool
    pronoun: bool
    #: For a possible replacement ("turn the carrots into potatoes"): the words of the
    #: new crop; ``rest`` then holds the words of the fields replaced.
    replacement: str | None = None


def read_instruction(text: str, recipe: SceneRecipe) -> Instruction:
    """Split ``text`` ("remove the carrots") into action and remainder; find ids and labels."""
    words = _words()
    rest = " ".join(text.split())
    polite = _phrase_pattern(words["politeness"])
    while (match := polite.match(rest)) is not None and match.end() > 0:
        rest = rest[match.end() :]
    rest = re.sub(r"[\s,.;!]*(?:please|thanks|thank you|thx)?[\s.!]*$", "", rest, flags=re.I)
    action: Action = "change"
    replacement = None
    for verbs, links in (("replace", "replace_links"), ("turn", "turn_links")):
        split = re.match(
            rf"^(?:{_alternatives(words[verbs])})\s+(.+?)\s+(?:{_alternatives(words[links])})"
            r"\s+(.+)$",
            rest,
            re.I,
        )
        if split is not None:
            action, rest, replacement = "replace", split.group(1), split.group(2)
            break
    else:
        for name in ("remove", "add", "change"):
            match = _phrase_pattern(words[name]).match(rest)
            if match is not None:
                action = "change" if name == "change" else name
                rest = rest[match.end() :]
                break
    named: list[str] = []
    for spec in sorted(recipe.fields, key=lambda f: -len(f.label)):
        # A new field may share an old one's label ("add a Nantes carrot field"): an
        # added field's anchor is named by id only.
        for name in (spec.id,) if action == "add" else (spec.id, spec.label):
            pattern = re.compile(rf"(?<![\w]){re.escape(name)}(?![\w])", re.I)
            if pattern.search(rest):
                named.append(spec.id)
                rest = pattern.sub(" ", rest)
                break
    rest = " ".join(rest.split()).strip(" ,.;:")
    lowered = f" {rest.lower()} "
    everything = any(f" {w} " in lowered for w in words["everything"])
    pronoun = any(f" {w} " in lowered for w in words["pronouns"])
    return Instruction(
        text=text,
        action=action,
        rest=rest,
        named=tuple(named),
        everything=everything,
        pronoun=pronoun,
        replacement=replacement,
    )


def matching_fields(intent: FieldIntent, recipe: SceneRecipe) -> list[FieldSpec]:
    """The fields of ``recipe`` that a field named in an instruction refers to.

    A crop matches its fields (a variety narrows them when one matches it, else
    it is the new variety: "make the apples Gala"); "the orchard" matches the
    fields of the crops an orchard may hold; a category its fields. A generic
    "field" matches nothing by itself.
    """
    fields = list(recipe.fields)
    if intent.crop is not None:
        same_crop = [f for f in fields if f.crop == intent.crop]
        if intent.variety is not None:
            exact = [f for f in same_crop if f.variety == intent.variety]
            if exact:
                return exact
        return same_crop
    if intent.crop_options:
        return [f for f in fields if f.crop in intent.crop_options]
    if intent.category is not None:
        return [f for f in fields if f.category == intent.category]
    return []


def fields_list(recipe: SceneRecipe) -> str:
    """``"apple_orchard_1 (Pink Lady apple orchard), carrot_field_1 (...)"``."""
    return ", ".join(f"{f.id} ({f.label})" for f in recipe.fields)


def unmatched(description: str, recipe: SceneRecipe) -> PromptError:
    """The error for an instruction that names a field the scene does not have."""
    return PromptError(
        f"the scene has no {description}",
        stage="edit",
        hint="its fields are: " + fields_list(recipe),
    )

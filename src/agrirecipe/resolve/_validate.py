"""The *validate* stage: an intent names only what the hierarchy holds, and every field
is traceable to the words that asked for it (the paper's intent validation).

Any strategy can err (the language model most of all), so every intent passes here
before crops are chosen; a failure is an :class:`UnknownCropError` with the nearest
known crops, or a :class:`PromptError` naming the field.
"""

from __future__ import annotations

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.resolve._casual import expand_casual
from agrirecipe.resolve._intent import ResolveContext, SceneIntent
from agrirecipe.resolve._lexicon import tokenize
from agrirecipe.resolve._lists import spread_value_lists

__all__ = ["validate_intent"]


def _words(text: str) -> set[str]:
    return {token.norm for token in tokenize(text) if token.norm.isalnum()}


def validate_intent(intent: SceneIntent, context: ResolveContext) -> None:
    """Catch intents that name what the hierarchy does not hold (any strategy can err)."""
    hierarchy = context.hierarchy
    # "the": references to labelled fields are spelled "the <crop>" ("north of A");
    # "in": "12 maize rows" is read as "maize in 12 rows"; "plants": "150 Pink Lady" as
    # "150 Pink Lady plants"; "one", "other": "the north block has ..., the south block
    # ..." is read as "one ..., the other ..."; "at", "rows", "long": "8 rows x 76 cm x
    # 30 m" as "8 rows at 76 cm, rows 30 m long"; "plot": "the polytunnel of tomatoes" as
    # "the plot of tomatoes"; "them": "between the two a strip of ..." as "between them";
    # "two", "fields", "each": "cereals on both sides of the track" as "cereals in two
    # fields, one each side of the track"; "on": "Left: corn" as "On the left, corn";
    # "end": "around the farmhouse: wheat to the north of it" as "wheat at the north end";
    # "first" ... "fourth": "strip 2 south of strip 1" as "the second south of the first";
    # "it": "a maize plot to its east" as "a maize plot east of it"; "of": "The western
    # plot has ..." as "one of them, west of the other, has ..."; "a": "the near wheat
    # field ..., and the one beyond it" as "and a wheat field beyond it"
    expanded = expand_casual(intent.prompt)
    prompt_words = (
        _words(intent.prompt)
        | _words(expanded)
        | _words(spread_value_lists(expanded))
        | {"the", "in", "plants", "one", "other", "at", "rows", "long", "plot", "them"}
        | {
            "two",
            "fields",
            "each",
            "on",
            "end",
            "first",
            "second",
            "third",
            "fourth",
            "it",
            "of",
            "a",
        }
    )
    for index, field in enumerate(intent.fields):
        path = f"fields[{index}]"
        # Intent validation (the paper's stage): every field is traceable to the words
        # that asked for it; a field the prompt never asked for is not built.
        asked = _words(field.text)
        if not asked or not asked <= prompt_words:
            raise PromptError(
                f"field {index + 1} ({field.text!r}) is not traceable to the words of the "
                f"prompt; the {intent.resolver or 'resolver'} strategy made a field nobody "
                "asked for",
                stage="validate",
                path=path,
                hint="rephrase the request, or try another resolver",
            )
        if field.crop is not None and field.crop not in hierarchy.crops:
            from rapidfuzz import process

            nearest = [
                str(m[0]) for m in process.extract(field.crop, list(hierarchy.crops), limit=3)
            ]
            raise UnknownCropError(
                f"{field.crop!r} is not a crop of the asset hierarchy",
                requested=field.crop,
                nearest=nearest,
                path=path,
            )
        if field.variety is not None and field.crop is not None:
            crop = hierarchy.crop(field.crop)
            if field.variety not in {v.name for v in crop.varieties}:
                raise UnknownCropError(
                    f"{field.variety!r} is not one of the {field.crop} varieties of the hierarchy",
                    requested=f"{field.variety} {field.crop}",
                    nearest=[v.name for v in crop.varieties][:3],
                    path=path,
                )
        if field.category is not None and field.category not in hierarchy.categories:
            raise PromptError(
                f"{field.category!r} is not a category of the asset hierarchy",
                stage="validate",
                path=path,
                hint="categories: " + ", ".join(hierarchy.categories),
            )
        unknown = [c for c in field.crop_options if c not in hierarchy.crops]
        if unknown:
            raise PromptError(
                f"crop options {unknown} are not in the asset hierarchy",
                stage="validate",
                path=path,
            )

"""Refusals: what a prompt asks that cannot be built, refused with a clear error (issue 8).

A prompt of scenery alone ("a parking lot with trees"), a real crop the hierarchy does
not hold ("an olive grove", refused with the nearest known crops), an unknown word where
a crop or variety name belongs ("a quinoa field", "Honeycrisp apples"), or a prompt that
asks for no crop ("bare soil, no crop at all") is an :class:`~agrirecipe.UnknownCropError`
or :class:`~agrirecipe.PromptError` naming the word and what is accepted.
:class:`~agrirecipe.resolve._parse.PromptReader` calls these at step 8 of its reading
(and :func:`reject_unknown_names`, :func:`reject_no_crop` once the fields are known).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.resolve._lexicon import Item, OtherCrop, everyday_words, vocabulary
from agrirecipe.resolve._mentions import Mention

if TYPE_CHECKING:
    from agrirecipe.hierarchy import Hierarchy

__all__ = [
    "EXAMPLES",
    "NearestCrops",
    "reject_no_crop",
    "reject_other_crops",
    "reject_scenery",
    "reject_unknown_names",
]

#: Requests a refusal offers as examples of what can be built.
EXAMPLES = (
    "'a healthy Pink Lady apple orchard in summer', "
    "'two carrot fields next to a wheat field', 'some fruit and vegetable fields'"
)
#: The strategy's nearest known crops to an unknown name (and what it is said to be like).
NearestCrops = Callable[[str, Sequence[str]], tuple[str, ...]]


def reject_scenery(items: Sequence[Item]) -> None:
    """ "a parking lot with trees": non-agricultural scenery with plants in general only.

    Such a prompt names no crop, category, field or farm: the plant words in it
    (trees, grass, bushes) are the scenery's, not a request for a crop field.
    """
    scenery = [item for item in items if item.role == "non_agricultural"]
    if not scenery:
        return
    generic = {str(word) for word in vocabulary()["generic_vegetation"]}
    for item in items:
        if item.role in ("head", "weak_variety", "container"):
            return
        if item.role in ("plot", "other_crop") and item.norm not in generic:
            return
    raise PromptError(
        f"{scenery[0].raw!r} is not an agricultural scene, and the prompt names no crop or field",
        stage="resolve",
        hint="agrirecipe builds crop fields, orchards, vineyards and farms; name a crop, "
        f"a variety or a kind of field, e.g. {EXAMPLES}",
    )


#: What may stand between a crop and the correction that takes it back ("olive grove? no,
#: I mean ...").
_BEFORE_A_CORRECTION = frozenset({"?", ",", "!", "...", ".", "-", "no", "nope", "oh", "hmm"})


def reject_other_crops(
    items: Sequence[Item], hierarchy: Hierarchy, nearest_crops: NearestCrops
) -> None:
    """A real crop the hierarchy does not hold ("olive grove") is refused with the nearest
    known crops; a likeness ("plum-shaped"), a kind said in brackets or the scenery's
    grass is not."""
    generic = {str(word) for word in vocabulary()["generic_vegetation"]}
    for index, item in enumerate(items):
        if item.role != "other_crop":
            continue
        following = items[index + 1] if index + 1 < len(items) else None
        before = items[index - 1] if index else None
        listed = any(n is not None and n.role == "conjunction" for n in (before, following))
        if item.norm in generic and not listed and (following is None or following.role != "plot"):
            # "the grass white underneath": the scenery's grass, not a grass crop
            # ("a grass field", "grass and wheat" still ask for it and are refused).
            item.role = "filler"
            item.data["scenery"] = "vegetation"
            continue
        if following is not None and (following.norm.split() or [""])[0] in _LIKENESSES:
            # "long plum-shaped fruit going red": a shape, not a plum crop
            item.role = "filler"
            continue
        if (
            before is not None
            and following is not None
            and (before.norm, following.norm) == ("(", ")")
            and index >= 2
            and items[index - 2].role == "head"
        ):
            # "roma (plum) tomatos": a kind said in brackets of the crop just named
            item.role = "filler"
            item.data["short_for"] = True
            continue
        opened = next(
            (at for at in range(index - 1, max(index - 3, 0) - 1, -1) if items[at].norm == "("),
            None,
        )
        if (
            following is not None
            and following.norm in ("one", "ones")
            and opened is not None
            and opened >= 1
            and items[opened - 1].role == "head"
            and all(i.norm in ("the", "a") for i in items[opened + 1 : index])
        ):
            # "roma toms (the plum ones)": a kind said in brackets of the crop just named
            item.role = "filler"
            item.data["short_for"] = True
            continue
        if any(
            earlier.role == "head" and earlier.tokens[0].norm == item.norm
            for earlier in items[:index]
        ):
            # "San Marzano and plum tomatoes (plum ones to the west)": the first word
            # of a crop named before stands for it
            item.role = "filler"
            item.data["short_for"] = True
            continue
        after = itertools.dropwhile(
            lambda i: i.role in ("filler", "plot") or i.norm in _BEFORE_A_CORRECTION,
            items[index + 1 :],
        )
        taken_back = next(after, item)
        then = next(after, None)
        if taken_back.role == "correction" and (then is None or then.norm not in ("also", "and")):
            # "hmm idk maybe spinach? no wait, lettuce": a crop taken back at once
            item.role = "filler"
            item.data["corrected"] = True
            continue
        other: OtherCrop = item.senses_of("other_crop")[0].value
        if other.variety_of is not None:
            names = [v.name for v in hierarchy.crop(other.variety_of).varieties]
            article = "an" if other.variety_of[0] in "AEIOU" else "a"
            raise UnknownCropError(
                f"{item.raw!r} is {article} {other.variety_of} variety the asset hierarchy "
                "does not hold",
                requested=item.raw,
                nearest=_by_spelling(item.raw, names),
                stage="resolve",
                hint=f"{other.variety_of} varieties: " + ", ".join(names),
            )
        nearest = nearest_crops(other.name, other.like)
        raise UnknownCropError(
            f"{item.raw!r} is not a crop of the asset hierarchy ({other.name} is unknown)",
            requested=item.raw,
            nearest=nearest,
            stage="resolve",
        )


def reject_unknown_names(
    items: Sequence[Item],
    mentions: Sequence[Mention],
    hierarchy: Hierarchy,
    nearest_crops: NearestCrops,
) -> None:
    """Unknown words where a crop or variety name belongs are unknown crops, not fillers."""
    position = {id(item): index for index, item in enumerate(items)}
    for mention in mentions:
        for sub in (mention, *mention.refinements):
            plots = [h for h in sub.heads if h.role == "plot"]
            named = sub.has_crop or sub.category is not None
            if plots and not named:
                word = _word_before(items, position.get(id(plots[0])))
                word = word or _word_after_of(items, position.get(id(plots[0])))
                # ("the little home orchard": an everyday word before a plot that
                # says its crops names no crop; real crops the hierarchy lacks were
                # refused by name before)
                everyday = word is not None and _everyday(word.norm)
                # ("Compact plot pair ...: strawberries ..., a lettuce block": nor
                # before plots whose crops are named after them)
                if word is not None and not (
                    everyday and (plots[0].data["value"].get("options") or sub.refinements)
                ):
                    _unknown_crop(word.raw, nearest_crops)
            crops = [h for h in sub.heads if h.role == "head" and h.senses_of("crop")]
            if crops and not any(h.senses_of("variety") for h in sub.heads):
                word = _word_before(items, position.get(id(crops[0])))
                if word is not None and word.tokens[0].capitalised and position[id(word)] > 0:
                    crop = str(crops[0].senses_of("crop")[0].value)
                    varieties = [v.name for v in hierarchy.crop(crop).varieties]
                    raise UnknownCropError(
                        f"{word.raw!r} is not one of the {crop} varieties of the hierarchy",
                        requested=f"{word.raw} {crops[0].raw}",
                        nearest=_by_spelling(word.raw, varieties),
                        stage="resolve",
                        hint=f"{crop} varieties: " + ", ".join(varieties),
                    )


def _everyday(word: str) -> bool:
    """An everyday word, or one made of an everyday word by "-ed" ("ridged plots",
    "terraced", "mulched": how a plot is made, never the name of a crop)."""
    words = everyday_words()
    return word in words or (
        word.endswith("ed") and len(word) > 5 and (word[:-1] in words or word[:-2] in words)
    )


def _unknown_crop(word: str, nearest_crops: NearestCrops) -> None:
    nearest = nearest_crops(word, ())
    raise UnknownCropError(
        f"{word!r} is not a crop of the asset hierarchy",
        requested=word,
        nearest=nearest,
        stage="resolve",
    )


#: Words after a crop's name that make it a likeness ("plum-shaped", "olive-green").
_LIKENESSES = frozenset(
    {"shaped", "sized", "size", "like", "coloured", "colored", "green", "shape", "skinned"}
    # ("scab all over, olive spots on the leaves": the colour of the marks)
    | {"spots", "spot", "spotted", "marks", "blotches", "lesions", "streaks", "flecks"}
)


def _word_before(items: Sequence[Item], index: int | None) -> Item | None:
    if index is None or index == 0:
        return None
    word = items[index - 1]
    # "Weed/crop": a mark is not a name
    return word if word.role == "unknown" and any(c.isalpha() for c in word.norm) else None


def _word_after_of(items: Sequence[Item], index: int | None) -> Item | None:
    if index is None or index + 2 >= len(items):
        return None
    if items[index + 1].role == "of" and items[index + 2].role == "unknown":
        return items[index + 2]
    return None


def _by_spelling(word: str, names: Sequence[str], limit: int = 3) -> tuple[str, ...]:
    from rapidfuzz import fuzz, process

    matches = process.extract(word, list(names), scorer=fuzz.WRatio, limit=limit)
    return tuple(str(m[0]) for m in matches)


#: Words a prompt says it grows none of ("No crop at all", "nothing planted").
_NO_CROP = frozenset({"crop", "crops", "plants", "planting", "plantings"})


def reject_no_crop(items: Sequence[Item], mentions: Sequence[Mention]) -> None:
    """ "Drone calibration field: bare soil, ... No crop at all.": a prompt that names no
    crop or kind of crop and says it wants none is refused, not given a crop at random."""
    if any(m.has_crop or m.category is not None for m in mentions):
        return
    for before, item in itertools.pairwise(items):
        if before.role == "negation" and item.norm in _NO_CROP:
            raise PromptError(
                f"the prompt asks for {before.raw} {item.raw}: there is no field to build",
                stage="resolve",
                hint=f"agrirecipe builds planted fields; name a crop, e.g. {EXAMPLES}",
            )

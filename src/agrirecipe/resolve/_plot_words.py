"""Plot words that ask for no field (pass 7 of ``_words``'s reading passes).

"to compare planting systems" (inside a phrase of unknown words), "in the near field"
(which plot, no placement), "golden and ready to strip" (a verb), "sheep in the paddock"
(pasture), "brown corky scab patches" (damage), "a patch in the middle where the leaves
have gone brown" (a part of a field), "the same" said right after a crop ("Walla
Walla the same": planted as the field before), and "each a block of 8 rows" after fields
counted (what each of them is), "a seagull on every other bed" (the beds of a field named
before), and "allotment-style" (a plot word that says what
something is like).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, reader_words

__all__ = ["plot_words_of_other_things"]

#: Words before "to" that make the plot word after it a verb ("ready to strip").
_BEFORE_A_VERB = frozenset({"ready", "about", "due", "time", "going", "set", "starting", "want"})


def plot_words_of_other_things(items: Sequence[Item]) -> None:
    """Run this module's passes over a prompt's items, in order."""
    _inside_unknown_phrases(items)
    _near_and_far(items)
    _likenesses(items)
    _verbs(items)
    _the_same(items)
    _pastures(items)
    _damage_and_parts(items)
    _each_a_plot(items)
    _every_other(items)


def _inside_unknown_phrases(items: Sequence[Item]) -> None:
    """'to compare planting systems': a plot word between two words the reader does not
    know is part of their phrase, not a field."""
    for before, item, after in zip(items, items[1:], items[2:], strict=False):
        if item.role == "plot" and before.role == after.role == "unknown":
            item.role = "filler"


def _near_and_far(items: Sequence[Item]) -> None:
    """'Bibb lettuce in the near field and ... cabbage beyond it': "near" or "far" between
    "the" and a plot word says which plot, no placement."""
    for the, item, plot in zip(items, items[1:], items[2:], strict=False):
        if the.norm == "the" and item.norm in ("near", "far") and plot.role == "plot":
            item.role = "filler"


#: Words after a plot word that make it say what something is like ("allotment-style").
_LIKE = frozenset({"style", "styled", "type", "like"})


def _likenesses(items: Sequence[Item]) -> None:
    """'The allotment-style corner of the farm: six little plots': a plot word before
    "style" or "type" describes what follows, it asks for no field."""
    for index, (item, after) in enumerate(itertools.pairwise(items)):
        following = items[index + 2] if index + 2 < len(items) else None
        # (not "the allotment-style plots", which are the plots themselves)
        plots = following is not None and following.role == "plot"
        # (not "a few wheat fields like whatever number u want", "fields like 3": the
        # "like" of casual talk before a count or a choice)
        casual = (
            after.norm == "like"
            and following is not None
            and (
                following.role in ("number", "quantity")
                or following.norm in reader_words("free_choice")
            )
        )
        if item.role == "plot" and after.norm in _LIKE and not plots and not casual:
            item.role = "filler"


def _verbs(items: Sequence[Item]) -> None:
    """'golden and ready to strip': a plot word after "ready to" is a verb; 'workers
    walking the strip between a wheat field and a potato field': a plot walked (or driven)
    along is a way through the fields."""
    for first, to, item in zip(items, items[1:], items[2:], strict=False):
        if (item.role == "plot" and to.norm == "to" and first.norm in _BEFORE_A_VERB) or (
            item.role == "plot" and to.norm == "the" and first.norm in _ALONG_A_WAY
        ):
            item.role = "filler"
    # "the grader and a row of big boxes stand on the headland": "stand" before where
    # something stands is a verb, not a stand of trees
    for item, after in itertools.pairwise(items):
        if item.role == "plot" and item.norm in _STAND and after.norm in _WHERE_IT_STANDS:
            item.role = "filler"


#: The plot words that are also verbs of standing, and the words of where after them.
_STAND = frozenset({"stand", "stands"})
_WHERE_IT_STANDS = frozenset(
    {"on", "in", "at", "by", "beside", "near", "along", "next", "against", "under", "around"}
)


#: Verbs of going along a way ("walking the strip between ...").
_ALONG_A_WAY = frozenset({"walking", "walk", "walks", "walked", "driving", "drive", "drives"})


def _the_same(items: Sequence[Item]) -> None:
    """'Stuttgarter at 30 cm rows ..., Walla Walla the same, and ...': a crop named, then
    "the same" alone, is planted as the field before it."""
    for index in range(1, len(items) - 1):
        said, rest = items[index : index + 2], items[index + 2 : index + 3]
        if (
            items[index - 1].role == "head"
            and [i.norm for i in said] == ["the", "same"]
            and all(i.role == "filler" for i in said)
            and (not rest or rest[0].role in ("separator", "conjunction"))
        ):
            said[1].role = "same_spacing"


#: The words between livestock and the plot it is on ("sheep in the paddock", "cows
#: graze the paddock").
_GRAZING = frozenset(
    {"in", "on", "graze", "grazes", "grazing", "grazed", "the", "a", "their", "that", "this"}
    # ("cows in the back paddock": which paddock)
    | {"back", "front", "top", "bottom", "near", "far", "home", "old", "big", "little", "lower"}
    | {"upper", "other", "next"}
)


def _pastures(items: Sequence[Item]) -> None:
    """'sheep in the paddock', 'a field of cows', 'the sheep paddock': pasture, no field of
    any crop (not "sheep grazing in the orchard": the orchard still grows trees)."""
    livestock = reader_words("livestock")
    for index, item in enumerate(items):
        spec = item.data.get("value") if item.role == "plot" else None
        if not isinstance(spec, dict) or spec.get("options") or spec.get("category"):
            continue
        words_before = [i.norm for i in items[max(0, index - 4) : index]]
        words_after = [i.norm for i in items[index + 1 : index + 3]]
        # ("sheep in the paddock", "Cows graze the paddock by the road")
        kept = next((k for k, w in enumerate(words_before) if w in livestock), None)
        if (
            (words_before and words_before[-1] in livestock)
            or (
                kept is not None
                and len(words_before) - kept >= 3
                and all(w in _GRAZING for w in words_before[kept + 1 :])
                and words_before[kept + 1] != "the"
            )
            or (
                len(words_after) == 2
                and words_after[0] in ("of", "with", "full of")
                and words_after[1] in livestock
            )
        ):
            item.role = "filler"
            item.data["scenery"] = "living"


def _damage_and_parts(items: Sequence[Item]) -> None:
    """'brown corky scab patches': patches right after a disease or a look are the damage,
    not plots; 'a patch in the middle where the leaves have gone brown': a part of a field
    named before; 'Patches of the wheat have yellow rust': parts of the field named."""
    named = False
    for index, item in enumerate(items):
        earlier = items[index - 1] if index else None
        later = items[index + 1] if index + 1 < len(items) else None
        if (
            item.role == "plot"
            and item.norm in ("patches", "patch")
            and earlier is not None
            and (earlier.role == "health" or "cue" in earlier.data)
        ):
            item.role = "filler"
        # "whole patches collapsing", "lapwings on the bare patches": once a field is
        # named, patches said with a look are parts of it
        elif (
            named
            and item.role == "plot"
            and item.norm == "patches"
            and (
                (earlier is not None and earlier.norm in reader_words("patch_looks"))
                or (
                    later is not None
                    and (
                        later.role in ("health", "cue") or later.norm in reader_words("patch_looks")
                    )
                )
            )
        ):
            item.role = "filler"
            if earlier is not None and earlier.role == "unknown":
                earlier.role = "filler"
        elif (
            named
            and item.role == "plot"
            and item.norm in ("patch", "patches")
            and _where(items[index + 1 : index + 6])
        ):
            # "a carrot field ..., but there's a patch in the middle where the leaves have
            # gone brown": a part of the field, said by what shows there
            item.role = "filler"
            if earlier is not None and earlier.role == "number":
                earlier.role = "filler"
        elif (
            item.role == "plot"
            and item.norm in ("patch", "patches", "parts", "areas", "bits")
            and later is not None
            and later.norm == "of"
            and index + 2 < len(items)
            and items[index + 2].norm in ("the", "our", "my", "this", "that")
        ):
            # "Patches of the wheat have yellow rust": parts of a field, not fields
            item.role = "filler"
        named = named or item.role in ("head", "plot", "category")


def _where(after: Sequence[Item]) -> bool:
    """Whether "where" follows within a few words that name no field."""
    for item in after:
        if item.norm == "where":
            return True
        if item.role in ("head", "plot", "category", "separator"):
            return False
    return False


def _each_a_plot(items: Sequence[Item]) -> None:
    """'three different kinds of fruit tree ..., each a block of 8 rows with 4 m between
    the rows': "each a <plot>" after a count says what each field counted is (its rows
    for every one), not one more field; unless a crop follows it in that clause."""
    counted = False
    for index, item in enumerate(items):
        if item.role == "number" and float(item.data.get("value", 1)) >= 2:
            counted = True
        if item.role == "separator" and item.norm in (".", "!", "?", ";"):
            counted = False
        if (
            not counted
            or item.role != "all"
            or item.norm != "each"
            or index + 2 >= len(items)
            or items[index + 1].norm not in ("a", "an")
            or items[index + 2].role != "plot"
        ):
            continue
        rest = []
        for later in items[index + 3 :]:
            if later.role in ("separator", "conjunction", "relation", "between", "trailer"):
                break
            rest.append(later)
        if any(i.role in ("head", "weak_variety", "category", "plot") for i in rest):
            continue
        items[index + 1].role = "filler"
        items[index + 2].role = "filler"


def _every_other(items: Sequence[Item]) -> None:
    """'a seagull on every other bed', 'a trap in each row': after a field is named, one
    plot word said with "every (other)" or "each" after a place word is the named field's
    beds or rows, not a field."""
    named = False
    for index, item in enumerate(items):
        if item.role in ("head", "weak_variety"):
            named = True
        if not named or item.role != "plot" or index < 2:
            continue
        spec = item.data.get("value")
        if not isinstance(spec, dict) or spec.get("plural"):
            continue
        before = [i.norm for i in items[max(0, index - 3) : index]]
        if before[-2:] == ["every", "other"] or (
            before[-1:] in (["every"], ["each"])
            and len(before) >= 2
            and before[-2] in ("on", "in", "along", "between", "down", "at")
        ):
            item.role = "filler"

"""Contradictions inside one noun phrase: a plot that cannot hold the crop named in it
("a vineyard of cabbages", "a carrot orchard"), a variety right before another crop's
name ("Nantes apples"), and a crop's alias that only names its plants ("tomato vines").
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from agrirecipe._errors import PromptError, UnknownCropError
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._mentions import (
    PRE_HEAD,
    Mention,
    combine_interpretations,
    head_interpretations,
    named_crops,
)

__all__ = ["check_adjacent_variety", "names_plants_of", "plot_conflict", "plot_excludes"]


def check_adjacent_variety(mention: Mention, item: Item, pending: Sequence[Item]) -> None:
    """'Nantes apples': a variety right before another crop's name is an unknown variety."""
    if pending or not mention.heads or item.role != "head":
        return
    last = mention.heads[-1]
    crops = [str(s.value) for s in item.senses_of("crop")]
    varieties = [s for s in last.senses_of("variety") if not s.weak]
    if crops and varieties and not last.senses_of("crop"):
        owner = varieties[0].crop or ""
        raise UnknownCropError(
            f"{last.raw!r} is a variety of {owner}, not of {crops[0]}: "
            f"no {crops[0]} variety is called {last.raw!r}",
            requested=f"{last.raw} {item.raw}",
            stage="resolve",
            hint=f"did you mean {last.raw} {owner.lower()}s, or another {crops[0]} variety?",
        )


# "of"-words that put the crop inside the plot ("a vineyard of cabbages", "an orchard
# planted with carrots"); "with" may as well mean a neighbour ("an orchard with a
# carrot field"), "under" a cover ("an orchard under snow").
_NOT_CONTAINMENT = frozenset({"with", "under"})


def plot_conflict(mention: Mention, item: Item, pending: Sequence[Item]) -> PromptError | None:
    """'a vineyard of cabbages', 'a carrot orchard': a plot noun that cannot hold the crop.

    Only a plot noun for a kind of planting (orchard, grove, vineyard, cornfield)
    restricts its crops; a noun for the plants themselves ("tomato vines", "banana
    trees") just names the crop's plants, and crops a noun tolerates by usage
    ("a banana orchard") pass.
    """
    if item.role == "plot":
        plot, crops = item.data["value"], named_crops(mention.interpretations)
        joined = not pending  # "a carrot orchard"
    elif item.role == "head" and mention.plot is not None and not mention.has_crop:
        plot, crops = mention.plot, named_crops(head_interpretations(item))
        # "a vineyard of (young) cabbages"
        joined = (
            bool(pending)
            and pending[0].role == "of"
            and pending[0].norm not in _NOT_CONTAINMENT
            and all(p.role in PRE_HEAD for p in pending[1:])
        )
    else:
        return None
    allowed = (*plot["options"], *plot["tolerates"])
    if not joined or plot["individual"] or not plot["options"] or not crops:
        return None
    if any(crop in allowed for crop in crops):
        return None
    word = plot["noun"] or "plot"
    if plot["noun"] == "field":  # "cornfield", "wheatfield"
        word = next(h for h in (item, *mention.heads) if h.role == "plot").norm.rstrip("s")
    article = "an" if word[0] in "aeiou" else "a"
    crop = crops[0]
    return PromptError(
        f"{_phrase(mention, item, pending)!r} is a contradiction: {article} {word} holds "
        f"{_listing(plot['options'])}, and {crop} is not grown in one",
        stage="resolve",
        hint=f"ask for a {crop.lower()} field, or {article} {word} next to a {crop.lower()} field",
    )


def names_plants_of(mention: Mention, item: Item) -> bool:
    """'tomato vines': a crop alias that is also a word for plants, right after another crop."""
    if item.role != "head" or not mention.has_crop:
        return False
    plots = [s.value for s in item.senses_of("plot") if s.value["individual"]]
    if not plots:
        return False
    return combine_interpretations(mention.interpretations, head_interpretations(item)) is None


def plot_excludes(plot: dict[str, Any], mention: Mention) -> bool:
    allowed = (*plot["options"], *plot["tolerates"])
    crops = named_crops(mention.interpretations)
    return bool(plot["options"]) and not any(crop in allowed for crop in crops)


def _listing(names: Sequence[str]) -> str:
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]


def _phrase(mention: Mention, item: Item, pending: Sequence[Item]) -> str:
    words = sorted([*mention.heads, *pending, item], key=lambda i: i.start)
    return " ".join(w.raw for w in words)

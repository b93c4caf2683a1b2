"""Purposes are no fields and no looks: a disease or crop named as what a dataset, model
or robot is for ("a late-blight detection dataset", "apple-counting scene").

A reading pass the parser runs once roles are assigned, before sizes are read; the
purpose words are scenery data (the ``purposes`` and ``robots`` groups) and the words
that open a purpose are ``reader_words("purpose_openers")``.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, reader_words

__all__ = ["purpose_diseases"]

#: Scenery groups whose words name what a request is for ("a blight detection dataset").
_PURPOSES = frozenset({"robots", "purposes"})


def _purpose(item: Item) -> bool:
    """A word naming what a request is for ("dataset", "test", "survey")."""
    group = item.data.get("scenery") or next(
        (sense.value for sense in item.senses_of("scenery")), None
    )
    return item.role in ("filler", "non_agricultural") and group in _PURPOSES


def _options(item: Item) -> tuple[str, ...]:
    """The crops a plot word says ("root crop": carrots, potatoes, onions)."""
    value = item.data.get("value")
    return tuple(value.get("options", ())) if isinstance(value, dict) else ()


def purpose_diseases(items: Sequence[Item], text: str) -> None:
    """'Late-blight detection dataset', 'a blight-spotting drone': a disease named as what
    a dataset or robot is for says nothing about the plants' health (scenery words).
    'Apple-counting scene', 'fruit-detection plots': a crop joined by a hyphen to what a
    robot does names the task, not a field."""
    for index, item in enumerate(items):
        # "for a banana canopy-segmentation dataset", "for citrus canopy scans", "training a
        # grape counting model": the crop
        # (or kind of crop) a purpose is about
        # ("Need it for a root-crop yield camera": a plot that says its crops, too)
        says_crops = item.role == "plot" and bool(_options(item))
        if (item.role not in ("head", "category") and not says_crops) or index == 0:
            continue
        opener = index - 1
        if items[opener].norm in ("a", "an", "the", "our", "my") and opener:
            opener -= 1
        # ("we're training a grape-bunch counting CNN on it": what a model is trained for)
        if items[opener].norm not in reader_words("purpose_openers"):
            continue
        for following in items[index + 1 : index + 5]:
            if _purpose(following):
                item.role = "filler"
                item.data["scenery"] = "purposes"
                break
            if following.role not in ("unknown", "filler"):
                break
    for index, item in enumerate(items):
        if item.role == "health":
            # "a late-blight spectral dataset": a disease, then words for the kind of data
            ahead = items[index + 1 : index + 4]
            end = next((n for n, i in enumerate(ahead) if i.role not in ("unknown",)), None)
            if (
                end is not None
                and _purpose(ahead[end])
                and len(text[item.end : ahead[0].start]) <= 1
            ):
                item.role = "filler"
                item.data["scenery"] = "purposes"
            continue
        after = items[index + 1 : index + 2]
        # "Apple-counting", "Vineyard-robot"; "a tropical-orchard SLAM test": a plot joined
        # by a hyphen to the word before it, then what the test is for
        joined_before = index > 0 and text[items[index - 1].end : item.start] == "-"
        if (
            after
            and _purpose(after[0])
            and item.role in ("head", "plot")
            and (text[item.end : after[0].start] == "-" or joined_before)
        ):
            item.role = "filler"
            item.data["scenery"] = "purposes"

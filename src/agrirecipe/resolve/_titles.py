"""Titles: a crop named alone before the field it heads (issue 8).

"Bananas from my trip to Tenerife! A plantation of banana plants behind an old stone
wall", "salad dataset: two lettuce plots, ...", "It's a citrus farm really: one big grove
on the hillside", "Mostly grain on this farm: three cereal fields ...": a crop (or a
farm of it, or what most of the farm grows) said before the one field or list of it that
follows is that field's title, not a field of its own. :func:`drop_titles` gives the
title's words to that field and drops it.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import named_varieties, names_a_variety, strong_crops
from agrirecipe.resolve._summaries import lend_and_drop
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = ["drop_titles"]


#: Words that say what most of a farm grows ("Mostly grain on this farm: ...").
_MOSTLY = frozenset({"mostly", "mainly", "largely", "predominantly", "primarily", "chiefly"})


def _mostly(
    clauses: Sequence[Clause],
    title: Mention,
    fields: Sequence[Mention],
    crop_categories: dict[str, str],
) -> bool:
    """Whether ``title`` says what most fields grow: "mostly" and a crop or category, no
    count or plot of its own, ended by a colon or a full stop, with a later field of it."""
    words = sorted(title.items, key=lambda i: i.start)
    if (
        not words
        or words[0].norm not in _MOSTLY
        or title.count is not None
        or title.plot is not None
        or title.refinements
    ):
        return False
    following = clauses[title.clause + 1] if title.clause + 1 < len(clauses) else None
    if following is None or following.link is None or following.link.norm not in (":", "."):
        return False
    crops = strong_crops(title) or {
        crop for crop, of in crop_categories.items() if of == title.category
    }
    return any(
        strong_crops(m) & crops or (m.category is not None and m.category == title.category)
        for m in fields
    )


def drop_titles(
    clauses: Sequence[Clause], mentions: list[Mention], crop_categories: dict[str, str]
) -> list[Mention]:
    """'Bananas from my trip to Tenerife! A plantation of banana plants behind an old
    stone wall, ...': a crop named alone, with no plot or count, in a first sentence of
    its own (or before a colon: "salad dataset: two lettuce plots, ..."), then one field of
    that crop in the next (or one plot listing fields of only that crop), is that field's
    title. Its words go to the field. So is a plot of a category alone ("Veg block for the
    drone. Three plots in a line: cabbages, ..., then onions, ..., then carrots ...")
    before one plot listing fields of only its crops. Return the fields left."""
    if len(mentions) < 2:
        return mentions
    title, field = mentions[0], mentions[1]
    crops = strong_crops(title)
    if _mostly(clauses, title, mentions[1:], crop_categories):
        # "Mostly grain on this farm: three cereal fields ..., plus one small strawberry
        # patch": what most of the farm grows, said before its fields
        lend_and_drop(clauses, title, mentions[1:2])
        return mentions[1:]
    # ("Just a spud farm, honestly. One big field of spuds, ...": the farm named by its
    # crop is a title too)
    farm = any(i.norm == "farm" for i in title.items)
    if _plot_named_before_a_colon(clauses, title, mentions[1:]):
        # "Home paddock: a 100 by 60 m patch of Walla Walla onions": the plot's name
        if not any(i.role == "size" for i in field.items):
            field.items.extend(i for i in title.items if i.role in ("size", "side"))
        lend_and_drop(clauses, title, mentions[1:])
        return mentions[1:]
    if _kind_of_farm(title, mentions[1:], crop_categories):
        # "It's a small fruit farm really, just one block of Conference pears": the
        # farm's kind, said of the whole, not one more field
        lend_and_drop(clauses, title, mentions[1:])
        return mentions[1:]
    category = title.category if not title.has_crop and title.plot is not None else None
    if category is not None:
        crops = {crop for crop, of in crop_categories.items() if of == category}
        if not _lists_only(field, crops):
            return mentions
    # ("grapes maybe? like a vineyard in autumn and a lil strawberry patch": a plot that
    # can hold the title's crop, with no other field after it that could)
    alone = farm or not any(_holds(m, crops) for m in mentions[2:])
    if (
        not crops
        or (title.plot is not None and not farm and category is None)
        or (title.count is not None and not (farm and title.count == 1))
        or title.refinements
        # ("popcorn?? can u even do that. a popcorn field": the same variety named again)
        or (names_a_variety(title) and not _same_variety(title, field))
        or not (
            strong_crops(field) == crops
            or _lists_only(field, crops)
            or (alone and _holds(field, crops))
        )
        or any(strong_crops(m) & crops for m in mentions[2:])
    ):
        return mentions
    # ("salad dataset: two lettuce plots, Cos ... and Lollo ...": or a heading that a
    # colon ends right after it)
    ends = next(
        (
            c
            for c in clauses[title.clause + 1 :]
            if c.link is not None
            and (
                c.link.norm in SENTENCE_MARKS
                or (c.link.norm == ":" and c.index == title.clause + 1)
                # ("A lettuce farm, just one huge field of lettuces": the farm's comma)
                or (farm and c.link.norm in (",", "-", "–", "—") and c.index == title.clause + 1)
            )
        ),
        None,
    )
    if ends is None or field.clause < ends.index:
        return mentions
    if ends.link is not None and ends.link.norm == ":" and field.clause != ends.index:
        return mentions  # ("cabbage: 0.75 m rows, 64 rows. A Red Express plot ...")
    said = {i.role for c in clauses[title.clause : ends.index] for i in c.items}
    looks = {"stage", "health", "season", "month", "cue"}
    # ("Cherry harvest robot trial, late June, fruit ripe. Two blocks: Kordia ..., Regina
    # ...": the look and time of every field listed after it)
    listed = _lists_only(field, crops) and not said & {"geometry", "size", "relation"}
    if said & {"geometry", "size", "relation", *looks} and not listed:
        return mentions  # ("cabbage: 0.75 m rows, ... A Red Express plot west of it")
    after_end = [c for c in clauses[ends.index :] if c.mentions]
    if not after_end or after_end[0].mentions[0] is not field:
        return mentions
    field.items.extend(i for i in title.items if i not in title.heads)
    if (farm or len(mentions) == 2) and _holds(field, crops):
        # "It's a citrus farm really: one big grove on the hillside", "grapse. thats it.
        # just a vinyard in fall": the title's crop
        names = [h for h in title.heads if h.role == "head"]
        field.heads.extend(names)
        field.items.extend(names)
        field.interpretations = title.interpretations
    for clause in clauses:
        clause.mentions = [field if m is title else m for m in clause.mentions]
    return mentions[1:]


def _plot_named_before_a_colon(
    clauses: Sequence[Clause], title: Mention, fields: Sequence[Mention]
) -> bool:
    """Whether ``title`` is a plot of no crop said alone before a colon that opens the
    prompt's one other field ("Home paddock: a 100 by 60 m patch of onions")."""
    after = clauses[title.clause + 1] if title.clause + 1 < len(clauses) else None
    return (
        len(fields) == 1
        and title.plot is not None
        and not title.has_crop
        and title.category is None
        and (title.count or 1) == 1
        and not title.refinements
        and after is not None
        and after.link is not None
        and after.link.norm == ":"
        and fields[0].clause == after.index
        and fields[0].has_crop
    )


def _kind_of_farm(
    title: Mention, fields: Sequence[Mention], crop_categories: dict[str, str]
) -> bool:
    """Whether ``title`` is a farm named by a category right before the word "farm" ("a
    fruit farm", "a small vegetable farm"), with no count or plot of its own, and every
    field named after it grows a crop of that category."""
    words = sorted(title.items, key=lambda i: i.start)
    named_so = any(
        before in title.heads and after.role == "container" and after.norm == "farm"
        for before, after in itertools.pairwise(words)
    )
    if (
        not named_so
        or title.has_crop
        or title.category is None
        or (title.count or 1) != 1
        or title.plot is not None
        or title.refinements
        or not fields
    ):
        return False
    crops = {crop for crop, of in crop_categories.items() if of == title.category}
    return all(strong_crops(m) and strong_crops(m) <= crops for m in fields)


def _same_variety(title: Mention, field: Mention) -> bool:
    """Whether ``field`` names the variety ``title`` names, and no other."""
    named = named_varieties(title)
    return bool(named) and named == named_varieties(field)


def _holds(field: Mention, crops: set[str]) -> bool:
    """Whether ``field`` is one plot of no crop that can hold ``crops`` ("one big grove")."""
    options = set(field.plot["options"]) if field.plot is not None else set()
    return (
        not field.has_crop
        and field.category is None
        and field.plot is not None
        and (field.count or 1) == 1
        and not field.refinements
        and (not options or crops <= options)
    )


def _lists_only(heading: Mention, crops: set[str]) -> bool:
    """Whether ``heading`` is a plot of no crop listing fields of only ``crops`` ("Potato
    variety trial for the robot. Four plots ...: Bintje, Fontane, Agria, ...")."""
    return (
        not heading.has_crop
        and len(heading.refinements) >= 2
        and all(strong_crops(r) and strong_crops(r) <= crops for r in heading.refinements)
    )

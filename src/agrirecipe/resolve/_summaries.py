"""Mentions that sum up fields named elsewhere, not more fields (issue 8).

"Two blocks for drone flights. Block A: ..., Block B: ...", "grapes ripening in both
blocks. Chardonnay: ... Cabernet: ...", "... Navel and Moro, adjacent blocks of 150 trees
each", "a cabbage field on either side of it (so 2 cabbage fields)", "three vegetable
strips ..., and three different crops please": a counted plot, a crop said of "both"
plots, a closing plural plot or a count said again counts or describes the fields named
before or after it. Each pass drops such a mention, lending its words to those fields.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._links import link_norm
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    names_a_group,
    names_a_variety,
    said_of_all_plots,
    strong_crops,
)
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = [
    "SUMMARY_ROLES",
    "drop_announced_plots",
    "drop_counted_summaries",
    "drop_forward_summaries",
    "drop_restated_counts",
    "drop_single_plot_counts",
    "drop_trailing_summaries",
    "lend_and_drop",
    "spread_counted_totals",
]


def drop_counted_summaries(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Two blocks for drone flights. Block A: Gala apples, ... Block B, south of A:
    Conference pears, ...': a counted plot of no crop, alone in its sentence, followed
    by as many fields of named crops in the sentences after it as it still lacks
    members, says what they are; it is not one more field. Return the fields left."""
    if len(mentions) < 2:
        return mentions
    first, later = mentions[0], mentions[1:]
    members = list({id(r): r for r in first.refinements}.values())
    if (
        first.has_crop
        or first.category is not None
        or first.plot is None
        or (first.count or 1) < 2
        or first.count != len(members) + len(later)
        or not all(_names_its_crops(m) and (m.count or 1) == 1 and not m.refinements for m in later)
        # ("two blocks. Vineyard: ...": a member labelled by a plot that says its crops)
        or not all(strong_crops(m) or (m.plot or {}).get("options") for m in members)
    ):
        return mentions
    ends = next(
        (
            c
            for c in clauses[first.clause + 1 :]
            if c.link is not None and c.link.norm in SENTENCE_MARKS
        ),
        None,
    )
    if ends is None or any(m.clause < ends.index for m in (*members, *later)):
        return mentions
    if not members:
        return later
    for mention in later:
        mention.is_refinement = True
        first.refinements.append(mention)
    return [first]


def _names_its_crops(mention: Mention) -> bool:
    """A crop named, or (in a part of the farm of its own: "and cereals down at the
    bottom") a category or a plot that says its crops."""
    return bool(strong_crops(mention)) or (
        any(i.role == "zone" for i in mention.items) and names_a_group(mention)
    )


#: Attributes a summary said before its fields gives each of them.
SUMMARY_ROLES = frozenset({"stage", "health", "cue", "season", "month"})


def lend_and_drop(clauses: Sequence[Clause], summary: Mention, fields: Sequence[Mention]) -> None:
    """Give ``summary``'s stage, health, cues and season to each of ``fields`` that states
    none of its own, and take ``summary`` out of its clause."""
    lent = [i for i in summary.items if i.role in SUMMARY_ROLES]
    for field in fields:
        own = {i.role for i in field.items}
        field.items.extend(i for i in lent if i.role not in own)
    for clause in clauses:
        clause.mentions = [m for m in clause.mentions if m is not summary]


def drop_forward_summaries(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'grapes ripening in both blocks, rows north-south. Chardonnay: 25 rows ...
    Cabernet: 18 rows ...': a crop said of "both" (or "all the") plots, with no variety,
    before the fields of that crop are named (two for "both"), describes each of them
    and is not one more field. Its stage, health, cues and season go to each field that
    states none of its own. Return the fields left."""
    for position, summary in enumerate(mentions):
        crops = strong_crops(summary)
        if (
            not said_of_all_plots(summary)
            or not crops
            or names_a_variety(summary)
            or summary.count is not None
        ):
            continue
        later = [m for m in mentions[position + 1 :] if strong_crops(m)]
        if len(later) < 2 or not all(strong_crops(m) <= crops for m in later):
            continue
        # (each field once: "east of the Chardonnay" names the Chardonnay again)
        named = {
            frozenset((c, v) for c, v, weak in m.interpretations or () if not weak) for m in later
        }
        if any(i.norm == "both" for i in summary.items) and len(named) != 2:
            continue
        lend_and_drop(clauses, summary, later)
        return [m for m in mentions if m is not summary]
    return mentions


def drop_announced_plots(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Orchard plus vineyard for the drone. 120 cherry trees, ...; next to them 20 rows of
    grapes at 2.5 m.': a plot whose noun names its crops (a vineyard) but no crop, in an
    opening sentence that names no crop, is the one field after that sentence of those
    crops; it is not one more field. The field takes the plot noun. Return the fields
    left."""
    if not mentions:
        return mentions
    _, end = _sentence_of(clauses, mentions[0].clause)
    heading = [m for m in mentions if m.clause < end]
    # (a heading names plots and what they are for: not "Vineyard for the pruning robot -
    # rows 2.4 m apart ...", a field said with its measures)
    if any(i.role in ("head", "geometry", "size") for c in clauses[:end] for i in c.items):
        return mentions
    for plot in heading:
        if (
            plot.plot is None
            or plot.has_crop
            or plot.category is not None
            or plot.plot["plural"]
            or not plot.plot["options"]
            or plot.count not in (None, 1)
            or plot.refinements
        ):
            continue
        options = set(plot.plot["options"])
        fitting = [
            m
            for m in mentions
            if m.clause >= end
            and any(strong_crops(r) and strong_crops(r) <= options for r in (*m.refinements, m))
        ]
        if len(fitting) != 1 or (fitting[0].count or 1) != 1 or fitting[0].refinements:
            continue
        field = fitting[0]
        if field.plot is None:
            field.plot = plot.plot
        lend_and_drop(clauses, plot, [field])
        return drop_announced_plots(clauses, [m for m in mentions if m is not plot])
    return mentions


def drop_single_plot_counts(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Only one field on the smallholding, a cabbage patch ...', 'veggies. any. just 1
    field': one plot of no crop, counted "one", in a prompt whose other words ask for
    exactly one field, says how many fields there are; it is not one more. Return the
    fields left."""
    for counted in mentions:
        if (
            counted.count != 1
            or counted.has_crop
            or counted.category is not None
            or counted.plot is None
            or counted.refinements
            # (not "a vineyard on one slope": a plot whose noun names its crop)
            or counted.plot["options"]
            or not _counted_one(counted)
            or any(i.role in ("size", "geometry") for i in counted.items)
        ):
            continue
        others = [m for m in mentions if m is not counted]
        if len(others) != 1 or (others[0].count or 1) != 1 or others[0].refinements:
            continue
        if not (others[0].has_crop or others[0].category is not None):
            continue
        lend_and_drop(clauses, counted, others)
        return others
    return mentions


#: Words that make a count the total of the fields named ("4 fields in total").
_TOTAL = frozenset({"total", "altogether", "overall", "all told", "in all"})


def spread_counted_totals(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'potatoes and cabbages, 4 fields in total', 'idk 3 or 4 fields total': a counted
    plural plot of no crop said to be the total, after uncounted fields of named crops,
    is how many fields they make together: the extra fields go to the named crops in
    turn (2 of potatoes, 2 of cabbages), not to crops chosen at random. Return the fields
    left."""
    for total in mentions:
        if (
            total.has_crop
            or total.category is not None
            or total.plot is None
            or total.count is None
            or total.refinements
            or not (
                any(
                    i.norm in _TOTAL or any(t.norm in _TOTAL for t in i.tokens) for i in total.items
                )
                # ("4 fields in all": "in" and "all" read apart)
                or "in all" in " ".join(i.norm for i in total.items)
            )
        ):
            continue
        named = [m for m in mentions if m is not total and m.clause < total.clause]
        if (heading := _heading_of_the_rest(clauses, named, total)) is not None:
            # "some veggies: a field of carrots & whatever else u want, at least 3 fields
            # total": the fields the list leaves are the heading's kind
            heading.count = total.count - (len(named) - 1)
            heading.implied_count = False
            lend_and_drop(clauses, total, named)
            return named
        if (
            len(named) < 2
            # (a plural's count only implied, "some fruit trees and some veggies, 4 or 5
            # fields total", is no count said)
            or any((m.count is not None and not m.implied_count) or m.refinements for m in named)
            # (or plots of a kind: "some fruit trees")
            or not all(m.has_crop or names_a_group(m) for m in named)
            or total.count < len(named)
            or len(named) != len(mentions) - 1
        ):
            continue
        for member in named:
            member.count, member.implied_count = None, False
        for extra in range(total.count - len(named)):
            member = named[extra % len(named)]
            member.count = (member.count or 1) + 1
        lend_and_drop(clauses, total, named)
        return named
    return mentions


def _heading_of_the_rest(
    clauses: Sequence[Clause], named: Sequence[Mention], total: Mention
) -> Mention | None:
    """The group of crops ("some veggies") that heads, before a colon, single fields of
    named crops and no more, when the total after them counts more fields than they
    name: it stands for the fields the list leaves; None otherwise."""
    if len(named) < 2 or total.count is None or total.count <= len(named):
        return None
    heading, listed = named[0], named[1:]
    if (
        heading.has_crop
        or not names_a_group(heading)
        or heading.refinements
        or (heading.count is not None and not heading.implied_count)
        or heading.clause + 1 >= len(clauses)
        or link_norm(clauses[heading.clause + 1]) != ":"
        or not all(m.has_crop and (m.count or 1) == 1 and not m.refinements for m in listed)
    ):
        return None
    return heading


def _counted_one(mention: Mention) -> bool:
    """Whether the mention's count is said "one", "1" or "single" before its plot word
    ("one big orchard", "just 1 field"; not "a field")."""
    head = min((h.start for h in mention.heads), default=0)
    return any(i.norm in ("one", "1", "single") and i.start < head for i in mention.items)


def drop_restated_counts(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'a cabbage field on either side of it (so 2 cabbage fields)', 'a wheat field, so 2
    wheat fields': a count said again with "so" after the crop it counts is that crop's
    number of fields, not more fields. The crop's mention takes the count unless a side
    word before already makes it two. Return the fields left."""
    kept: list[Mention] = []
    for mention in mentions:
        if (restated := _restated_as_different(kept, mention)) is not None:
            # "three vegetable strips ..., and three different crops please": the same
            # fields, said to be of different crops
            restated.distinct = restated.distinct_crops = True
            for clause in clauses:
                clause.mentions = [m for m in clause.mentions if m is not mention]
            continue
        first = min(mention.items, key=lambda i: i.start, default=None)
        crops = strong_crops(mention)
        earlier = [m for m in kept if crops and strong_crops(m) == crops]
        if (
            first is None
            or first.norm != "so"
            or (mention.count or 1) < 2
            or mention.refinements
            or len(earlier) != 1
        ):
            kept.append(mention)
            continue
        counted = earlier[0]
        after = clauses[counted.clause + 1] if counted.clause + 1 < len(clauses) else None
        sided = (
            after is not None
            and after.link is not None
            and after.link.data.get("value") in ("each_side", "flanks")
        )
        if not sided and (counted.count or 1) == 1 and not counted.refinements:
            counted.count = mention.count
        for clause in clauses:
            clause.mentions = [m for m in clause.mentions if m is not mention]
    return kept


def _restated_as_different(kept: Sequence[Mention], mention: Mention) -> Mention | None:
    """The one earlier counted mention of no crop that ``mention`` ("three different
    crops": no crop, and no plot but a word for the plants) counts again, or None."""
    if (
        not mention.distinct
        or mention.has_crop
        or (mention.plot is not None and not mention.plot["individual"])
        or (mention.count or 1) < 2
        or mention.refinements
    ):
        return None
    earlier = [
        m
        for m in kept
        if m.count == mention.count
        and not m.has_crop
        and not m.refinements
        and (mention.category is None or m.category in (None, mention.category))
    ]
    return earlier[0] if len(earlier) == 1 and len(kept) == 1 else None


def drop_trailing_summaries(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Navel oranges at 7 x 4 m and Moro blood oranges at 6 x 3 m, adjacent blocks of 150
    trees each': a plural plot of no crop, closing the sentence of two or more fields of
    named crops (uncounted, or counted as many), is the plots they are in: not more
    fields. Its stage, health, cues, season, size and measures go to each field that
    states none of its own. Return the fields left."""
    for position, summary in enumerate(mentions):
        # ("lollo rosso, romaine & iceberg - 3 salad plots": plots of the crop of them all)
        crops = strong_crops(summary)
        of_their_crop = (
            bool(crops)
            and not names_a_variety(summary)
            and all(strong_crops(m) and strong_crops(m) <= crops for m in mentions[:position])
        )
        if (
            position < 2
            or (summary.has_crop and not of_their_crop)
            or summary.category is not None
            or summary.plot is None
            or summary.refinements
        ):
            continue
        # ("jonagold n conferance pears n kordia cherries, one big orchard": the one plot
        # they share)
        one = summary.count == 1 and _counted_one(summary)
        if not one and not (
            summary.plot["plural"]
            and (
                summary.implied_count
                or summary.count == position
                # ("flint corn & popping corn, separate fields": the fields they are in)
                or (summary.distinct and summary.count is None)
            )
        ):
            continue
        options = set(summary.plot["options"])
        if one and options and not all(strong_crops(m) <= options for m in mentions[:position]):
            continue
        start, end = _sentence_of(clauses, summary.clause)
        fields = mentions[:position]
        if (
            any(m.clause < start for m in fields)
            or any(m.clause < end for m in mentions[position + 1 :])
            or not all(
                strong_crops(m) and (m.count or 1) == 1 and not m.refinements for m in fields
            )
        ):
            continue
        lent = [i for i in summary.items if i.role in (*SUMMARY_ROLES, "size", "geometry")]
        for field in fields:
            own = {i.role for i in field.items}
            keys = {g.key for i in field.items if i.role == "geometry" for g in i.data["geometry"]}
            field.items.extend(
                i
                for i in lent
                if (i.role != "geometry" and i.role not in own)
                # (measures by what they measure: "150 trees each" beside "at 7 x 4 m")
                or (i.role == "geometry" and not keys & {g.key for g in i.data["geometry"]})
            )
        for clause in clauses:
            clause.mentions = [m for m in clause.mentions if m is not summary]
        return [m for m in mentions if m is not summary]
    return mentions


def _sentence_of(clauses: Sequence[Clause], index: int) -> tuple[int, int]:
    """The first clause of the sentence clause ``index`` is in, and the first after it."""
    start = index
    while start > 0 and link_norm(clauses[start]) not in SENTENCE_MARKS:
        start -= 1
    end = next(
        (
            c.index
            for c in clauses[index + 1 :]
            if c.link is not None and c.link.norm in SENTENCE_MARKS
        ),
        len(clauses),
    )
    return start, end

"""Counts of fields said with plurals and lists (issue 8's structure passes).

"carrot fields" asks for more than one field, "fruit and vegetable fields" does not;
"two or three wheat fields" is the lower count; "wheat and maize, 2 fields each", "a
list of crops, 3 plots" and "3 fields: ..." count the members of a list: each pass sets
the count of the mentions it reads, before their members are folded in
(``_refinements``).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import link_norm, listing
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_before_head,
    definite_words,
    first_word,
)

__all__ = [
    "apply_plural_counts",
    "count_a_list_after_it",
    "count_plots_of_a_list",
    "share_count_over_a_list",
    "take_the_lower_count",
]


def apply_plural_counts(clauses: Sequence[Clause], plural_count: int) -> None:
    """ "carrot fields" asks for more than one field; "fruit and vegetable fields" does not.

    A vague amount ("several", "lots of") counts fields only when fields or a
    category are named, never plants ("lots of grapes" is one big vineyard).

    A plural plot noun without a number stands for ``plural_count`` fields, unless
    the plural is shared with a coordinated mention that names no plot of its own
    ("Riesling and Pinot Noir vineyards", "orchards of Gala and Fuji"), or the
    mention points back at fields already named ("..., the trees are healthy").
    """
    definite = definite_words()
    for position, clause in enumerate(clauses):
        for index, mention in enumerate(clause.mentions):
            plots = [h for h in mention.heads if h.role == "plot"]
            # ("strawberry plants in a field with loads of ripe red berries": one field)
            fields_named = any(
                not h.data["value"]["individual"] and h.data["value"].get("plural") for h in plots
            )
            if mention.count is None and mention.quantity is not None:
                # "several vegetable fields", "lots of vegetables": fields; "lots of grapes":
                # many vines in one vineyard; "a few beds of Cos": one field of beds.
                one_field = bool(plots) and plots[-1].data["value"].get("one_field")
                if one_field and mention.has_crop:
                    continue
                first = _own_first_word(mention)
                if first is not None and (first.norm in definite or first.role == "reference"):
                    continue  # "the harvester has lifted the first few beds": of a field named
                if fields_named or (mention.category is not None and not mention.has_crop):
                    mention.count = mention.quantity
                continue
            spec = plots[-1].data["value"] if plots else {}
            first = first_word(mention)
            if (
                mention.count is None
                and spec.get("plural")
                and first is not None
                and first.norm == "both"
                and not any(c.mentions for c in clauses[:position])
            ):
                # "Spray-drone trial, both blocks in full bloom. Conference pears ... and
                # ... Kordia cherries": two fields, named after it
                mention.count = 2
                continue
            if mention.count is not None or not spec.get("plural") or spec.get("individual"):
                continue
            if spec.get("one_field") and mention.has_crop:
                continue  # "Elsanta strawberry beds": one field of beds
            first = _own_first_word(mention)
            if first is not None and first.norm in definite:
                continue
            if definite_before_head(clause, mention):
                continue  # "a quick rundown of the plots. Plot 1: ..."
            link = clause.link if index == 0 else None
            # (after a colon that no field heads, a plural still counts: "a mixed farm
            # please: some veg fields, an orchard and a wheat field")
            opens_a_list = (
                link is not None
                and link.norm == ":"
                and not any(c.mentions for c in clauses[:position])
                and first is not None
                and first.norm in ("some", "a few", "several")
            )
            if link is not None and link.role == "separator" and not opens_a_list:
                continue
            neighbours = []
            if index == 0 and listing(link) and position > 0:
                neighbours += clauses[position - 1].mentions[-1:]
            following = clauses[position + 1] if position + 1 < len(clauses) else None
            if (
                index == len(clause.mentions) - 1
                and following is not None
                and listing(following.link)
            ):
                neighbours += following.mentions[:1]
            if any(not any(h.role == "plot" for h in n.heads) for n in neighbours):
                continue
            mention.count = plural_count
            mention.implied_count = True


def take_the_lower_count(clauses: Sequence[Clause]) -> None:
    """ "4 or 5 cereal fields", "like 2 or 3 plots of maize": the lower of two numbers
    said as alternatives (the fewer fields a reader can be sure were asked for)."""
    for before, clause in itertools.pairwise(clauses):
        if before.mentions or not clause.mentions or clause.link is None:
            continue
        mention = clause.mentions[0]
        said = [i for i in before.items if i.role != "filler"]
        first = clause.items[0] if clause.items else None
        if (
            clause.link.norm != "or"
            or len(said) != 1
            or said[0].role != "number"
            or first is None
            or first.role != "number"
            or first not in mention.items
            or mention.count is None
        ):
            continue
        lower, upper = said[0].data.get("value"), first.data.get("value")
        if (
            isinstance(lower, int | float)
            and isinstance(upper, int | float)
            and float(lower).is_integer()
            and 1 < lower < upper == mention.count
        ):
            mention.count = int(lower)
    # "some veg fields, like 3 or 4, near a farmhouse": a count said after a plural that
    # said none (the lower of two)
    for clause, following in itertools.pairwise(clauses):
        if not clause.mentions or following.mentions or following.link is None:
            continue
        plural = clause.mentions[-1]
        said = [i for i in following.items if i.role != "filler"]
        if (
            not plural.implied_count
            or following.link.norm != ","
            or len(said) != 1
            or said[0].role != "number"
            or not isinstance(value := said[0].data.get("value"), int | float)
            or not float(value).is_integer()
            or not 1 < value <= 20
        ):
            continue
        plural.count = int(value)
        plural.implied_count = False
        said[0].role = "filler"  # (counted: not a number for anything else)
        index = following.index + 1
        if index < len(clauses):
            alternative = clauses[index]
            if link_norm(alternative) == "or" and not alternative.mentions:
                for item in alternative.items:
                    if item.role == "number":
                        item.role = "filler"


def share_count_over_a_list(clauses: Sequence[Clause]) -> None:
    """ "two wheat and maize fields", "4 different cereal & veg fields": a number said
    before crops that share one plural plot noun counts the fields of them all, shared
    out in the order named (one wheat and one maize field; two of each), not the fields
    of the first crop alone."""
    for clause, following in itertools.pairwise(clauses):
        if not clause.mentions or len(following.mentions) != 1:
            continue
        first, second = clause.mentions[-1], following.mentions[0]
        plots = [h for h in second.heads if h.role == "plot"]
        if (
            first.count is None
            or first.count < 2
            or first.implied_count
            or any(h.role == "plot" for h in first.heads)
            or second.count is not None
            or not plots
            or not plots[-1].data["value"].get("plural")
            or following.link is None
            or following.link.role != "conjunction"
            or any(i.start < second.heads[0].start for i in following.items if i.role != "filler")
        ):
            continue
        total = first.count
        first.count = (total + 1) // 2
        second.count = total - first.count
        second.distinct = second.distinct or first.distinct
        second.implied_count = False


def count_a_list_after_it(clauses: Sequence[Clause]) -> None:
    """'flint corn & dent corn 2 fields', 'roma toms & beef tomatoes & cherry toms 3 plots':
    a number and plural plot said right after the last of a list of named crops, and as
    many as the list names, count the list's fields (one each), not more of the last."""
    for position, clause in enumerate(clauses):
        if len(clause.mentions) != 1 or position == 0:
            continue
        last = clause.mentions[0]
        heads = [h for h in last.heads if h.role != "plot"]
        plots = [h for h in last.heads if h.role == "plot"]
        numbers = [i for i in last.items if i.role == "number"]
        if (
            last.count is None
            or last.count < 2
            or not heads
            or not plots
            or not plots[-1].data["value"].get("plural")
            or len(numbers) != 1
            or numbers[0].start < max(h.start for h in heads)
        ):
            continue
        listed = [last]
        index = position
        while index > 0 and len(listed) < last.count:
            link = clauses[index].link
            previous = clauses[index - 1]
            if link is None or link.role not in ("conjunction", "separator"):
                break
            if len(previous.mentions) != 1 or previous.mentions[0].count is not None:
                break
            listed.append(previous.mentions[0])
            index -= 1
        # (or kinds: "grain + grain + veg lol 3 fields")
        if len(listed) == last.count and all(m.has_crop or m.category is not None for m in listed):
            last.count = None
            last.implied_count = False


def count_plots_of_a_list(clauses: Sequence[Clause]) -> None:
    """'three 12 x 100 m strips of winter wheat, spelt and durum': a number of plural
    plots "of" a list of as many crops is one plot of each, each of the plots' size (not
    three of the first and one each of the others)."""
    for position, clause in enumerate(clauses):
        if not clause.mentions:
            continue
        first = clause.mentions[-1]
        plots = [h for h in first.heads if h.role == "plot"]
        crops = [h for h in first.heads if h.role != "plot"]
        if (
            first.count is None
            or first.count < 2
            or not plots
            or not crops
            or not plots[-1].data["value"].get("plural")
            or plots[-1].start > min(h.start for h in crops)
        ):
            continue
        listed: list[Mention] = []
        for following in clauses[position + 1 :]:
            if (
                len(listed) == first.count - 1
                or following.link is None
                or not (following.link.role == "conjunction" or following.link.norm == ",")
                or len(following.mentions) != 1
            ):
                break
            member = following.mentions[0]
            if member.count is not None or member.plot is not None or not member.has_crop:
                break
            listed.append(member)
        if len(listed) != first.count - 1:
            continue
        first.count = None
        first.implied_count = False
        size = [i for i in first.items if i.role in ("size", "side", "dimension_joiner")]
        for member in listed:
            if not any(i.role == "size" for i in member.items):
                member.items.extend(size)


def _own_first_word(mention: Mention) -> Item | None:
    """The mention's first word, past the article of a place that holds its fields
    ("The farm's got some fruit fields": "the" is the farm's, not the fields')."""
    ordered = sorted(mention.items, key=lambda item: item.start)
    if len(ordered) >= 2 and ordered[1].role == "container" and ordered[1] not in mention.heads:
        return next((i for i in ordered[2:] if i.norm not in ("s", "has", "have", "got")), None)
    return ordered[0] if ordered else None

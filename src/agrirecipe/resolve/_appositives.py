"""Plots said with a field, and crops said of a plot (issue 8): one field, not two.

:func:`merge_appositive_plots`: "Gala, a 2 ha block" and "..., in a field bordered by a
ditch" are one field; "a few diff fruits, like 4 fields" says the count again; "The
vineyard on the south slope is Pinot Noir" names the plot's crop; "In the field beyond
the stone wall there's an old Comice pear orchard" says where the field stands; "A, B
and C, 3 lettuce plots" counts a list again.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from agrirecipe.resolve._lexicon import reader_words
from agrirecipe.resolve._links import coordinated
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    descriptive_words,
    names_a_variety,
    same_variety,
    strong_crops,
)
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = ["merge_appositive_plots"]


#: The words that open a plot said as where a crop is planted ("in rows across a field").
_PLANTED_IN = [["in", "rows"], ["in", "lines"], ["in", "drills"], ["in", "beds"], ["in", "ridges"]]


def merge_appositive_plots(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'chillies, a 15 by 30 m patch, and ...': a plot said right after a crop, between
    commas and naming no crop of its own, is that crop's plot, not another field.

    "Romaine, Iceberg and Lollo Rosso, each a 10 m x 20 m plot", "... Each plot 15 m
    wide and 40 m long": a plot of each, with a size, gives that size to every field
    named before it that states none."""
    kept: list[Mention] = []
    for mention in mentions:
        sizes = [i for i in mention.items if i.role in ("size", "side", "dimension_joiner")]
        if (
            len(kept) >= 2
            and not mention.has_crop
            and mention.category is None
            and mention.plot is not None
            and not mention.refinements
            and any(i.role == "size" for i in sizes)
            and any(i.norm in ("each", "every") for i in mention.items if i.role == "all")
        ):
            for earlier in kept:
                if not any(i.role == "size" for i in earlier.items):
                    earlier.items.extend(sizes)
            clause = clauses[mention.clause] if mention.clause < len(clauses) else None
            if clause is not None:
                clause.mentions = [m for m in clause.mentions if m is not mention]
            continue
        clause = clauses[mention.clause] if mention.clause < len(clauses) else None
        previous = kept[-1] if kept else None
        if (
            clause is not None
            and previous is not None
            # ("Any cereal will do: one plot drilled at 12.5 cm row spacing, 10 m x 50 m")
            and (previous.has_crop or (previous.category is not None and previous.plot is None))
            and (previous.count or 1) == 1
            and not mention.has_crop
            and mention.plot is not None
            and (mention.count or 1) == 1
            and not mention.refinements
            and clause.link is not None
            # ("we only grow sweet peppers now - one outdoor field, roughly 60 by 120 m";
            # "...; a whole grove of sick-looking trees": a plot said with a look)
            and (
                clause.link.norm in (",", ":", "-", "–", "—")
                or (clause.link.norm == ";" and _said_with_a_look(clause))
                # ("idk just lettuces?? like a small 20x20 m patch": "like" says which)
                or (
                    clause.link.norm in ("?", "!")
                    and bool(clause.items)
                    and clause.items[0].norm == "like"
                )
            )
            # ("Lady Finger bananas: 3 m x 3 m grid, 1,111 plants/ha, a 90 x 60 m block")
            # ("Spelt in ear and just flowering, a 2 ha field": how it looks, between)
            and all(
                not c.mentions
                and all(
                    i.role
                    in (
                        "geometry",
                        "filler",
                        "place",
                        "container",
                        "unknown",
                        "cue",
                        "stage",
                        "health",
                        "season",
                        "month",
                        "of",
                    )
                    for i in c.items
                )
                for c in clauses[previous.clause + 1 : mention.clause]
            )
            and previous.clause < mention.clause
            # (not "a lettuce field on my left and ..., past the gate, the orchard": a plot
            # that cannot hold the crop named before is a field of its own)
            and not _holds_none_of(mention.plot, strong_crops(previous))
            # ("onions now, one field of about 6 acres"; "Navel oranges, a 2 ha block with
            # the fruit still small": the crop's own fruit)
            and all(
                i.role
                in ("number", "size", "plot", "filler", "of", "cue", "stage", "health", "geometry")
                # ("young cabbage transplants, in rows across a brown field")
                or (i.role == "side" and i.norm == "across")
                # ("one plot drilled at 12.5 cm row spacing": how it is sown; "a 1.5 ha block
                # with the cableway running through it": what runs through it)
                or (
                    i.role == "unknown"
                    and any(j.role in ("geometry", "size") for j in clause.items)
                )
                or (i.role == "head" and i.norm in descriptive_words())
                for i in clause.items
            )
            # ("Regina cherries, one block up on the hill, ...": a plot where it grows)
            and (
                any(i.role == "size" for i in clause.items)
                or any(i.role == "filler" and i.scenery for i in clause.items)
                or _size_said_next(clauses, mention.clause)
                or _said_with_a_look(clause)
                # ("young cabbage transplants, in rows across a brown field": how it is
                # planted in the plot)
                or [i.norm for i in clause.items[:2]] in _PLANTED_IN
                # ("Just Regina cherries on this farm, one orchard, fruit ripening ...": how
                # many plots the crop is grown in, with no field named after it)
                or (
                    bool(clause.items)
                    and clause.items[0].norm == "one"
                    and not any(c.mentions for c in clauses[mention.clause + 1 :])
                )
            )
        ):
            # (with how it looks: "apples, a grove of sick trees")
            previous.items.extend(
                i for i in mention.items if i.role in ("size", "geometry", "cue", "health")
            )
            if previous.plot is None:
                previous.plot = mention.plot
            clause.mentions = [m for m in clause.mentions if m is not mention]
            continue
        if (
            clause is not None
            and previous is not None
            and _the_crop_said_next(clause, previous, mention)
        ):
            # "our only crop, a field of corn": the crop named right after says which
            kept[-1] = mention
            home = clauses[previous.clause]
            home.mentions = [m for m in home.mentions if m is not previous]
            continue
        if previous is not None and _where_it_stands(clauses, previous, mention):
            # "In the field beyond the stone wall there's an old Comice pear orchard": the
            # plot named first is where the field of the crop stands
            kept[-1] = mention
            home = clauses[previous.clause]
            home.mentions = [m for m in home.mentions if m is not previous]
            continue
        if clause is not None and previous is not None and _is_its_crop(clause, previous, mention):
            # "The vineyard on the south slope is Pinot Noir": the plot named, then its crop
            mention.items.extend(previous.items)
            mention.plot = mention.plot or previous.plot
            kept[-1] = mention
            for each in clauses:
                each.mentions = [mention if m is previous else m for m in each.mentions]
            clause.mentions = [m for m in clause.mentions if m is mention]
            if previous.has_crop:
                # ("The apple block east of it is Jonagored": the block stands where it was
                # named, so "east of it" places it against the field before)
                clause.mentions = []
                mention.clause = previous.clause
            continue
        if clause is not None and (listed := _listed_again(clauses, clause, mention)):
            # "butterhead + lollo rosso + romaine, 3 lettuce plots": the list counted
            # again, with the plot its members are grown in
            for member in listed:
                member.items.extend(
                    i for i in mention.items if i.role not in ("number", "head", "plot")
                )
                if member.plot is None:
                    member.plot = mention.plot
            for again in mention.refinements:
                named = next(m for m in listed if same_variety(m, again))
                named.items.extend(i for i in again.items if i.role not in ("number", "head"))
                for other in clauses:
                    if other.refinement is again:
                        other.refinement = named
                    if other.refined_parent is mention:
                        other.refined_parent = None
            clause.mentions = [m for m in clause.mentions if m is not mention]
            continue
        if (
            clause is not None
            and previous is not None
            and _count_said_again(clause, previous, mention)
        ):
            # "a few diff fruits, like 4 fields", "some veggies maybe 2 or 3 fields": how
            # many of them; "an orchard, just an orchard": the same field said again
            if (
                mention.plot is not None
                and mention.count is not None
                and clause.link is not None
                and clause.link.norm != "or"
            ):
                previous.count = mention.count
            elif clause.link is not None and clause.link.norm == "or" and previous.count is None:
                # "some cereals, like 3 or 4 fields": the lower of the two
                lower = [
                    int(i.data["value"])
                    for i in clauses[mention.clause - 1].items
                    if i.role == "number" and float(i.data.get("value") or 0).is_integer()
                ]
                if len(lower) == 1 and 1 < lower[0] <= (mention.count or 0):
                    previous.count = lower[0]
            clause.mentions = [m for m in clause.mentions if m is not mention]
            continue
        if (
            clause is not None
            and previous is not None
            and _a_part_where(clauses, previous, mention)
        ):
            # "Onions in neat rows ..., then suddenly a patch where everything has gone
            # yellow": a part of the field just named, where something happens
            clause.mentions = [m for m in clause.mentions if m is not mention]
            continue
        if clause is not None and previous is not None and _where_it_grows(previous, mention):
            # "Bibb lettuce transplants ..., in a field bordered by a ditch": the field the
            # crop just named grows in, not another field
            # (with how it looks: "apples, a grove of sick trees")
            previous.items.extend(
                i for i in mention.items if i.role in ("size", "geometry", "cue", "health")
            )
            if previous.plot is None:
                previous.plot = mention.plot
            clause.mentions = [m for m in clause.mentions if m is not mention]
            # ("... side by side on a terrace in the Algarve in March": the time said with
            # the plot stays in its clause, for the fields it is said of)
            clause.loose.extend(i for i in mention.items if i.role in ("month", "season"))
            continue
        kept.append(mention)
    return kept


def _count_said_again(clause: Clause, previous: Mention, mention: Mention) -> bool:
    """Whether ``mention`` only says again how many fields ``previous`` is ("a few
    different fruits, like 4 fields"; "maybe 2 or 3 fields") or repeats it ("an orchard,
    just an orchard")."""
    if clause.link is None or mention.has_crop or mention.category is not None:
        return False
    if previous.clause >= mention.clause or mention.refinements or previous.refinements:
        return False
    words = [i.norm for i in clause.items]
    heads = [h.norm for h in mention.heads]
    if words[:1] in (["just"], ["only"], ["simply"]) and heads == [h.norm for h in previous.heads]:
        return clause.link.norm == ","
    plural = mention.plot is not None and bool(mention.plot.get("plural"))
    return (
        plural
        and (previous.has_crop or previous.category is not None)
        and mention.count is not None
        and clause.link.norm in (",", "or")
        and all(i.role in ("number", "filler", "plot") for i in clause.items)
        and (
            clause.link.norm == "or"
            or any(i.norm in reader_words("approximately") for i in clause.items)
        )
    )


def _is_its_crop(clause: Clause, previous: Mention, mention: Mention) -> bool:
    """Whether ``mention`` says what a plot of no crop just named grows: "The vineyard on
    the south slope is Pinot Noir" (a copula opens its clause, after a placement)."""
    words = [i.norm for i in sorted(clause.items, key=lambda i: i.start)]
    # "The apple block east of it is Jonagored", "the cabbages east of them are Golden
    # Acre": a field of a crop, then one of its varieties after the placement's pronoun
    pronoun = words[:1] in (["it"], ["them"]) and words[1:2] in (["is"], ["are"], ["s"])
    of_its_crop = (
        pronoun
        and previous.has_crop
        and not names_a_variety(previous)
        and names_a_variety(mention)
        and strong_crops(mention) <= strong_crops(previous)
    )
    return (
        (of_its_crop or (not previous.has_crop and words[:1] in (["is"], ["are"], ["was"])))
        and previous.category is None
        # ("the cabbages east of them are Golden Acre": the crop's plants, named with no plot)
        and (previous.plot is not None or of_its_crop)
        and (previous.count or 1) == 1
        and not previous.refinements
        and mention.has_crop
        and mention.plot is None
        and mention.count is None
        and previous.clause == clause.index - 1
        and clause.link is not None
        and clause.link.role in ("trailer", "relation")
    )


def _the_crop_said_next(clause: Clause, previous: Mention, mention: Mention) -> bool:
    """Whether ``previous`` is "our only crop" (the word "crop" alone, no count) and
    ``mention``, right after a comma or colon, names the crop."""
    words = {h.norm for h in previous.heads}
    return (
        words == {"crop"}
        and not previous.has_crop
        and previous.category is None
        and previous.count is None
        and not previous.refinements
        and mention.has_crop
        and previous.clause == clause.index - 1
        and clause.link is not None
        and clause.link.norm in (",", ":", "-", "–", "—")
    )


def _listed_again(clauses: Sequence[Clause], clause: Clause, mention: Mention) -> list[Mention]:
    """The list just before ``clause`` that ``mention`` counts again ("A, B and C, 3
    lettuce plots", "Comice vs Durondeau: two adjacent pear blocks": as many members as
    it counts, each of the mention's crop), or []."""
    if (
        clause.link is None
        or clause.link.norm not in (",", ":")
        or mention.count is None
        or mention.count < 2
        or mention.plot is None
        or not mention.plot["plural"]
        or not all(i.role in ("number", "head", "plot", "filler") for i in clause.items)
    ):
        return []
    crops = strong_crops(mention)
    group = coordinated(clauses, clause.index)
    if (
        len(group) != mention.count
        or not crops
        or not all(strong_crops(m) and strong_crops(m) <= crops and m.count is None for m in group)
        # ("Nantes vs Imperator: two carrot plots, ..., the Imperator plot to the south":
        # members said after it are the ones listed, named again)
        or not all(any(same_variety(m, r) for m in group) for r in mention.refinements)
    ):
        return []
    return group


def _where_it_stands(clauses: Sequence[Clause], previous: Mention, mention: Mention) -> bool:
    """Whether ``previous``, a plot of no crop opening the prompt with "in" or "on" ("In
    the field beyond the stone wall"), is where the field ``mention`` names stands, said
    with "there's" in the same sentence."""
    words = [i.norm for i in sorted(previous.items, key=lambda i: i.start)]
    said = [i.norm for i in mention.items if i.start < min(h.start for h in mention.heads)]
    return (
        previous.clause == 0
        and not previous.has_crop
        and previous.category is None
        and previous.plot is not None
        and previous.count is None
        and not previous.refinements
        and words[:1] in (["in"], ["on"])
        and mention.has_crop
        and (mention.count or 1) == 1
        and "there" in said
        and not any(
            c.link is not None and c.link.norm in SENTENCE_MARKS
            for c in clauses[previous.clause + 1 : mention.clause + 1]
        )
    )


def _size_said_next(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the clause after ``position`` names no field and gives a size ("one
    outdoor field, roughly 60 by 120 m")."""
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    return (
        following is not None
        and not following.mentions
        and any(i.role == "size" for i in following.items)
    )


def _a_part_where(clauses: Sequence[Clause], previous: Mention, mention: Mention) -> bool:
    """Whether ``mention`` is a plot of no crop ("a patch", "one corner") said right
    before "where ..." after a field of a crop: a part of that field."""
    following = clauses[mention.clause + 1] if mention.clause + 1 < len(clauses) else None
    return (
        previous.has_crop
        and not mention.has_crop
        and mention.category is None
        and mention.plot is not None
        and (mention.count or 1) == 1
        and not mention.refinements
        and previous.clause < mention.clause
        and following is not None
        and following.link is not None
        and following.link.norm in ("where", "in which")
    )


def _where_it_grows(previous: Mention, mention: Mention) -> bool:
    """'..., in a field with an old stone wall': a plot of no crop, said with "in" right
    after one field of a crop, is where that crop grows."""
    words = [i.norm for i in mention.items]
    return (
        previous.has_crop
        and (previous.count or 1) == 1
        and not mention.has_crop
        and mention.category is None
        and mention.plot is not None
        and (mention.count or 1) == 1
        and not mention.refinements
        and not mention.other
        and len(words) >= 3
        and previous.clause < mention.clause
        and (
            (words[0] in ("in", "on") and words[1] in ("a", "an", "one"))
            or _plants_in_a_plot(mention)
            # "standing in neat rows in a wet field": past words about how they stand;
            # "It's for a robot navigation test in a plantation": past what it is for
            or any(
                words[j] in ("in", "on")
                and words[j + 1] in ("a", "an", "one")
                and all(
                    i.role in ("filler", "unknown")
                    or (i.role in ("of", "non_agricultural") and i.norm != "of")
                    for i in mention.items[:j]
                )
                for j in range(1, min(len(words) - 1, 9))
            )
        )
    )


#: Words that put plants inside a plot ("leaves poking out of a white field").
_INSIDE = frozenset({"in", "on", "across", "over", "through", "throughout", "within"})


def _plants_in_a_plot(mention: Mention) -> bool:
    """'..., purple-tinged leaves poking out of a white field': the plants of the crop
    just named, said to grow in a plot of no crop (a plant-part word, then "in"/"out
    of"/"across" a plot), describe that crop's field."""
    items = sorted(mention.items, key=lambda i: i.start)
    words = [i.norm for i in items]
    article = next((k for k, w in enumerate(words) if w in ("a", "an", "one")), -1)
    if article < 2:
        return False
    inside = words[article - 1] in _INSIDE or words[article - 2 : article] == ["out", "of"]
    before = items[: article - (1 if words[article - 1] in _INSIDE else 2)]
    parts = descriptive_words()
    return (
        inside
        and any(i.norm in parts for i in before)
        and all(i.role in ("filler", "unknown", "cue", "health", "stage") for i in before)
    )


def _holds_none_of(plot: dict[str, Any], crops: set[str]) -> bool:
    """Whether a plot noun that names the crops it holds ("orchard") can hold none of
    ``crops`` (a lettuce field is no orchard)."""
    allowed = {*plot.get("options", ()), *plot.get("tolerates", ())}
    return bool(plot.get("options")) and bool(crops) and not allowed & crops


def _said_with_a_look(clause: Clause) -> bool:
    """Whether a plot's clause says how its plants look ("a grove of sick-looking trees")."""
    return any(i.role in ("cue", "health") for i in clause.items)

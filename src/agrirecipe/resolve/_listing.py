"""Whether a clause lists one more member of a plural mention, or names one again
(issue 8's structure passes, read by :mod:`agrirecipe.resolve._refinements`).

"two fields, wheat and maize" lists two members; "..., wheat north of the potatoes" names
a member again; "3 blocks: maize | cabbage | maize again" lists maize again as one more;
"Two Chantenay carrot plots and one Danvers plot" adds a field of another variety.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._links import PRONOUNS, listing
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_before_head,
    names_a_variety,
    pronoun_one,
    same_variety,
    strong_crops,
    with_plot_noun,
)

__all__ = [
    "adds_a_field",
    "listed_again",
    "listed_fields",
    "lists_exactly",
    "named_again",
    "names_again",
    "names_varieties_of",
    "placed_against",
    "placed_by_scenery",
]


def lists_exactly(
    clauses: Sequence[Clause], start: int, count: int | None, *, to_the_end: bool = False
) -> bool:
    """Whether the clauses from ``start`` to the end of the sentence (or of the prompt)
    name exactly ``count`` fields, joined as a list (commas and "and"): single fields, or
    members counted that add up to it ("4 plots, 2 of potatoes and 2 of onions")."""
    named = listed_fields(clauses, start, to_the_end=to_the_end)
    return (
        count is not None
        and count >= 2
        and len(named) >= 2
        and sum(m.count or 1 for m in named) == count
    )


def listed_fields(
    clauses: Sequence[Clause], start: int, *, to_the_end: bool = False
) -> list[Mention]:
    """The fields of named crops the clauses from ``start`` name, to the end of the
    sentence (or of the prompt), joined as a list (commas and "and")."""
    named: list[Mention] = []
    for clause in clauses[start:]:
        link = clause.link
        if (
            not to_the_end
            and clause.index > start
            and link is not None
            and not listing(link)
            and (
                link.norm in (".", "!", "?", ";")
                # ("Two plots, carrots on the west and onions on the east: Nantes carrots
                # ..., and Sturon onions ...": a colon after the list opens its details)
                or link.norm == ":"
                # ("two 0.25 ha plots, carrots north of onions": the list placed in itself)
                or (
                    link.role == "relation"
                    and not bare_crop_first(clause)
                    # ("Two fields in this one, a field of young maize next to a wheat
                    # field": a new field, said with "a", placed against the one before)
                    and not _new_field_first(clause)
                    # ("two fields, wheat by the barn, maize near the river")
                    and not placed_by_scenery(clause)
                    # ("... Conference pears ... and, north of them, Kordia cherries")
                    and not (
                        not clause.mentions
                        and any(i.norm in PRONOUNS for i in clause.items)
                        and all(i.norm in PRONOUNS or i.role == "filler" for i in clause.items)
                    )
                )
            )
        ):
            break
        if _placed_again(clauses, clause, named):
            # ("Two orchards, apple and cherry, cherries north of the apples": a member
            # listed already, named again to place it, ends the list)
            break
        # fields named again ("the Comice") or plot words alone ("Beds and ridges run
        # NW-SE") name no new field
        # ("Two blocks ..., Conference pears and the Kordia cherries": a crop said with
        # "the" but named nowhere before is a member all the same)
        named.extend(
            m
            for m in clause.mentions
            if (m.has_crop or _plot_of_a_crop(m))
            and (
                not definite_before_head(clause, m)
                or (bool(strong_crops(m)) and not _named_before(clauses[: clause.index], m))
            )
        )
    return named


def _placed_again(clauses: Sequence[Clause], clause: Clause, named: Sequence[Mention]) -> bool:
    """Whether ``clause`` only names again, bare, a crop or plot the list named already,
    and the next clause places it ("..., apple and cherry, cherries north of the apples";
    "an orchard ... and a vegetable field ..., orchard east of the veg")."""
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    if (
        len(clause.mentions) != 1
        or following is None
        or following.link is None
        or following.link.role not in ("relation", "between")
        or not all(i.role in ("head", "filler", "plot") for i in clause.mentions[0].items)
    ):
        return False
    again = clause.mentions[0]
    if own := strong_crops(again):
        return any(strong_crops(m) == own for m in named)
    noun = again.plot.get("noun") if again.plot is not None and not again.category else None
    return noun is not None and any(
        m.plot is not None and m.plot.get("options") for m in with_plot_noun(named, noun)
    )


def _named_before(clauses: Sequence[Clause], mention: Mention) -> bool:
    """Whether a field the clauses name (a mention, or a member folded into its plural)
    grows a crop ``mention`` names."""
    own = strong_crops(mention)
    return any(strong_crops(m) & own for c in clauses for m in c.named)


def _plot_of_a_crop(mention: Mention) -> bool:
    """Whether ``mention`` is one plot whose noun names its crops ("a vineyard")."""
    plot = mention.plot
    return mention.count == 1 and plot is not None and not plot["plural"] and bool(plot["options"])


def named_again(again: Mention, member: Mention) -> bool:
    """Whether ``again`` ("the wheat") names ``member`` again: the same crop, and no other
    variety ("between the Cos and the Bibb" after "Iceberg" names two more fields)."""
    if not strong_crops(again) & strong_crops(member):
        return False
    said = {v for _, v, _ in again.interpretations or () if v}
    return (
        not said
        or not names_a_variety(member)
        or bool(said & {v for _, v, _ in member.interpretations or () if v})
    )


def placed_by_scenery(clause: Clause) -> bool:
    """'near the river', 'by the sheds': a relation to scenery, naming no field (not
    "beside it", which points back at one)."""
    return (
        not clause.mentions
        and bool(clause.items)
        and (
            all(i.role in ("filler", "non_agricultural") for i in clause.items)
            # "of the packing shed": what scenery it is a side of
            or (
                clause.items[0].role == "of"
                and all(i.role in ("of", "filler", "unknown") for i in clause.items)
                and any("scenery" in i.data for i in clause.items)
            )
        )
        and not any(i.norm in PRONOUNS for i in clause.items)
    )


def bare_crop_first(clause: Clause) -> bool:
    """Whether the clause opens with a crop named without an article ("onions")."""
    return (
        bool(clause.mentions)
        and bool(clause.items)
        and clause.items[0] in clause.mentions[0].heads
        and clause.mentions[0].has_crop
    )


def _new_field_first(clause: Clause) -> bool:
    """Whether the clause opens with a field said with "a" or "an" ("a wheat field")."""
    return (
        len(clause.items) >= 2
        and bool(clause.mentions)
        and clause.items[0].norm in ("a", "an")
        and clause.items[1] in clause.mentions[0].items
        and (clause.mentions[0].has_crop or clause.mentions[0].plot is not None)
    )


def listed_again(clauses: Sequence[Clause], clause: Clause, parent: Mention) -> bool:
    """Whether ``clause``, a crop of the list after ``parent``'s stated count named again,
    is one more member: the count has room for it and the rest of the list, and it is
    not placed against another field ("..., wheat north of the potatoes")."""
    link = clause.link
    room = (parent.count or 0) - len(parent.refinements)
    return (
        link is not None
        and link.role == "separator"
        and parent.count is not None
        and not parent.implied_count
        and room > 0
        and len(listed_fields(clauses, clause.index)) <= room
        and not placed_against(clauses, clause)
    )


def names_again(member: Mention, sub: Mention, *, placed: bool = False) -> bool:
    """Whether ``sub`` (no count, no variety, no plot of its own) names ``member``'s crop.

    A plot of its own is allowed when ``sub`` is placed against another field ("...,
    chillies in 1 m rows, chilli plot west of the bananas")."""
    crops = strong_crops(sub)
    return (
        sub.count is None
        and bool(crops)
        and crops == strong_crops(member)
        and not names_a_variety(sub)
        and (placed or not any(h.role == "plot" for h in sub.heads))
    )


def placed_against(clauses: Sequence[Clause], clause: Clause) -> bool:
    """Whether the clause after ``clause`` places it ("... west of the bananas")."""
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    return (
        following is not None
        and following.link is not None
        and following.link.role in ("relation", "between")
    )


def names_varieties_of(sub: Mention, parent: Mention) -> bool:
    """``sub`` names, without a count of its own, a variety of the crop ``parent`` names."""
    crops = strong_crops(parent)
    if not crops and parent.plot is not None and len(parent.plot["options"]) == 1:
        crops = {parent.plot["options"][0]}  # "two vineyards, chardonnay ..."
    named = {(c, v) for c, v, weak in sub.interpretations or () if v is not None and not weak}
    # "3 cherry blocks: Lapins, Regina and Bing": "cherry" may also be a tomato variety;
    # the crop the members name decides which reading the parent has
    common = crops & {c for c, _ in named}
    return (
        (
            sub.count is None
            or (sub.count == 1 and pronoun_one(sub))
            # ("two wheat plots: durum wheat north of a winter wheat plot")
            or (sub.count == 1 and any(i.norm in ("a", "an") for i in sub.items))
        )
        and len(common) == 1
        and bool(named)
        and {c for c, _ in named} <= crops
        and not any(v is not None for c, v, _ in parent.interpretations or () if c in common)
    )


def adds_a_field(clause: Clause, parent: Mention) -> bool:
    """'... and one of chillies' after a plural that named its crop, '... and one Danvers
    plot' after a plural of another variety: one more field.

    "one of" followed by a crop or variety (not "them"), joined by "and" to a plural
    mention that already says what its fields are, counts a further field.
    """
    words = [i for i in clause.items if i.norm != "the"]
    if (
        len(words) >= 2
        and words[0].role == "number"
        and words[1].role == "head"
        and clause.mentions
        and names_a_variety(clause.mentions[0])
        and names_a_variety(parent)
        and not same_variety(parent, clause.mentions[0])
    ):
        # "Two Chantenay carrot plots and one Danvers plot": a field of another variety
        return True
    if len(words) < 3 or words[0].role != "number" or words[1].role != "of":
        return False
    return words[2].role == "head" and bool(strong_crops(parent))

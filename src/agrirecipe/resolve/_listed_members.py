"""A member listed after the plural mention that announced it (issue 8's structure
passes), for :func:`~agrirecipe.resolve._refinements.apply_refinements`.

"two fields: sweetcorn and durum wheat", "four fields, two of them blighted", "Three
potato fields in a line. The middle one has blight", "five fields, some of them
diseased": :func:`fold_listed_member` folds a clause joined to the listing into the
announced mention's members (a counted member as that many, a share of them, the member
at a place, the rest), reads a vague or unsaid number of fields as the count the list or
a count said again gives it, and raises a ``PromptError`` when more members are listed
than were announced.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import NamedTuple

from agrirecipe._errors import PromptError
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import link_norm, listing
from agrirecipe.resolve._listing import (
    adds_a_field,
    listed_again,
    listed_fields,
    lists_exactly,
    names_again,
    names_varieties_of,
    placed_against,
)
from agrirecipe.resolve._member_refs import per_plot, place_said, plots_again
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_before_head,
    definite_words,
    has_room,
    names_a_variety,
    same_variety,
    strong_crops,
)

__all__ = ["Listing", "fits", "fold_listed_member"]


class Listing(NamedTuple):
    """Where the listing stands when a clause is joined to it."""

    #: Members are being listed one after another ("two fields: wheat, ...").
    enumerating: bool
    #: The word the clause opens with ("one", "the middle one", "two of them").
    first: Item | None
    #: "two of them": how many of the announced fields the clause is said of.
    share_of: int | None
    #: The clause opens with a word pointing at members ("one", "the other").
    is_reference: bool


def fits(sub: Mention, parent: Mention, crop_categories: dict[str, str]) -> bool:
    """Whether ``sub`` can describe members of ``parent``."""
    sub_crops = strong_crops(sub)
    if sub.plot is not None and sub.plot["narrows"] and not sub_crops:
        options = set(sub.plot["options"])
        if sub.plot["category"] is not None:
            options |= {c for c, cat in crop_categories.items() if cat == sub.plot["category"]}
        sub_crops = options
    if sub.category is not None and not sub_crops:
        sub_crops = {c for c, cat in crop_categories.items() if cat == sub.category}
    if not sub_crops:
        return True
    parent_crops = strong_crops(parent)
    if parent_crops:
        return bool(parent_crops & sub_crops)
    if parent.category is not None:
        return any(crop_categories.get(c) == parent.category for c in sub_crops)
    if parent.plot is not None and parent.plot["options"]:
        return bool(set(parent.plot["options"]) & sub_crops)
    return True


def fold_listed_member(
    clauses: Sequence[Clause],
    clause: Clause,
    parent: Mention,
    state: Listing,
    crop_categories: dict[str, str],
) -> bool | None:
    """Fold ``clause`` (joined to the listing by a comma, "and", a colon...) into
    ``parent``'s members. Returns None when the clause is no member of ``parent`` (the
    caller reads it as a mention of its own); else whether members are still being
    listed one after another."""
    link = clause.link
    assert link is not None
    previous = clauses[clause.index - 1] if clause.index else None
    enumerating, first, share_of, is_reference = state
    sub = (
        clause.mentions[0]
        if clause.mentions
        else Mention(items=list(clause.loose), clause=clause.index)
    )
    listed_members = list({id(r): r for r in parent.refinements}.values())
    if per_plot(sub) and parent.count is not None and len(listed_members) >= parent.count:
        # "lettuce at 35 cm, cabbage at 75 cm and tomatoes at 150 cm, 12 rows per
        # plot": after the full list, a measure of each listed plot
        for member in listed_members:
            member.items.extend(i for i in sub.items if i.role == "geometry")
        clause.mentions, clause.loose = [], []
        clause.refined_parent = parent
        return enumerating
    # A generic plural mention followed by ':' lists its members; so does a
    # plural crop followed by its varieties ("two beds of lettuce, lollo rosso
    # and bibb").
    if (
        parent.quantity is not None
        and parent.count == parent.quantity
        and not parent.refinements
        and link.norm == ","
        and len(vague := listed_fields(clauses, clause.index)) >= 2
        and all((m.count or 1) == 1 for m in vague)
    ):
        # "A patchwork of veg beds ..., I can make out onions, carrots and lettuce":
        # a vague number of fields is as many as the list after it names
        parent.count = len(vague)
    lists_members = not strong_crops(parent) and (
        enumerating
        or link.norm in (":", "-", "—", "–")
        # "two blocks, 150 cherry trees ... and 300 apple trees ...": as many
        # fields as announced, listed after a comma
        or (link.norm == "," and lists_exactly(clauses, clause.index, parent.count))
        # "4 plots of 6 beds each, one per variety (Romaine, Iceberg, ...)"
        or (
            link.norm == "("
            and (parent.distinct or (previous is not None and _all_distinct(previous.items)))
            and lists_exactly(clauses, clause.index, parent.count)
        )
        # "... on two bed plots. Lollo Rosso: 4 beds ... Beside it, carrots: ..."
        or (
            link.norm in (".", "?", "!")  # ("... for our sim? Gala apples ...")
            and lists_exactly(clauses, clause.index, parent.count, to_the_end=True)
        )
    )
    lists_members = lists_members or (
        names_varieties_of(sub, parent) and (enumerating or link.role == "separator")
    )
    if (
        link.norm in (".", "!", "?", ";")
        and clause.mentions
        and not sub.has_crop
        and sub.plot is not None
        and sub.plot["plural"]
    ):
        # "Lower terraces: Chardonnay. Upper terraces: Riesling.": a new heading
        lists_members = False
    # (not the heading the plots follow: "Bell pepper vs jalapeño comparison: two
    # plots .... California Wonder on the west plot, Jalapeños on the east one")
    named_before = (
        [m for c in clauses[: parent.clause] for m in c.mentions]
        if link_norm(clauses[parent.clause]) != ":"
        else []
    )
    if clause.mentions and (
        (
            any(
                same_variety(r, sub)
                # "two different fruits: apples and apples" still lists two members
                or (
                    link.role == "separator"
                    and not parent.distinct
                    and names_again(r, sub, placed=placed_against(clauses, clause))
                )
                for r in parent.refinements
            )
            # "3 blocks: maize | cabbage | maize again": a crop listed again is a
            # member of its own while the count still has room for it
            and not listed_again(clauses, clause, parent)
        )
        # "centenary & albion strawberries, 2 fields, albion south of centenary":
        # the count says again how many fields were named; the varieties after it
        # are those fields named again
        or (names_a_variety(sub) and any(same_variety(m, sub) for m in named_before))
    ):
        # "..., Valencia east of Hamlin", "bintje spuds & nantes carrots, carrots
        # east of the spuds": a member named again
        lists_members = False

    if (
        parent.implied_count
        and not parent.refinements
        and link.norm == ":"
        and clause.mentions
        and sub.has_crop
        and (sub.count or 1) >= 2
        and sub.plot is not None
        and sub.plot["plural"]
    ):
        # "Seeding-rate strips for the NDVI camera: three wheat plots of 10 x 2 m at 100,
        # 150 and 200 plants/m2": counted plots of a crop are the fields themselves; the
        # uncounted plural before the colon is their heading
        return None
    room = (parent.count or 1) - len(parent.refinements)
    if (
        parent.implied_count
        and lists_members
        and clause.mentions
        and (sub.count or 1) > room
        # ("Variety strips ...: Agria, Fontane and Russet Burbank, ..., strips in that order
        # from west to east": the plots said again, no member more)
        and not (plots_again(sub) and len(parent.refinements) >= 2)
    ):
        # "camera plots: Jalapeño, Padrón and California Wonder": as many as listed
        parent.count = len(parent.refinements) + (sub.count or 1)
        room = sub.count or 1
    # "five fields: 2 of maize and 3 of wheat": a listed member may be counted
    listable = lists_members and bool(clause.mentions)
    listed = listable and 1 <= (sub.count or 1) <= room
    follows_parent = clauses[clause.index - 1].refined_parent is None
    if (
        is_reference
        and link.role == "conjunction"
        and follows_parent
        and adds_a_field(clause, parent)
    ):
        is_reference = False  # "three fields of sweet peppers and one of chillies"
    fitting = fits(sub, parent, crop_categories)
    definite = (bool(clause.items) and clause.items[0].norm in definite_words()) or (
        bool(clause.mentions) and definite_before_head(clause, clause.mentions[0])
    )  # "..., with the popping corn between the other two" points back
    if (
        listable
        and (enumerating or (sub.count or 1) > 1)
        and fitting
        and not definite  # "..., the carrots have blight" points back
        and listing(link)
        and (sub.count or 1) > room
        and parent.rest is None
        # ("..., 12 rows per plot, plots laid out east to west": a measure of every
        # plot, and the plots again)
        and not plots_again(sub)
        and not per_plot(sub)
    ):
        # "two fields: sweetcorn, durum wheat and romaine lettuce"
        raise PromptError(
            f"{parent.text!r} announces {parent.count} field(s), but "
            f"{len(parent.refinements) + (sub.count or 1)} or more are listed after it",
            stage="resolve",
            hint="make the count match the list, or drop the count",
        )
    if (
        share_of is not None
        and len(clause.items) == 3
        and (
            parent.implied_count
            or (parent.quantity is not None and parent.count == parent.quantity)
        )
        and not parent.refinements
        and clauses[clause.index - 1].mentions[-1:] == [parent]
    ):
        # "a patchwork of small fruit fields, five or six of them, each ...",
        # "some veg fields, three of them, all young": a vague or unsaid number of
        # fields said again as a count, not a share of them
        parent.count = share_of
        clause.loose, clause.refined_parent = [], parent
        return enumerating
    if (is_reference or listed) and fitting and has_room(parent):
        sub.is_refinement = True
        kind = first.data.get("value") if first is not None else "one"
        if share_of is not None:
            # "four fields, two of them blighted": exactly that many members.
            sub.count = None
            room = (parent.count or 1) - len(parent.refinements)
            parent.refinements.extend([sub] * min(share_of, room))
        elif kind == "rest":
            parent.rest = sub
            # ("The middle one has blight, the other two look fine")
            parent.refinements = [sub if r.unsaid else r for r in parent.refinements]
        elif (at := place_said(first, parent)) is not None:
            # "Three potato fields in a line. The middle one has blight": the
            # member at that place, the ones before it held open
            while len(parent.refinements) < at:
                parent.refinements.append(Mention(clause=clause.index, unsaid=True))
            if at < len(parent.refinements):
                parent.refinements[at] = sub
            else:
                parent.refinements.append(sub)
        elif kind in ("some", "half"):
            # "five fields, some of them diseased": the first half of the members.
            total = parent.count or 1
            share = (total + 1) // 2 if kind == "some" else max(1, total // 2)
            parent.refinements.extend([sub] * min(share, total - len(parent.refinements)))
        elif listed and (sub.count or 1) > 1:
            members, sub.count = sub.count or 1, None
            parent.refinements.extend([sub] * members)
        elif blank := next((r for r in parent.refinements if r.unsaid), None):
            # ("The last one has blight, the first one is fine")
            parent.refinements[parent.refinements.index(blank)] = sub
        else:
            parent.refinements.append(sub)
        clause.mentions, clause.loose = [], []
        clause.refined_parent = parent
        clause.refinement = sub if listed or is_reference else None
        return listed

    return None


def _all_distinct(items: Sequence[Item]) -> bool:
    """Words that only say the fields before differ ("one per variety")."""
    return bool(items) and all(i.role == "distinct" for i in items)

"""Refinements: the members a plural mention lists (issue 8's structure passes).

"Two orchards: one of Gala, one of Fuji", "three fields: wheat, maize and potatoes",
"four fields, two of them blighted", "two vineyards, chardonnay west of riesling":
:func:`apply_refinements` folds each member into the plural mention that announced
it, so the mention stands for that many fields with each member's own words, and
raises a ``PromptError`` when more members are listed than were announced.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._decompose import MentionBuilder
from agrirecipe.resolve._geometry import geometry_nouns
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import link_norm
from agrirecipe.resolve._listed_members import Listing, fits, fold_listed_member
from agrirecipe.resolve._listing import (
    named_again,
    names_varieties_of,
    placed_by_scenery,
)
from agrirecipe.resolve._member_refs import (
    BACK_POINTERS,
    counted_reference,
    member_said_again,
)
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    EACH,
    POINTER_WORDS,
    definite_before_head,
    descriptive_words,
    names_a_variety,
    per_bed,
    same_variety,
    strong_crops,
)

__all__ = ["apply_refinements"]

#: Words after "<number> of" that point back at a plural mention ("two of them").


def apply_refinements(
    clauses: Sequence[Clause], crop_categories: dict[str, str], builder: MentionBuilder
) -> list[Mention]:
    """Fold refinements into their plural mention; return the remaining top-level mentions."""
    _join_of_which(clauses)
    top: list[Mention] = []
    parent: Mention | None = None
    enumerating = False
    for clause in clauses:
        previous = clauses[clause.index - 1] if clause.index else None
        if (
            not clause.items
            and not clause.mentions
            and clause.link is not None
            and clause.link.role in ("separator", "conjunction", "trailer")
        ):
            # ", and potatoes", "(...), then", "onions in the middle, ...": words between
            # members end no listing.
            if previous is not None:
                clause.refined_parent = previous.refined_parent
                clause.refinement = previous.refinement
                if (
                    clause.link.role == "trailer"
                    and not previous.items
                    and not previous.mentions
                    and previous.link is not None
                    and previous.link.role in ("separator", "conjunction")
                ):
                    # "Bing cherries and, to the east, Durondeau pears": a placement
                    # said before the member it places
                    clause.refinement = None
            continue
        if (
            enumerating
            and parent is not None
            and previous is not None
            and previous.refined_parent is parent
            and clause.link is not None
            and clause.link.role in ("relation", "between")
            and len(clause.mentions) == 1
            and definite_before_head(clause, clause.mentions[0])
            and any(named_again(clause.mentions[0], r) for r in parent.refinements)
        ):
            # "three fields: wheat up by the woods, potatoes right next to the wheat, and
            # ...": the member a relation places against, named again; the listing goes on
            again = clause.mentions[0]
            clause.mentions = [next(r for r in parent.refinements if named_again(again, r))]
            clause.refined_parent = parent
            clause.refinement = previous.refinement
            continue
        if (
            parent is not None
            and clause.link is not None
            and clause.link.role in ("separator", "conjunction", "relation")
            and (member := member_said_again(clause, parent)) is not None
        ):
            # "two maize plots, one at 9 plants/m2 and one at 7 plants/m2, the denser plot
            # to the east": a member said already, named again to place or describe it
            said = clause.mentions[0].items if clause.mentions else clause.items
            member.items.extend(i for i in said if i.role in ("stage", "health", "cue"))
            clause.mentions, clause.loose = [], []
            clause.refined_parent, clause.refinement = parent, member
            continue
        if (
            enumerating
            and parent is not None
            and previous is not None
            and previous.refined_parent is parent
            and not clause.mentions
            and clause.items
            and clause.link is not None
            and clause.link.norm not in (".", "!", "?")  # a new sentence ends the listing
            and (
                all(_member_detail(i) for i in clause.items)
                # "Jalapeños hanging dark and shiny", "Spelt furthest away and gone the
                # colour of straw": words about the member, joined by "and"
                # "Conference pears on one side, branches bent with fruit, ...": or by a
                # comma
                or (
                    (clause.link.role == "conjunction" or clause.link.norm == ",")
                    and all(
                        i.role in ("unknown", "filler", "of", "cue", "stage", "health")
                        for i in clause.items
                    )
                )
                # "Conference pears heavy with fruit that is just starting to turn yellow"
                or clause.link.norm in _RELATIVE
                # "Riesling north of it, 25 rows at 2 m": placed against the one before;
                # "Padron peppers along the other side, still flowering": likewise
                or (
                    clause.link.role == "relation"
                    and (
                        clause.items[0].norm in POINTER_WORDS
                        or (
                            clause.items[0].role == "reference"
                            and all(i.role in ("reference", "filler") for i in clause.items)
                        )
                        # "two blocks - Ladyfinger down near the river, Gros Michel up
                        # by the sheds": placed by the scenery
                        or placed_by_scenery(clause)
                    )
                )
                # "two groves, Washington Navel on the north side of the packing shed and
                # Valencia Late ...": a side of the scenery
                or (clause.link.role == "trailer" and placed_by_scenery(clause))
            )
        ):
            # "carrots (75 cm ridges, 2 rows per ridge), onions ...": the listed member's
            # own details; the listing goes on after them.
            clause.refined_parent = parent
            # "field corn, flint corn and popping corn, 8 rows each at 76 cm": for them all
            # ("75 cm ridges, 2 rows on each": each ridge, not each member)
            # ("with white flowers all over the ridges": "all over" is no "all")
            shared = any(
                t.norm in EACH
                for i in clause.items
                if not per_bed(i) and i.role != "filler"
                for t in i.tokens
            )
            # "Two strawberry plots of 10 beds each, Elsanta and Albion, beds 1.3 m ...":
            # measures after the last member of a full list describe them all
            ended = (
                parent.count is not None
                and len({id(r) for r in parent.refinements}) >= parent.count
                and previous.link is not None
                and previous.link.role == "conjunction"
                and all(i.role in ("geometry", "of", "filler") for i in clause.items)
                and any(i.role == "geometry" for i in clause.items)
                # ("Comice, 16 rows, and Durondeau, 12 rows": each member its own)
                and not any(i.role == "geometry" for r in parent.refinements for i in r.items)
                and not any(
                    i.role == "geometry"
                    for c in clauses[: clause.index]
                    if c.refined_parent is parent and c.refinement is not None
                    for i in c.items
                )
            )
            clause.refinement = None if shared or ended else previous.refinement
            continue
        first = _opening(clause.items)
        share_of = counted_reference(clause.items)
        is_reference = share_of is not None or (
            first is not None
            and (
                first.role == "reference"
                or (first.role == "number" and bool(first.data.get("reference")))
            )
        )
        link = clause.link
        joined = link is not None and link.role in ("separator", "conjunction")
        if (
            parent is not None
            and link is not None
            # ("Three apple blocks: Fuji between Cripps Pink and Golden Delicious")
            and link.role in ("relation", "between")
            and clauses[clause.index - 1].refined_parent is parent
            and len(clause.mentions) == 1
            and (
                names_varieties_of(clause.mentions[0], parent)
                # "two plots: a pear orchard, and north of it a strawberry field"
                or (
                    enumerating
                    and not strong_crops(parent)
                    and fits(clause.mentions[0], parent, crop_categories)
                )
            )
        ):
            joined = True  # "two vineyards, chardonnay west of riesling": the next member
        if (
            parent is not None
            and link is not None
            and link.norm == ":"
            and not strong_crops(parent)
            and len(clause.mentions) >= 2
            and all(m.count is not None and m.has_crop for m in clause.mentions)
            and sum(m.count or 0 for m in clause.mentions) == parent.count
        ):
            # "4 fields: 2 wheat 2 corn": counted members said without a comma
            for member in clause.mentions:
                members, member.count = member.count or 1, None
                member.is_refinement = True
                parent.refinements.extend([member] * members)
            clause.mentions, clause.loose = [], []
            clause.refined_parent = parent
            continue
        if (
            parent is not None
            and previous is not None
            and previous.mentions[-1:] == [parent]
            and not parent.refinements
            and _bracketed_variety(clause, parent)
            and clause.index + 1 < len(clauses)
            and link_norm(clauses[clause.index + 1]) == ")"
        ):
            # "2 strawberry fields (sonata)": the variety of them all
            for head in clause.mentions[0].heads:
                builder.add_head(parent, head)
            parent.items.extend(i for i in clause.mentions[0].items if i.role != "head")
            clause.mentions, clause.loose = [], []
            continue
        if (
            parent is not None
            and previous is not None
            and (listed_member := previous.refinement) is not None
            and previous.refined_parent is parent
            and _bracketed_variety(clause, listed_member)
        ):
            # "2 fields: carrots (nantes) & cabbage (savoy)": the listed member's variety
            for head in clause.mentions[0].heads:
                builder.add_head(listed_member, head)
            listed_member.items.extend(i for i in clause.mentions[0].items if i.role != "head")
            clause.mentions, clause.loose = [], []
            clause.refined_parent, clause.refinement = parent, listed_member
            continue
        if parent is not None and joined and len(clause.mentions) <= 1:
            folded = fold_listed_member(
                clauses,
                clause,
                parent,
                Listing(enumerating, first, share_of, is_reference),
                crop_categories,
            )
            if folded is not None:
                enumerating = folded
                continue
        # ("three of wheat on the north side of the farm and three of maize ...": a side
        # of the farm places the member and the listing goes on)
        placement = (
            link is not None
            and link.role == "trailer"
            and not clause.mentions
            and all(i.role in ("of", "filler", "container") for i in clause.items)
        )
        if parent is not None and _member_plot(clause, previous, parent):
            # "Two banana blocks. Dwarf Cavendish, block 50 m by 40 m. Lady Finger, ...":
            # the member's own plot; the listing goes on after it
            assert previous is not None and previous.refinement is not None
            plot = clause.mentions[0]
            for item in plot.items:
                if item in plot.heads:
                    builder.add_head(previous.refinement, item)
                else:
                    previous.refinement.items.append(item)
            clause.mentions = []
            clause.refined_parent, clause.refinement = parent, previous.refinement
            continue
        describing = parent is not None and _describes_plants(clause.mentions)
        if describing and previous is not None:
            clause.refined_parent = previous.refined_parent  # the listing goes on after it
            clause.refinement = previous.refinement
        if not placement and not describing:
            # "imperator on the north side and danvers ..." goes on listing
            enumerating = False
        top.extend(clause.mentions)
        if clause.mentions and not describing:
            # "two apple blocks: Granny ..., fruit bright green ..., and Fuji ...": words
            # about the fruit or plants do not end the listing of the members
            last = clause.mentions[-1]
            if _both_before_a_list(clauses, clause, last):
                last.count = 2  # "both blocks of the vineyard are ripe: Chardonnay ..., ..."
            parent = last if (last.count or 1) >= 2 else None
    for mention in top:
        members = len({id(r) for r in mention.refinements})
        if mention.implied_count and 0 < members < (mention.count or 1):
            # "sensor test strips: a capsicum strip between a tomato strip and ...": an
            # uncounted plural is as many fields as it lists, not one more of no crop
            mention.count = len(mention.refinements)
    return top


def _opening(items: Sequence[Item]) -> Item | None:
    """The word a clause opens with, past "the" and past a word of its own before "one"
    ("the untreated one full of late blight, the sprayed one clean": each "one" a member)."""
    words = [i for i in items if i.norm != "the"]
    if (
        len(words) >= 2
        and items[0].norm == "the"
        and words[0].role in ("unknown", "filler")
        and words[1].norm == "one"
        and bool(words[1].data.get("reference"))
    ):
        return words[1]
    return words[0] if words else None


def _bracketed_variety(clause: Clause, member: Mention) -> bool:
    """Whether a clause opened by a bracket names only a variety of the crop of the
    member listed just before it ("carrots (nantes)")."""
    if clause.link is None or clause.link.norm != "(" or len(clause.mentions) != 1:
        return False
    said = clause.mentions[0]
    crops = strong_crops(said)
    return (
        names_a_variety(said)
        # ("Big Mike (Gros Michel)": the same variety by its other name)
        and (not names_a_variety(member) or same_variety(member, said))
        and bool(crops)
        and crops == strong_crops(member)
        and said.count is None
        and all(h.role == "head" for h in said.heads)
    )


def _describes_plants(mentions: Sequence[Mention]) -> bool:
    """One uncounted mention named only by a word for plants or their parts ("fruit")."""
    if len(mentions) != 1 or mentions[0].count is not None:
        return False
    heads = mentions[0].heads
    return bool(heads) and all(h.norm in descriptive_words() for h in heads)


def _both_before_a_list(clauses: Sequence[Clause], clause: Clause, mention: Mention) -> bool:
    """'both blocks of the vineyard are ripe: Chardonnay ..., Riesling ...': "both" and a
    plural plot of no crop, right before a colon, announce the two fields listed."""
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    return (
        mention.count is None
        and not mention.has_crop
        and any(h.role == "plot" and h.data["value"]["plural"] for h in mention.heads)
        and any(i.norm == "both" for i in mention.items)
        and following is not None
        and link_norm(following) == ":"
    )


def _member_plot(clause: Clause, previous: Clause | None, parent: Mention) -> bool:
    """'Two banana blocks. Dwarf Cavendish, block 50 m by 40 m. Lady Finger, ...': one
    plot of no crop right after a member is that member's plot (merged with it later);
    the listing goes on after it."""
    if previous is None or previous.refined_parent is not parent or previous.refinement is None:
        return False
    if len(clause.mentions) != 1 or link_norm(clause) != ",":
        return False
    plot = clause.mentions[0]
    return (
        plot.count is None
        and not plot.has_crop
        and plot.category is None  # ("..., the cereal plot west of the root plot")
        and not definite_before_head(clause, plot)
        and plot.plot is not None
        and not plot.plot["plural"]
        and not clause.loose
    )


#: Words that open a relative clause about the member just listed.
_RELATIVE = frozenset({"that", "which", "where", "whose"})


def _member_detail(item: Item) -> bool:
    """A word of a listed member's details: "ridges 100 m long", "(75 cm, 2 rows per ridge)",
    "cabbage in the middle one" (the plot named by "one")."""
    return (
        item.role in _MEMBER_DETAIL_ROLES
        or (item.role in ("unknown", "length_unit") and item.norm in (*geometry_nouns(), "cm", "m"))
        or (item.role == "number" and item.norm == "one")
    )


#: Words a listed member's details may hold without naming another field.
_MEMBER_DETAIL_ROLES = frozenset(
    {
        "stage",
        "health",
        "size",
        "geometry",
        "cue",
        "same_size",
        "same_spacing",
        "filler",
        "of",
        "month",
        "season",
    }
)


def _join_of_which(clauses: Sequence[Clause]) -> None:
    """ "three of which are blighted": "which" cut the clause; put it back together."""
    for clause, following in itertools.pairwise(clauses):
        words = [i.role for i in clause.items]
        if (
            words == ["number", "of"]
            and not clause.mentions
            and following.link is not None
            and following.link.norm in BACK_POINTERS
        ):
            clause.items = [*clause.items, following.link, *following.items]
            clause.loose = [*clause.loose, following.link, *following.loose]
            clause.mentions, following.mentions = following.mentions, []
            for mention in clause.mentions:
                mention.clause = clause.index
            following.items, following.loose = [], []

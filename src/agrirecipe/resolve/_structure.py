"""How mentions relate across clauses: shared heads, corrections, refinements.

- *Shared heads*: "navel and valencia orange groves" is two groves; a bare
  variety name gets its crop from the mention it is coordinated with.
- *Corrections*: "cherry tomatoes? no, I mean cherry trees" keeps the trees.
- *Refinements*: "Two orchards: one of Gala, one of Fuji" and "three
  fields: wheat, maize and potatoes" describe the members of a plural mention.
- *Shared attributes*: "ripe wheat and maize", "..., both 2 ha".

Descriptions of plants already named are in ``_descriptions``; mentions that point
back at fields already named ("the carrots ...", "a carrot field, nantes variety") in
``_coreference``. The small mention tests both use are public here.
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Sequence
from typing import Any

from agrirecipe._errors import PromptError
from agrirecipe.resolve._decompose import Clause, Mention, MentionBuilder
from agrirecipe.resolve._geometry import geometry_nouns
from agrirecipe.resolve._lexicon import Item, vocabulary
from agrirecipe.resolve._relations import listing

__all__ = [
    "EACH",
    "another_field",
    "apply_corrections",
    "apply_each_side",
    "apply_plural_counts",
    "apply_refinements",
    "attribute_of",
    "definite_before_head",
    "definite_words",
    "descriptive_words",
    "drop_negated",
    "first_word",
    "has_room",
    "names_a_variety",
    "one_of_the",
    "per_bed",
    "promote_weak_varieties",
    "pronoun_one",
    "raise_conflicts",
    "same_variety",
    "share_counted_fields",
    "share_leading_attributes",
    "share_trailing_attributes",
    "strong_crops",
]


def strong_crops(mention: Mention) -> set[str]:
    return {crop for crop, _, weak in mention.interpretations or () if not weak}


def promote_weak_varieties(clauses: Sequence[Clause], builder: MentionBuilder) -> None:
    """A clause holding only a weak variety name ("navel and valencia oranges") gets a head.

    The crop comes from the mention the clause is coordinated with (the next
    clause, joined by "and"), else from the nearest earlier mention.
    """
    for position, clause in enumerate(clauses):
        _fold_described_plants(clause)
        if clause.mentions:
            _promote_into_plot(clauses, clause)
            continue
        weak = [item for item in clause.loose if item.role == "weak_variety"]
        if not weak:
            continue
        neighbours: list[Mention] = []
        following = clauses[position + 1] if position + 1 < len(clauses) else None
        if (
            following is not None
            and following.link is not None
            # "navel and valencia oranges"; "Sonata in 10 beds north of Malling Centenary"
            and following.link.role in ("conjunction", "relation", "between")
            and following.mentions
        ):
            neighbours.append(following.mentions[0])
        neighbours += [m for c in reversed(clauses[:position]) for m in reversed(c.mentions)]
        for neighbour in neighbours:
            crops = strong_crops(neighbour)
            senses = [s for s in weak[0].senses_of("variety") if s.crop in crops]
            if not senses:
                continue
            mention = _promote(clause, weak[0], senses[0])
            if neighbour is (following.mentions[0] if following and following.mentions else None):
                mention.plot = neighbour.plot
            break
        else:
            crops = {s.crop for s in weak[0].senses_of("variety") if s.crop}
            in_list = clause.link is not None and (listing(clause.link) or clause.link.norm == ":")
            at = clause.loose.index(weak[0])
            # "half acre of russets": what a size or a plot is "of" is a crop
            planted = at > 0 and clause.loose[at - 1].role == "of"
            if len(crops) == 1 and planted:
                _promote(clause, weak[0], weak[0].senses_of("variety")[0])
            elif len(crops) == 1 and weak[0].tokens[0].capitalised and in_list:
                # "west to east: Lollo, then Imperator carrots": a capitalised name in a
                # list of fields is its variety even when no field beside it is its crop
                _promote(clause, weak[0], weak[0].senses_of("variety")[0])


def _fold_described_plants(clause: Clause) -> None:
    """ "Sonata with grey mould furring the fruit": after a weak variety name, a mention
    made only of words for plants or fruit describes that variety's field; its words
    become the clause's loose words so the name can head the clause."""
    weak = [
        i
        for i in clause.items
        if i.role == "weak_variety" or (i.role == "filler" and i.senses_of("variety"))
    ]
    if not weak or not clause.mentions:
        return
    words = descriptive_words()
    if not all(h.norm in words for m in clause.mentions for h in m.heads):
        return
    first = min(h.start for m in clause.mentions for h in m.heads)
    if weak[0].start > first:
        return
    loose = {id(i): i for i in clause.loose}
    for mention in clause.mentions:
        for head in mention.heads:
            head.role = "filler"
        loose.update((id(i), i) for i in mention.items)
    clause.loose = sorted(loose.values(), key=lambda i: i.start)
    clause.mentions = []
    weak[0].role = "weak_variety"


def _promote_into_plot(clauses: Sequence[Clause], clause: Clause) -> None:
    """ "second plot of Sonata", "Sonata in the open ground": a weak variety name right
    after a crop-less plot's "of", or opening the plot's clause, names the plot's crop
    when an earlier field grows that crop."""
    if len(clause.mentions) != 1:
        return
    mention = clause.mentions[0]
    if mention.has_crop or mention.plot is None or mention.category is not None:
        return
    ordered = sorted(clause.items, key=lambda i: i.start)
    for index, item in enumerate(ordered):
        opens = index == 0 and item.tokens[0].capitalised
        if item.role not in ("weak_variety", "filler") or not (
            opens or (index > 0 and ordered[index - 1].role == "of")
        ):
            continue
        named = {c for c2 in clauses[: clause.index] for m in c2.mentions for c in strong_crops(m)}
        senses = [s for s in item.senses_of("variety") if s.crop in named]
        if senses:
            item.role = "head"
            item.data["promoted"] = True
            if item not in mention.items:
                mention.items.append(item)
            mention.heads.append(item)
            mention.interpretations = [(str(senses[0].crop), str(senses[0].value), False)]
        return


def _promote(clause: Clause, item: Item, sense: Any) -> Mention:
    """Make a weak variety name the head of its clause's one mention."""
    item.role = "head"
    item.data["promoted"] = True
    mention = Mention(clause=clause.index)
    mention.items = [i for i in clause.loose if i is not item]
    mention.heads.append(item)
    mention.items.append(item)
    mention.interpretations = [(str(sense.crop), str(sense.value), False)]
    clause.mentions, clause.loose = [mention], []
    return mention


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
            fields_named = any(not h.data["value"]["individual"] for h in plots)
            if mention.count is None and mention.quantity is not None:
                # "several vegetable fields", "lots of vegetables": fields; "lots of grapes":
                # many vines in one vineyard; "a few beds of Cos": one field of beds.
                one_field = bool(plots) and plots[-1].data["value"].get("one_field")
                if one_field and mention.has_crop:
                    continue
                if fields_named or (mention.category is not None and not mention.has_crop):
                    mention.count = mention.quantity
                continue
            spec = plots[-1].data["value"] if plots else {}
            if mention.count is not None or not spec.get("plural") or spec.get("individual"):
                continue
            if spec.get("one_field") and mention.has_crop:
                continue  # "Elsanta strawberry beds": one field of beds
            first = first_word(mention)
            if first is not None and first.norm in definite:
                continue
            if definite_before_head(clause, mention):
                continue  # "a quick rundown of the plots. Plot 1: ..."
            link = clause.link if index == 0 else None
            if link is not None and link.role == "separator":
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


def apply_corrections(clauses: Sequence[Clause]) -> list[str]:
    """Drop the mention a correction ("no, I mean ...") replaces; return what was dropped."""
    dropped: list[str] = []
    for position, clause in enumerate(clauses):
        if not clause.mentions:
            continue
        first_head = clause.mentions[0].heads[0]
        corrected = any(
            item.role == "correction" and item.start < first_head.start
            for item in clause.mentions[0].items
        ) or _correction_before(clauses, position)
        if not corrected:
            continue
        for earlier in reversed(clauses[:position]):
            if earlier.mentions:
                new, old = clause.mentions[0], earlier.mentions[-1]
                if (
                    not new.has_crop
                    and new.category is None
                    and new.plot is not None
                    and old.has_crop
                    and len(clause.mentions) == 1
                ):
                    # "the Valencia groove (sorry, grove)": only the plot word is
                    # corrected; the crop named stays
                    plots = [h for h in old.heads if h.role == "plot"]
                    old.heads = [h for h in old.heads if h.role != "plot"] + new.heads
                    old.items = [i for i in old.items if i not in plots] + [
                        i for i in new.items if i.role != "correction"
                    ]
                    old.plot = new.plot
                    clause.mentions = []
                    dropped.append(" ".join(h.raw for h in plots) or new.text)
                    break
                dropped.append(earlier.mentions.pop().text)
                while earlier.mentions and earlier.mentions[-1].continued:
                    dropped.append(earlier.mentions.pop().text)
                break
    return dropped


def _correction_before(clauses: Sequence[Clause], position: int) -> bool:
    """A correction word alone in the clause right before ("no, I mean, ...")."""
    if position == 0:
        return False
    previous = clauses[position - 1]
    return not previous.mentions and any(i.role == "correction" for i in previous.loose)


def first_word(mention: Mention) -> Item | None:
    ordered = sorted(mention.items, key=lambda item: item.start)
    return ordered[0] if ordered else None


def _fits(sub: Mention, parent: Mention, crop_categories: dict[str, str]) -> bool:
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


def has_room(parent: Mention) -> bool:
    """Whether a counted plural can take another listed member."""
    return parent.rest is None and len(parent.refinements) < (parent.count or 1)


def apply_refinements(clauses: Sequence[Clause], crop_categories: dict[str, str]) -> list[Mention]:
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
                        clause.items[0].norm in _POINTERS
                        or (
                            clause.items[0].role == "reference"
                            and all(i.role in ("reference", "filler") for i in clause.items)
                        )
                    )
                )
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
        first = next((i for i in clause.items if i.norm != "the"), None)
        share_of = _counted_reference(clause.items)
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
            and link.role == "relation"
            and clauses[clause.index - 1].refined_parent is parent
            and len(clause.mentions) == 1
            and (
                _names_varieties_of(clause.mentions[0], parent)
                # "two plots: a pear orchard, and north of it a strawberry field"
                or (
                    enumerating
                    and not strong_crops(parent)
                    and _fits(clause.mentions[0], parent, crop_categories)
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
        if parent is not None and joined and len(clause.mentions) <= 1:
            assert link is not None
            sub = (
                clause.mentions[0]
                if clause.mentions
                else Mention(items=list(clause.loose), clause=clause.index)
            )
            # A generic plural mention followed by ':' lists its members; so does a
            # plural crop followed by its varieties ("two beds of lettuce, lollo rosso
            # and bibb").
            if (
                parent.quantity is not None
                and parent.count == parent.quantity
                and not parent.refinements
                and link.norm == ","
                and len(vague := _listed(clauses, clause.index)) >= 2
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
                or (link.norm == "," and _lists_exactly(clauses, clause.index, parent.count))
                # "... on two bed plots. Lollo Rosso: 4 beds ... Beside it, carrots: ..."
                or (
                    link.norm == "."
                    and _lists_exactly(clauses, clause.index, parent.count, to_the_end=True)
                )
            )
            lists_members = lists_members or (
                _names_varieties_of(sub, parent) and (enumerating or link.role == "separator")
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
            named_before = [m for c in clauses[: parent.clause] for m in c.mentions]
            if clause.mentions and (
                any(
                    same_variety(r, sub)
                    # "two different fruits: apples and apples" still lists two members
                    or (link.role == "separator" and not parent.distinct and _names_again(r, sub))
                    for r in parent.refinements
                )
                # "centenary & albion strawberries, 2 fields, albion south of centenary":
                # the count says again how many fields were named; the varieties after it
                # are those fields named again
                or (names_a_variety(sub) and any(same_variety(m, sub) for m in named_before))
            ):
                # "..., Valencia east of Hamlin", "bintje spuds & nantes carrots, carrots
                # east of the spuds": a member named again
                lists_members = False
            room = (parent.count or 1) - len(parent.refinements)
            if (
                parent.implied_count
                and lists_members
                and clause.mentions
                and (sub.count or 1) > room
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
                and _adds_a_field(clause, parent)
            ):
                is_reference = False  # "three fields of sweet peppers and one of chillies"
            fits = _fits(sub, parent, crop_categories)
            definite = (bool(clause.items) and clause.items[0].norm in definite_words()) or (
                bool(clause.mentions) and definite_before_head(clause, clause.mentions[0])
            )  # "..., with the popping corn between the other two" points back
            if (
                listable
                and (enumerating or (sub.count or 1) > 1)
                and fits
                and not definite  # "..., the carrots have blight" points back
                and listing(link)
                and (sub.count or 1) > room
                and parent.rest is None
            ):
                # "two fields: sweetcorn, durum wheat and romaine lettuce"
                raise PromptError(
                    f"{parent.text!r} announces {parent.count} field(s), but "
                    f"{len(parent.refinements) + (sub.count or 1)} or more are listed after it",
                    stage="resolve",
                    hint="make the count match the list, or drop the count",
                )
            if (is_reference or listed) and fits and has_room(parent):
                sub.is_refinement = True
                kind = first.data.get("value") if first is not None else "one"
                if share_of is not None:
                    # "four fields, two of them blighted": exactly that many members.
                    sub.count = None
                    room = (parent.count or 1) - len(parent.refinements)
                    parent.refinements.extend([sub] * min(share_of, room))
                elif kind == "rest":
                    parent.rest = sub
                elif kind in ("some", "half"):
                    # "five fields, some of them diseased": the first half of the members.
                    total = parent.count or 1
                    share = (total + 1) // 2 if kind == "some" else max(1, total // 2)
                    parent.refinements.extend([sub] * min(share, total - len(parent.refinements)))
                elif listed and (sub.count or 1) > 1:
                    members, sub.count = sub.count or 1, None
                    parent.refinements.extend([sub] * members)
                else:
                    parent.refinements.append(sub)
                clause.mentions, clause.loose = [], []
                clause.refined_parent = parent
                clause.refinement = sub if listed or is_reference else None
                enumerating = listed
                continue
        placement = link is not None and link.role == "trailer" and not clause.items
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
            parent = last if (last.count or 1) >= 2 else None
    for mention in top:
        members = len({id(r) for r in mention.refinements})
        if mention.implied_count and 0 < members < (mention.count or 1):
            # "sensor test strips: a capsicum strip between a tomato strip and ...": an
            # uncounted plural is as many fields as it lists, not one more of no crop
            mention.count = len(mention.refinements)
    return top


def per_bed(item: Item) -> bool:
    """A measure whose "each" is each bed's ("2 rows on each")."""
    return item.role == "geometry" and any(m.key == "rows_per_bed" for m in item.data["geometry"])


def _describes_plants(mentions: Sequence[Mention]) -> bool:
    """One uncounted mention named only by a word for plants or their parts ("fruit")."""
    if len(mentions) != 1 or mentions[0].count is not None:
        return False
    heads = mentions[0].heads
    return bool(heads) and all(h.norm in descriptive_words() for h in heads)


#: Words that open a relative clause about the member just listed.
_RELATIVE = frozenset({"that", "which", "where", "whose"})

#: Pronouns after a relation word that point back at the member before.
_POINTERS = frozenset({"it", "them", "this", "that", "these", "those"})

#: Words that give a listed member's details to every member listed.
EACH = frozenset({"each", "all", "both"})


def _member_detail(item: Item) -> bool:
    """A word of a listed member's details: "ridges 100 m long", "(75 cm, 2 rows per ridge)"."""
    return item.role in _MEMBER_DETAIL_ROLES or (
        item.role in ("unknown", "length_unit") and item.norm in (*geometry_nouns(), "cm", "m")
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


def _lists_exactly(
    clauses: Sequence[Clause], start: int, count: int | None, *, to_the_end: bool = False
) -> bool:
    """Whether the clauses from ``start`` to the end of the sentence (or of the prompt)
    name exactly ``count`` single fields, joined as a list (commas and "and")."""
    named = _listed(clauses, start, to_the_end=to_the_end)
    return (
        count is not None
        and count >= 2
        and len(named) == count
        and all((m.count or 1) == 1 for m in named)
    )


def _listed(clauses: Sequence[Clause], start: int, *, to_the_end: bool = False) -> list[Mention]:
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
                # ("two 0.25 ha plots, carrots north of onions": the list placed in itself)
                or (link.role == "relation" and not _bare_crop_first(clause))
            )
        ):
            break
        # fields named again ("the Comice") or plot words alone ("Beds and ridges run
        # NW-SE") name no new field
        named.extend(
            m for m in clause.mentions if m.has_crop and not definite_before_head(clause, m)
        )
    return named


def _bare_crop_first(clause: Clause) -> bool:
    """Whether the clause opens with a crop named without an article ("onions")."""
    return (
        bool(clause.mentions)
        and bool(clause.items)
        and clause.items[0] in clause.mentions[0].heads
        and clause.mentions[0].has_crop
    )


def names_a_variety(mention: Mention) -> bool:
    """Whether the mention names a variety (not only a crop)."""
    return any(v is not None for _, v, weak in mention.interpretations or () if not weak)


def _names_again(member: Mention, sub: Mention) -> bool:
    """Whether ``sub`` (no count, no variety, no plot of its own) names ``member``'s crop."""
    crops = strong_crops(sub)
    return (
        sub.count is None
        and bool(crops)
        and crops == strong_crops(member)
        and not names_a_variety(sub)
        and not any(h.role == "plot" for h in sub.heads)
    )


def _names_varieties_of(sub: Mention, parent: Mention) -> bool:
    """``sub`` names, without a count of its own, a variety of the crop ``parent`` names."""
    crops = strong_crops(parent)
    if not crops and parent.plot is not None and len(parent.plot["options"]) == 1:
        crops = {parent.plot["options"][0]}  # "two vineyards, chardonnay ..."
    named = {(c, v) for c, v, weak in sub.interpretations or () if v is not None and not weak}
    # "3 cherry blocks: Lapins, Regina and Bing": "cherry" may also be a tomato variety;
    # the crop the members name decides which reading the parent has
    common = crops & {c for c, _ in named}
    return (
        (sub.count is None or (sub.count == 1 and pronoun_one(sub)))
        and len(common) == 1
        and bool(named)
        and {c for c, _ in named} <= crops
        and not any(v is not None for c, v, _ in parent.interpretations or () if c in common)
    )


def pronoun_one(mention: Mention) -> bool:
    """'a spring wheat one', 'the Roma one': "one" after the head stands for a field."""
    heads = [h.start for h in mention.heads]
    return bool(heads) and any(i.norm == "one" and i.start > max(heads) for i in mention.items)


def another_field(clauses: Sequence[Clause], clause: Clause, mention: Mention) -> bool:
    """ "; Padron plot north of it", "second plot of Sonata": a plot placed against the
    field before it, or called a second one, is a new field, not that field again."""
    if not any(h.role == "plot" for h in mention.heads):
        return False
    if any(i.norm in _ORDINAL_NEW for i in clause.items):
        return True
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    return (
        clause.mentions[-1:] == [mention]
        and following is not None
        and following.link is not None
        and following.link.role == "relation"
        and not following.mentions
        and bool(following.items)
        and all(i.norm in _POINTERS or i.role == "reference" for i in following.items)
    )


_ORDINAL_NEW = frozenset({"second", "third", "fourth", "another", "2nd", "3rd", "4th", "new"})


def one_of_the(clause: Clause, mention: Mention) -> bool:
    """'a ladder against one of the pear trees': one of a field's own plants or rows."""
    head = min(h.start for h in mention.heads)
    before = [i for i in clause.items if i.end <= head]
    return (
        len(before) >= 3
        and before[-3].norm == "one"
        and before[-2].role == "of"
        and before[-1].norm in definite_words()
    )


def _adds_a_field(clause: Clause, parent: Mention) -> bool:
    """'... and one of chillies' after a plural that named its crop: one more field.

    "one of" followed by a crop or variety (not "them"), joined by "and" to a plural
    mention that already says what its fields are, counts a further field.
    """
    words = [i for i in clause.items if i.norm != "the"]
    if len(words) < 3 or words[0].role != "number" or words[1].role != "of":
        return False
    return words[2].role == "head" and bool(strong_crops(parent))


#: Words after "<number> of" that point back at a plural mention ("two of them").
_BACK_POINTERS = frozenset({"them", "which", "these", "those", "the fields", "the plots"})


def _join_of_which(clauses: Sequence[Clause]) -> None:
    """ "three of which are blighted": "which" cut the clause; put it back together."""
    for clause, following in itertools.pairwise(clauses):
        words = [i.role for i in clause.items]
        if (
            words == ["number", "of"]
            and not clause.mentions
            and following.link is not None
            and following.link.norm in _BACK_POINTERS
        ):
            clause.items = [*clause.items, following.link, *following.items]
            clause.loose = [*clause.loose, following.link, *following.loose]
            clause.mentions, following.mentions = following.mentions, []
            for mention in clause.mentions:
                mention.clause = clause.index
            following.items, following.loose = [], []


def _counted_reference(items: Sequence[Item]) -> int | None:
    """The count of "<number> of them" / "two of which" opening a clause, else None."""
    words = [i for i in items if i.norm != "the"]
    if len(words) < 3 or words[0].role != "number" or words[1].role != "of":
        return None
    if words[2].norm not in _BACK_POINTERS:
        return None
    value = float(words[0].data.get("value", 0))
    if value != int(value) or value < 1:
        return None
    return int(value)


_SHARED_ROLES = ("stage", "health", "cue")


def share_leading_attributes(clauses: Sequence[Clause]) -> None:
    """'harvest-ready maize and wheat': a stage or health word before the first of a list
    of bare crop names ("and wheat", ", wheat") describes each of them.

    A listed mention is bare when its head is its first word (no article, count or
    attribute of its own before it); a mention that states the attribute keeps its own.
    """
    for position, clause in enumerate(clauses):
        if len(clause.mentions) != 1:
            continue
        first = clause.mentions[0]
        start = min(h.start for h in first.heads)
        leading = [i for i in first.items if i.role in _SHARED_ROLES and i.start < start]
        if not leading:
            continue
        for following in clauses[position + 1 :]:
            if not listing(following.link) or len(following.mentions) != 1:
                break
            mention = following.mentions[0]
            if not following.items or following.items[0] is not mention.heads[0]:
                break
            own = {i.role for i in mention.items}
            lent = [i for i in leading if i.role not in own]
            mention.items.extend(lent)
            mention.borrowed.extend(lent)


def share_trailing_attributes(clauses: Sequence[Clause]) -> None:
    """'durondeau pear trees and fuji apple trees covered in blossom': a stage or health
    word after the second of two bare crop names joined by "and" describes both.

    Both mentions must be bare (their head is their first word) and the first must
    state no such attribute of its own ("young carrots and potatoes in bloom" keeps
    the carrots young).
    """
    for position in range(1, len(clauses)):
        clause, previous = clauses[position], clauses[position - 1]
        link = clause.link
        if link is None or link.role != "conjunction":
            continue
        if len(clause.mentions) != 1 or len(previous.mentions) != 1:
            continue
        first, second = previous.mentions[0], clause.mentions[0]
        if not _bare(previous, first) or not _bare(clause, second):
            continue
        last_head = max(h.start for h in second.heads)
        # "apples and pears at 3.5 x 1 m": a spacing after both is both fields'
        trailing = [
            i
            for i in second.items
            if (i.role in _SHARED_ROLES or _spacing(i)) and i.start > last_head
        ]
        own = {attribute_of(i) for i in first.items}
        # "cherry tomatoes with the trusses already red, and peppers, still only
        # flowering": the tomatoes' own cue keeps their stage
        first.items.extend(i for i in trailing if attribute_of(i) not in own)


def _spacing(item: Item) -> bool:
    """A measure of how rows and plants are spaced ("at 3.5 x 1 m"), nothing counted."""
    spacings = ("row_spacing_m", "in_row_spacing_m", "plants_per_ha", "bed_width_m")
    return item.role == "geometry" and all(
        m.key in spacings and not m.share for m in item.data["geometry"]
    )


def attribute_of(item: Item) -> str:
    """The attribute an item states: its role, or for a visual cue the cue's attribute."""
    cue = item.data.get("cue") if item.role == "cue" else None
    return str(cue.attribute) if cue is not None else item.role


def _bare(clause: Clause, mention: Mention) -> bool:
    words = [i for i in clause.items if i.role != "filler" or i in mention.heads]
    return bool(words) and words[0] is mention.heads[0] and mention.count is None


def apply_each_side(clauses: Sequence[Clause]) -> None:
    """'a vineyard with a strawberry field on each side': that field stands twice."""
    for position, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role != "trailer" or link.data.get("value") != "each_side":
            continue
        before = [m for c in clauses[:position] for m in c.mentions]
        if len(before) >= 2 and (before[-1].count or 1) == 1 and not before[-1].refinements:
            before[-1].count = 2


def raise_conflicts(clauses: Sequence[Clause]) -> None:
    """Raise the first contradiction of a mention still standing after corrections."""
    for clause in clauses:
        for mention in clause.mentions:
            if mention.conflict is not None:
                raise mention.conflict


_ANY = frozenset({"any", "a", "an", "the", "some"})


def share_counted_fields(mentions: Sequence[Mention]) -> list[Mention]:
    """'6 fields in total, half vegetables half fruit', '4 fields, a mix of fruit and
    vegetables': categories named after a counted generic mention say what its fields
    are; they are not more fields.

    The counted mention's fields are shared among the categories that follow it
    (bare categories, no count, crop or plot of their own): by their fractions
    ("half ... half ...") when those add up, evenly otherwise.
    """
    result: list[Mention] = []
    index = 0
    while index < len(mentions):
        mention = mentions[index]
        index += 1
        result.append(mention)
        if (
            not mention.count
            or mention.count < 2
            or mention.has_crop
            or mention.category is not None
            or mention.refinements
            or (mention.plot is not None and mention.plot["options"])
        ):
            continue
        shares: list[Mention] = []
        while index + len(shares) < len(mentions):
            candidate = mentions[index + len(shares)]
            if (
                candidate.category is None
                or candidate.has_crop
                or candidate.count is not None
                or candidate.plot is not None
                or candidate.refinements
            ):
                break
            shares.append(candidate)
        if not 2 <= len(shares) <= mention.count:
            continue
        fractions = [
            sum(float(i.data.get("value", 0)) for i in share.items if i.role == "fraction")
            for share in shares
        ]
        counts = [round(mention.count * f) for f in fractions]
        if sum(counts) != mention.count or 0 in counts:
            base, extra = divmod(mention.count, len(shares))
            counts = [base + (1 if k < extra else 0) for k in range(len(shares))]
        mention.refinements = [s for s, n in zip(shares, counts, strict=True) for _ in range(n)]
        for share in shares:
            share.is_refinement = True
        index += len(shares)
    return result


def drop_negated(clauses: Sequence[Clause]) -> list[str]:
    """'no crops or anything', 'no apples, just pears': a negated mention asks for no field.

    A mention whose head follows a negation word ("no", "not", "without", with
    at most an article or "any" between) is removed from its clause. Returns
    the texts dropped.
    """
    dropped: list[str] = []
    for clause in clauses:
        for mention in list(clause.mentions):
            head = min(mention.heads, key=lambda h: h.start)
            before = [i for i in clause.items if i.end <= head.start]
            while before and before[-1].norm in _ANY:
                before.pop()
            if before and before[-1].role == "negation":
                clause.mentions.remove(mention)
                dropped.append(mention.text)
    return dropped


@functools.lru_cache(maxsize=1)
def descriptive_words() -> frozenset[str]:
    vocab = vocabulary()
    return frozenset(
        str(word) for word in (*vocab["plant_part_words"], *vocab["descriptive_heads"])
    )


@functools.lru_cache(maxsize=1)
def definite_words() -> frozenset[str]:
    return frozenset(str(word) for word in vocabulary()["definite_words"])


def definite_before_head(clause: Clause, mention: Mention) -> bool:
    """Whether the word right before the mention's first head is "the", "its"... or a
    vague quantity of the plants of a crop named ("a few peppers have scabby spots")."""
    head = min(mention.heads, key=lambda h: h.start)
    before = [i for i in clause.items if i.end <= head.start]
    return bool(before) and (
        before[-1].norm in definite_words() or bool(before[-1].data.get("counts_plants"))
    )


def same_variety(earlier: Mention, mention: Mention) -> bool:
    """Both name the same variety outright (not a weak reading) and ``mention`` no count."""
    if mention.count is not None:
        return False

    def named(m: Mention) -> set[tuple[str, str]]:
        return {(c, v) for c, v, weak in m.interpretations or () if v is not None and not weak}

    return bool(named(mention)) and named(mention) <= named(earlier)

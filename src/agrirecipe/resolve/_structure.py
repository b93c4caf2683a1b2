"""How mentions relate across clauses: shared heads, corrections, refinements.

- *Shared heads*: "navel and valencia orange groves" is two groves (a bare weak
  variety name gets its crop in ``_weak_varieties``).
- *Corrections*, alternatives, choices left open and negations (mentions the text
  takes back) are read in ``_retractions``.
- *Refinements* ("Two orchards: one of Gala, one of Fuji") are read in
  ``_refinements``.
- *Shared attributes*: "ripe wheat and maize", "..., both 2 ha".
- *Counts* of plural mentions and lists ("carrot fields", "wheat and maize, 2 fields
  each") are read in ``_counts``.

Descriptions of plants already named are in ``_descriptions``; mentions that point
back at fields already named ("the carrots ...", "a carrot field, nantes variety") in
``_coreference``. The small mention tests both use are public here.
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, vocabulary
from agrirecipe.resolve._links import link_norm, listing
from agrirecipe.resolve._mentions import Clause, Mention

__all__ = [
    "EACH",
    "POINTER_WORDS",
    "another_field",
    "apply_each_side",
    "attribute_of",
    "definite_before_head",
    "definite_words",
    "describing_verbs",
    "descriptive_words",
    "first_word",
    "has_room",
    "names_a_group",
    "names_a_variety",
    "one_of_the",
    "per_bed",
    "plant_part_words",
    "pronoun_one",
    "raise_conflicts",
    "said_of_all_plots",
    "same_variety",
    "share_counted_fields",
    "share_leading_attributes",
    "share_trailing_attributes",
    "strong_crops",
    "with_plot_noun",
]


def with_plot_noun(mentions: Sequence[Mention], noun: object) -> list[Mention]:
    """The mentions named by the plot noun ``noun`` ("orchard", "field"), in order: the
    fields a bare plot noun said again may name."""
    return [m for m in mentions if m.plot is not None and m.plot.get("noun") == noun]


def strong_crops(mention: Mention) -> set[str]:
    return {crop for crop, _, weak in mention.interpretations or () if not weak}


def names_a_group(mention: Mention) -> bool:
    """Whether the mention says a group of crops without naming one: a category ("cereals",
    "veg") or a plot that says its crops ("vineyard", "root veg", "fruit trees")."""
    return mention.category is not None or bool((mention.plot or {}).get("options"))


def first_word(mention: Mention) -> Item | None:
    ordered = sorted(mention.items, key=lambda item: item.start)
    return ordered[0] if ordered else None


def has_room(parent: Mention) -> bool:
    """Whether a counted plural can take another listed member."""
    return parent.rest is None and len(parent.refinements) < (parent.count or 1)


def per_bed(item: Item) -> bool:
    """A measure whose "each" is each bed's ("2 rows on each")."""
    return item.role == "geometry" and any(m.key == "rows_per_bed" for m in item.data["geometry"])


#: Pronouns after a relation word that point back at the member before.
POINTER_WORDS = frozenset({"it", "them", "this", "that", "these", "those"})

#: Words that give a listed member's details to every member listed.
EACH = frozenset({"each", "all", "both"})


def named_varieties(mention: Mention) -> set[tuple[str, str | None, bool]]:
    """The (crop, variety, weak) readings of the mention that name a variety strongly."""
    return {i for i in mention.interpretations or () if i[1] is not None and not i[2]}


def names_a_variety(mention: Mention) -> bool:
    """Whether the mention names a variety (not only a crop)."""
    return bool(named_varieties(mention))


def said_of_all_plots(mention: Mention) -> bool:
    """'in both blocks', 'all the plots': "both" or "all" right before a plural plot noun
    the mention is headed by."""
    ordered = sorted(mention.items, key=lambda i: i.start)
    return any(
        a.norm in ("both", "all")
        and b.role == "plot"
        and b in mention.heads
        and b.norm.endswith("s")
        for a, b in itertools.pairwise(ordered)
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
        and all(i.norm in POINTER_WORDS or i.role == "reference" for i in following.items)
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
            # ("ripe wheat, maize in tassel": a cue of its own says its stage)
            own = {attribute_of(i) for i in mention.items}
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
        # ("the corn is ripe and the lettuce has mildew": two sentences, each its own; not
        # "the corn and the lettuce have mildew")
        said_of_one = bool(trailing) and any(
            i.norm in _SINGULAR_VERBS and last_head < i.start < min(t.start for t in trailing)
            for i in clause.items
        )
        described = any(i.role in _SHARED_ROLES for i in first.items)
        if said_of_one or described:
            continue
        # "cherry tomatoes with the trusses already red, and peppers, still only
        # flowering": the tomatoes' own cue keeps their stage
        first.items.extend(i for i in trailing if attribute_of(i) not in own)


#: Verbs that say something of one field ("the lettuce has mildew").
_SINGULAR_VERBS = frozenset({"is", "has", "was", "looks", "shows", "s"})


def _spacing(item: Item) -> bool:
    """A measure of how rows and plants are spaced ("at 3.5 x 1 m"), nothing counted."""
    spacings = ("row_spacing_m", "in_row_spacing_m", "plants_per_ha", "bed_width_m", "alley_m")
    return item.role == "geometry" and all(
        m.key in spacings and not m.share for m in item.data["geometry"]
    )


def attribute_of(item: Item) -> str:
    """The attribute an item states: its role, or for a visual cue the cue's attribute."""
    cue = item.data.get("cue") if item.role == "cue" else None
    return str(cue.attribute) if cue is not None else item.role


def _bare(clause: Clause, mention: Mention) -> bool:
    words = [i for i in clause.items if i.role != "filler" or i in mention.heads]
    # (any head first: "navel oranges" holds the heads "oranges" and "navel")
    return bool(words) and any(words[0] is h for h in mention.heads) and mention.count is None


def apply_each_side(clauses: Sequence[Clause]) -> None:
    """'a vineyard with a strawberry field on each side': that field stands twice."""
    for position, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role != "trailer" or link.data.get("value") != "each_side":
            continue
        said = clauses[position - 1].items if position else []
        if said and "scenery" in max(said, key=lambda i: i.start).data:
            continue  # "... with hawthorn hedges on both sides": the hedges' sides
        if said and _a_headland(max(said, key=lambda i: i.start)):
            continue  # "a cabbage field with a 5 m headland on each side": the headland's
        following = clauses[position + 1] if position + 1 < len(clauses) else None
        if following is not None and link_norm(following) == ":" and following.mentions:
            continue  # ("Veg on both sides of the maize: onions to the west ..., cabbages
            # to the east": each side's field named after the colon)
        before = [m for c in clauses[:position] for m in c.mentions]
        if len(before) >= 2 and (before[-1].count or 1) == 1 and not before[-1].refinements:
            before[-1].count = 2
        elif position:
            # "3 fields: maize in the middle, potatoes either side of it": a member of a
            # counted list with room left stands for two of its fields
            heading = clauses[position - 1].refined_parent
            member = clauses[position - 1].refinement
            if (
                heading is not None
                and member is not None
                and has_room(heading)
                and (member.count or 1) == 1
                and sum(1 for r in heading.refinements if r is member) == 1
            ):
                at = next(i for i, r in enumerate(heading.refinements) if r is member)
                heading.refinements.insert(at, member)
                member.count = 2


def _a_headland(item: Item) -> bool:
    """Whether the item is a measure of a field's headland ("a 5 m headland")."""
    return item.role == "geometry" and any(
        match.key == "headland_m" for match in item.data.get("geometry", ())
    )


def raise_conflicts(clauses: Sequence[Clause]) -> None:
    """Raise the first contradiction of a mention still standing after corrections."""
    for clause in clauses:
        for mention in clause.mentions:
            if mention.conflict is not None:
                raise mention.conflict


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


@functools.lru_cache(maxsize=1)
def plant_part_words() -> frozenset[str]:
    """Words for the fruit of a crop ("fruit", "berries", "the first hands")."""
    return frozenset(str(word) for word in vocabulary()["plant_part_words"])


@functools.lru_cache(maxsize=1)
def describing_verbs() -> frozenset[str]:
    """Verbs that say what plants look like or do ("have", "are", "wilting")."""
    return frozenset(str(word) for word in vocabulary()["describing_verbs"])


@functools.lru_cache(maxsize=1)
def descriptive_words() -> frozenset[str]:
    """Words for the plants of a field or their parts ("fruit", "vines", "leaves")."""
    vocab = vocabulary()
    return frozenset(
        str(word) for word in (*vocab["plant_part_words"], *vocab["descriptive_heads"])
    )


@functools.lru_cache(maxsize=1)
def definite_words() -> frozenset[str]:
    return frozenset(str(word) for word in vocabulary()["definite_words"])


@functools.cache
def _definite_extents() -> frozenset[str]:
    """Words between "the" and the field it names again ("the whole field")."""
    return frozenset(str(word) for word in vocabulary()["definite_extents"])


def definite_before_head(clause: Clause, mention: Mention) -> bool:
    """Whether the word right before the mention's first head is "the", "its"... ("the
    whole field") or a vague quantity of the plants of a crop named ("a few peppers have
    scabby spots")."""
    head = min(mention.heads, key=lambda h: h.start)
    before = [i for i in clause.items if i.end <= head.start]
    # ("the whole field", "the two maize blocks")
    while len(before) > 1 and (
        before[-1].norm in _definite_extents() or before[-1].role == "number"
    ):
        before.pop()
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

"""When a word for plants that names a crop ("the vines", "pear trees") is a field of
its own rather than the plants of a field named before.

"Bare vines pruned back ..., and the pear trees ...": it opens the prompt before a field
of another crop; "the pear orchard has fire blight, the vines have downy mildew": no
field before grows a crop whose plants it may stand for; "apple trees nearest, pear
trees beyond them and the vines on the hill", "the strawberry field, the vines are
across the road": it is put in a place of its own after fields of other crops.
:func:`~agrirecipe.resolve._descriptions.dissolve_plant_parts` asks these before it
makes such a mention a description.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import reader_words, vocabulary
from agrirecipe.resolve._links import link_norm
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    strong_crops,
)

__all__ = [
    "may_hold",
    "names_another_crop",
    "placed_crop_of_its_own",
    "plants_of_no_field_before",
    "said_to_be_somewhere",
]


def names_another_crop(
    clauses: Sequence[Clause], position: int, mention: Mention, others_before: bool
) -> bool:
    """Whether a word for plants that names a crop ("vines") opens the prompt before a
    field of another crop: a field of its own ("Bare vines pruned back ..., and the pear
    trees ... are bare too"; not "Russet potatoes, ... vines dying back", the haulm)."""
    crops = strong_crops(mention)
    if not crops or others_before:
        return False
    following = [strong_crops(m) for c in clauses[position + 1 :] for m in c.mentions][:1]
    return bool(following) and bool(following[0]) and not crops & following[0]


def plants_of_no_field_before(clauses: Sequence[Clause], position: int, mention: Mention) -> bool:
    """Whether the mention is only a word for plants that names a crop ("the vines") and
    no field named before grows a crop whose plants it may stand for
    (``plant_words_of`` in vocabulary.yaml): a field of that crop."""
    words = vocabulary().get("plant_words_of", {})
    heads = [h for h in mention.heads if h.role == "head"]
    if len(heads) != 1 or heads[0].norm not in words or not strong_crops(mention):
        return False
    may_be = set(words[heads[0].norm])
    earlier = [strong_crops(m) for c in clauses[:position] for m in c.mentions]
    if not earlier:
        # "from north to south: the vines, then the greens, then the cereals": the first
        # of fields named in order, the next of another crop
        following = next((c for c in clauses[position + 1 :] if c.items or c.mentions), None)
        return (
            following is not None
            and link_norm(following) == "then"
            and len(following.mentions) == 1
            and not strong_crops(following.mentions[0]) & may_be
        )
    return all(crops and not crops & may_be for crops in earlier)


#: Words that open a place after a word for plants ("the vines on the hill").
_PLACING = frozenset({"on", "in", "at", "along", "up", "down", "across", "over", "by", "beyond"})


def placed_crop_of_its_own(
    clauses: Sequence[Clause], position: int, mention: Mention, crop_categories: dict[str, str]
) -> bool:
    """Whether "and the vines on the hill" (a word for plants that names a crop, joined by
    "and" and put in a place of its own, or placed against a field: "and the vines south
    of the carrots") follows fields that all name other crops: a field of that crop
    ("apple trees nearest, pear trees beyond them and the vines on the hill"; not "the
    Riesling ..., and the vines are bare", nor "tomatoes and the vines heavy")."""
    clause = clauses[position]
    crops = strong_crops(mention)
    # (a field named by a plot word or a category alone holds only the crops they allow:
    # "orchard north of the veg garden, and the vines south of the veg garden")
    earlier = [may_hold(m, crop_categories) for c in clauses[:position] for m in c.mentions]
    head = max(h.end for h in mention.heads)
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    # ("..., then a hawthorn hedge, and past the hedge the vines go up the slope", "and
    # behind the barn the vines": placed past scenery, a place of their own)
    first_head = min(h.start for h in mention.heads)
    before = [i for i in mention.items if i.end <= first_head]
    past_scenery = any(i.scenery for i in before) and (
        (clause.link is not None and clause.link.role == "relation")
        or (bool(before) and before[0].norm in reader_words("placed_past"))
    )
    # ("the strawberry field, the vines are across the road": said to be somewhere)
    placed_by_be = said_to_be_somewhere(mention)
    return (
        clause.link is not None
        and (
            clause.link.role == "conjunction"
            or past_scenery
            or (clause.link.role == "separator" and placed_by_be)
        )
        and bool(crops)
        and bool(earlier)
        and all(e and not e & crops for e in earlier)
        and (
            past_scenery
            or any(i.start >= head and i.norm in _PLACING for i in mention.items)
            # "apple trees north of the carrots, and the vines south of the carrots"
            or (
                following is not None
                and following.link is not None
                and following.link.role in ("relation", "between")
            )
        )
    )


def said_to_be_somewhere(mention: Mention) -> bool:
    """Whether the words after the mention's heads say where it is, by scenery ("the
    vines are across the road", "the vines are on the hill")."""
    head = max(h.end for h in mention.heads)
    after = [i for i in sorted(mention.items, key=lambda i: i.start) if i.start >= head]
    # (a place: "across the road", not how they grow: "on stakes")
    return (
        len(after) >= 3
        and after[0].norm in ("are", "is")
        and after[1].norm in _PLACING
        and any(i.scenery for i in after[2:])
    )


def may_hold(mention: Mention, crop_categories: dict[str, str]) -> set[str]:
    """The crops a field mention may be: those it names, else those its plot word or its
    category allow (none known: an empty set)."""
    named = {crop for crop, _, _ in mention.interpretations or ()}
    if named:
        return strong_crops(mention) or named
    if mention.plot is not None and mention.plot["options"]:
        return {*mention.plot["options"], *mention.plot["tolerates"]}
    category = mention.category or (mention.plot or {}).get("category")
    return {crop for crop, of in crop_categories.items() if category and of == category}

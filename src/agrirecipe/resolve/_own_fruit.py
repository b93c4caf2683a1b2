"""When a mention made of a crop's word or a part of a plant is the fruit or a part of a
field named before, not a field of its own (issue 8): "the Navel block ..., full of orange
fruit", "a wheelbarrow full of split fruit", "Padron ..., still flowering with little green
peppers", "the Golden Delicious block beyond it with pale yellow apples".
:func:`agrirecipe.resolve._descriptions.dissolve_plant_parts` asks :func:`is_own_fruit`
before it makes such a mention a description.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, reader_words, singular
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_words,
    descriptive_words,
    names_a_variety,
    plant_part_words,
    strong_crops,
)

__all__ = ["is_own_fruit"]

#: Words between fruit and the container it is put in ("fruit already in bins").
_PUT_IN = frozenset({"already", "now", "still", "being", "put", "picked", "packed", "in", "into"})


def is_own_fruit(
    clauses: Sequence[Clause], position: int, mention: Mention, *, others_before: bool
) -> bool:
    """Whether the one mention of clause ``position`` is the named fields' own fruit or
    part, or what scenery holds ("a wheelbarrow full of split fruit")."""
    clause, before = clauses[position], clauses[:position]
    return (
        _fruit_of_named_crop(mention, before)
        or _part_of_named_crop(mention, before)
        or _held_by_scenery(clause, mention)
        or (others_before and _bare_part_after_with(clause, mention))
        or _crop_fruit_after_with(clause, mention, before)
        or _bare_part_after_a_dash(clauses, position, mention)
    )


def _fruit_of_named_crop(mention: Mention, before: Sequence[Clause]) -> bool:
    """ "full of orange fruit" after an orange block: a crop word before a word for the
    fruit, naming no variety, is the colour or fruit of a crop already named."""
    parts = plant_part_words()
    if (
        mention.count is not None
        or not any(h.norm in parts for h in mention.heads)
        or names_a_variety(mention)
    ):
        return False
    crops = strong_crops(mention)
    named = {c for clause in before for m in clause.mentions for c in strong_crops(m)}
    return bool(crops) and crops <= named


def _bare_part_after_a_dash(clauses: Sequence[Clause], position: int, mention: Mention) -> bool:
    """ "these Beefsteak tomatoes - massive ribbed fruit, but ...": a bare word for the
    fruit (no crop, no count, no plot) right after a dash or colon that follows a crop
    named is that crop's fruit."""
    clause = clauses[position]
    link = clause.link
    if (
        position == 0
        or link is None
        or link.norm not in ("-", "–", "—", ":")
        or mention.count is not None
        or strong_crops(mention)
        or not all(h.norm in plant_part_words() for h in mention.heads)
        or any(i.role == "plot" for i in clause.items)
    ):
        return False
    before = clauses[position - 1].mentions
    return bool(before) and bool(strong_crops(before[-1]))


def _part_of_named_crop(mention: Mention, before: Sequence[Clause]) -> bool:
    """ "the first hands of bananas just forming" after a Cavendish plantation: a part of
    the plants ("hands of", "bunches of") of a crop already named, naming no variety."""
    if mention.count is not None or names_a_variety(mention) or not mention.heads:
        return False
    first = min(h.start for h in mention.heads)
    said = [i for i in mention.items if i.start < first]
    if len(said) < 2 or said[-1].role != "of" or said[-2].norm not in plant_part_words():
        return False
    crops = strong_crops(mention)
    named = {c for clause in before for m in clause.mentions for c in strong_crops(m)}
    return bool(crops) and crops <= named


def _bare_part_after_with(clause: Clause, mention: Mention) -> bool:
    """ "branches bent with fruit", "heavy with berries": a bare word for the fruit (no
    crop, no count) after "with" or "of", once a field is named, is that field's fruit."""
    if mention.count is not None or strong_crops(mention):
        return False
    if not all(h.norm in plant_part_words() for h in mention.heads):
        return False
    if any(i.role == "plot" for i in clause.items):
        return False  # "a plot full of fruit" asks for a field of fruit
    head = min(h.start for h in mention.heads)
    before = [i for i in clause.items if i.end <= head]
    # ("hung with glossy fruit", "both carrying fruit": a word of bearing before it, past
    # plain adjectives)
    while (
        before
        and before[-1].role in ("unknown", "filler", "cue")
        and before[-1].norm not in (reader_words("bearing"))
    ):
        before.pop()
    return bool(before) and (before[-1].role == "of" or before[-1].norm in reader_words("bearing"))


def _crop_fruit_after_with(clause: Clause, mention: Mention, before: Sequence[Clause]) -> bool:
    """ "Padron on the other, still flowering with little green peppers": a bare plural of
    a crop named before, after "with" (past plain adjectives), is that field's fruit; so is
    a loose few of them ("a Granny leaf ..., with a couple of apples behind it"), and the
    fruit a field's variety bears ("the Golden Delicious block beyond it with pale yellow
    apples")."""
    crops = strong_crops(mention)
    if (
        not crops
        or (mention.count is not None and not _loose_few(mention))
        or (names_a_variety(mention) and not _varieties_named_before(mention, before))
        or any(h.role == "plot" for h in mention.heads)
        or not any(strong_crops(m) & crops for c in before for m in c.mentions)
    ):
        return False
    head = min(h.start for h in mention.heads)
    said = [i for i in clause.items if i.end <= head]
    # (not "w/ the lettuce in the middle": a field named again by "the")
    while (
        said
        and (said[-1].role in ("unknown", "filler", "cue") or said[-1] in _few_words(mention))
        and said[-1].norm != "with"
        and said[-1].norm not in definite_words()
    ):
        said.pop()
    return bool(said) and said[-1].norm == "with"


def _varieties_named_before(mention: Mention, before: Sequence[Clause]) -> bool:
    """Whether the mention names its variety by the fruit's colour ("yellow apples") and
    that variety is one a field named before has (not "with Red Express between the other
    two": a member named again)."""
    crops = {c.lower() for c in strong_crops(mention)}
    if not any(
        len(h.tokens) == 2
        and h.tokens[0].norm in reader_words("colours")
        and singular(h.tokens[1].norm) in crops
        for h in mention.heads
    ):
        return False
    named = {
        (crop, variety)
        for c in before
        for m in c.mentions
        for crop, variety, weak in m.interpretations or ()
        if not weak
    }
    return all(
        (crop, variety) in named
        for crop, variety, weak in mention.interpretations or ()
        if not weak
    )


def _few_words(mention: Mention) -> list[Item]:
    """The count words ("a couple of", "a few") before the mention's head."""
    head = min(h.start for h in mention.heads)
    return [i for i in mention.items if i.end <= head and i.role == "number"]


def _loose_few(mention: Mention) -> bool:
    """ "a couple of apples", "a few cherries": a count that is a handful of fruit, not of
    fields (no plot word, no variety)."""
    numbers = [i for i in mention.items if i.role == "number"]
    return (
        bool(numbers)
        and all(set(i.norm.split()) & reader_words("loose_few") for i in numbers)
        and not any(i.role == "plot" for i in mention.items)
    )


def _held_by_scenery(clause: Clause, mention: Mention) -> bool:
    """ "a wheelbarrow full of split fruit", "crates of apples": plants or fruit that a
    piece of scenery holds (the words before them: the scenery, "of", describing words)."""
    if mention.count is not None or not all(h.norm in descriptive_words() for h in mention.heads):
        return False
    head = min(h.start for h in mention.heads)
    before = [i for i in clause.items if i.end <= head]
    while before and before[-1].role in ("unknown", "filler") and "scenery" not in before[-1].data:
        before.pop()  # "split", "ripe-looking"
    if len(before) >= 2 and before[-1].role == "of" and "scenery" in before[-2].data:
        return True
    # "some fruit already in bins": fruit put in a container
    last = max(h.end for h in mention.heads)
    after = [i.norm for i in clause.items if i.start >= last]
    while after and after[0] in _PUT_IN:
        after.pop(0)
    while after and after[0] in ("a", "an", "the", "some", "their"):
        after.pop(0)
    return bool(after) and after[0] in reader_words("produce_containers")

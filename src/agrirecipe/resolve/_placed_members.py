"""Where a mention is placed, which tells it from the fields named before (issue 8).

:func:`~agrirecipe.resolve._coreference.merge_coreferences` asks these: a crop named
again "to the north, ..." of two fields counted before is one of them; "Left of it is
our Bintje" is one side of what was named; "the Jalapeño beds beside them" and "...,
beside it, sweetcorn" are placed against the plants named before, so they are other
fields; "south plot" after "north plot", "bottom left maize" after "top right maize" are
other plots.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import strong_crops
from agrirecipe.resolve._zones import zone_of

__all__ = [
    "in_another_zone",
    "measures_after_a_placed_reference",
    "on_a_side_of_it",
    "other_side",
    "placed_against_another",
    "placed_by_a_pronoun",
    "placed_first",
    "placed_past_a_pronoun",
    "related_to",
]


def placed_first(clauses: Sequence[Clause], clause: Clause) -> bool:
    """Whether a direction alone opens the clause's sentence ("Two blocks ... . To the
    north, Jonagored apples: ..."): the field after it is placed, one of those counted."""
    if clause.index == 0 or clause.link is None or clause.link.norm != ",":
        return False
    before = clauses[clause.index - 1]
    return (
        not before.items
        and not before.mentions
        and before.link is not None
        and before.link.role in ("trailer", "relation")
    )


#: Sides a field is said on of something named before ("left of it").
_SIDE_WORDS = frozenset({"left", "right", "north", "south", "east", "west"})


def on_a_side_of_it(mention: Mention) -> bool:
    """Whether the mention opens with a side of what a pronoun names ("Left of it is our
    Bintje"): one part of what was named before."""
    words = [i.norm for i in mention.items[:3]]
    return len(words) == 3 and words[0] in _SIDE_WORDS and words[1:] == ["of", "it"]


def placed_against_another(clauses: Sequence[Clause], clause: Clause, mention: Mention) -> bool:
    """Whether the mention is placed against a field of another crop named right after it
    ("Two veg plots ..., lettuce directly north of the cabbage": one member each)."""
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    if following is None or following.link is None or not following.mentions:
        return False
    other = strong_crops(following.mentions[0])
    return (
        following.link.role in ("relation", "between")
        and bool(other)
        and not other & strong_crops(mention)
    )


def related_to(clauses: Sequence[Clause], clause: Clause, earlier: Mention) -> bool:
    """Whether ``clause`` opens with a relation word right after ``earlier``."""
    link = clause.link
    if link is None or link.role not in ("relation", "between", "trailer"):
        return False
    before = [m for c in clauses[: clause.index] for m in c.mentions]
    return bool(before) and before[-1] is earlier


def placed_past_a_pronoun(clauses: Sequence[Clause], clause: Clause) -> bool:
    """Whether the clause before ``clause`` places it against a field by a pronoun
    ("..., beside it, sweetcorn"; "and north of them, pears")."""
    if clause.index == 0 or clause.link is None or clause.link.norm != ",":
        return False
    previous = clauses[clause.index - 1]
    link = previous.link
    return (
        link is not None
        and link.role in ("relation", "between")
        and not previous.mentions
        and [i.norm for i in previous.items] in (["it"], ["them"], ["that"], ["those"])
        # (not "a sweetcorn plot next to them, sweetcorn 4 rows ...": the placement of the
        # field right before it)
        and clause.index >= 2
        and not clauses[clause.index - 2].mentions
    )


def placed_by_a_pronoun(clauses: Sequence[Clause], clause: Clause) -> bool:
    """Whether the clause after ``clause`` places its field against plants named before
    it by a plural pronoun ("the Jalapeño beds beside them still only flowering")."""
    if clause.index + 1 >= len(clauses):
        return False
    following = clauses[clause.index + 1]
    link = following.link
    return (
        link is not None
        and link.role == "relation"
        and not following.mentions
        and bool(following.items)
        and following.items[0].norm in ("them", "those")
    )


_SIDES = frozenset(
    {"north", "south", "east", "west", "upper", "lower", "top", "bottom", "front", "back"}
)


def other_side(earlier: Mention, mention: Mention) -> bool:
    """Whether a plot of no crop is told apart from the field before it by a side word
    ("North plot ... ; south plot ...")."""
    if strong_crops(mention) or mention.plot is None:
        return False
    said = {i.norm for i in mention.items if i.norm in _SIDES}
    before = {i.norm for i in earlier.items if i.norm in _SIDES}
    return bool(said) and bool(before) and not said & before


def in_another_zone(kept: Sequence[Mention], mention: Mention) -> bool:
    """Whether ``mention`` names a crop again in a zone of its own, when every earlier
    field of that crop lies in another zone ("top right maize, bottom left maize")."""
    own = zone_of(mention.items)
    crops = strong_crops(mention)
    same = [m for k in kept for m in (k.refinements or [k]) if strong_crops(m) & crops]
    return own is not None and bool(same) and all(zone_of(m.items) not in (None, own) for m in same)


def measures_after_a_placed_reference(clauses: Sequence[Clause]) -> None:
    """'plus 1 acre of cherries south of the vines at 16 x 8 ft': row measures said after
    the field a new one is placed against, when that field is named again with "the"
    (a crop named in an earlier sentence or clause), are the new field's: its measures
    were said when it was named. They move from the reference to the subject (the one
    field of the clause before) when the subject says no row measure of its own."""
    for position, clause in enumerate(clauses[1:], start=1):
        link, previous = clause.link, clauses[position - 1]
        if (
            link is None
            or link.role != "relation"
            or len(clause.mentions) != 1
            or len(previous.mentions) != 1
            or not previous.mentions[0].has_crop
        ):
            continue
        reference, subject = clause.mentions[0], previous.mentions[0]
        words = sorted(reference.items, key=lambda item: item.start)
        heads = [i.start for i in reference.heads]
        crops = strong_crops(reference)
        if not words or words[0].norm != "the" or not heads or not crops:
            continue
        named_before = any(
            strong_crops(m) & crops for c in clauses[: position - 1] for m in c.mentions
        )
        measures = [i for i in words if i.role == "geometry" and i.start > max(heads)]
        if (
            not named_before
            or not measures
            or any(i.role == "geometry" for i in subject.items)
            or any(i.role == "geometry" for i in words if i.start < max(heads))
        ):
            continue
        gone = {id(i) for i in measures}
        reference.items = [i for i in reference.items if id(i) not in gone]
        subject.items.extend(measures)

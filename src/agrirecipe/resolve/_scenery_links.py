"""Relation words said of scenery, not of fields: "a tractor parked by the Bintje",
"east of it" after a ditch, "kids weeding between them", "a reel in the middle of the
lettuce".

:func:`agrirecipe.resolve._relations.read_relations` asks these before it relates
fields; a relation they claim is listed in ``--explain`` as not used.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, reader_words
from agrirecipe.resolve._links import following_list, listed_after
from agrirecipe.resolve._mentions import Clause
from agrirecipe.resolve._rows import TOWARDS

__all__ = [
    "between_scenery",
    "not_placed",
    "pronoun_of_scenery",
    "pronoun_past_an_aside",
    "scenery_in_the_middle",
    "scenery_placed_by_a_field",
]


def scenery_placed_by_a_field(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the relation word of clause ``position`` places the scenery said right
    before it ("..., with the village road running along the east side"; "with a
    tractor parked by the Bintje": by a field named before)."""
    clause = clauses[position]
    link = clause.link
    assert link is not None
    return bool(
        link.role in ("trailer", "relation")
        and (
            not clause.mentions
            # "..., with a tractor parked by the Bintje", "the sprayer boom folded up by
            # the first field": scenery placed by a field named before
            or (
                link.role == "relation"
                and all(
                    any(m is n for c in clauses[:position] for n in c.named)
                    for m in clause.mentions
                )
            )
        )
        and position
        and not clauses[position - 1].mentions
        and any(i.scenery for i in clauses[position - 1].items)
        # (not "bananas along the stream to the east of them": scenery placed itself)
        and not_placed(clauses[position - 1])
        # (nor "a maize field ... and, across a narrow ditch right next to it, carrots":
        # the scenery said on the way, "it" the field)
        and not pronoun_past_an_aside(clauses, position)
        # (not "in two polytunnels next to each other: tunnel 1 is Elsanta, ...")
        and not (link.role == "trailer" and len(listed_after(clauses, position)) >= 2)
        # (nor "From the road heading north you cross a hedge, then the strawberry
        # beds, then the apple orchard": the fields in a row, from the road)
        and not (
            link.role == "trailer"
            and str(link.data.get("value")) in TOWARDS
            and len(following_list(clauses, position)) >= 2
        )
    )


def pronoun_of_scenery(clauses: Sequence[Clause], position: int, *, the_two: bool) -> bool:
    """Whether the pronoun clause ``position`` ("east of it", "between them") points at
    scenery: no field named before it at all, or scenery said right before it."""
    clause = clauses[position]
    link = clause.link
    assert link is not None
    # "A ditch runs through the middle. East of it is a field of sweetcorn": no field
    # was named before the pronoun, so it points at scenery
    no_field_before = (
        not the_two
        and (
            link.role == "relation"  # (not "From north to south it goes orchard, ...")
            and not any(
                i.role in ("head", "plot", "category") for c in clauses[:position] for i in c.items
            )
        )
    )
    # "..., kids in yellow hats weeding between them": scenery placed, no field
    return no_field_before or bool(
        not clause.mentions
        and position
        and not clauses[position - 1].named
        and any(i.scenery for i in clauses[position - 1].items)
        # (not "bananas along the stream to the east of them": a placement goes on)
        and (
            (placed_by := clauses[position - 1].link) is None
            or placed_by.role not in ("relation", "trailer", "between")
            # ("... side by side with the tractor between them": the fields' own row)
            or placed_by.norm == "side by side with"
        )
        and not pronoun_past_an_aside(clauses, position)
    )


def between_scenery(clauses: Sequence[Clause], position: int) -> bool:
    """Whether "between" at clause ``position`` has scenery on both sides ("Between the
    house and the road is the strawberry field"): the field lies between landmarks, no
    field between two others."""
    clause = clauses[position]
    other = clauses[position + 1] if position + 1 < len(clauses) else None
    if (
        clause.link is None
        or clause.link.role != "between"
        or clause.mentions
        or not any(_landmark(i) for i in clause.items)
        or other is None
        or other.link is None
        or other.link.norm != "and"
    ):
        return False
    heads = [h.start for m in other.mentions for h in m.heads]
    first_head = min(heads, default=None)
    return any(_landmark(i) and (first_head is None or i.end <= first_head) for i in other.items)


def _landmark(item: Item) -> bool:
    """A word for scenery or for a thing of no farm ("the house", "the road")."""
    return item.scenery or item.role == "non_agricultural"


def scenery_in_the_middle(clauses: Sequence[Clause], position: int) -> bool:
    """ "There's an irrigation reel in the middle of the lettuce": scenery placed."""
    link = clauses[position].link
    assert link is not None
    return bool(
        link.role == "trailer"
        and link.data.get("value") == "middle"
        and position
        and not clauses[position - 1].named
        and any(i.scenery for i in clauses[position - 1].items)
    )


def pronoun_past_an_aside(clauses: Sequence[Clause], position: int) -> bool:
    """Whether clause ``position`` places against a pronoun ("right next to it") right
    after scenery said on the way ("across a narrow ditch"), with a field after it."""
    clause, previous = clauses[position], clauses[position - 1]
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    return (
        [i.norm for i in clause.items] in (["it"], ["them"])
        and bool(previous.items)
        and previous.items[0].norm in reader_words("placed_past")
        and following is not None
        and bool(following.mentions)
        and any(c.mentions for c in clauses[: position - 1])
    )


def not_placed(clause: Clause) -> bool:
    """Whether a clause is not itself placed by a relation word before it."""
    return clause.link is None or clause.link.role not in ("relation", "trailer", "between")

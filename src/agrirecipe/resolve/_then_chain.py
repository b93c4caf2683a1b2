"""Fields named one after another with "then" (issue 8): "it goes vineyard, then a hedge,
then salad greens, then corn", "three fields: cabbages nearest to us, then a wheat field,
and past that a field of potatoes". :func:`then_chain` lays them one beside the next,
the middle one of three between the others, unless the text placed them already.
:func:`agrirecipe.resolve._relations.read_relations` asks it after the relation words.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._intent import RelationIntent, TraceStep
from agrirecipe.resolve._links import field_relations, link_norm
from agrirecipe.resolve._mentions import Clause, Mention

__all__ = ["then_chain"]


def then_chain(
    clauses: Sequence[Clause],
    members: dict[int, list[int]],
    related: set[frozenset[int]],
    trace: list[TraceStep],
) -> list[RelationIntent]:
    """'it goes vineyard, then a hedge, then salad greens, then corn', 'you pass the
    strawberries, then the Riesling vineyard': fields named one after another with
    "then" lie one beside the next (the middle one of three between the others),
    unless the text already placed them ("west to east: ..., then ...")."""
    chain: list[Mention] = []
    said: set[frozenset[int]] = set()  # pairs the chain's own last words placed
    for position, clause in enumerate(clauses):
        link = clause.link
        # ("three fields: cabbages nearest to us, then a wheat field, ...": the members
        # of a counted list, folded into it, in the order named)
        own = clause.mentions or [
            r for r in (clause.refinement,) if r is not None and r.clause == position
        ]
        if not own:
            continue
        mention = own[0]
        if (
            len(chain) >= 2
            and _past_the_last(clauses, position, chain[-1])
            and len(members.get(id(chain[-1]), [])) == 1
            and len(members.get(id(mention), [])) == 1
        ):
            # "..., then a wheat field, and past that a field of potatoes": the chain
            # goes on past its last field, placed by its own words
            said.add(frozenset((members[id(chain[-1])][0], members[id(mention)][0])))
            chain.append(mention)
            continue
        follows = (link is not None and link.norm == "then") or (
            position > 0
            and clauses[position - 1].link is not None
            and clauses[position - 1].link.norm == "then"  # type: ignore[union-attr]
            and not clauses[position - 1].items
        )
        # ("the Fuji trees, then the Pink Lady further back, and the Golden Delicious out
        # on the far boundary": the last of a "then" list joined by "and")
        follows = follows or (
            link is not None
            and link.norm == "and"
            and len(chain) >= 2
            and chain[-1].clause >= position - 2
            and not any(c.link is not None and c.link.norm == "then" for c in clauses[position:])
        )
        if follows and chain:
            if all(mention is not m for m in chain):
                chain.append(mention)
        elif not chain or len(chain) < 2:
            chain = [own[-1]]
    fields = [m for m in chain if len(members.get(id(m), [])) == 1]
    indices = [members[id(m)][0] for m in fields]
    if len(fields) < 2 or any(
        frozenset(pair) in related and frozenset(pair) not in said
        for pair in itertools.pairwise(indices)
    ):
        return []
    link_item = next(c.link for c in clauses if c.link is not None and c.link.norm == "then")
    relations: list[RelationIntent] = []
    for first, second in itertools.pairwise(fields):
        if frozenset((members[id(first)][0], members[id(second)][0])) in said:
            continue
        relations.extend(field_relations("next_to", second, (first,), members, link_item, trace))
    if len(fields) == 3:
        relations.extend(
            field_relations("between", fields[1], (fields[0], fields[2]), members, link_item, trace)
        )
    return relations


def _past_the_last(clauses: Sequence[Clause], position: int, last: Mention) -> bool:
    """Whether clause ``position`` ("and past that a field of potatoes") places its field
    against "that" or "it", the field ``last`` named just before, after an "and"."""
    clause = clauses[position]
    link = clause.link
    return (
        link is not None
        and link.role == "relation"
        and bool(clause.items)
        and clause.items[0].norm in ("that", "it")
        and position >= 2
        and link_norm(clauses[position - 1]) == "and"
        and not clauses[position - 1].items
        # (no other field named since; identity, not equality: comparing mentions field
        # by field is slow)
        and not any(
            c.mentions or (c.refinement is not None and c.refinement is not last)
            for c in clauses[last.clause + 1 : position]
        )
    )

"""Fields in a row, in an order or around a middle one.

"three strips from west to east: ..." (a directed row), "the first ... north of the second"
(ordinals), "one above the other", "three plots: carrots, onions in the middle, then
potatoes" (a listed middle), "Z with X on each side" (surrounded), "Spelt on one side
of the hedge, ... onions on the other", "three adjacent fields", "potatoes, onions and
cabbages side by side" (a row said after a list), "cherries further east still" (past
the furthest field that way), "on the far side of the dinkel" (the dinkel in the middle).
Each reader returns
the relations it finds; :func:`agrirecipe.resolve._relations.read_relations` calls them
in its order (a "then" chain is :mod:`agrirecipe.resolve._then_chain`).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from agrirecipe.resolve._intent import RelationIntent, TraceStep
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import (
    OPENING_MARKS,
    coordinated,
    field_relations,
    fields_of,
    following_list,
    link_norm,
    listed_after,
    listing,
    says,
)
from agrirecipe.resolve._measures import sentence_start
from agrirecipe.resolve._mentions import Clause, Mention

__all__ = [
    "FURTHER",
    "OTHER_SIDE",
    "TOWARDS",
    "Row",
    "adjacent_rows",
    "directed_row",
    "furthest",
    "in_a_row",
    "listed_middle",
    "on_the_other_side",
    "one_and_the_other",
    "one_side_and_the_other",
    "ordinal_pair",
    "side_by_side",
    "surrounded",
]


_ORDINALS = {"first": 0, "second": 1, "third": 2, "fourth": 3}


def ordinal_pair(clauses: Sequence[Clause], position: int) -> tuple[int, int] | None:
    """The members "the first ... north of the second" name (0-based), or None."""

    def ordinal(clause: Clause) -> int | None:
        # ("the second block is east of the first": a plot word of no crop says nothing)
        words = [
            w
            for i in clause.items
            if i.role != "plot"
            for w in i.norm.split()
            if w not in _ORDINAL_FILLERS
        ]
        if any(m.has_crop or m.category is not None for m in clause.mentions) or len(words) != 1:
            return None
        return _ORDINALS.get(words[0])

    if position == 0:
        return None
    subject, obj = ordinal(clauses[position - 1]), ordinal(clauses[position])
    return (subject, obj) if subject is not None and obj is not None else None


#: Words around an ordinal that say nothing more ("the first one is ...").
_ORDINAL_FILLERS = frozenset({"the", "one", "is", "lies", "sits", "are"})


def one_and_the_other(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the relation at ``position`` is said as "one above the other"."""
    clause = clauses[position]
    before = clauses[position - 1] if position else None
    return (
        before is not None
        and not before.mentions
        and [i.norm for i in before.items] == ["one"]
        and not clause.mentions
        and [i.norm for i in clause.items] == ["the other"]
    )


def _named_again_in_order(
    clauses: Sequence[Clause], position: int, members: dict[int, list[int]]
) -> list[int]:
    """The fields the clause of a row's direction and the clauses listed after it name,
    each once, in order ("... north to south as veg, fruit, veg")."""
    named = clauses[position].named[-1:]
    for index, clause in enumerate(clauses[position + 1 :], start=position + 1):
        # (after the colon or dash of the direction's own clause: "west to east: wheat,
        # ...", "from north to south - potatoes, corn, wheat")
        colon = index == position + 1 and link_norm(clause) in OPENING_MARKS
        if not clause.named and named and link_norm(clause) in _SAID_OF_A_MEMBER:
            # ("Stripes from top to bottom: Durum wheat that's heading, young Flint corn,
            # then Savoy cabbages": words about the member before; an empty comma)
            continue
        if not (listing(clause.link) or colon) or len(clause.named) != 1:
            break
        named.append(clause.named[0])
    fields = fields_of(named, members)
    return fields if len(fields) == len(named) else []


#: Links of a clause that says more of the member before it, inside a row's list.
_SAID_OF_A_MEMBER = frozenset({"that", "which", "who", ","})


#: "from west to east": each field of the row lies on this side of the next one.
TOWARDS = {
    "towards_east": "west_of",
    "towards_west": "east_of",
    "towards_north": "south_of",
    "towards_south": "north_of",
}


def directed_row(
    clauses: Sequence[Clause],
    position: int,
    members: dict[int, list[int]],
    link: Item,
    trace: list[TraceStep],
    warnings: list[str],
) -> list[RelationIntent]:
    """'three strips from west to east: wheat, potatoes, maize', 'A, B and C from north
    to south': the fields in the order named, each on one side of the next."""
    fields = fields_of(list(reversed(coordinated(clauses, position, past_asides=True))), members)
    # "Two vegetable plots and one fruit plot, laid out north to south as veg, fruit, veg":
    # the same fields, named again in the order they lie
    again = _named_again_in_order(clauses, position, members)
    if len(again) == len(fields) >= 2 and set(again) == set(fields):
        fields = again
    elif len(fields) < 2 and len(again) >= 3:
        # "Stripes from top to bottom: Durum wheat that's heading, young Flint corn, then
        # Savoy cabbages": the list after the direction, past words about its members
        fields = again
    if len(fields) < 2:
        # "going west to east: tomatoes first, then the jalapenos, then peppers";
        # "going east you pass Hamlin oranges, then Navel": the clause's own field first
        own = clauses[position].mentions[-1:]
        previous = clauses[position - 1] if position else None
        start: list[Mention] = []
        if previous is not None and previous.link is not None and previous.link.norm == "then":
            # "Gala trees first, then heading east the Durondeau pears": from the field
            # named before "then"
            start = [m for c in clauses[:position] for m in c.mentions][-1:]
        fields = fields_of(start + following_list(clauses, position, own), members)
    if len(fields) < 2:
        # "Jonagored apples (3.5 m rows), Chardonnay vines (2.5 m rows) and Regina
        # cherries (5 m rows) in three blocks from west to east": a list whose members
        # each carry their measures in brackets
        fields = fields_of(_listed_with_measures(clauses, position), members)
    if len(fields) < 2:
        # "Block 1 Fuji. Block 2 ... The blocks go west to east in that order."
        fields = fields_of(_all_named_before(clauses, position), members)
    if len(fields) < 2:
        warnings.append(f"ignored {link.raw!r}: it needs two or more fields before it")
        return []
    if link.norm.startswith("looking") and any(
        i.role == "zone" for c in clauses[position:] for m in c.mentions for i in m.items
    ):
        # "Looking north: wheat at the far north end, ... strawberries closest to me":
        # the zones place the fields; the view only says where the viewer faces
        return []
    kind = TOWARDS[str(link.data["value"])]
    trace.append(
        TraceStep(
            stage="decompose",
            subject=link.raw,
            detail=f"{len(fields)} fields in a row, each {kind.replace('_', ' ')} the next",
        )
    )
    return [
        RelationIntent(kind=kind, subject=a, objects=(b,), text=link.raw)
        for a, b in itertools.pairwise(fields)
    ]


#: What a bracket of a listed member's measures holds ("(3.5 m rows)").
_MEASURE_ROLES = frozenset({"geometry", "size", "filler", "of", "number", "plot"})


def _listed_with_measures(clauses: Sequence[Clause], position: int) -> list[Mention]:
    """The fields of a list that runs from its sentence's start to the row word at
    ``position``, each member's measures in brackets after it; [] when the sentence is
    anything else."""
    start = sentence_start(clauses, position)
    colon = [c.index for c in clauses[start:position] if link_norm(c) in OPENING_MARKS]
    start = colon[-1] if colon else start  # ("LiDAR benchmark farm: ...": after it)
    named: list[Mention] = []
    for clause in clauses[start:position]:
        norm = link_norm(clause)
        if clause.index > start and not (listing(clause.link) or norm in ("(", ")")):
            return []
        if not clause.mentions and not all(i.role in _MEASURE_ROLES for i in clause.items):
            return []
        named.extend(clause.mentions)
    bracketed = any(link_norm(c) == "(" for c in clauses[start:position])
    return named if bracketed and all(m.has_crop for m in named) else []


def _all_named_before(clauses: Sequence[Clause], position: int) -> list[Mention]:
    """The fields named before a sentence that opens with "the blocks" (a plural plot
    word and no crop) and is placed by the row word at ``position``: every one of them,
    in the order named."""
    start = sentence_start(clauses, position)
    words = [i for c in clauses[start:position] for i in c.items]
    plural = [
        i
        for i in words
        if i.role == "plot" and isinstance(v := i.data.get("value"), dict) and v.get("plural")
    ]
    if (
        not words
        or words[0].norm not in ("the", "all", "these", "those")
        or not plural
        or any(i.role in ("head", "category", "weak_variety") for i in words)
    ):
        return []
    return list({id(m): m for c in clauses[:start] for m in c.mentions}.values())


def listed_middle(
    clauses: Sequence[Clause], position: int, link: Item
) -> tuple[Mention, tuple[Mention, Mention]] | None:
    """'three plots: carrots, onions in the middle, then potatoes': the middle one of
    three listed members is between the other two."""
    if link.role != "trailer" or link.data.get("value") != "middle" or not position:
        return None
    previous = clauses[position - 1]
    parent, member = previous.refined_parent, previous.refinement
    if parent is None or member is None:
        return None
    listed: list[Mention] = []
    for sub in parent.refinements:
        if not any(sub is seen for seen in listed):
            listed.append(sub)
    if len(listed) != 3 or listed[1] is not member:
        return None
    return member, (listed[0], listed[2])


def one_side_and_the_other(
    clauses: Sequence[Clause],
    members: dict[int, list[int]],
    relations: Sequence[RelationIntent],
    trace: list[TraceStep],
) -> list[RelationIntent]:
    """'Spelt on one side of the hedge, ..., and Walla Walla onions on the other': two
    fields on the two sides of one thing are next to each other."""
    mentions = [m for c in clauses for m in c.mentions]
    one = next((m for m in mentions if says(m, ("one", "side"))), None)
    other = next(
        (m for m in mentions if m is not one and any(i.norm == "the other" for i in m.items)),
        None,
    )
    if one is None or other is None or len(members.get(id(one), [])) != 1:
        return []
    if len(members.get(id(other), [])) != 1:
        return []
    pair = {members[id(one)][0], members[id(other)][0]}
    if any({r.subject, *r.objects} == pair for r in relations):
        return []
    side = next(i for i in one.items if i.norm == "side")
    middle = _said_in_the_middle(clauses, (one, other))
    if middle is not None and len(members.get(id(middle), [])) == 1:
        # "In the middle, Kordia cherries ... On one side Gala apples ...; on the other
        # side Comice pears": the one in the middle is between the two sides
        return field_relations("between", middle, (one, other), members, side, trace)
    return field_relations("next_to", other, (one,), members, side, trace)


def _said_in_the_middle(clauses: Sequence[Clause], sides: Sequence[Mention]) -> Mention | None:
    """The field a clause opening "in the middle" names (in it or right after its comma),
    when it is none of ``sides``."""
    for index, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role != "trailer" or link.data.get("value") != "middle":
            continue
        after = clauses[index + 1] if index + 1 < len(clauses) else None
        right_after = not clause.items and after is not None and link_norm(after) == ","
        named = clause.mentions or (after.mentions if right_after and after is not None else [])
        if named and all(named[0] is not m for m in sides):
            return named[0]
    return None


def adjacent_rows(
    clauses: Sequence[Clause], members: dict[int, list[int]], trace: list[TraceStep]
) -> list[RelationIntent]:
    """'three adjacent fields': the fields of a mention described as adjacent, in a row."""
    rows: list[RelationIntent] = []
    seen: set[int] = set()
    # ("Comice vs Durondeau: two adjacent pear blocks": one word said of the fields of a
    # list counted again)
    shared: dict[int, tuple[Item, Mention, list[int]]] = {}
    for clause in clauses:
        for mention in clause.mentions:
            fields = members.get(id(mention), [])
            adjacent = [i for i in mention.items if i.data.get("adjacent")]
            if not adjacent or id(mention) in seen:
                continue
            seen.add(id(mention))
            if len(fields) >= 2:
                rows += in_a_row(fields, mention, adjacent[0], trace, ordered=False)
            elif len(fields) == 1:
                word = adjacent[0]
                shared.setdefault(id(word), (word, mention, []))[2].extend(fields)
    for word, first, fields in shared.values():
        if len(fields) >= 2:
            rows += in_a_row(fields, first, word, trace, ordered=False)
    return rows


@dataclass
class Row:
    """The relations of fields said side by side or in a row."""

    relations: list[RelationIntent]
    #: The middle of three said side by side (kept unless the text puts another there).
    middles: list[RelationIntent] = field(default_factory=list)
    #: The two fields said next to each other (for one said "on the far side of" one).
    said: list[tuple[str, Mention, tuple[Mention, ...]]] = field(default_factory=list)


def side_by_side(
    clauses: Sequence[Clause],
    position: int,
    members: dict[int, list[int]],
    trace: list[TraceStep],
    warnings: list[str],
) -> Row | None:
    """'potatoes, onions and cabbages side by side', 'three plots in a line: ...',
    'comice and bartlett pears next to each other': the fields the row word at
    ``position`` follows (or the list after its colon), each beside the next; None when
    the clause's word is no such row word."""
    clause = clauses[position]
    link = clause.link
    # ("the cabbage and the lettuce fields side by side with the tractor between them":
    # side by side, and the scenery with them)
    with_scenery = (
        link is not None
        and link.role == "relation"
        and link.norm == "side by side with"
        and not clause.mentions
        and any(i.scenery for i in clause.items)
    )
    if link is None or not (
        with_scenery or (link.role == "trailer" and link.data.get("value") in ("next_to", "row"))
    ):
        return None
    ordered = link.data.get("value") == "row"
    group = coordinated(clauses, position, past_asides=ordered) or listed_after(clauses, position)
    if len(group) == 1 and not members.get(id(group[0])):
        # "cabbage on the left, tomatoes on the right. The two fields touch at the fence":
        # the fields a summary said again (dropped as no field of its own) stand for it
        named = list({id(m): m for c in clauses[: group[0].clause] for m in c.mentions}.values())
        if len(named) == (group[0].count or 0):
            group = named
    if ordered and (_placed_each(clauses, group) or _middle_said_after(clauses, position)):
        # "Three pear blocks in a line: Conference at the west end, Comice at the east end
        # and Williams between them": the places said, not the order named
        return Row([])
    if len(group) > 2:
        # "potatoes, onions and cabbages side by side": a row, each beside the next (so of
        # three, the middle one between the others)
        row = Row([])
        for first, second in zip(group[1:], group, strict=False):
            row.relations += field_relations("next_to", first, (second,), members, link, trace)
        if len(group) == 3:
            middle = field_relations(
                "between", group[1], (group[2], group[0]), members, link, trace
            )
            (row.relations if ordered else row.middles).extend(middle)
        return row
    if len(group) == 2:
        # "comice and bartlett pears next to each other": the two side by side
        pair = field_relations("next_to", group[0], (group[1],), members, link, trace)
        return Row(pair, said=[("next_to", group[0], (group[1],))])
    fields = members.get(id(group[0]), []) if len(group) == 1 else []
    if len(fields) >= 2:
        # "two different fruits side by side": the fields of one mention in a row (in the
        # order its members are listed: "three plots side by side: lettuce, then cabbage,
        # then carrots" has the cabbage between)
        listed = ordered or bool(group[0].refinements)
        found = in_a_row(fields, group[0], link, trace, ordered=listed)
        return Row(
            [r for r in found if ordered or r.kind != "between"],
            middles=[r for r in found if not ordered and r.kind == "between"],
        )
    if ordered:
        warnings.append(f"ignored {link.raw!r}: it needs two or more fields before it")
        return Row([])
    return None


def _middle_said_after(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the sentence goes on after a row word to say which field is in the middle
    ("3 fields in a row w/ the potatos in the middle"): then that, not the order named,
    orders the row."""
    for clause in clauses[position + 1 :]:
        link = clause.link
        if link is not None and link.norm in (".", "!", "?"):
            return False
        if link is not None and link.role == "trailer" and link.data.get("value") == "middle":
            return True
    return False


def _placed_each(clauses: Sequence[Clause], group: Sequence[Mention]) -> bool:
    """Whether the fields of a row are placed one by one after it (by zones, or by a
    relation said between them): then the row's order is not the order named."""
    fields = [r for m in group for r in ({id(r): r for r in m.refinements}.values() or (m,))]
    if len(fields) < 3:
        return False
    zoned = sum(1 for m in fields if any(i.role == "zone" for i in m.items))
    first = min(m.clause for m in fields)
    last = max(c.index for c in clauses if c.refinement in fields or c.index <= first) + 1
    links = [c.link for c in clauses[first : last + 1] if c.link is not None]
    related = any(link.role in ("relation", "between") for link in links)
    # "three plots in a line: strawberries between lettuce and onions", "...: peppers in
    # the middle, tomatoes on the west side, ...": the one between the other two orders a
    # row of three
    between = len(fields) == 3 and any(
        link.role == "between" or (link.role == "trailer" and link.data.get("value") == "middle")
        for link in links
    )
    return zoned >= 2 or (zoned >= 1 and related) or between


def in_a_row(
    fields: Sequence[int], mention: Mention, word: Item, trace: list[TraceStep], *, ordered: bool
) -> list[RelationIntent]:
    """The fields of one mention side by side in the order named; with ``ordered`` and
    three of them, the middle one also between the other two ("in a line")."""
    trace.append(
        TraceStep(
            stage="decompose",
            subject=word.raw,
            detail=f"the {len(fields)} fields of {mention.text!r} in a row",
        )
    )
    row = [
        RelationIntent(kind="next_to", subject=b, objects=(a,), text=word.raw)
        for a, b in itertools.pairwise(fields)
    ]
    if ordered and len(fields) == 3:
        row.append(
            RelationIntent(
                kind="between", subject=fields[1], objects=(fields[0], fields[2]), text=word.raw
            )
        )
    return row


def surrounded(
    value: str,
    clauses: Sequence[Clause],
    position: int,
    before: Sequence[Mention],
    after: Sequence[Mention] = (),
) -> tuple[Any, Mention, tuple[Mention, ...]] | None:
    """'Z with X on each side' and 'X, Y and Z, Z in the middle': Z between the other two.

    For "on each side" the mention just before the words is on both sides (its
    count was made two by :func:`~agrirecipe.resolve._structure.apply_each_side`)
    and the one before it is in the middle.
    """
    distinct: list[Mention] = []
    for mention in before:  # a field named twice counts once
        if mention.refinements and any(r is m for r in mention.refinements for m in before):
            continue  # "three strips: A, B and C": the members stand, not the plural
        if not any(mention is seen for seen in distinct):
            distinct.append(mention)
    if value == "each_side":
        if len(distinct) < 2 or (distinct[-1].count or 1) < 2:
            return None
        return "between", distinct[-2], (distinct[-1], distinct[-1])
    middle = before[-1] if before else None
    others = [m for m in distinct if m is not middle]
    end = next(
        (
            c.index
            for c in clauses[position + 1 :]
            if c.link is not None and c.link.norm in (".", "!", "?", ";")
        ),
        len(clauses),
    )
    later = list(
        {id(m): m for c in clauses[position + 1 : end] for m in c.named if m is not middle}.values()
    )
    if middle is not None and not others:
        # "california wonder in the middle, cayenne on one side, padron on the other": the
        # two named after it in its sentence
        if len(later) == 2:
            return "between", middle, (later[0], later[1])
        return None
    if middle is not None and len(others) == 1 and (others[0].count or 1) < 2 and later:
        # "Bintje at the front, Russet in the middle and Agria at the back": one named
        # before the middle, one after it
        return "between", middle, (others[0], later[0])
    if middle is not None and len(others) == 1 and (others[0].count or 1) == 2:
        return "between", middle, (others[0], others[0])  # "two potato fields and ..."
    if middle is None or len(others) != 2:
        return None
    return "between", middle, (others[0], others[1])


#: The words that place a field past the last one that way ("further east").
FURTHER = frozenset({"further", "farther", "furthest", "farthest"})


def furthest(
    kind: str,
    subject: Mention,
    start: Mention,
    read: Sequence[tuple[str, Mention, tuple[Mention, ...]]],
) -> Mention:
    """The field placed furthest ``kind`` of ``start`` by the relations read so far."""
    seen = {id(start)}
    current = start
    while True:
        past = next(
            (
                placed
                for said, placed, objects in read
                if said == kind
                and objects == (current,)
                and placed is not subject
                and id(placed) not in seen
            ),
            None,
        )
        if past is None:
            return current
        seen.add(id(past))
        current = past


#: Words that put a field on the far side of another from a third.
OTHER_SIDE = frozenset(
    {"on the other side of", "the other side of", "on the far side of", "the far side of"}
)


def on_the_other_side(
    beyond: Sequence[tuple[Mention, Mention, Item]],
    said: Sequence[tuple[str, Mention, tuple[Mention, ...]]],
    members: dict[int, list[int]],
    trace: list[TraceStep],
) -> list[RelationIntent]:
    """'a strip of dinkel beside it (the potatoes), and on the other side of the dinkel a
    cabbage plot': the dinkel lies between the potatoes and the cabbages."""
    relations: list[RelationIntent] = []
    for far, middle, link in beyond:
        for kind, subject, objects in said:
            pair = (subject, *objects)
            if kind != "next_to" or len(pair) != 2 or far in pair:
                continue
            if middle is subject or middle is objects[0]:
                near = objects[0] if middle is subject else subject
                relations += field_relations("between", middle, (near, far), members, link, trace)
                break
    return relations

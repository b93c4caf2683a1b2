"""Relations between fields: which mentions a relation word links, and in which direction.

"X north of Y" relates the mentions on either side; "X with Y to the north"
(a trailing direction) relates the last two named; "between" takes the two
mentions after it (or two members of one plural mention); a pronoun ("north of
them") points back at a mention already named; "side by side" after a list
makes a row. Plural mentions expand to their fields.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from typing import Any, get_args

from agrirecipe.recipe import RelationKind
from agrirecipe.resolve._decompose import Clause, Mention
from agrirecipe.resolve._intent import RelationIntent, TraceStep
from agrirecipe.resolve._landmarks import across_landmarks, held_by, landmark_of
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import (
    ARTICLES,
    OPPOSITE,
    PRONOUNS,
    THE_TWO,
    coordinated,
    field_relations,
    fields_of,
    following_list,
    last_named,
    listed_after,
    own_mentions,
    says,
)

__all__ = ["read_relations"]


def read_relations(
    clauses: Sequence[Clause],
    members: dict[int, list[int]],
    trace: list[TraceStep],
    warnings: list[str],
) -> list[RelationIntent]:
    """Relations between fields from the relation words between mentions.

    ``members`` maps ``id(mention)`` to the indexes of the fields it became.
    """
    relations: list[RelationIntent] = _adjacent_rows(clauses, members, trace)
    placed = _placements(clauses, members)
    for position, subject, centre in _placement_pairs(clauses, members, placed):
        link = clauses[position].link
        assert link is not None
        kind = link.data["value"]
        relations.extend(field_relations(kind, subject, (centre,), members, link, trace))
    landmarks: list[tuple[str, str, Mention, Item]] = []
    directed = _directed_neighbours(clauses)
    for position, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role not in ("relation", "between", "trailer"):
            continue
        if position in placed or position in directed.values():
            continue
        landmark = landmark_of(clause)
        if landmark is not None and clause.mentions:
            # "east of the yard there's 2 ha of apples": placed by the yard
            landmarks.append((str(link.data.get("value")), landmark, clause.mentions[0], link))
            continue
        if (
            link.role == "relation"
            and not clause.mentions
            and clause.items
            # ("tomatos right next to them in the glasshouse": next to the fields before)
            and clause.items[0].norm not in PRONOUNS
            # ("a lettuce field east of the big barn, and east of that again ...", "split
            # by a hawthorn hedge")
            and all(
                i.role in ("filler", "non_agricultural")
                or (i.role == "number" and i.norm in ARTICLES)
                for i in clause.items
            )
            and any("scenery" in i.data or i.role == "non_agricultural" for i in clause.items)
        ):
            # "the Winter Wheat east of the farmhouse ..., and west of the house the Russet
            # potatoes": kept to pair with a field on the landmark's other side
            named = [m for c in clauses[:position] for m in c.named]
            landmark = landmark_of(clause)
            held = held_by(clauses, position, landmark)
            if held is not None:
                # "In the tomato tunnel: ... Outside, right beside the tunnel, 6 rows of
                # peppers": placed by the field the scenery holds
                container, subject = held
                kind = str(link.data["value"])
                relations.extend(field_relations(kind, subject, (container,), members, link, trace))
                continue
            if named and landmark is not None and position - 1 == named[-1].clause:
                landmarks.append((str(link.data.get("value")), landmark, named[-1], link))
                continue
            # "a test strip along the farm track": placed by scenery, not by a field
            trace.append(
                TraceStep(
                    stage="decompose", subject=link.raw, detail="relative to scenery: not used"
                )
            )
            continue
        if (
            link.role in ("trailer", "relation")
            and not clause.mentions
            and position
            and not clauses[position - 1].mentions
            and any(i.scenery for i in clauses[position - 1].items)
            # (not "bananas along the stream to the east of them": scenery placed itself)
            and _not_placed(clauses[position - 1])
            # (not "in two polytunnels next to each other: tunnel 1 is Elsanta, ...")
            and not (link.role == "trailer" and len(listed_after(clauses, position)) >= 2)
        ):
            # "..., with the village road running along the east side", "Rain covers
            # rolled up above both": the scenery is placed, not a field
            trace.append(
                TraceStep(
                    stage="decompose", subject=link.raw, detail="relative to scenery: not used"
                )
            )
            continue
        # each field once, where last named ("blood oranges (Moro)" names one twice)
        before = last_named([m for c in clauses[:position] for m in c.named])
        if _of_everything(clause) and before and position - 1 == before[-1].clause:
            # "..., and a field of Agria potatoes south of everything": of each field
            for other in before[:-1]:
                relations.extend(
                    field_relations(link.data["value"], before[-1], (other,), members, link, trace)
                )
            continue
        # a pronoun's clause ("north of it") names no field of its own after the word
        after = [
            m for c in clauses[position:] for m in (c.named if c is not clause else own_mentions(c))
        ]
        said = " ".join(i.norm for i in clause.items)
        the_two = not clause.mentions and said in THE_TWO
        pronoun = bool(clause.items) and (
            clause.items[0].norm in PRONOUNS
            # "cherry tomatoes in between the two", "between both"
            or the_two
        )
        if (
            pronoun
            and not clause.mentions
            and position
            and not clauses[position - 1].named
            and any(i.scenery for i in clauses[position - 1].items)
            # (not "bananas along the stream to the east of them": a placement goes on)
            and (
                (placed_by := clauses[position - 1].link) is None
                or placed_by.role not in ("relation", "trailer", "between")
            )
        ):
            # "..., kids in yellow hats weeding between them": scenery placed, no field
            trace.append(
                TraceStep(stage="decompose", subject=link.raw, detail="said of scenery: not used")
            )
            continue
        if (
            pronoun
            and not clause.mentions
            and position
            and clauses[position - 1].named
            and clauses[position - 1].items  # not "one ... and, north of it, one ..."
        ):
            # "put valencia oranges north of it, and a banana plot ...": the pronoun
            # ends its clause after a subject, so it points back and the fields after
            # are not its subject ("a cherry orchard and, south of it, two fields" is)
            after = []
        if link.role == "trailer" and link.data.get("value") in ("next_to", "row"):
            ordered = link.data.get("value") == "row"
            group = coordinated(clauses, position) or listed_after(clauses, position)
            if len(group) > 2:
                # "potatoes, onions and cabbages side by side": a row, each beside the next.
                for first, second in zip(group[1:], group, strict=False):
                    relations.extend(
                        field_relations("next_to", first, (second,), members, link, trace)
                    )
                if ordered and len(group) == 3:
                    relations.extend(
                        field_relations(
                            "between", group[1], (group[2], group[0]), members, link, trace
                        )
                    )
                continue
            if len(group) == 2:
                # "comice and bartlett pears next to each other": the two side by side
                relations.extend(
                    field_relations("next_to", group[0], (group[1],), members, link, trace)
                )
                continue
            fields = members.get(id(group[0]), []) if len(group) == 1 else []
            if len(fields) >= 2:
                # "two different fruits side by side": the fields of one mention in a row.
                relations += _row(fields, group[0], link, trace, ordered=ordered)
                continue
            if ordered:
                warnings.append(f"ignored {link.raw!r}: it needs two or more fields before it")
                continue
        if link.role == "trailer" and str(link.data.get("value")) in _TOWARDS:
            relations += _directed_row(clauses, position, members, link, trace, warnings)
            continue
        if _one_and_the_other(clauses, position) and link.role == "relation":
            # "bananas, 2 plots, one above the other": the two named last, the first
            # named on the relation's side
            kind = link.data["value"]
            if len(before) >= 2:
                relations.extend(
                    field_relations(kind, before[-2], (before[-1],), members, link, trace)
                )
            elif (
                before
                and len(fields := members.get(id(before[-1]), [])) == 2
                and kind in get_args(RelationKind)
            ):
                # "two wheat plots, one north of the other"
                relations.append(
                    RelationIntent(
                        kind=kind, subject=fields[0], objects=(fields[1],), text=link.raw
                    )
                )
            continue
        ordinals = _ordinal_pair(clauses, position)
        if ordinals is not None and link.role == "relation" and before:
            # "one at 70,000 plants/ha, the other at 100,000; the first north of the second"
            fields = next(
                (f for m in reversed(before) if len(f := members.get(id(m), [])) >= 2), []
            )
            kind = link.data["value"]
            said_first, said_second = ordinals
            if max(ordinals) < len(fields) and kind in get_args(RelationKind):
                relations.append(
                    RelationIntent(
                        kind=kind,
                        subject=fields[said_first],
                        objects=(fields[said_second],),
                        text=link.raw,
                    )
                )
                continue
        listed = _listed_middle(clauses, position, link)
        if listed is not None:
            relations.extend(field_relations("between", listed[0], listed[1], members, link, trace))
            continue
        if link.role == "trailer" and link.data.get("value") in ("each_side", "middle"):
            pairs = _surrounded(str(link.data["value"]), clauses, position, before, after)
        elif (sides := _placed_by_the_middle(clauses, position)) is not None:
            # "To the north an orchard; in the middle wheat; to the south potatoes": each
            # side's field against the one in the middle
            pairs = (str(link.data["value"]), sides[0], (sides[1],))
        elif (fronted := _fronted(clauses, position)) is not None:
            # "...; west of the peppers an onion plot": the field after the object
            pairs = (link.data.get("value", "next_to"), fronted[0], (fronted[1],))
        else:
            # "pears on the north block, bananas ...": a trailer right after a field
            # places that field ("..., and to the north, pears" places the one after).
            attached = position > 0 and bool(clauses[position - 1].named)
            pairs = _relation_mentions(link, before, after, pronoun=pronoun, attached=attached)
        if pairs is None:
            warnings.append(f"ignored {link.raw!r}: it needs a field on each side")
            continue
        kind, subject, objects = pairs
        if position in directed and kind == "next_to":
            kind = str(clauses[directed[position]].link.data["value"])  # type: ignore[union-attr]
        relations.extend(field_relations(kind, subject, objects, members, link, trace))
        if (
            the_two
            and kind != "between"
            and len(before) >= 3
            and subject is before[-1]
            and objects == (before[-2],)
        ):
            # "Padron on the west side, Cayenne on the east side, and corn south of both"
            relations.extend(field_relations(kind, subject, (before[-3],), members, link, trace))
    relations += across_landmarks(landmarks, members, trace)
    related = {frozenset((r.subject, *r.objects)) for r in relations if len(r.objects) == 1}
    relations += _then_chain(clauses, members, related, trace)
    relations += _one_side_and_the_other(clauses, members, relations, trace)
    # "San Marzano and beef tomatoes, with cherry tomatoes in between them": two fields
    # with a third between them are not next to each other
    flanking = {frozenset(r.objects) for r in relations if r.kind == "between"}
    relations = [
        r
        for r in relations
        if not (r.kind == "next_to" and frozenset((r.subject, *r.objects)) in flanking)
    ]
    unique: dict[tuple[object, ...], RelationIntent] = {}
    for relation in relations:  # "in a line, in this order": one row
        unique.setdefault((relation.kind, relation.subject, relation.objects), relation)
    return list(unique.values())


def _directed_neighbours(clauses: Sequence[Clause]) -> dict[int, int]:
    """'further north again, beyond the orchard, there's wheat': a direction said on its
    own just before a 'next to' word gives that word its side. Maps the position of
    the 'next to' clause to the direction's."""
    found: dict[int, int] = {}
    for position, clause in enumerate(clauses):
        link = clause.link
        if (
            link is None
            or link.role != "trailer"
            or link.data.get("value") not in OPPOSITE
            or clause.mentions
            or any(i.role != "filler" for i in clause.items)
        ):
            continue
        following = position + 1
        while (
            following < len(clauses)
            and not clauses[following].items
            and clauses[following].link is not None
            and clauses[following].link.role == "separator"  # type: ignore[union-attr]
        ):
            following += 1
        if following < len(clauses):
            nxt = clauses[following].link
            if nxt is not None and nxt.role == "relation" and nxt.data.get("value") == "next_to":
                found[following] = position
    return found


def _then_chain(
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
    for position, clause in enumerate(clauses):
        link = clause.link
        if not clause.mentions:
            continue
        mention = clause.mentions[0]
        follows = (link is not None and link.norm == "then") or (
            position > 0
            and clauses[position - 1].link is not None
            and clauses[position - 1].link.norm == "then"  # type: ignore[union-attr]
            and not clauses[position - 1].items
        )
        if follows and chain:
            if all(mention is not m for m in chain):
                chain.append(mention)
        elif not chain or len(chain) < 2:
            chain = [clause.mentions[-1]]
    fields = [m for m in chain if len(members.get(id(m), [])) == 1]
    indices = [members[id(m)][0] for m in fields]
    if len(fields) < 2 or any(frozenset(pair) in related for pair in itertools.pairwise(indices)):
        return []
    link_item = next(c.link for c in clauses if c.link is not None and c.link.norm == "then")
    relations: list[RelationIntent] = []
    for first, second in itertools.pairwise(fields):
        relations.extend(field_relations("next_to", second, (first,), members, link_item, trace))
    if len(fields) == 3:
        relations.extend(
            field_relations("between", fields[1], (fields[0], fields[2]), members, link_item, trace)
        )
    return relations


_ORDINALS = {"first": 0, "second": 1, "third": 2, "fourth": 3}


def _ordinal_pair(clauses: Sequence[Clause], position: int) -> tuple[int, int] | None:
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


def _not_placed(clause: Clause) -> bool:
    """Whether a clause is not itself placed by a relation word before it."""
    return clause.link is None or clause.link.role not in ("relation", "trailer", "between")


def _one_and_the_other(clauses: Sequence[Clause], position: int) -> bool:
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


#: "from west to east": each field of the row lies on this side of the next one.
_TOWARDS = {
    "towards_east": "west_of",
    "towards_west": "east_of",
    "towards_north": "south_of",
    "towards_south": "north_of",
}


#: What "everything" a field is placed against may be said as ("south of all the rest").
_EVERYTHING = frozenset(
    {
        "everything",
        "everything else",
        "all the rest",
        "the rest",
        "all the others",
        "the others",
        "all of them",
        "all the other fields",
        "all the other plots",
    }
)


def _of_everything(clause: Clause) -> bool:
    """Whether a relation's clause names every other field ("south of everything")."""
    return not clause.mentions and " ".join(i.norm for i in clause.items) in _EVERYTHING


def _placed_by_the_middle(
    clauses: Sequence[Clause], position: int
) -> tuple[Mention, Mention] | None:
    """The field a direction opening clause ``position`` places ("To the north an
    orchard; in the middle ...") and the field "in the middle" it is placed against, or
    None."""
    clause = clauses[position]
    link = clause.link
    if link is None or link.role != "trailer" or link.data.get("value") not in OPPOSITE:
        return None
    placed = _opened_by(clauses, position)
    if placed is None:
        return None
    middles = [
        c.mentions[0]
        for c in clauses
        if c.link is not None
        and c.link.role == "trailer"
        and c.link.data.get("value") == "middle"
        and len(c.mentions) == 1
    ]
    if len(middles) != 1 or middles[0] is placed:
        return None
    return placed, middles[0]


def _opened_by(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The one field a direction opening clause ``position`` places: in that clause ("To
    the north an orchard") or right after a comma ("To the north, the orchard, ...")."""
    clause = clauses[position]
    if len(clause.mentions) == 1 and clause.items[:1] == clause.mentions[0].items[:1]:
        return clause.mentions[0]
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    if (
        not clause.mentions
        and not clause.items
        and following is not None
        and following.link is not None
        and following.link.norm == ","
        and len(following.mentions) == 1
    ):
        return following.mentions[0]
    return None


def _fronted(clauses: Sequence[Clause], position: int) -> tuple[Mention, Mention] | None:
    """'West of the peppers, an onion plot', 'north of A: Conference pears': a relation
    that opens its sentence, its object and then its subject (subject, object)."""
    clause = clauses[position]
    link = clause.link
    if link is None or link.role != "relation" or not clause.mentions:
        return None
    if position:
        previous = clauses[position - 1]
        opens = not previous.items and (
            previous.link is None
            or previous.link.norm in (";", ".", ":", "!", ",")
            or previous.link.role == "conjunction"  # ", and south of the bananas a citrus"
        )
        if not opens:
            return None
    if len(clause.mentions) >= 2:
        subject, target = clause.mentions[1], clause.mentions[0]
    else:
        after = position + 1
        while (
            after + 1 < len(clauses)
            and not clauses[after].mentions
            and clauses[after].link is not None
            and clauses[after].link.norm == ","  # type: ignore[union-attr]
            and all(i.role in ("filler", "side", "of") for i in clauses[after].items)
        ):
            after += 1  # "south of the orchard, across the lane, there's ...": scenery between
        following = clauses[after] if after < len(clauses) else None
        if (
            following is None
            or following.link is None
            or following.link.norm not in (":", ",")
            or not following.mentions
        ):
            return None
        subject, target = following.mentions[0], clause.mentions[0]
    return None if subject is target else (subject, target)


def _directed_row(
    clauses: Sequence[Clause],
    position: int,
    members: dict[int, list[int]],
    link: Item,
    trace: list[TraceStep],
    warnings: list[str],
) -> list[RelationIntent]:
    """'three strips from west to east: wheat, potatoes, maize', 'A, B and C from north
    to south': the fields in the order named, each on one side of the next."""
    fields = fields_of(list(reversed(coordinated(clauses, position))), members)
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
        warnings.append(f"ignored {link.raw!r}: it needs two or more fields before it")
        return []
    if link.norm.startswith("looking") and any(
        i.role == "zone" for c in clauses[position:] for m in c.mentions for i in m.items
    ):
        # "Looking north: wheat at the far north end, ... strawberries closest to me":
        # the zones place the fields; the view only says where the viewer faces
        return []
    kind = _TOWARDS[str(link.data["value"])]
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


def _listed_middle(
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


def _one_side_and_the_other(
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
    return field_relations("next_to", other, (one,), members, side, trace)


def _adjacent_rows(
    clauses: Sequence[Clause], members: dict[int, list[int]], trace: list[TraceStep]
) -> list[RelationIntent]:
    """'three adjacent fields': the fields of a mention described as adjacent, in a row."""
    rows: list[RelationIntent] = []
    seen: set[int] = set()
    for clause in clauses:
        for mention in clause.mentions:
            fields = members.get(id(mention), [])
            adjacent = [i for i in mention.items if i.data.get("adjacent")]
            if len(fields) < 2 or not adjacent or id(mention) in seen:
                continue
            seen.add(id(mention))
            rows += _row(fields, mention, adjacent[0], trace, ordered=False)
    return rows


def _row(
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


def _surrounded(
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
    if middle is not None and not others:
        # "california wonder in the middle, cayenne on one side, padron on the other": the
        # two named after it in its sentence
        end = next(
            (
                c.index
                for c in clauses[position + 1 :]
                if c.link is not None and c.link.norm in (".", "!", "?", ";")
            ),
            len(clauses),
        )
        others = list(
            {
                id(m): m for c in clauses[position + 1 : end] for m in c.named if m is not middle
            }.values()
        )
        if len(others) == 2:
            return "between", middle, (others[0], others[1])
        return None
    if middle is not None and len(others) == 1 and (others[0].count or 1) == 2:
        return "between", middle, (others[0], others[0])  # "two potato fields and ..."
    if middle is None or len(others) != 2:
        return None
    return "between", middle, (others[0], others[1])


def _relation_mentions(
    link: Item,
    before: Sequence[Mention],
    after: Sequence[Mention],
    *,
    pronoun: bool,
    attached: bool = False,
) -> tuple[Any, Mention, tuple[Mention, ...]] | None:
    kind = link.data.get("value", "between") if link.role != "between" else "between"
    if kind == "flanks":
        # "Durondeau and Williams pears on either side of a Jonagold block"
        if not after:
            return None
        if pronoun and before:
            # "the Cabernet, and either side of it Chardonnay ... and Pinot Nero ...": it
            # lies between the two named after
            return ("between", before[-1], (after[0], after[1])) if len(after) >= 2 else None
        if before and (before[-1].count or 1) >= 2:
            return "between", after[0], (before[-1], before[-1])
        if len(before) >= 2:
            return "between", after[0], (before[-2], before[-1])
        return None
    if pronoun and not after and len(before) >= 2:
        # "a couple of wheat fields and a maize field in between them".
        if kind == "between" and (before[-2].count or 1) >= 2:
            return kind, before[-1], (before[-2], before[-2])
        if kind != "between":
            return kind, before[-1], (before[-2],)
    if pronoun and not after and len(before) >= 3 and kind == "between":
        # "wheat, maize and a strawberry patch between them".
        return kind, before[-1], (before[-3], before[-2])
    if pronoun and before and after:
        # "two potato fields and between them / north of them a wheat field": the
        # pronoun is the object, named before; the subject comes after.
        objects = (before[-1],) if kind != "between" else (before[-1], before[-1])
        if kind != "between" or (before[-1].count or 1) >= 2:
            return kind, after[0], objects
        if len(before) >= 2:
            # "wheat in the north, maize in the south, and in between them a strip of
            # strawberries": the two fields named last
            return kind, after[0], (before[-2], before[-1])
    if link.role == "between":
        # each once ("carrots (nantes) & cabbage (savoy)" names each twice)
        after = list({id(m): m for m in after}.values())
        if after and before and (after[0].count or 1) >= 2:
            return "between", before[-1], (after[0], after[0])
        if len(after) < 2:
            return None
        if before:
            return "between", before[-1], (after[0], after[1])
        if len(after) >= 3:
            return "between", after[2], (after[0], after[1])
        return None
    if link.role == "trailer":
        if len(before) >= 2 and before[-1].clause == before[-2].clause:
            return kind, before[-1], (before[-2],)
        if before and after and attached:
            return kind, before[-1], (after[0],)
        if before and after:
            return kind, after[0], (before[-1],)
        if len(before) >= 2:
            return kind, before[-1], (before[-2],)
        return None
    if before and after:
        return kind, before[-1], (after[0],)
    if len(after) >= 2:
        return kind, after[1], (after[0],)
    if len(before) >= 2:
        # "... with an onion field to the north of them": the object was named before.
        return kind, before[-1], (before[-2],)
    return None


def _placements(clauses: Sequence[Clause], members: dict[int, list[int]]) -> dict[int, Mention]:
    """Fields placed by a trailing direction right after them: "wheat to the north, ...".

    Maps the position of the trailer's clause to the one mention of the clause before
    it ("an orchard with wheat to the north" names two and is read as before).
    """
    placed: dict[int, Mention] = {}
    for position, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role != "trailer" or link.data.get("value") not in OPPOSITE:
            continue
        if position == 0 or clause.mentions or any(i.role != "filler" for i in clause.items):
            continue
        previous = clauses[_past_a_bracket(clauses, position - 1)].named
        if len(previous) == 1 and id(previous[0]) in members:
            placed[position] = previous[0]
    return placed


def _past_a_bracket(clauses: Sequence[Clause], index: int) -> int:
    """``index``, or the clause before the bracket that clause ``index`` closes ("a
    Cabernet vineyard (2.7 m rows) to the south": the vineyard is placed)."""
    link = clauses[index].link
    if clauses[index].named or link is None or link.norm != ")":
        return index
    for back in range(index - 1, 0, -1):
        opening = clauses[back].link
        if opening is not None and opening.norm == "(":
            # ("(2.7 m rows, 1.2 m vines)": the bracket may name the same field again)
            inside = {id(m) for c in clauses[back:index] for m in c.named}
            return back - 1 if inside <= {id(m) for m in clauses[back - 1].named} else index
    return index


def _placement_pairs(
    clauses: Sequence[Clause], members: dict[int, list[int]], placed: dict[int, Mention]
) -> list[tuple[int, Mention, Mention]]:
    """(trailer position, placed field, what it is placed relative to) for each placement.

    A placed field is related to the nearest field named without a direction (the
    one before it, else the first after it): "an orchard, wheat to the north and
    maize to the south", "wheat to the north, maize to the south and strawberries
    between them". With no such field, opposite placements relate to each other:
    "wheat to the north, maize to the south" is wheat north of maize. A placement
    left without a partner is dropped here and read the usual way.
    """
    placed_ids = {id(m) for m in placed.values()}
    # A field placed by a direction word of its own ("valencia oranges north of it")
    # is not the centre others are placed around.
    for clause, following in itertools.pairwise(clauses):
        link = following.link
        if (
            clause.mentions
            and link is not None
            and link.role == "relation"
            and link.data.get("value") in OPPOSITE
        ):
            placed_ids.add(id(clause.mentions[-1]))
    free = [m for c in clauses for m in c.named if id(m) not in placed_ids and id(m) in members]
    pairs: list[tuple[int, Mention, Mention]] = []
    waiting: list[tuple[int, Mention]] = []
    for position, mention in placed.items():
        earlier = [m for m in free if m.clause < mention.clause]
        later = [m for m in free if m.clause > mention.clause]
        centre = earlier[-1] if earlier else (later[0] if later else None)
        if centre is not None:
            pairs.append((position, mention, centre))
            continue
        kind = clauses[position].link.data["value"]  # type: ignore[union-attr]
        partner = next(
            (
                (p, m)
                for p, m in waiting
                if clauses[p].link.data["value"] == OPPOSITE[kind]  # type: ignore[union-attr]
            ),
            None,
        )
        if partner is None:
            waiting.append((position, mention))
            continue
        waiting.remove(partner)
        pairs.append((partner[0], partner[1], mention))
    for position, _ in waiting:
        del placed[position]
    return pairs

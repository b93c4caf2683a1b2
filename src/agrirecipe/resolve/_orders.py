"""Orders between fields the words imply but do not say (issue 8).

"the onions in between them" with the potatoes north and the carrots south of the onions
puts the potatoes north of the carrots (:func:`complete_orders`); a field said to be
next to another that zones already place in order is placed by the zones
(:func:`drop_placed_neighbours`); "three wheat fields running north to south, with a
maize field at the southern end" puts the maize past the last wheat field
(:func:`past_a_row_end`). The prompt reader (``_parse``) asks these once the
relation words and the zones are read.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.recipe import RelationKind
from agrirecipe.resolve._intent import RelationIntent
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._zones import zone_of

__all__ = ["complete_orders", "drop_placed_neighbours", "past_a_row_end"]


def complete_orders(
    relations: Sequence[RelationIntent], fields: Sequence[Sequence[Item]]
) -> list[RelationIntent]:
    """Orders the words imply but do not say, on each axis.

    "the onions in between them" with the potatoes north and the carrots south of
    the onions puts the potatoes north of the carrots (and with only the potatoes
    placed, the carrots south of the onions); "Gala along the top, pears
    below them, at the bottom Granny" puts the pears north of the Granny (a field
    placed next to the top zone lies above the bottom zone, and vice versa).
    """
    edges: dict[str, set[tuple[int, int]]] = {"ns": set(), "ew": set()}
    for relation in relations:
        if relation.kind == "between":
            continue
        (other,) = relation.objects
        if relation.kind in ("north_of", "west_of"):
            pair = (relation.subject, other)
        elif relation.kind in ("south_of", "east_of"):
            pair = (other, relation.subject)
        else:
            continue
        edges["ns" if relation.kind in ("north_of", "south_of") else "ew"].add(pair)
    zones: dict[int, str] = {}
    for index, items in enumerate(fields):
        zone = zone_of(items)
        if zone is not None:
            zones[index] = zone
    added: list[tuple[str, int, int]] = []

    def related(axis: str, a: int, b: int) -> bool:
        return (a, b) in edges[axis] or (b, a) in edges[axis]

    for relation in relations:
        if relation.kind != "between":
            continue
        middle, (a, b) = relation.subject, relation.objects
        for axis in ("ns", "ew"):
            for first, last in ((a, b), (b, a)):
                path = (first, middle) in edges[axis] and (middle, last) in edges[axis]
                if path and not related(axis, first, last):
                    added.append((axis, first, last))
                # "Cos sandwiched between onions and potatoes; onions on the north side":
                # one end placed, the other end lies on the far side of the middle one
                if (first, middle) in edges[axis] and not related(axis, middle, last):
                    added.append((axis, middle, last))
                # ("...; potatoes on the west side": the ends placed, the middle between)
                if (first, last) in edges[axis]:
                    if not related(axis, first, middle):
                        added.append((axis, first, middle))
                    if not related(axis, middle, last):
                        added.append((axis, middle, last))
    for axis, (high, low) in (("ns", ("north", "south")), ("ew", ("west", "east"))):
        tops = [i for i, z in zones.items() if z == high]
        bottoms = [i for i, z in zones.items() if z == low]
        for top in tops:
            for bottom in bottoms:
                for middle in range(len(fields)):
                    if middle in zones:
                        continue
                    if (top, middle) in edges[axis] and not related(axis, middle, bottom):
                        added.append((axis, middle, bottom))
                    if (middle, bottom) in edges[axis] and not related(axis, top, middle):
                        added.append((axis, top, middle))
    kinds: dict[str, RelationKind] = {"ns": "north_of", "ew": "west_of"}
    completed = [
        RelationIntent(kind=kinds[axis], subject=high_index, objects=(low_index,))
        for axis, high_index, low_index in dict.fromkeys(added)
    ]
    # "onions in the west field, Imperator in the middle one and Danvers in the east
    # field": a field with one field on each side of it on one axis is between them
    middles = {r.subject for r in relations if r.kind == "between"}
    other_axis = {"ns": "ew", "ew": "ns"}
    for axis in ("ns", "ew"):
        for middle in range(len(fields)):
            before = [a for a, b in edges[axis] if b == middle]
            after = [b for a, b in edges[axis] if a == middle]
            if (
                len(before) == 1
                and len(after) == 1
                and len({middle, before[0], after[0]}) == 3
                and middle not in middles
                # ("Riesling to the north, Pinot Nero to the south, Chardonnay to the
                # east": the east parcel lies east of both ends, beside them, not in line)
                and not (
                    related(other_axis[axis], middle, before[0])
                    and related(other_axis[axis], middle, after[0])
                )
            ):
                middles.add(middle)
                completed.append(
                    RelationIntent(kind="between", subject=middle, objects=(before[0], after[0]))
                )
                placed_against = {
                    r.subject for r in relations if r.objects == (middle,) and r.kind != "between"
                }
                if (
                    {before[0], after[0]} <= placed_against
                    and not related(axis, before[0], after[0])
                    and (axis, *before, *after) not in added
                ):
                    # "cherries on the north block, pears on the south block, and
                    # strawberries in between": the two placed against the middle one are
                    # in that order themselves
                    completed.append(
                        RelationIntent(kind=kinds[axis], subject=before[0], objects=(after[0],))
                    )
    return completed


#: A zone at one end of an axis: the axis, and whether it is the far end of its order.
_ENDS = {"north": ("ns", False), "south": ("ns", True), "west": ("ew", False), "east": ("ew", True)}


def past_a_row_end(
    relations: Sequence[RelationIntent], fields: Sequence[Sequence[Item]]
) -> list[RelationIntent]:
    """'Three wheat fields in a line running north to south, with a maize field at the
    southern end': the one field given an end of its own, of fields placed in a row on
    that axis, lies past the row's last field that way."""
    zones = {index: zone_of(items) for index, items in enumerate(fields)}
    zoned = [(index, zone) for index, zone in zones.items() if zone is not None]
    if len(zoned) != 1 or zoned[0][1] not in _ENDS:
        return []
    (index, zone) = zoned[0]
    axis, far = _ENDS[zone]
    edges: set[tuple[int, int]] = set()
    for relation in relations:
        if index in (relation.subject, *relation.objects):
            return []  # (placed already: the words say where)
        if relation.kind in ("north_of", "west_of", "south_of", "east_of"):
            (other,) = relation.objects
            first = relation.kind in ("north_of", "west_of")
            pair = (relation.subject, other) if first else (other, relation.subject)
            if ("ns" if relation.kind in ("north_of", "south_of") else "ew") == axis:
                edges.add(pair)
    placed = {i for pair in edges for i in pair}
    if len(placed) < 2:
        return []
    # the row's end that way: the one field with none past it
    ends = [i for i in placed if not any(pair[0 if far else 1] == i for pair in edges)]
    if len(ends) != 1:
        return []
    kinds: dict[str, RelationKind] = {"ns": "north_of", "ew": "west_of"}
    high, low = (ends[0], index) if far else (index, ends[0])
    return [RelationIntent(kind=kinds[axis], subject=high, objects=(low,))]


def drop_placed_neighbours(
    relations: Sequence[RelationIntent], zoned: Sequence[RelationIntent]
) -> list[RelationIntent]:
    """Two fields their zones place on one side of each other are not only 'next to'
    each other ("the orchard at the north end, then wheat": north of, not beside)."""
    placed = {frozenset((r.subject, *r.objects)) for r in zoned if r.kind != "between"}
    return [
        r
        for r in relations
        if r.kind != "next_to"
        or frozenset((r.subject, *r.objects)) not in placed
        # ("two wheat fields next to each other: dinkel on the left, durum on the right":
        # said to touch, and placed too)
        or _said_to_touch(r)
    ]


#: Words that say fields touch, whatever side each is on.
_TOUCHING = ("each other", "one another", "side by side", "touch", "meet", "adjoin")


def _said_to_touch(relation: RelationIntent) -> bool:
    text = (relation.text or "").lower()
    return any(words in text for words in _TOUCHING)

"""Zones of a farm: "stone fruit along the top, roots in the middle, grain at the bottom".

The zone words are data (``data/zones.yaml``). :func:`find_zones` finds them in
the prompt's words (one regular expression per zone, linear in the prompt's
length); each becomes a ``zone`` item that belongs to the field of its clause.
:func:`zone_relations` then places the fields: top above middle above bottom
(``north_of``), left of centre left of right (``west_of``).
"""

from __future__ import annotations

import functools
import itertools
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import yaml

from agrirecipe.recipe import RelationKind
from agrirecipe.resolve._intent import RelationIntent
from agrirecipe.resolve._lexicon import DATA_DIR, Item, Token, vocabulary

__all__ = [
    "ZoneMatch",
    "find_zones",
    "lone_side",
    "zone_of",
    "zone_owners",
    "zone_relations",
]

#: Where each zone lies on the north-south and east-west axes (0 first, 2 last).
_PLACES: dict[str, dict[str, int]] = {
    "north": {"ns": 0},
    "south": {"ns": 2},
    "west": {"ew": 0},
    "east": {"ew": 2},
    "northwest": {"ns": 0, "ew": 0},
    "northeast": {"ns": 0, "ew": 2},
    "southwest": {"ns": 2, "ew": 0},
    "southeast": {"ns": 2, "ew": 2},
    # a photo's depth: only "between" is read from it
    "near": {"depth": 0},
    "far": {"depth": 2},
}
# (the quarters first: "top left" is the north-west, not the north)
_ZONES = (*sorted(_PLACES, key=lambda zone: -len(_PLACES[zone])), "middle")


@dataclass(frozen=True, slots=True)
class ZoneMatch:
    """A zone word and its tokens (``first``..``last`` - 1)."""

    zone: str
    first: int
    last: int


@functools.cache
def _patterns() -> tuple[tuple[str, re.Pattern[str]], ...]:
    """(zone, pattern) for each zone, after ("order", pattern) for the words that are not."""
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "zones.yaml").read_text("utf-8"))
    orders = "|".join(re.escape(str(p)) for p in sorted(data["orders"], key=len, reverse=True))
    # ("On the left of the picture is a field of cabbage": a side of the photo, a zone)
    frames = "|".join(re.escape(str(w)) for w in data["frames"])
    patterns = [
        (
            "order",
            re.compile(rf"(?<![a-z0-9])(?:{orders})(?![a-z0-9])(?! the (?:{frames})(?![a-z0-9]))"),
        )
    ]
    for zone in _ZONES:
        phrases = sorted((str(p) for p in data[zone]), key=len, reverse=True)
        alternation = "|".join(re.escape(p) for p in phrases)
        patterns.append((zone, re.compile(rf"(?<![a-z0-9])(?:{alternation})(?![a-z0-9])")))
    for zone, words in data["bare_places"].items():
        alternation = "|".join(re.escape(str(w)) for w in sorted(words, key=len, reverse=True))
        # ("the road running along the east side.": placed by a preposition, a relation)
        # ("cereals SW and veg SE": or before "and" and the next member)
        pattern = (
            rf"(?<![a-z0-9])(?<!along )(?<!on )(?<!by )(?:{alternation})(?= [,.;:!?]| -| and |$)"
        )
        patterns.append((str(zone), re.compile(pattern)))
    for zone, words in data["bare_sides"].items():
        alternation = "|".join(re.escape(str(w)) for w in words)
        after_a_name = r"(?<=[a-z] )(?<!all )(?<! s )(?<! is )(?<! was )(?<! are )(?<!nothing )"
        pattern = rf"{after_a_name}(?:{alternation})(?= [,.;]| and |$)"
        patterns.append((str(zone), re.compile(pattern)))
    for zone, words in data["leading_places"].items():
        alternation = "|".join(re.escape(str(w)) for w in sorted(words, key=len, reverse=True))
        opening = r"(?:^|(?<=[,.;:!?] )|(?<= and ))"
        pattern = rf"{opening}(?:{alternation})(?= [a-z])(?! (?:of|wind|winds|breeze)\b)"
        patterns.append((str(zone), re.compile(pattern)))
    nouns = sorted((*vocabulary()["plot_nouns"], "one", "ones"), key=len, reverse=True)
    plots = "|".join(re.escape(str(n)) for n in nouns)
    for zone, words in data["before_plots"].items():
        alternation = "|".join(re.escape(str(w)) for w in words)
        pattern = rf"(?<![a-z0-9])(?:{alternation})(?= (?:{plots})(?![a-z0-9]))"
        patterns.append((str(zone), re.compile(pattern)))
    for zone, words in data["opening_plots"].items():
        alternation = "|".join(re.escape(str(w)) for w in words)
        opening = r"(?:^|(?<=[,.;:!?] ))"
        pattern = rf"{opening}(?:{alternation})(?= (?:{plots})(?![a-z0-9]))"
        patterns.append((str(zone), re.compile(pattern)))
    return tuple(patterns)


def find_zones(tokens: Sequence[Token], claimed: Sequence[bool] = ()) -> list[ZoneMatch]:
    """Zone words of the prompt, when it describes a farm by zones (two or more of them).

    One zone word alone ("top quality", "the middle field") is not a zoning, and
    "in the middle" counts only beside a zone on either side of it.
    """
    found, taken = _zone_matches(tokens, claimed)
    found = _as_seen(found, tokens)
    found = _paired_sides(found, tokens)
    if not any(m.zone == "near" for m in found):
        # ("the Kordia cherries on the far side of the pears", "... carrots on the far
        # side": "the far side" is a depth only opposite a near side said too)
        found = [m for m in found if not _a_far_side(m, tokens)]
    compass = any(m.zone in _PLACES and "depth" not in _PLACES[m.zone] for m in found)
    # "looking east ...: potatoes closest to me": the compass places, not the depth; the
    # depth words stay zone words ("potatoes closest to the camera at the bottom"), read
    # after a field's compass zone
    sides = {m.zone for m in found if m.zone != "middle"}
    if compass:
        sides -= {"near", "far"}
    if len(sides) == 1 and (other := _the_other_half(found, tokens, taken)) is not None:
        found.append(other)  # "Half the farm is maize, the northern half, and the rest ..."
        sides.add(other.zone)
    if len(sides) < 2 and not (sides and any(m.zone == "middle" for m in found)):
        return _row_end(found, tokens, claimed)
    return sorted(found, key=lambda m: m.first)


#: The axis of each compass side, and the row directions of the relation words on it.
_AXES = {"north": "ns", "south": "ns", "west": "ew", "east": "ew"}
_ROW_DIRECTIONS = {
    "ns": ("towards_north", "towards_south"),
    "ew": ("towards_east", "towards_west"),
}


def _row_end(
    found: Sequence[ZoneMatch], tokens: Sequence[Token], claimed: Sequence[bool]
) -> list[ZoneMatch]:
    """'Three wheat fields in a line running north to south, with a maize field at the
    southern end': one end zone of its own is a zone when the prompt lays fields out in a
    row on that axis (past the row's end: :func:`agrirecipe.resolve._orders.past_a_row_end`)."""
    if len(found) != 1 or found[0].zone not in _AXES:
        return []
    match = found[0]
    if tokens[match.last - 1].norm != "end":
        return []
    free = " ".join(
        t.norm if not (claimed and claimed[i]) and not match.first <= i < match.last else "|"
        for i, t in enumerate(tokens)
    )
    return [match] if _row_direction(_AXES[match.zone]).search(free) else []


@functools.cache
def _row_direction(axis: str) -> re.Pattern[str]:
    """The relation words that lay fields out in a row on ``axis`` ("north to south")."""
    trailers = vocabulary()["relation_trailers"]
    phrases = sorted(
        (str(p) for d in _ROW_DIRECTIONS[axis] for p in trailers[d]), key=len, reverse=True
    )
    alternation = "|".join(re.escape(p) for p in phrases)
    return re.compile(rf"(?<![a-z0-9])(?:{alternation})(?![a-z0-9])")


def _a_far_side(match: ZoneMatch, tokens: Sequence[Token]) -> bool:
    """Whether the zone match is "(on) the far side"."""
    words = [t.norm for t in tokens[match.first : match.last]]
    return match.zone == "far" and words[-3:] == ["the", "far", "side"]


@functools.cache
def _bare_sides() -> dict[str, str]:
    """The bare side words ("left", "right") and the zone each names."""
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "zones.yaml").read_text("utf-8"))
    return {str(w): str(zone) for zone, words in data["bare_sides"].items() for w in words}


def _paired_sides(found: Sequence[ZoneMatch], tokens: Sequence[Token]) -> list[ZoneMatch]:
    """A bare "left" or "right" is a zone only across from a zone on the other side
    ("cereals left, fruit right"; not "potatoes with a few tubers left, ...")."""
    across = {"west": "east", "east": "west"}
    zones = {m.zone for m in found}
    sides = _bare_sides()
    return [
        m
        for m in found
        if not (
            m.last - m.first == 1
            and sides.get(tokens[m.first].norm) == m.zone
            and across[m.zone] not in zones
        )
    ]


def _zone_matches(
    tokens: Sequence[Token], claimed: Sequence[bool] = ()
) -> tuple[list[ZoneMatch], list[bool]]:
    """Every zone word of the prompt, and the tokens they (and the order words) take."""
    starts: list[int] = []
    offset = 0
    for token in tokens:
        starts.append(offset)
        offset += len(token.norm) + 1
    text = " ".join(token.norm for token in tokens)
    index_of = {start: index for index, start in enumerate(starts)}
    taken = list(claimed) or [False] * len(tokens)
    found: list[ZoneMatch] = []
    for zone, pattern in _patterns():
        for match in pattern.finditer(text):
            first = index_of.get(match.start())
            end = match.end()
            last = next((i for i, s in enumerate(starts) if s >= end), len(tokens))
            if first is None or any(taken[first:last]):
                continue
            if first and tokens[first - 1].norm == "from" and zone != "order":
                continue  # "shot from the top of the water tower": where the photo is taken
            if zone != "order":
                last = _past_part_of(tokens, last)
                found.append(ZoneMatch(zone, first, last))
            for index in range(first, last):
                taken[index] = True
    return found, taken


@functools.cache
def _parts_of() -> frozenset[str]:
    """Words a zone is said to be part of ("the top third of the slope")."""
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "zones.yaml").read_text("utf-8"))
    return frozenset(str(w) for w in data["parts_of"])


def _past_part_of(tokens: Sequence[Token], last: int) -> int:
    """The end of a zone word with what it is part of ("top third of the slope")."""
    words = [t.norm for t in tokens[last : last + 3]]
    if len(words) == 3 and words[:2] == ["of", "the"] and words[2] in _parts_of():
        return last + 3
    return last


#: The opposite side of each compass side.
_OPPOSITE_SIDE = {"north": "south", "south": "north", "east": "west", "west": "east"}
#: Words for the half of a farm that one half leaves.
_REST = (
    ("the", "rest"),
    ("the", "remainder"),
    ("the", "other", "half"),
    ("the", "remaining", "half"),
)


def _the_other_half(
    found: Sequence[ZoneMatch], tokens: Sequence[Token], taken: Sequence[bool]
) -> ZoneMatch | None:
    """'Half the farm is maize, the northern half, and the rest is wheat': the rest of a
    farm one half of which is named lies on the other side."""
    halves = [
        m
        for m in found
        if m.zone in _OPPOSITE_SIDE and any(t.norm == "half" for t in tokens[m.first : m.last])
    ]
    if len(halves) != 1:
        return None
    words = [t.norm for t in tokens]
    for start in range(halves[0].last, len(words)):
        for rest in _REST:
            end = start + len(rest)
            if tuple(words[start:end]) == rest and not any(taken[start:end]):
                return ZoneMatch(_OPPOSITE_SIDE[halves[0].zone], start, end)
    return None


#: Compass sides in clockwise order, and how far each turns a view that faces north.
_CLOCKWISE = ("north", "east", "south", "west")
#: Words of a zone said from where the viewer stands ("on the left", "top of the frame").
_VIEWED = frozenset({"left", "right", "frame", "picture", "photo", "shot"})


def _as_seen(found: Sequence[ZoneMatch], tokens: Sequence[Token]) -> list[ZoneMatch]:
    """'Looking south from the yard: Centenary on the left, ... Sonata on the right': a
    viewer facing south has east on the left, so left and right (and the top and bottom
    of the frame) turn with the way the viewer faces; a map's own sides do not."""
    facing = next(
        (
            b.norm
            for a, b in itertools.pairwise(tokens)
            if a.norm in ("looking", "facing") and b.norm in _CLOCKWISE
        ),
        "north",
    )
    turn = _CLOCKWISE.index(facing)
    if not turn:
        return list(found)
    seen: list[ZoneMatch] = []
    for match in found:
        words = {t.norm for t in tokens[match.first : match.last]}
        if match.zone in _CLOCKWISE and words & _VIEWED:
            zone = _CLOCKWISE[(_CLOCKWISE.index(match.zone) + turn) % 4]
            match = ZoneMatch(zone, match.first, match.last)
        seen.append(match)
    return seen


def zone_of(items: Sequence[Item]) -> str | None:
    """A field's zone: a compass one before a photo's depth ("closest to me at the south
    end" is south)."""
    zones = [str(i.data["zone"]) for i in items if i.role == "zone"]
    return next((z for z in zones if z not in ("near", "far")), zones[0] if zones else None)


def zone_relations(fields: Sequence[Sequence[Item]]) -> list[RelationIntent]:
    """Relations between the fields of neighbouring zones (by field index)."""
    zones: dict[int, str] = {}
    for index, items in enumerate(fields):
        zone = zone_of(items)
        if zone is not None:
            zones[index] = zone
    if list(zones.values()) == ["middle"] and len(fields) == 3:
        # "Chantenay, Imperator and Danvers carrots ..., Imperator in the middle": of three
        # fields, the one in the middle lies between the other two
        middle = next(iter(zones))
        others = tuple(index for index in range(3) if index != middle)
        return [RelationIntent(kind="between", subject=middle, objects=others)]
    if len(set(zones.values())) < 2:
        return []
    runs = _fill_middle(zones)
    used = {axis for z in zones.values() if z != "middle" for axis in _PLACES[z]}
    middle_axis: str = (
        next(axis for axis in ("ns", "ew") if axis in used) if used - {"depth"} else "depth"
    )
    places: dict[int, dict[str, float]] = {
        index: {middle_axis: 1} if zone == "middle" else dict(_PLACES[zone])
        for index, zone in zones.items()
    }
    if middle_axis != "depth":
        for run in runs:
            # "vines at the top, then stone fruit, then roots, and grain in the bottom
            # band": two or more fields between the ends lie in the order named
            for step, index in enumerate(run):
                places[index] = {middle_axis: 1 + step / len(run)}
    relations: list[RelationIntent] = []
    axes: tuple[tuple[str, RelationKind], ...] = (  # (axis, kind of its order)
        ("ns", "north_of"),
        ("ew", "west_of"),
        ("depth", "between"),  # (only "between": a photo's depth is no compass side)
    )
    for axis, kind in axes:
        across = "ew" if axis == "ns" else "ns"
        rows: dict[float, list[int]] = {}
        for index, place in places.items():
            if axis in place:
                rows.setdefault(place[axis], []).append(index)
        order = sorted(rows)
        for upper, lower in itertools.pairwise(order if axis != "depth" else ()):
            for subject in rows[upper]:
                if across not in places[subject] and all(across in places[o] for o in rows[lower]):
                    # "fruit trees across the north, ... in the south-east corner and cereals
                    # in the south-west": a whole side lies beyond each quarter across from it
                    relations.extend(
                        RelationIntent(kind=kind, subject=subject, objects=(o,))
                        for o in rows[lower]
                    )
                    continue
                # "NW quarter" lies north of the SW one, the one across on the other axis
                other = next(
                    (
                        o
                        for o in rows[lower]
                        if places[o].get(across) == places[subject].get(across)
                    ),
                    rows[lower][0],
                )
                relations.append(RelationIntent(kind=kind, subject=subject, objects=(other,)))
        if order == [0, 1, 2]:  # "X on the left, Y in the middle, Z on the right"
            relations.extend(
                RelationIntent(kind="between", subject=middle, objects=(rows[0][0], rows[2][0]))
                for middle in rows[1]
            )
    relations.extend(_across_the_others(places))
    for index, zone in zones.items():
        # "veg on the east side, grapes on the west side and a bit of wheat in between":
        # between the two fields named right before it, however they were placed
        if (
            zone == "middle"
            and index >= 2
            and any(i.role == "zone" and i.norm.startswith("in between") for i in fields[index])
            and not any(r.kind == "between" and r.subject == index for r in relations)
        ):
            relations.append(
                RelationIntent(kind="between", subject=index, objects=(index - 2, index - 1))
            )
    return relations


def _across_the_others(places: dict[int, dict[str, float]]) -> list[RelationIntent]:
    """'vegetables on the left, fruit on the right, and cereals across the whole bottom':
    the one field placed on one axis, beside two or more placed only on the other, lies on
    its side of each of them."""
    relations: list[RelationIntent] = []
    sides: tuple[tuple[str, str, RelationKind, RelationKind], ...] = (
        ("ns", "ew", "north_of", "south_of"),
        ("ew", "ns", "west_of", "east_of"),
    )
    for axis, across, kind, opposite in sides:
        alone = [i for i, place in places.items() if set(place) == {axis}]
        others = [i for i, place in places.items() if set(place) == {across}]
        if len(alone) != 1 or len(others) < 2 or len({places[o][across] for o in others}) < 2:
            continue
        if any(axis in place for i, place in places.items() if i not in alone):
            continue
        (subject,) = alone
        side: RelationKind = kind if places[subject][axis] == 0 else opposite
        relations.extend(
            RelationIntent(kind=side, subject=subject, objects=(other,)) for other in others
        )
    return relations


_OPPOSITE_ZONES = (("north", "south"), ("west", "east"), ("near", "far"))


def _fill_middle(zones: dict[int, str]) -> list[list[int]]:
    """'the orchard at the north end, then wheat, then strawberries at the south end':
    fields named between two opposite zones, with no zone of their own, are in the
    middle (only when no field is said to be in the middle). Returns each run of fields
    so filled, in the order named."""
    runs: list[list[int]] = []
    if "middle" in zones.values():
        return runs
    for first, last in itertools.pairwise(sorted(zones)):
        if {zones[first], zones[last]} in ({*pair} for pair in _OPPOSITE_ZONES):
            runs.append(list(range(first + 1, last)))
            for index in runs[-1]:
                zones[index] = "middle"
    return runs


_HEADS = ("head", "weak_variety", "plot")
_SENTENCE_ENDS = frozenset({".", "!", "?", ";"})


def zone_owners(items: Sequence[Item], fields: Sequence[Sequence[Item]]) -> list[list[Item]]:
    """Each field's items, a zone said before its field after a break moved to that field.

    "At the top: Chantenay carrots" and "..., and down at the bottom by the ditch a
    few rows of Granny" put their zone in the clause of the field before; a zone that
    follows its field's name without a break ("Royal Gala along the top hedge") stays.
    """
    owner: dict[int, int] = {}
    for index, field_items in enumerate(fields):
        for item in field_items:
            owner.setdefault(id(item), index)
    moved = [list(field_items) for field_items in fields]
    for position, item in enumerate(items):
        if item.role != "zone" or id(item) not in owner:
            continue
        broken = True
        depth = 0
        for before in reversed(items[:position]):
            # "onions (stuttgarter) at the top": a bracket after the name does not break
            if before.role == "separator" and before.norm in (")", "("):
                depth += 1 if before.norm == ")" else -1
                if depth >= 0:
                    continue
            if depth > 0:
                continue
            if before.role == "separator" and before.norm in _SENTENCE_ENDS:
                break
            if before.role in ("separator", "conjunction"):
                break
            if before.role in _HEADS:
                broken = False
                break
        if not broken:
            continue
        for after in items[position + 1 :]:
            if after.role == "separator" and after.norm in _SENTENCE_ENDS:
                break
            target = owner.get(id(after))
            if (
                after.role in _HEADS
                and target is not None
                and any(i.role == "zone" and i is not item for i in fields[target])
                # (not a label: "North-west: Bing cherries. North-east: Williams pears.")
                and items[position + 1].norm not in (":", "-", "–", "—")
            ):
                # "Half the farm is maize, the northern half, and the rest is wheat": the
                # next field has a zone of its own, so this one stays with its field
                break
            if after.role in _HEADS and target is not None:
                moved = [
                    [i for i in field_items if i is not item] + ([item] if index == target else [])
                    for index, field_items in enumerate(moved)
                ]
                break
    return moved


#: The relation of a field said to lie on one side.
_SIDE_KINDS: dict[str, RelationKind] = {
    "north": "north_of",
    "south": "south_of",
    "east": "east_of",
    "west": "west_of",
}


def lone_side(
    tokens: Sequence[Token], claimed: Sequence[bool], fields: Sequence[Sequence[Item]]
) -> list[RelationIntent]:
    """'hamlin + valencia orange groves, hamlin on the left', 'sonata strawbs & elsanta
    strawberries, sonata up north': of two fields, one named again with a side of its
    own lies on that side of the other (one side said, of one of two fields)."""
    if len(fields) != 2:
        return []
    found, _ = _zone_matches(tokens, claimed)
    found = _as_seen(found, tokens)
    if len(found) != 1 or found[0].zone not in _SIDE_KINDS or not found[0].first:
        return []
    named = tokens[found[0].first - 1]
    # (named again: not "wheat and maize on the left", both of them on the left)
    owners = [
        index
        for index, items in enumerate(fields)
        if any(i.role in _HEADS and i.end == named.end for i in items)
        and any(i.role in _HEADS and i.end < named.start for i in items)
    ]
    if len(owners) != 1:
        return []
    subject = owners[0]
    return [
        RelationIntent(kind=_SIDE_KINDS[found[0].zone], subject=subject, objects=(1 - subject,))
    ]

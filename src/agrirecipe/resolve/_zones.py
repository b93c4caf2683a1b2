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
from agrirecipe.resolve._lexicon import DATA_DIR, Item, Token

__all__ = ["ZoneMatch", "find_zones", "zone_relations"]

_AXES = {"north": ("ns", 0), "south": ("ns", 2), "west": ("ew", 0), "east": ("ew", 2)}


@dataclass(frozen=True, slots=True)
class ZoneMatch:
    """A zone word and its tokens (``first``..``last`` - 1)."""

    zone: str
    first: int
    last: int


@functools.cache
def _patterns() -> tuple[tuple[str, re.Pattern[str]], ...]:
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "zones.yaml").read_text("utf-8"))
    patterns = []
    for zone in ("north", "south", "west", "east", "middle"):
        phrases = sorted((str(p) for p in data[zone]), key=len, reverse=True)
        alternation = "|".join(re.escape(p) for p in phrases)
        patterns.append((zone, re.compile(rf"(?<![a-z0-9])(?:{alternation})(?![a-z0-9])")))
    return tuple(patterns)


def find_zones(tokens: Sequence[Token], claimed: Sequence[bool] = ()) -> list[ZoneMatch]:
    """Zone words of the prompt, when it describes a farm by zones (two or more of them).

    One zone word alone ("top quality", "the middle field") is not a zoning, and
    "in the middle" counts only beside a zone on either side of it.
    """
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
            found.append(ZoneMatch(zone, first, last))
            for index in range(first, last):
                taken[index] = True
    sides = {m.zone for m in found if m.zone != "middle"}
    if len(sides) < 2 and not (sides and any(m.zone == "middle" for m in found)):
        return []
    return sorted(found, key=lambda m: m.first)


def zone_relations(fields: Sequence[Sequence[Item]]) -> list[RelationIntent]:
    """Relations between the fields of neighbouring zones (by field index)."""
    zones: dict[int, str] = {}
    for index, items in enumerate(fields):
        zone = next((str(i.data["zone"]) for i in items if i.role == "zone"), None)
        if zone is not None:
            zones[index] = zone
    if len(set(zones.values())) < 2:
        return []
    used = {_AXES[z][0] for z in zones.values() if z != "middle"}
    middle_axis = "ns" if "ns" in used else "ew"
    relations: list[RelationIntent] = []
    axes: tuple[tuple[str, RelationKind], ...] = (("ns", "north_of"), ("ew", "west_of"))
    for axis, kind in axes:
        rows: dict[int, list[int]] = {}
        for index, zone in zones.items():
            where = (middle_axis, 1) if zone == "middle" else _AXES[zone]
            if where[0] == axis:
                rows.setdefault(where[1], []).append(index)
        order = sorted(rows)
        for upper, lower in itertools.pairwise(order):
            for subject in rows[upper]:
                relations.append(
                    RelationIntent(kind=kind, subject=subject, objects=(rows[lower][0],))
                )
    return relations

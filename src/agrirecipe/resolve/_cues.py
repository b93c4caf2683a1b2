"""Visual cues: "straw-coloured heads", "hoarfrost on bare branches", "curled leaves".

The phrases are data (``data/cues.yaml``). :func:`add_cues` puts them in the
lexicon as ``cue`` senses; a cue item attaches to its field like any attribute
word. :func:`apply_cues` then fills the attributes the prompt did not state and
reports a cue that disagrees with a stated word (the stated word wins).
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import yaml

from agrirecipe.resolve._lexicon import DATA_DIR, Item, Lexicon, Sense

__all__ = ["Cue", "CueReading", "add_cues", "apply_cues", "ripe_colour"]

_ATTRIBUTES = ("stage", "season", "health")


@dataclass(frozen=True, slots=True)
class Cue:
    """What a cue phrase says: one attribute's value, maybe only for deciduous crops."""

    attribute: str
    value: str
    deciduous_only: bool = False
    #: Says the attribute only when no other cue of the field does ("knee high").
    weak: bool = False


@dataclass(frozen=True, slots=True)
class CueReading:
    """The attributes a field's cues fill, and the disagreements to report."""

    values: dict[str, str]
    warnings: tuple[str, ...]
    used: tuple[str, ...]


@functools.cache
def _data() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "cues.yaml").read_text("utf-8"))
    return data


@functools.cache
def _table() -> tuple[tuple[str, Cue], ...]:
    data = _data()
    entries: list[tuple[str, Cue]] = []
    for attribute in _ATTRIBUTES:
        for value, phrases in (data.get(attribute) or {}).items():
            if value == "weak":
                for weak_value, weak_phrases in phrases.items():
                    entries.extend(
                        (str(p), Cue(attribute, str(weak_value), weak=True)) for p in weak_phrases
                    )
            elif isinstance(phrases, dict):
                for phrase in phrases.get("deciduous", ()):
                    entries.append((str(phrase), Cue(attribute, str(value), True)))
            else:
                entries.extend((str(p), Cue(attribute, str(value))) for p in phrases)
    return tuple(entries)


@functools.cache
def _autumn_looks() -> frozenset[str]:
    return frozenset(str(p) for p in _data().get("autumn_looks", ()))


def ripe_colour(crop: str, colour: str) -> Cue | None:
    """The Maturation cue of a bare colour said of ``crop`` ("the wheat golden"), if the
    crop only shows that colour ripe (``ripe_colours`` in cues.yaml)."""
    colours = _data().get("ripe_colours", {}).get(crop, ())
    return Cue("stage", "Maturation") if colour in {str(c) for c in colours} else None


def add_cues(lexicon: Lexicon) -> None:
    """Add every cue phrase to the lexicon (a phrase that also names an attribute keeps
    both senses; the stated sense wins when roles are given)."""
    for phrase, cue in _table():
        lexicon.add(phrase, Sense("cue", cue))


def apply_cues(
    items: Sequence[Item],
    stated: dict[str, str | None],
    *,
    deciduous: bool | None,
    field_text: str,
) -> CueReading:
    """Attribute values from a field's cue items.

    ``stated`` holds what the prompt's own words gave (None when unstated);
    ``deciduous`` is the field's crop's leaf habit (None for a generic field,
    where a deciduous-only cue still counts). The first cue of an attribute
    wins; a cue that disagrees with a stated value is reported, not used.
    """
    values: dict[str, str] = {}
    warnings: list[str] = []
    used: list[str] = []
    # "not in ear yet", "no flowers": a negated cue says nothing
    cued = sorted(
        (i for i in items if "cue" in i.data and not i.data.get("negated")),
        key=lambda i: i.start,
    )
    strong = {i.data["cue"].attribute for i in cued if not i.data["cue"].weak}
    for item in cued:
        cue: Cue = item.data["cue"]
        if (cue.deciduous_only and deciduous is False) or (cue.weak and cue.attribute in strong):
            continue
        if (
            cue.attribute == "health"
            and deciduous
            and "Fall" in (stated.get("season"), values.get("season"))
            and item.norm in _autumn_looks()
        ):
            used.append(f"{item.raw!r} -> autumn leaves, not {cue.value}")
            continue
        said = stated.get(cue.attribute)
        if said is not None:
            if said != cue.value:
                warnings.append(
                    f"{field_text!r}: {item.raw!r} suggests {cue.value}, but the prompt says "
                    f"{said}; kept {said}"
                )
            continue
        if cue.attribute not in values:
            values[cue.attribute] = cue.value
            used.append(f"{item.raw!r} -> {cue.attribute} {cue.value}")
    return CueReading(values, tuple(warnings), tuple(used))

"""Spacings said by reference to another field (issue 8).

"Regina directly south, same spacing, 8 rows", "a Chardonnay block of the same size and
spacing": :func:`same_spacing` gives a field the row and plant spacing of the field named
before it. "Riesling at 1.8 m row spacing and Spätburgunder at 2.0 m":
:func:`parallel_spacing` reads a bare value after a crop's name as the spacing the field
said before it stated.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._intent import FieldIntent, RowSpec
from agrirecipe.resolve._lexicon import Item, number_value

__all__ = ["parallel_spacing", "same_spacing"]


#: What "same spacing" copies from the field before: how its rows and plants are spaced.
_SPACINGS = (
    "row_spacing_m",
    "in_row_spacing_m",
    "bed_width_m",
    "alley_m",
    "rows_per_bed",
    "plants_per_ha",
)


def _same_keys(word: Item) -> tuple[str, ...]:
    """The row measures one "same" phrase copies from the field before."""
    norm = word.norm
    direction = any(w in norm for w in ("direction", "orientation", "bearing", "heading")) or (
        norm.startswith(("rows", "with rows")) and "way" in norm
    )
    # "6 beds of 200-ft rows, and the same layout of Sonata": the whole planting again
    # ("the Pinot Noir block ... is planted exactly the same way": likewise)
    if any(w in norm for w in ("layout", "spec", "setup", "set up", "again")) or (
        "way" in norm and not direction
    ):
        return (
            *_SPACINGS,
            *("rows", "beds", "row_length_m", "plants_per_row", "row_bearing_deg", "headland_m"),
        )
    # "same row count and spacing": how many rows, with or without their spacing
    # ("2 beds of the same width and row count": the rows on each bed)
    if "count" in norm or "number of" in norm or "per bed" in norm:
        return ("rows", "rows_per_bed", *(_SPACINGS if "spacing" in norm else ()))
    if "row width" in norm:  # "on the same row width": the rows' spacing
        return ("row_spacing_m",)
    if "width" in norm:  # "10 beds of the same width", "the same bed width"
        return ("bed_width_m",)
    if direction:
        return ("row_bearing_deg",)
    if "length" in norm or "long" in norm:
        return ("row_length_m",)
    return _SPACINGS


def same_spacing(intent: FieldIntent, before: FieldIntent, words: Sequence[Item]) -> FieldIntent:
    """'Kordia, 10 rows at 4.6 m ...; Regina, same spacing, 8 rows': the spacings of the
    field before, except those this field states itself; 'rows in the same direction':
    its rows' bearing; '16 rows of the same length': its rows' length."""
    if before.rows is None:
        return intent
    # ("the same row spacing, the same tree spacing and the same row length": each word's)
    keys = tuple(dict.fromkeys(k for word in words for k in _same_keys(word)))
    copied = {k: getattr(before.rows, k) for k in keys if getattr(before.rows, k) is not None}
    if not copied:
        return intent
    own = intent.rows
    if own is not None:
        copied = {k: v for k, v in copied.items() if getattr(own, k) is None}
        rows = own.model_copy(update=copied)
    else:
        rows = RowSpec(**copied, text="same spacing")
    return intent.model_copy(update={"rows": rows})


def parallel_spacing(
    intent: FieldIntent,
    items: Sequence[Item],
    others: Sequence[tuple[FieldIntent, Sequence[Item]]],
    ranges: dict[str, tuple[float, float]] | None = None,
) -> FieldIntent:
    """'Riesling at 1.8 m row spacing and Spätburgunder at 2.0 m', 'tomato rows 1.5 m
    apart, capsicum 0.9 m, maize 0.75 m': a bare 'at 2.0 m' or '0.9 m' after a crop's
    name is the spacing the field whose measure was said last before it stated. With no
    such field ("10 rows in each: apples at 3.5 m, pears at 3.5 m, cherries at 4.6 m"),
    "at" right after the crop's name is the spacing whose sourced range (``ranges``, by
    key) holds the value: the only one, or the rows' when both do and rows are counted."""
    lengths = ("row_spacing_m", "in_row_spacing_m", "bed_width_m")
    ordered = sorted(items, key=lambda i: i.start)
    for at, (first, number, unit) in enumerate(
        zip(ordered, ordered[1:], ordered[2:], strict=False)
    ):
        if unit.role != "length_unit" or not (
            first.norm in ("at", "on") or (first.role == "head" and number.role == "filler")
        ):
            continue
        value = number_value(number.norm)
        factors = [float(s.value) for s in unit.senses_of("length_unit")]
        if value is None or value <= 0 or not factors:
            continue
        spoken = [
            (max(i.start for i in other if i.role == "geometry" and i.start < number.start), before)
            for before, other in others
            if any(i.role == "geometry" and i.start < number.start for i in other)
        ]
        bare_at = first.norm == "at" and at > 0 and ordered[at - 1].role == "head"
        if not spoken:
            if bare_at and ranges:
                return _spacing_by_range(intent, value * factors[0], ranges)
            return intent
        before = max(spoken, key=lambda s: s[0])[1]
        own = intent.rows
        said = [  # what that field said and this one does not (a shared 'both' is in both)
            k
            for k in lengths
            if before.rows is not None
            and getattr(before.rows, k) is not None
            and (own is None or getattr(own, k) is None)
        ]
        if len(said) != 1:
            if bare_at and ranges and not said:
                # ("10 rows in each: apples at 3.5 m, ...": the fields before said no spacing)
                return _spacing_by_range(intent, value * factors[0], ranges)
            return intent
        metres = round(value * factors[0], 6)
        text = f"{first.raw} {number.raw} {unit.raw}"
        rows = (
            intent.rows.model_copy(update={said[0]: metres})
            if intent.rows is not None
            else RowSpec(**{said[0]: metres}, text=text)
        )
        return intent.model_copy(update={"rows": rows})
    return intent


def _spacing_by_range(
    intent: FieldIntent, metres: float, ranges: dict[str, tuple[float, float]]
) -> FieldIntent:
    """``intent`` with a bare "at 3.5 m" said of it as the spacing whose range holds it."""
    own = intent.rows
    if own is not None and (own.row_spacing_m is not None or own.in_row_spacing_m is not None):
        return intent
    fits = [k for k, (low, high) in ranges.items() if low <= metres <= high]
    if len(fits) > 1:
        fits = ["row_spacing_m"] if own is not None and own.rows is not None else []
    if len(fits) != 1:
        return intent
    metres = round(metres, 6)
    rows = (
        own.model_copy(update={fits[0]: metres})
        if own is not None
        else RowSpec(**{fits[0]: metres}, text=f"at {metres:g} m")
    )
    return intent.model_copy(update={"rows": rows})

"""Sizes, heights and latitudes from the roles of a prompt's items.

Number-unit patterns become sizes ("2 ha", "50 by 100 m", "half an acre", "a 3 x 4
grid of 10 m plots"), plant heights ("1.2 m tall") and latitudes ("35°S",
"latitude -33"); a negative or impossible number is a :class:`PromptError` naming it.
Runs after :func:`agrirecipe.resolve._scan.assign_roles`.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

from agrirecipe._errors import PromptError
from agrirecipe.resolve._intent import SizeIntent
from agrirecipe.resolve._lexicon import Item, Sense, Token, number_value

__all__ = ["read_heights", "read_latitude", "read_sizes"]


def _amount(item: Item) -> float | None:
    """The number an item stands for when a unit follows ("2", "two", "half a", "a",
    "another")."""
    if item.norm == "another":  # "... on another hectare": one more of the unit
        return 1.0
    if item.role in ("number", "fraction") or item.has("number", "fraction"):
        if item.senses:
            sense = item.senses_of("number", "fraction")
            if sense:
                return float(sense[0].value)
        return number_value(item.norm)
    return None


def _unit(item: Item, kind: str) -> float | None:
    senses = item.senses_of(kind)
    return float(senses[0].value) if senses else None


def _mixed_numbers(items: list[Item]) -> list[Item]:
    """ "one and a half hectares", "2 and a quarter acres": one number before a unit."""
    out: list[Item] = []
    index = 0
    while index < len(items):
        item = items[index]
        window = items[index : index + 4]
        if (
            len(window) == 4
            and item.role == "number"
            and window[1].norm == "and"
            and window[2].role == "fraction"
            and window[3].has("area_unit", "length_unit")
        ):
            whole, part = _amount(item), _amount(window[2])
            if whole is not None and part is not None and part < 1:
                merged = Item(
                    tokens=(*item.tokens, *window[1].tokens, *window[2].tokens),
                    senses=(Sense("number", whole + part),),
                    role="number",
                    data={"value": whole + part},
                )
                out.append(merged)
                index += 3
                continue
        out.append(item)
        index += 1
    return out


_TALL = frozenset({"tall", "high", "in height", "high and", "tall and"})


def read_heights(items: list[Item]) -> list[Item]:
    """ "plants about three metres tall", "trees 4 m high": how tall the plants are, a
    description of the field's plants (never a count or a size)."""
    out: list[Item] = []
    index = 0
    while index < len(items):
        window = items[index : index + 3]
        if (
            len(window) == 3
            and window[0].role == "number"
            and window[1].has("length_unit")
            and window[2].norm in _TALL
        ):
            amount, unit = _amount(window[0]), _unit(window[1], "length_unit")
            merged = Item(
                tokens=tuple(t for i in window for t in i.tokens),
                senses=(),
                role="filler",
                data={"described": "height", "height_m": (amount or 0.0) * (unit or 1.0)},
            )
            out.append(merged)
            index += 3
            continue
        out.append(items[index])
        index += 1
    return out


def read_sizes(items: list[Item]) -> list[Item]:
    """Replace number-unit patterns with one item of role ``"size"`` (``data["size"]``).

    Understood: ``<n> <area unit>`` ("2 ha", "half a hectare", "1 acre",
    "5000 m2"), ``<n> [unit] by|x <n> [unit]`` ("50 by 100 m", "50x100m"),
    and ``<n> <unit> wide/long`` pairs ("40 m wide and 80 m long").
    """
    items = _mixed_numbers(items)
    out: list[Item] = []
    index = 0
    pending_side: dict[str, float] = {}
    pending_items: list[Item] = []
    while index < len(items):
        grid = _grid_of_plots(items, index)
        if grid:
            # "2 x 2 plots of 20 x 20 m": four plots, counted by rows and columns
            for item in items[index : index + 2]:
                item.role = "filler"
            items[index + 2].data["value"] = grid
            out.extend(items[index : index + 3])
            index += 3
            continue
        layout = _match_layout(items, index)
        if layout:
            # "four plots in a 2x2 grid": how the plots are laid out, not a size or a count
            for item in items[index : index + layout]:
                item.role = "filler"
            out.extend(items[index : index + layout])
            index += layout
            continue
        matched = _match_area(items, index) or _match_rectangle(items, index)
        if matched is not None or _match_side(items, index) is not None:
            _reject_negative(items, index)
        if matched is not None:
            size, width = matched
            out.append(_size_item(items[index : index + width], size))
            index += width
            continue
        side = _match_side(items, index)
        if side is not None:
            name, metres, width = side
            pending_side[name] = metres
            pending_items.extend(items[index : index + width])
            if len(pending_side) == 2:
                size = SizeIntent(
                    width_m=pending_side["width"],
                    length_m=pending_side["length"],
                    text=" ".join(i.raw for i in pending_items),
                )
                out.append(_size_item(pending_items, size))
                pending_side, pending_items = {}, []
            index += width
            continue
        if (
            len(pending_side) == 1
            and items[index].norm in ("by", "x", "and", "×", ",")
            and _match_side(items, index + 1) is not None
        ):
            # "10 m wide by 80 m long", "three 12 m wide, 80 m long strips": the word
            # between two sides joins them
            pending_items.append(items[index])
            index += 1
            continue
        if (
            len(pending_side) == 1
            and items[index].norm in ("by", "x", "×")
            and index + 2 < len(items)
            and (amount := _number_at(items, index + 1)) is not None
            and (factor := _unit(items[index + 2], "length_unit")) is not None
        ):
            # "3 m wide x 120 m": after one side, the other side said bare
            other = "length" if "width" in pending_side else "width"
            said = items[index : index + 3]
            pending_side[other] = _positive(amount * factor, " ".join(i.raw for i in said))
            pending_items.extend(said)
            out.append(
                _size_item(
                    pending_items,
                    SizeIntent(
                        width_m=pending_side["width"],
                        length_m=pending_side["length"],
                        text=" ".join(i.raw for i in pending_items),
                    ),
                )
            )
            pending_side, pending_items = {}, []
            index += 3
            continue
        out.append(items[index])
        index += 1
    if pending_side:
        # One side only: a square is the least surprising reading ("a 100 m wide field").
        metres = next(iter(pending_side.values()))
        size = SizeIntent(
            width_m=metres, length_m=metres, text=" ".join(i.raw for i in pending_items)
        )
        out.append(_size_item(pending_items, size))
        out.sort(key=lambda item: item.start)
    return out


def _size_item(parts: Sequence[Item], size: SizeIntent) -> Item:
    tokens: tuple[Token, ...] = tuple(t for part in parts for t in part.tokens)
    item = Item(tokens, (Sense("filler"),), role="size")
    item.data["size"] = size
    return item


_MINUS = frozenset({"-", "−", "–"})


def _reject_negative(items: Sequence[Item], index: int) -> None:
    """'-2 hectares': a minus sign written onto a size's number (not '50-100 m')."""
    if index == 0:
        return
    sign = items[index - 1]
    written = sign.raw in _MINUS and sign.end == items[index].start
    if not written and sign.norm not in ("minus", "negative"):
        return
    if index >= 2 and _amount(items[index - 2]) is not None:
        return  # a range or a dash between numbers
    words = " ".join(item.raw for item in items[index : index + 2])
    _positive(-1.0, sign.raw + ("" if written else " ") + words)


def _positive(value: float, text: str) -> float:
    if not math.isfinite(value):
        raise PromptError(
            f"{text!r} is not a size: the number is not finite",
            stage="resolve",
            hint="give a size as a number such as '2 ha' or '50 by 100 m'",
        )
    if value <= 0:
        raise PromptError(
            f"a field cannot measure {text!r}",
            stage="resolve",
            hint="give a positive size such as '2 ha' or '50 by 100 m'",
        )
    return value


def _match_area(items: Sequence[Item], index: int) -> tuple[SizeIntent, int] | None:
    amount = _amount(items[index])
    if amount is None:
        return None
    for width in (1, 2):
        if index + width >= len(items):
            return None
        unit_item = items[index + width]
        factor = _unit(unit_item, "area_unit")
        if factor is not None:
            text = " ".join(i.raw for i in items[index : index + width + 1])
            return SizeIntent(area_m2=_positive(amount * factor, text), text=text), width + 1
        # "2 square metres" is tagged as one unit; allow one filler word ("2 full hectares").
        if unit_item.role not in ("filler",):
            return None
    return None


def _match_rectangle(items: Sequence[Item], index: int) -> tuple[SizeIntent, int] | None:
    first = _number_at(items, index)
    if first is None:
        return None
    position = index + 1
    unit_a = _unit(items[position], "length_unit") if position < len(items) else None
    if unit_a is not None:
        position += 1
    if position >= len(items) or not items[position].has("dimension_joiner"):
        return None
    position += 1
    second = _number_at(items, position) if position < len(items) else None
    if second is None:
        return None
    position += 1
    unit_b = _unit(items[position], "length_unit") if position < len(items) else None
    if unit_b is not None:
        position += 1
    factor_b = unit_b if unit_b is not None else (unit_a if unit_a is not None else 1.0)
    factor_a = unit_a if unit_a is not None else factor_b
    text = " ".join(i.raw for i in items[index:position])
    size = SizeIntent(
        width_m=_positive(first * factor_a, text),
        length_m=_positive(second * factor_b, text),
        text=text,
    )
    return size, position - index


def _match_layout(items: Sequence[Item], index: int) -> int:
    """The number of items of a layout of plots at ``index`` ("2 x 2 grid", "arranged 2
    by 2"), or 0."""
    window = items[index : index + 4]
    if (
        len(window) >= 3
        and _number_at(items, index) is not None
        and window[1].has("dimension_joiner")
        and _number_at(items, index + 2) is not None
    ):
        if len(window) == 4 and window[3].norm in _ARRANGEMENTS:
            return 4
        # ("Four 25 x 25 m plots ..., arranged 2 by 2: ...": no unit, after "arranged")
        if (
            index
            and items[index - 1].norm in _ARRANGED
            and (len(window) == 3 or window[3].role not in ("length_unit", "area_unit"))
        ):
            return 3
    return 0


#: Words before "2 by 2" that make it how plots are laid out ("arranged 2 by 2").
_ARRANGED = frozenset({"arranged", "laid", "set", "placed", "out"})


def _grid_of_plots(items: Sequence[Item], index: int) -> float:
    """The number of plots a grid said before their plural noun counts ("2 x 2 plots",
    "3 by 4 blocks"), or 0."""
    window = items[index : index + 4]
    if len(window) < 4 or not window[1].has("dimension_joiner"):
        return 0
    rows, columns = _number_at(items, index), _number_at(items, index + 2)
    spec = window[3].data.get("value") if window[3].role == "plot" else None
    if (
        rows is None
        or columns is None
        or window[2].role != "number"
        or not (isinstance(spec, dict) and spec.get("plural"))
        or not (rows.is_integer() and columns.is_integer() and 1 <= rows * columns <= 64)
    ):
        return 0
    return rows * columns


#: Words after "2 x 2" that make it a layout of plots, not a plot's size.
_ARRANGEMENTS = frozenset({"grid", "layout", "arrangement", "pattern", "matrix", "array", "square"})


def _number_at(items: Sequence[Item], index: int) -> float | None:
    item = items[index]
    if not item.senses:
        return number_value(item.norm)
    numbers = item.senses_of("number")
    # Articles ("a") are numbers too, but never a side of a rectangle.
    if numbers and item.norm not in ("a", "an"):
        return float(numbers[0].value)
    return None


def _match_side(items: Sequence[Item], index: int) -> tuple[str, float, int] | None:
    amount = _number_at(items, index)
    if amount is None or index + 2 >= len(items):
        return None
    factor = _unit(items[index + 1], "length_unit")
    sides = items[index + 2].senses_of("side")
    if factor is None or not sides:
        return None
    text = " ".join(i.raw for i in items[index : index + 3])
    return str(sides[0].value), _positive(amount * factor, text), 3


_LATITUDE = re.compile(
    r"(?:latitude|lat\.?)\s*(?:of\s*)?([-−]?\d+(?:\.\d+)?)\s*°?\s*([ns](?:orth|outh)?\b)?"
    r"|([-−]?\d+(?:\.\d+)?)\s*(?:°|deg\b|degrees?\b)\s*(?:latitude\s*)?([ns](?:orth|outh)?\b)?",
    re.IGNORECASE,
)


def read_latitude(prompt: str, items: list[Item]) -> tuple[float | None, str | None, list[Item]]:
    """A latitude written in the prompt ("at 35°S", "latitude -33.4"), and the items left.

    Returns ``(latitude_deg, text, items)``; the latitude's tokens are removed
    so that its number is not read as a count.
    """
    # "rows at 30 degrees from north" is a row direction (a geometry item), not a latitude.
    stated = [(i.start, i.end) for i in items if i.role == "geometry"]
    match = next(
        (
            m
            for m in _LATITUDE.finditer(prompt)
            if not any(start < m.end() and m.start() < end for start, end in stated)
        ),
        None,
    )
    if match is None:
        return None, None, items
    number = match.group(1) or match.group(3)
    direction = (match.group(2) or match.group(4) or "").lower()
    value = float(number.replace("−", "-"))
    if direction.startswith("s"):
        value = -abs(value)
    elif direction.startswith("n"):
        value = abs(value)
    if not -90.0 <= value <= 90.0:
        raise PromptError(
            f"latitude {value:g} is not on Earth",
            stage="resolve",
            hint="a latitude lies between -90 (south) and 90 (north) degrees",
        )
    start, end = match.span()
    kept = [item for item in items if item.end <= start or item.start >= end]
    return value, match.group().strip(), kept

"""Reading tagged phrases: each item's role in the sentence, sizes and latitudes.

After :meth:`Lexicon.tag` every item has the senses its words can have; here
each item gets the one *role* it plays in this prompt ("head", "stage",
"relation", "number", ...), and number-unit patterns become sizes ("2 ha",
"50 by 100 m", "half an acre") and latitudes ("35°S", "latitude -33").
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

from agrirecipe._errors import PromptError
from agrirecipe.resolve._intent import SizeIntent
from agrirecipe.resolve._lexicon import Item, Sense, Token, number_value, vocabulary

__all__ = ["assign_roles", "read_heights", "read_latitude", "read_sizes"]

# Sense kinds in the order they win when a phrase has several (a crop name beats
# its use as a colour; "one" is a number unless decomposition sees a reference).
_ROLE_ORDER = (
    "geometry",
    "zone",
    "other_crop",
    "plot",
    "container",
    "non_agricultural",
    "place",
    "hemisphere",
    "stage",
    "season",
    "month",
    "health",
    "cue",
    "negation",
    "relation",
    "relation_trailer",
    "conjunction",
    "separator",
    "number",
    "reference",
    "correction",
    "quantity",
    "fraction",
    "all",
    "distinct",
    "other",
    "of",
    "area_unit",
    "length_unit",
    "dimension_joiner",
    "side",
    "same_size",
    "same_spacing",
    "scenery",
    "filler",
)


def assign_roles(items: Sequence[Item]) -> None:
    """Give every item its role (in place)."""
    cues = {str(word) for word in vocabulary()["month_cues"]}
    previous: Item | None = None
    for index, item in enumerate(items):
        following = items[index + 1] if index + 1 < len(items) else None
        alone = (
            _alone(previous, following)
            or _opening_month(item, previous, following)
            # "May flight: Winter Wheat and Spring Wheat plots": a capitalised month that
            # opens the prompt (not "May I have ...")
            or (
                item.raw[:1].isupper()
                and previous is None
                and following is not None
                and following.norm not in _NOT_AFTER_A_MONTH
            )
            # "March sunshine", "June rain": a month's weather
            or (
                item.raw[:1].isupper()
                and following is not None
                and any(sense.value == "sky" for sense in following.senses_of("scenery"))
            )
        )
        item.role = _role(item, previous, cues, alone=alone)
        after = items[index + 2] if index + 2 < len(items) else None
        if item.role == "relation" and _attributive(item, previous, following, after):
            item.role = "filler"  # "three adjacent fields": the fields in a row
            item.data["adjacent"] = True
        if (
            item.role in ("length_unit", "area_unit")
            and item.has("scenery")
            and (previous is None or previous.role not in ("number", "fraction", "quantity"))
        ):
            item.role = "filler"  # "east of the yard": the farmyard, not three feet
            item.data["scenery"] = item.senses_of("scenery")[0].value
        if (
            item.role == "separator"
            and item.norm in _POINTING
            and previous is not None
            and previous.role in ("relation", "between")
        ):
            item.role = "filler"  # "north of that, pears": the pronoun, not "that" joining
        if (
            item.role == "plot"
            and previous is not None
            and previous.role == "trailer"
            and _placement_plot(item, following)
        ):
            # "pears on the north block": where the pears are, not another field
            item.role = "filler"
            item.data["placement"] = True
        if (
            previous is not None
            and previous.role == "number"
            and previous.norm in ("a", "an")
            and item.role in ("filler", "non_agricultural")
            and ("scenery" in item.data or item.role == "non_agricultural")
        ):
            previous.role = "filler"  # "a sprayer is working in the potatoes": no count
        if (
            previous is not None
            and previous.role == "number"
            and previous.norm in ("a", "an")
            and item.role == "unknown"
            and following is not None
            and following.norm in _PREPOSITIONS
        ):
            previous.role = "filler"  # "a scarecrow in the veg": the scarecrow's article
        if (
            previous is not None
            and previous.role == "relation"
            and previous.norm in ("near", "by", "outside", "close to")
            and item.senses_of("place")
        ):
            previous.role = "filler"  # "Our block near Mildura has ...": where the farm is
        if (
            previous is not None
            and previous.role == "health"
            and item.role == "filler"
            and "scenery" in item.data
        ):
            previous.role = "filler"  # "a rusty gate": the gate's, not the plants' health
        if (
            previous is not None
            and previous.role == "plot"
            and (
                item.role == "non_agricultural"
                or (item.role == "filler" and "scenery" in item.data)
            )
            # ("a vineyard on the south-facing slope": where it is, not the machine's kind)
            and item.data.get("scenery") != "aspects"
            and not (index >= 2 and items[index - 2].role in ("head", "weak_variety"))
        ):
            # "a row-crop robot test", "an orchard sprayer": the machine's kind, not a field
            previous.role = "filler"
            previous.data["modifier"] = True
        if (
            previous is not None
            and previous.role in ("stage", "cue")
            and item.role in ("filler", "non_agricultural")
            and "scenery" in item.data
        ):
            previous.role = "filler"  # "a harvesting gripper": the machine's job, not a stage
        previous = item
    _ripening_fruit(items)


#: Words after "a <word>" that show the word is a thing somewhere, not a crop's name.
_PREPOSITIONS = frozenset(
    {
        "in",
        "on",
        "at",
        "by",
        "near",
        "among",
        "amongst",
        "under",
        "over",
        "beside",
        "with",
        "across",
        "along",
        "between",
        "inside",
        "behind",
        "above",
        "below",
    }
)

# Colour changes that are a disease's sign on leaves but ripening on the fruit.
_COLOURING = frozenset({"yellowing", "browning", "reddening", "colouring", "coloring"})
_FRUIT_WORDS = frozenset(
    {
        "bunch",
        "bunches",
        "fruit",
        "fruits",
        "berries",
        "grapes",
        "apples",
        "ears",
        "heads",
        "pods",
        "cobs",
        "hands",
        "fingers",
        "bananas",
        "tomatoes",
        "oranges",
        "pears",
    }
)
_LEAF_WORDS = frozenset({"leaf", "leaves", "foliage", "canopy", "tops", "haulm"})


def _ripening_fruit(items: Sequence[Item]) -> None:
    """'the bunches fat and yellowing': the fruit ripening, not a sick plant."""
    from agrirecipe.resolve._cues import Cue

    for index, item in enumerate(items):
        if item.role != "health" or item.norm not in _COLOURING:
            continue
        window = [i.norm for i in items[max(0, index - 4) : index]]
        if any(w in _FRUIT_WORDS for w in window) and not any(w in _LEAF_WORDS for w in window):
            item.role = "cue"
            item.data["cue"] = Cue("stage", "Maturation")


# Words that point back to a field when they follow a relation word ("north of that").
_POINTING = frozenset({"that", "this", "which"})


def _placement_plot(item: Item, following: Item | None) -> bool:
    """A singular plot noun of any crop with no crop or "of" after it ("the north block,")."""
    plot = item.data.get("value") or {}
    return (
        not plot.get("plural")
        and not plot.get("options")
        and not plot.get("category")
        and (following is None or not following.has("crop", "category", "variety", "of"))
    )


def _attributive(
    item: Item, previous: Item | None, following: Item | None, after: Item | None
) -> bool:
    """'three adjacent fields', 'two neighbouring orchards', 'three adjacent test strips':
    "next to" used as an adjective."""
    return (
        item.data.get("value") == "next_to"
        and len(item.tokens) == 1
        and previous is not None
        and previous.role in ("number", "quantity", "distinct")
        and following is not None
        and (
            following.has("plot", "crop", "category", "variety")
            # ("three adjacent test strips": one word of what the plots are for between)
            or (
                all(sense.kind in ("filler", "scenery") for sense in following.senses)
                and after is not None
                and after.has("plot")
                and not after.has("crop", "variety")
            )
        )
    )


#: Words after an opening "May" that make it the verb ("May I have ...").
_NOT_AFTER_A_MONTH = frozenset(
    {
        "i",
        "we",
        "you",
        "it",
        "they",
        "be",
        "have",
        "need",
        "the",
        "this",
        "these",
        "those",
        "all",
        "our",
    }
)


def _alone(previous: Item | None, following: Item | None) -> bool:
    """Between separators (or at the end): ", may" is a month, "may I" is not; an emoji
    or other mark with no letters parts words too ("late blight 😩 sept")."""
    return (
        previous is not None
        and (previous.has("separator") or _no_letters(previous))
        and (following is None or following.has("separator") or _no_letters(following))
    )


def _no_letters(item: Item) -> bool:
    return not item.senses and not any(c.isalnum() for c in item.norm)


def _role(item: Item, previous: Item | None, cues: set[str], *, alone: bool = False) -> str:
    senses = item.senses
    if not senses:
        value = number_value(item.norm)
        if value is not None:
            item.data["value"] = value
            return "number"
        return "unknown"
    kinds = {sense.kind for sense in senses}
    looks = [s for s in senses if s.kind == "cue"]
    if looks:  # kept even when a stated sense wins the role ("dormant": a stage, and winter)
        item.data["cue"] = looks[0].value
    strong_variety = any(s.kind == "variety" and not s.weak for s in senses)
    if kinds & {"crop", "category"} or strong_variety:
        return "head"
    if "variety" in kinds and not kinds & {"stage", "season", "health"}:
        return "weak_variety"
    for kind in _ROLE_ORDER:
        if kind not in kinds:
            continue
        sense = next(s for s in senses if s.kind == kind)
        if (
            kind == "month"
            and sense.weak
            and not alone
            and (previous is None or previous.norm.split()[-1] not in cues)
            and not _named_month(item, previous)
        ):
            continue
        if kind == "relation" and sense.value == "between":
            return "between"
        if kind == "geometry":
            # One phrase may state two values ("20 rows at 5 m": rows and their spacing).
            item.data["geometry"] = tuple(s.value for s in item.senses_of("geometry"))
            return "geometry"
        if kind == "cue":
            return "cue"
        if kind == "zone":
            item.data["zone"] = sense.value
            return "zone"
        if kind == "scenery":  # read as a filler word; --explain lists it as not used
            item.data["scenery"] = sense.value
            return "filler"
        if kind == "number" and "reference" in kinds:
            item.data["reference"] = True
        item.data["value"] = sense.value
        return {"relation_trailer": "trailer"}.get(kind, kind)
    return "filler"


def _opening_month(item: Item, previous: Item | None, following: Item | None) -> bool:
    """'March on our farm in Sicily: ...': a capitalised month word opening a sentence,
    before "on", "in", "at" or a mark, is the month (a verb would take an object)."""
    return (
        (previous is None or previous.norm in (".", "!", "?", ";"))
        and item.raw[:1].isupper()
        and following is not None
        and following.norm in ("on", "in", "at", ",", ":", "-", "and")
    )


def _named_month(item: Item, previous: Item | None) -> bool:
    """ "Cloudy May morning", "on 20 May": a capitalised month word inside a sentence,
    or one right after a day number, is the month."""
    if previous is None or previous.norm in (".", "!", "?", ":", ";"):
        return False
    if previous.role == "number" and previous.raw.isdigit():
        return True
    return item.raw[:1].isupper() and not item.raw.isupper()


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
            and items[index].norm in ("by", "x", "and", "×")
            and _match_side(items, index + 1) is not None
        ):
            # "10 m wide by 80 m long": the word between two sides joins them
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
    """The number of items of a layout of plots at ``index`` ("2 x 2 grid"), or 0."""
    window = items[index : index + 4]
    if (
        len(window) == 4
        and _number_at(items, index) is not None
        and window[1].has("dimension_joiner")
        and _number_at(items, index + 2) is not None
        and window[3].norm in _ARRANGEMENTS
    ):
        return 4
    return 0


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

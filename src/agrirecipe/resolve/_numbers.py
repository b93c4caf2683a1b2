"""What a number is in its place, when it counts no fields: a measure, a name, a year, a
time, a date, parts of each plant, plants, scenery.

Row 1 of :func:`agrirecipe.resolve._words.read_words`'s table, as one ordered list of
small passes (:func:`numbers_that_count_no_fields`); each turns a number that does not
count fields into a filler and says in ``data`` what it was ("measure", "year", "time",
"date", "label", "counts_plants", "counts_scenery"), for ``--explain``.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._geometry import geometry_nouns
from agrirecipe.resolve._lexicon import Item, reader_words
from agrirecipe.resolve._looks import crops_of
from agrirecipe.resolve._structure import descriptive_words

__all__ = ["is_structure", "numbers_that_count_no_fields"]

#: Words before and after a number that make it a year ("plan for 2027", "2026 season").
_BEFORE_A_YEAR = frozenset({"in", "for", "since", "from", "until", "plan", "year"})
_AFTER_A_YEAR = frozenset({"season", "seasons", "crop", "harvest", "plan", "plans", "growing"})

#: Parts of a field: "in one corner of the carrots" names no field of its own.
_PARTS = frozenset({"corner", "end", "edge", "side", "part"})

#: Words before a month that make it a time to come ("not ready until November").
_BEFORE_A_TIME_TO_COME = frozenset({"until", "till", "til", "by", "before"})

#: Units of time after a number that make it an age or a time ("planted ten days ago").
_UNITS_OF_TIME = frozenset(
    {"day", "days", "week", "weeks", "wks", "month", "months", "year", "years", "yr", "yrs"}
    | {"hour", "hours", "hrs", "minute", "minutes", "mins", "fortnight", "fortnights"}
)


def numbers_that_count_no_fields(items: Sequence[Item]) -> None:
    """Run the number passes, in order, over a prompt's items."""
    _measures_and_names(items)
    _years_times_and_parts(items)
    _counts_of_each_plant(items)
    _counts_of_scenery(items)
    _counts_of_plants(items)
    _numbers_that_name_plots(items)
    _dates(items)


def is_structure(item: Item) -> bool:
    """A structure crops grow under ("tunnels"), which a number may count as fields."""
    return any(sense.value == "structures" for sense in item.senses_of("scenery"))


def _day_of_month(item: Item) -> bool:
    value = item.data.get("value")
    return isinstance(value, float) and value.is_integer() and 1 <= value <= 31


def _measures_and_names(items: Sequence[Item]) -> None:
    """ "3.5 m in the pears": a number with a length unit is a measure, never a count of
    fields (what no size or geometry pattern read stays a filler); "on Gisela 6": a
    number after a capitalised unknown word is a rootstock's or machine's name."""
    for item, following in itertools.pairwise(items):
        if item.role == "number" and following.role == "length_unit":
            item.role = "filler"
            item.data["measure"] = True
    for index in range(1, len(items)):
        before, item = items[index - 1], items[index]
        after = items[index + 1] if index + 1 < len(items) else None
        if (
            item.role == "number"
            and item.raw.isdigit()
            and before.role == "unknown"
            and before.raw[:1].isupper()
            and (after is None or after.role not in ("plot", "head", "weak_variety", "category"))
        ):
            item.role = "filler"  # "on Gisela 6": a rootstock's or machine's name


def _years_times_and_parts(items: Sequence[Item]) -> None:
    """A year ("plan for 2027"), a time to come ("ready until November"), one of the
    fields named ("in 1 of em"), a part of a field ("one corner of the carrots") and an
    age ("ten days ago"): no count of fields."""
    # "Carrot plan for 2027", "the 2026 season": a year, no count of fields
    for index, item in enumerate(items):
        word_before = items[index - 1].norm if index else ""
        word_after = items[index + 1].norm if index + 1 < len(items) else ""
        if (
            item.role == "number"
            and item.raw.isdigit()
            and len(item.raw) == 4
            and 1900 <= int(item.raw) <= 2100
            and (
                word_before in _BEFORE_A_YEAR
                or word_after in _AFTER_A_YEAR
                # "in January 2026", "spring 2024": the year of a month or season
                or (index > 0 and items[index - 1].role in ("month", "season"))
            )
        ):
            item.role = "filler"
            item.data["year"] = True
        # "won't be ready until November", "picked by October": a time to come, not when
        # the scene is
        # (not a look reached by then: "both in ear by mid-June" is how they are in June)
        reached = word_before == "by" and index >= 2 and items[index - 2].role in ("stage", "cue")
        if item.role == "month" and word_before in _BEFORE_A_TIME_TO_COME and not reached:
            item.role = "filler"
            item.data["time"] = True
        # "2 wheat fields w/ a combine in 1 of em": one of the fields named, no count
        word_after_next = items[index + 2].norm if index + 2 < len(items) else ""
        if (
            item.role == "number"
            and word_before in ("in", "on", "at", "across")
            and word_after == "of"
            and word_after_next in ("them", "em", "those", "these")
        ):
            item.role = "filler"
        # "In one corner of the carrots", "at one end of the wheat": a part of a field
        # named, no count of fields
        if (
            item.role == "number"
            and item.norm in ("one", "a")
            and word_after in _PARTS
            and word_after_next == "of"
        ):
            item.role = "filler"
        # "planted ten days ago", "10 year old trees": an age or a time, no count of fields
        if item.role == "number" and word_after in _UNITS_OF_TIME:
            item.role = "filler"
            item.data["time"] = True


def _counts_of_each_plant(items: Sequence[Item]) -> None:
    """Leaves or flowers of each plant, "one strip each", "single rows", "one carrot
    every 2 cm": how each plant or member is planted, no count of fields."""
    # "just a couple of leaves per plant": leaves on each plant, no count of fields
    for index, item in enumerate(items):
        if item.role == "plot" and index and items[index - 1].norm in ("per", "each", "a"):
            spec = item.data.get("value")
            # (not "a fruit tree block": the plants of the plot after it)
            after = items[index + 1] if index + 1 < len(items) else None
            if (
                isinstance(spec, dict)
                and spec.get("individual")
                and not (after is not None and after.role == "plot")
            ):
                item.role = "filler"
        if (
            item.role == "number"
            and index + 1 < len(items)
            and items[index + 1].norm in ("leaves", "leaf", "true leaves", "flowers", "fruits")
        ):
            item.role = "filler"
    # "Three pepper varieties, one strip each: ...": how each member is planted
    for first, plot, each in zip(items, items[1:], items[2:], strict=False):
        if (
            first.norm in ("one", "1", "a")
            and plot.role == "plot"
            and each.norm in ("each", "apiece")
        ):
            first.role = plot.role = "filler"
    # "onions in single rows 30 cm apart": how the rows are planted, no count of fields
    for item, following in itertools.pairwise(items):
        if (
            item.role == "number"
            and item.norm in ("single", "double", "twin")
            and following.role == "geometry"
            and following.norm.split()[0] in geometry_nouns()
        ):
            item.role = "filler"
    # "one carrot every 2 cm": one plant of the crop, every so far along the row
    for first, head, spacing in zip(items, items[1:], items[2:], strict=False):
        if (
            first.role == "number"
            and first.norm in ("one", "1", "a", "an")
            and head.role in ("head", "weak_variety")
            and spacing.role == "geometry"
            and any(m.key == "in_row_spacing_m" for m in spacing.data["geometry"])
        ):
            first.role = "filler"


def _counts_of_scenery(items: Sequence[Item]) -> None:
    """ "three tractors", "between the two tracks": a number before scenery counts it;
    "a combine already working in the spelt" is no field."""
    # "between the two tracks", "three tractors": a number before scenery counts it
    # ("two reflective targets": past words the lexicon does not know)
    for index, (item, following) in enumerate(itertools.pairwise(items)):
        counted = following
        for word in items[index + 1 : index + 3]:
            if word.role != "unknown":
                counted = word
                break
        if (
            item.role == "number"
            and item.norm not in ("a", "an")
            # ("In our three greenhouses we grow San Marzano, Beefsteak and cherry tomatoes")
            and (counted.scenery or counted.role == "non_agricultural")
            and not is_structure(counted)
        ):
            item.role = "filler"
            item.data["counts_scenery"] = True
        elif item.role == "number" and item.norm in ("a", "an") and following.role == "cue":
            item.role = "filler"  # "a combine already working in the spelt": not a field


def _counts_of_plants(items: Sequence[Item]) -> None:
    """Parts of each plant counted ("pruned back to two canes") and, after a crop is
    named, a vague quantity of its fruit, leaves or plants ("lots of fruit")."""
    # "dormant vines pruned back to two canes", "at the 2-3 true leaf stage": parts of each
    # plant counted (past a second number of a range)
    for index, item in enumerate(items):
        if item.role != "number":
            continue
        end = index + 1
        while end < len(items) and (
            items[end].role == "number" or items[end].norm in ("-", "to", "or")
        ):
            end += 1
        # ("2-3 true leaf stage": a cue phrase that opens with a part counts it too)
        part = items[end].norm.split() if end < len(items) else []
        if part and part[0] in reader_words("counted_parts"):
            for counted in items[index:end]:
                if counted.role == "number":
                    counted.role = "filler"
                    counted.data["counts_plants"] = True
    # "Jalapenos in the tunnel, lots of fruit turning red": after a crop is named, a vague
    # quantity of fruit, leaves or plants counts plants, not fields
    described = descriptive_words()
    # ("a few peppers have scabby spots" after Jalapenos: some of that field's plants,
    # read like "the peppers")
    named: set[str] = set()
    for index, (item, following) in enumerate(itertools.pairwise(items)):
        if item.role in ("head", "weak_variety"):
            named |= crops_of(item)
        if not named or item.role != "quantity":
            continue
        ahead = items[index + 2 : index + 6]
        # ("lots of yellow flowers"): past the colours said of them
        while following.norm in reader_words("colours") and ahead:
            following, ahead = ahead[0], ahead[1:]
        plants_named = (
            following.role == "head"
            and following.has("crop")
            and crops_of(following) <= named
            and not any(i.role in ("plot", "size", "geometry") for i in ahead)
            and any(i.role in ("health", "cue", "stage") for i in ahead)
        )
        of_plants = following.norm in described and following.role != "category"
        if (of_plants and not any(i.role == "plot" for i in ahead[:1])) or plants_named:
            item.role = "filler"
            item.data["counts_plants"] = True


def _numbers_that_name_plots(items: Sequence[Item]) -> None:
    """ "the 70k plot lies north of the 95k plot": a number before one plot names it."""
    # "the 70k plot lies north of the 95k plot": a number before one plot names it
    for before, item, following in zip(items, items[1:], items[2:], strict=False):
        spec = following.data.get("value") if following.role == "plot" else None
        if (
            before.norm in ("the", "this", "that")
            and item.role == "number"
            and isinstance(spec, dict)
            and not spec.get("plural")
            and not spec.get("individual")
        ):
            item.role = "filler"
            item.data["label"] = True


def _dates(items: Sequence[Item]) -> None:
    """ "on 20 April", "April 3rd": a day of the month is a date, not a count of fields."""
    # "on 20 April", "April 3rd": a day of the month is a date, not a count of fields
    words = [i for i in items if i.role != "separator" or i.norm not in (",",)]
    for index, item in enumerate(words):
        if item.role != "number" or not _day_of_month(item):
            continue
        said_before = words[index - 1] if index else None
        said_after = words[index + 1] if index + 1 < len(words) else None
        if (said_after is not None and said_after.role == "month") or (
            said_before is not None
            and said_before.role == "month"
            and (
                said_after is None
                or said_after.role not in ("plot", "head", "weak_variety", "category")
            )
        ):
            item.role = "filler"
            item.data["date"] = True

"""Reading tagged phrases: each item's role in the sentence.

After :meth:`Lexicon.tag` every item has the senses its words can have; here
each item gets the one *role* it plays in this prompt ("head", "stage",
"relation", "number", ...). Sizes, heights and latitudes are read from the roles
in ``_sizes``.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import Item, number_value, vocabulary

__all__ = ["assign_roles"]

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

"""What words of looks are in their place: colours that are crop words, a colour change
that is ripening, weather on the plants, looks negated, readiness said of other things.

Reading passes of :func:`agrirecipe.resolve._words.read_words` (rows 2, 2a, 2c, 3, 4 and
4a of its table), each deciding what a look word is where the lexicon alone cannot.
The words each pass looks for are data (``reader_words`` in vocabulary.yaml).
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._cues import ripe_colour
from agrirecipe.resolve._lexicon import Item, Sense, reader_words

__all__ = [
    "colour_after_a_look",
    "colour_lists",
    "colours_are_not_crops",
    "crops_of",
    "negated_looks",
    "past_and_other_readiness",
    "ripe_colours",
    "ripening_colours",
    "weather_on_plants",
]


def _holds_not(plot: Item, crops: set[str]) -> bool:
    """Whether ``plot`` is a plot word that can hold none of ``crops`` ("roots")."""
    spec = plot.data.get("value") if plot.role == "plot" else None
    options = set(spec.get("options", ())) if isinstance(spec, dict) else set()
    return bool(options) and bool(crops) and not options & crops


def crops_of(item: Item) -> set[str]:
    """The crops a crop or variety word names."""
    return {str(s.value) for s in item.senses_of("crop")} | {
        str(s.crop) for s in item.senses_of("variety") if s.crop
    }


def _worn_scenery(items: Sequence[Item], first: Item) -> bool:
    """'Rusty watering can', 'a rusted gate', 'a rusty old harvester': the scenery's look
    (a worn look before scenery, past at most two plain adjectives), not the crop's."""
    if first.role != "health" or first.norm not in reader_words("worn_looks"):
        return False
    after = [i for i in items if i.start > first.start][:3]
    for item in after:
        if item.has("scenery") and not item.has("crop", "variety", "plot", "category"):
            return True
        if item.role not in ("filler", "unknown") or item.has("crop", "variety", "plot"):
            return False
    return False


def _maker_of(first: Item, second: Item) -> bool:
    """'Shot on my old Fuji camera': a variety name right before a device names its
    maker, not a field."""
    return (
        first.role == "head"
        and bool(first.senses_of("variety"))
        and not first.senses_of("crop")
        and second.norm in reader_words("devices")
    )


def colours_are_not_crops(items: Sequence[Item], text: str) -> None:
    """'striped yellow-orange with rust', 'olive-green velvety patches': a crop word joined
    by a hyphen to a colour is a colour, not a field (nor an unknown crop). 'an orange
    tractor', 'orange crates': a crop word that is a colour, before scenery, is its colour."""
    for item in items:
        # "the red-orange cobs": two colours joined by a hyphen, not the "red orange" (Moro)
        if (
            item.role in ("head", "weak_variety")
            and len(item.tokens) == 2
            and all(t.norm in reader_words("colours") for t in item.tokens)
            and text[item.tokens[0].end : item.tokens[1].start] == "-"
        ):
            item.role = "filler"
            item.data["colour"] = True
    for index, (first, second) in enumerate(itertools.pairwise(items)):
        third = items[index + 2] if index + 2 < len(items) else None
        if (
            (
                first.role in ("head", "other_crop", "category")
                and second.has("scenery")
                and not second.has("crop", "variety", "plot", "category")
                and (
                    first.norm in reader_words("colours")
                    # "a grain trailer", "the potato harvester": what the machine carries
                    or any(sense.value == "machines" for sense in second.senses_of("scenery"))
                    # "Fruit research station": what a site or building is for
                    or (
                        first.has("category")
                        and not first.has("crop", "variety")
                        and any(
                            s.value in ("sites", "buildings", "robots", "purposes")
                            for s in second.senses_of("scenery")
                        )
                        # (not "grain and veg test strips": plots of the kinds listed)
                        and not (
                            third is not None
                            and third.role == "plot"
                            and index > 0
                            and items[index - 1].role == "conjunction"
                        )
                    )
                )
            )
            or _worn_scenery(items, first)
            or _maker_of(first, second)
        ):
            first.role = "filler"
            first.data["colour"] = True
            continue
        if (
            first.norm in reader_words("colour_crops")
            and text[first.end : second.start] == " "
            and (
                second.norm in reader_words("colours")
                # "the orange roots are heaped in the trailer": no orange grows in roots
                or (first.role == "head" and _holds_not(second, crops_of(first)))
            )
        ):
            first.role = "filler"  # "olive green blotches", "lime green", "cherry red"
            first.data["colour"] = True
            continue
        if text[first.end : second.start] != "-":
            continue
        for crop, colour in ((first, second), (second, first)):
            if crop.role in ("head", "other_crop") and colour.norm in reader_words("colours"):
                crop.role = "filler"
                crop.data["colour"] = True
    for index, word in enumerate(items):
        if (
            word.role == "head"
            and word.norm in reader_words("colours")
            and (_colours_a_part(items[index + 1 :]) or _colours_the_fruit(items, index))
        ) or (
            word.role in ("head", "weak_variety")
            and word.norm in reader_words("colours")
            and _said_of_scenery(items, index)
        ):
            word.role = "filler"
            word.data["colour"] = True


def _said_of_scenery(items: Sequence[Item], index: int) -> bool:
    """Whether a crop word that is a colour describes the sky or light named just before
    it in its sentence, with no crop named between."""
    for item in reversed(items[max(0, index - 6) : index]):
        if item.norm in (".", "!", "?", ";", ","):
            return False
        if item.role in ("head", "weak_variety", "plot"):
            return False
        if item.norm in reader_words("coloured_scenery"):
            return True
    return False


def _colours_the_fruit(items: Sequence[Item], index: int) -> bool:
    """'sweet peppers, red, yellow and orange fruit', 'peppers with orange fruit': a crop
    word that is a colour, before "fruit", after another colour or after another crop
    named in its sentence, is the colour of that crop's fruit."""
    if index + 1 >= len(items) or items[index + 1].norm not in ("fruit", "fruits"):
        return False
    colour = items[index]
    colours = reader_words("colours")
    listed = (
        index >= 2
        and items[index - 1].norm in ("and", "&", "or", ",")
        and (items[index - 2].norm in colours)
    )
    named = False
    for item in reversed(items[:index]):
        if item.role == "separator" and item.norm in (".", "!", "?", ";"):
            break
        if item.role == "head" and crops_of(item) - crops_of(colour):
            named = True
            break
    return listed or named


def _colours_a_part(after: Sequence[Item]) -> bool:
    """Whether the words after a colour crop word name a part of a plant, past other
    colours joined to it ("their orange shoulders", "the orange and red kernels")."""
    colours = reader_words("colours")
    for item in after[:5]:
        if item.norm in ("and", "&", "or", ",", "-") or (
            item.norm in colours and not item.has("crop", "variety", "plot")
        ):
            continue
        return item.norm in reader_words("coloured_parts") and not item.has("crop", "plot")
    return False


def colour_lists(items: Sequence[Item]) -> None:
    """'white and purple blooms over the whole field': "and" between two colours of one
    thing that is no crop or plot joins the colours, not two fields."""
    colours = reader_words("colours")
    for first, joiner, second, thing in zip(items, items[1:], items[2:], items[3:], strict=False):
        if (
            joiner.role == "conjunction"
            and first.norm in colours
            and second.norm in colours
            and first.role in ("filler", "unknown")
            and second.role in ("filler", "unknown")
            and not thing.has("crop", "variety", "plot", "category")
        ):
            joiner.role = "filler"


#: The plants a colour may be said to hang on ("ripe and orange on the trees").
#: Words after a colour that say why something is that colour ("orange from the rust").
_WHY_A_COLOUR = frozenset({"from", "after", "because", "since", "with"})
_ON_THE_PLANTS = frozenset({"trees", "tree", "plants", "vines", "bushes", "branches"})


def colour_after_a_look(items: Sequence[Item]) -> None:
    """'Washington Navels, fruit hanging ripe and orange, packed crates', 'pulling them up
    long and orange', 'the carrots are orange': a crop word that is a colour, ending its
    phrase after a look joined by "and" (not a crop or plot), a copula or an intensifier,
    is a colour."""
    leads = reader_words("colour_leads")
    for index in range(1, len(items)):
        joiner, word = items[index - 1], items[index]
        look = items[index - 2] if index >= 2 else None
        after = items[index + 1] if index + 1 < len(items) else None
        described = joiner.norm in leads or (
            joiner.norm in ("and", "&")
            and look is not None
            and look.role not in ("head", "plot", "number", "separator", "conjunction")
        )
        if (
            word.role == "head"
            and word.norm in reader_words("colour_crops")
            and described
            and (
                after is None
                or after.role in ("separator", "conjunction")
                # ("fruit ripe and orange on the trees": where the colour hangs)
                or (after.role == "filler" and after.norm.split()[-1] in _ON_THE_PLANTS)
                # ("my boots came out orange from walking through": why it is that colour)
                or (after.role == "filler" and after.norm in _WHY_A_COLOUR)
            )
        ):
            word.role = "filler"
            word.data["colour"] = True


def ripening_colours(items: Sequence[Item]) -> None:
    """'tops all flopped over and yellowing': a colour change said with a ripeness cue is
    the crop ripening (senescence), not disease; 'the young green bunch': a young part of
    the plants says nothing of the field's stage."""
    for index, item in enumerate(items):
        if item.role != "health" or item.norm not in reader_words("senescence"):
            continue
        near = [i for i in items[max(0, index - 3) : index + 4] if i is not item]
        if any(_ripeness(i) for i in near):
            item.role = "filler"
    # "tops still green but the roots ... ready for lifting": the leaves, not the field
    for before, item in itertools.pairwise(items):
        stage_cue = item.role == "cue" and all(
            sense.value.attribute == "stage" for sense in item.senses_of("cue")
        )
        if (item.role == "stage" or stage_cue) and before.norm in reader_words("green_parts"):
            item.role = "filler"
    # "a purple flower bud below the young green bunch": the part is young, not the field
    parts = reader_words("young_parts")
    for index, item in enumerate(items):
        if item.role == "stage" and item.norm in ("young", "new", "fresh"):
            following = [i for i in items[index + 1 : index + 3] if i.role != "filler"]
            if any(i.norm in parts for i in items[index + 1 : index + 3]) and not any(
                i.role in ("head", "plot") for i in following[:1]
            ):
                item.role = "filler"


#: Words between a crop and the colour said of it ("the wheat is now golden"), and the
#: parts whose colour shows ripeness ("Cabernet vines with the bunches gone nearly black",
#: "a block of Chardonnay where the grapes are golden", "peppers gone bright red").
_COLOUR_LINKS = frozenset(
    {
        *("is", "are", "now", "all", "gone", "turned", "looking", "looks", "going", "turning"),
        *("with", "the", "its", "their", "where", "whose", "have", "has", "got"),
        *("nearly", "almost", "fully", "mostly", "bright", "deep", "dark", "rich"),
        *("bunches", "grapes", "berries", "fruit", "fruits", "cobs", "kernels", "ears"),
        *("heads", "husks", "stalks", "pods", "vines"),
    }
)
#: How many of those words a colour may stand after its crop.
_COLOUR_REACH = 6


def ripe_colours(items: Sequence[Item]) -> None:
    """'the wheat golden', 'the tomatoes are red': a bare colour said right after a crop
    that only shows it ripe is a Maturation cue (``ripe_colours`` in cues.yaml)."""
    for index, item in enumerate(items):
        if item.role not in ("filler", "weak_variety", "unknown", ""):
            continue
        back = index - 1
        while back >= 0 and index - back <= _COLOUR_REACH and items[back].norm in _COLOUR_LINKS:
            back -= 1
        head = items[back] if back >= 0 else None
        if head is None or head.role != "head" or len(crops := crops_of(head)) != 1:
            continue
        if any(s.crop in crops for s in item.senses_of("variety")):
            continue  # "apples golden": a variety's name is not a look
        after = items[index + 1] if index + 1 < len(items) else None
        if after is not None and after.role in ("head", "plot"):
            continue  # "the wheat golden acre cabbages": words of another phrase
        cue = ripe_colour(next(iter(crops)), item.norm)
        if cue is not None:
            item.role = "cue"
            item.senses = (*item.senses, Sense("cue", cue))
            item.data["cue"] = cue


def _ripeness(item: Item) -> bool:
    """A cue or stated word for a ripening crop ("tops flopped over", "ready to lift")."""
    if item.role == "stage":
        return str(item.data.get("value")) == "Maturation"
    return item.role == "cue" and any(
        sense.value.attribute == "stage" and sense.value.value == "Maturation"
        for sense in item.senses_of("cue")
    )


def past_and_other_readiness(items: Sequence[Item]) -> None:
    """'wire hoops ready for the fleece': not the crop's stage. 'drilled last October;
    it's May now': a month said as when the crop was sown is not the scene's time (when
    another time is said)."""
    times = [i for i in items if i.role in ("month", "season")]
    for index, item in enumerate(items):
        following = [i.norm for i in items[index + 1 : index + 4]]
        if item.role == "stage" and item.norm == "ready" and following[:1] == ["for"]:
            what = next((word for word in following[1:] if word != "the"), "")
            if what not in reader_words("harvests"):
                item.role = "filler"
        if item.role != "month" or len(times) < 2:
            continue
        # ("they went in back in April": past "back")
        before = [i.norm for i in items[max(0, index - 4) : index]]
        last = before[-1] if before else ""
        if (
            last == "last"
            or last in reader_words("sown")
            # "sown in April", "sown back in April"
            or (last == "in" and any(w in reader_words("sown") for w in before[:-1]))
        ):
            item.role = "filler"
            item.data["sown"] = True


def weather_on_plants(items: Sequence[Item]) -> None:
    """'January King cabbages dusted with snow': a look said of weather on the plants
    ("dusted with", "covered in" snow, frost, dew) is no disease."""
    for first, of, what in zip(items, items[1:], items[2:], strict=False):
        if (
            first.role == "health"
            and of.norm in ("with", "in", "by")
            and what.norm in reader_words("weather_coats")
        ):
            first.role = "filler"


def negated_looks(items: Sequence[Item]) -> None:
    """'not in ear yet', 'no flowers yet', 'no spots on the leaves': a stage word or a
    visual cue right after a negation says what the field is not, so it says nothing."""
    for negation, item in itertools.pairwise(items):
        if negation.role == "negation" and (item.role == "stage" or "cue" in item.data):
            item.data["negated"] = True

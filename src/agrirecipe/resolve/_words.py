"""What single words are, before clauses are built (issue 8's reading passes).

:func:`read_words` runs the passes in this order over the tagged words of a prompt;
each decides what a word is in its place, where the lexicon alone cannot:

==  ====================================================  ===========================
#   pass                                                  example
==  ====================================================  ===========================
1   a number with a length unit, a rootstock's name, a    "3.5 m in the pears",
    year, one plant every so far, a count of scenery or   "one carrot every 2 cm",
    of fruit: not a count of fields                       "plan for 2027"
1a  "one" after "this" or "that" counts nothing, and      "Two fields in this one",
    an article before a farm is the farm's; a farm        "A mixed farm with ...",
    word said as a verb is none                           "holding a GNSS pole"
1b  "twin" of no rows; a compound such as "Crop-row" or   "Citrus twin"
    "Pear-vs-apple"
2   a crop word joined to a colour, or a colour crop      "olive-green patches",
    word before scenery or a part of a plant, is a        "an orange tractor",
    colour; a crop word before a machine names its load   "their orange shoulders",
                                                          "a grain trailer"
2a  a colour crop word after "ripe and" is a colour;      "hanging ripe and orange",
    "and" between two colours joins them                  "white and purple blooms"
2b  "different" before a measure says nothing of crops;   "at different densities",
    kinds counted are different crops                     "3 kinds of fruit trees"
2c  a colour change beside a ripeness cue is ripening;    "flopped over and yellowing",
    a young part of the plant is no young field           "the young green bunch"
2d  a capitalised variety name right before a plot word   "the Conference block"
    names that plot's crop
2e  "the X ones": X short for a variety named before      "the beef ones", "the pinot"
3   readiness said of the past or of other things         "ready for the fleece"
4   a stage word or cue after a negation says nothing     "not in ear yet"
4a  a look of weather on the plants is no disease         "dusted with snow"
5   "all" before a plain word stresses it                 "all green and even"
5a  "each" after a count of rows, before a length, is     "30 rows at 75 cm, each
    each row                                              200 m long"
5b  "every field" says something of every field           "each plot gets a headland"
6   plots a list of crops is grown in are its own fields  "A and B in 2 plots"
7   a plot word inside an unknown phrase, a verb, a       "compare planting systems",
    pasture or a part where something shows is no field   "ready to strip", "sheep in
    (``_plot_words``)                                     the paddock"
7a  a place said right after scenery is the scenery's     "my boots in the foreground"
8   a sentence about the rows or beds of every field      "Ridges and beds all 80 m"
9   a number after one plot or tunnel names it            "in plot 2", "tunnel two has"
10  a size followed by "in total" is the farm's           "40 ha in total"
11  sizes given "respectively"                            "2 ha and 3 ha respectively"
==  ====================================================  ===========================

The words each pass looks for are data (``reader_words`` in vocabulary.yaml). The
passes about numbers (1) live in ``_numbers``, those about looks (2, 2a, 2c, 3, 4,
4a) in ``_looks``; purposes ("a blight detection dataset") are read after the roles,
in ``_purposes``.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._fields import ATTRIBUTE_ROLES
from agrirecipe.resolve._geometry import geometry_nouns
from agrirecipe.resolve._lexicon import Item, reader_words
from agrirecipe.resolve._looks import (
    colour_after_a_look,
    colour_lists,
    colours_are_not_crops,
    crops_of,
    negated_looks,
    past_and_other_readiness,
    ripe_colours,
    ripening_colours,
    weather_on_plants,
)
from agrirecipe.resolve._numbers import is_structure, numbers_that_count_no_fields
from agrirecipe.resolve._plot_words import plot_words_of_other_things
from agrirecipe.resolve._structure import descriptive_words

__all__ = ["SENTENCE_MARKS", "read_words", "reader_words"]

#: Marks that end a sentence.
SENTENCE_MARKS = frozenset({".", "!", "?", ";"})


def read_words(items: Sequence[Item], text: str) -> None:
    """Run the word passes, in order, over a prompt's items (see the module's table)."""
    numbers_that_count_no_fields(items)
    _this_one(items)
    _article_of_a_container(items)
    _twins_and_compounds(items, text)
    colours_are_not_crops(items, text)
    colour_after_a_look(items)
    colour_lists(items)
    _measured_differences(items)
    _counted_kinds(items)
    ripening_colours(items)
    ripe_colours(items)
    _variety_before_its_plot(items)
    _short_names_of_named_varieties(items)
    past_and_other_readiness(items)
    negated_looks(items)
    weather_on_plants(items)
    _all_as_intensifier(items)
    _each_row(items)
    _every_plot(items)
    _plots_of_a_list(items)
    plot_words_of_other_things(items)
    _places_of_scenery(items)
    _row_words_of_every_field(items)
    _plot_numbers_are_names(items)
    _totals_are_not_sizes(items)
    _respective_sizes(items)


def _twins_and_compounds(items: Sequence[Item], text: str) -> None:
    """'Citrus twin: ...', 'orchard twin': a digital twin, not two of anything (only
    "twin rows" and "twin beds" count); 'Crop-row detection': a compound, not a crop plot."""
    for item, following in itertools.pairwise(items):
        if (
            item.role == "number"
            and item.norm == "twin"
            and following.norm not in reader_words("twinned")
        ) or (
            item.role == "plot"
            and item.norm in ("crop", "crops")
            and text[item.end : following.start] == "-"
        ):
            item.role = "filler"
        # "Pear-vs-apple LiDAR comparison": what is compared, not a field
        if text[item.end : following.start] == "-" and "vs" in (item.norm, following.norm):
            for compared in (item, following):
                if compared.role in ("head", "plot", "category"):
                    compared.role = "filler"
    if items and items[-1].role == "number" and items[-1].norm == "twin":
        items[-1].role = "filler"


def _totals_are_not_sizes(items: Sequence[Item]) -> None:
    """'we farm about 40 ha in total - 25 ha of wheat, ...': a total is not a field's size.

    'Banana test area, 1.5 ha in total': the only size said of one field of one crop is
    that field's size."""
    norms = [i.norm for i in items]
    totals = []
    for index, item in enumerate(items):
        if item.role != "size":
            continue
        after = tuple(norms[index + 1 : index + 3])
        said = next(
            (
                w.split()
                for w in reader_words("totals")
                if after[: len(w.split())] == tuple(w.split())
            ),
            None,
        )
        # ("A lettuce block ..., 2,000 m² in total, plus a 1,000 m² cabbage block": the
        # lettuce's own total, another field added to it)
        added = [
            n for n in norms[index + 1 + len(said or ()) : index + 4 + len(said or ())] if n != ","
        ]
        if said is not None and added[:1] != ["plus"]:
            totals.append(item)
    sizes = [i for i in items if i.role == "size"]
    crops = {crop for i in items if i.role == "head" for crop in crops_of(i)}
    one_field = (
        len(totals) == len(sizes) == 1
        and len(crops) == 1
        and not any(i.role == "category" for i in items)
        and not any(i.role == "number" and i.data.get("value", 1) != 1 for i in items)
        # ("Lettuces in long beds ..., about 0.5 ha in total": beds are one field)
        and not any(
            i.role == "plot" and i.data["value"]["plural"] and not i.data["value"].get("one_field")
            for i in items
            if "value" in i.data
        )
    )
    for item in [] if one_field else totals:
        item.role = "filler"
        item.data["total"] = True


def _measured_differences(items: Sequence[Item]) -> None:
    """'Three maize plots at different densities': fields that differ in a measure (or a
    stage) are not thereby different crops or varieties."""
    for item, following in itertools.pairwise(items):
        if item.role == "distinct" and following.norm in reader_words("measured_differences"):
            item.role = "filler"


def _counted_kinds(items: Sequence[Item]) -> None:
    """'an orchard with 3 kinds of fruit trees', '3 varieties of apples', 'three different
    crops': kinds counted are different crops or varieties, one field each."""
    for index in range(1, len(items) - 1):
        number, kind, of = items[index - 1], items[index], items[index + 1]
        if (
            number.role == "number"
            and number.norm not in ("a", "an", "one")
            and kind.norm in reader_words("kinds")
            and of.norm == "of"
        ):
            kind.role = "distinct"
            number.data["counts_kinds"] = True  # ("3 kinds of fruit trees": not plants)
    for number, different, plot in zip(items, items[1:], items[2:], strict=False):
        # "the vegetable side is three different crops": different crops counted
        if number.role == "number" and different.role == "distinct" and plot.role == "plot":
            number.data["counts_kinds"] = number.norm not in ("a", "an", "one")


def _variety_before_its_plot(items: Sequence[Item]) -> None:
    """'the Conference block with the Royal Gala next to it': a capitalised name of one
    crop's variety, also an everyday word, right before a plot word names the plot's
    crop, as a lowercase "conference" would not."""
    for item, plot in itertools.pairwise(items):
        if item.role not in ("filler", "weak_variety") or plot.role != "plot":
            continue
        spec = plot.data.get("value")
        if not isinstance(spec, dict) or spec.get("individual"):
            continue
        senses = item.senses_of("variety")
        if not item.tokens[0].capitalised or len({s.crop for s in senses}) != 1:
            continue
        options = spec.get("options") or ()
        if options and senses[0].crop not in options:
            continue
        item.role = "head"
        item.data["promoted"] = True


def _short_names_of_named_varieties(items: Sequence[Item]) -> None:
    """'cherry tomatoes ..., Beefsteak tomatoes ...; the beef ones have big fruit, the
    cherry ones are still in flower': "the X one(s)", X the first word or the start of
    a variety named before, is that variety (not a cherry orchard, not an unknown);
    "pinot noir vines ...; the pinot has downy mildew": an unknown "the X", X the first
    word of a variety's name said before, too."""
    for index in range(1, len(items)):
        item = items[index]
        ones = index + 1 < len(items) and items[index + 1].norm in ("one", "ones")
        if items[index - 1].norm != "the" or not (ones or item.role == "unknown"):
            continue
        # ("the plum ones" after "plum tomatoes": no plum orchard)
        if item.role not in ("unknown", "filler", "head", "weak_variety", "other_crop"):
            continue
        word = item.norm
        # ("the pinot has downy mildew" after "pinot noir vines": a name's first word)
        named = [
            earlier
            for earlier in items[: index - 1]
            if earlier.role == "head"
            and earlier.senses_of("variety")
            and earlier.norm != word
            and (
                # ("the beefs are still green" after "Beef tomatoes": its plural too)
                (
                    earlier.norm.split()[0] in (word, word.removesuffix("s"))
                    and len(earlier.norm.split()) > 1
                )
                or (ones and len(word) >= 4 and earlier.norm.split()[0].startswith(word))
            )
        ]
        if len({n.norm for n in named}) == 1:
            item.senses = tuple(named[0].senses_of("variety"))
            item.role = "head"


def _respective_sizes(items: Sequence[Item]) -> None:
    """'30x40m and 30x60m respectively': sizes listed before "respectively" are one for
    each field named before them, in order (``give_respectively`` gives them out)."""
    for index, item in enumerate(items):
        if item.norm != "respectively":
            continue
        sizes: list[Item] = []
        for before in reversed(items[:index]):
            if before.role == "size":
                sizes.insert(0, before)
            elif not (
                before.role == "conjunction" or (before.role == "separator" and before.norm == ",")
            ):
                break
        if len(sizes) >= 2:
            for place, size in enumerate(sizes):
                size.data["share"] = (place, len(sizes), sizes[0].start)


#: Words after "all" that carry what is said of all fields ("all in flower", "all are ill").
_ALL_CARRIERS = frozenset(
    {"in", "at", "on", "of", "with", "the", "are", "is", "were", "was", "have", "look", "looking"}
)


def _article_of_a_container(items: Sequence[Item]) -> None:
    """'A mixed farm with some vegetable plots': the article is the farm's, no count of
    the fields the farm holds. 'a person holding a GNSS pole': a container word said as
    a verb, before what is held, is no farm."""
    for item, following in itertools.pairwise(items):
        if (
            item.role == "container"
            and item.norm in reader_words("container_verbs")
            and following.norm in reader_words("held_openers")
        ):
            item.role = "filler"
    for index, item in enumerate(items):
        if item.role != "number" or item.norm not in ("a", "an"):
            continue
        for following in items[index + 1 : index + 4]:
            if following.role == "container":
                item.role = "filler"
                break
            if following.role not in ("filler", "distinct", "unknown"):
                break


def _places_of_scenery(items: Sequence[Item]) -> None:
    """'..., and my boots in the foreground', 'a tractor in the middle': a place said
    right after scenery, with no field named since the last break, is the scenery's."""
    for index, item in enumerate(items):
        if item.role != "zone" or index == 0 or not items[index - 1].scenery:
            continue
        for before in reversed(items[:index]):
            if before.role in ("separator", "conjunction"):
                item.role = "filler"
                item.data["scenery"] = "places"
                break
            if before.role in ("head", "plot", "weak_variety", "category"):
                break
        else:
            item.role = "filler"
            item.data["scenery"] = "places"


def _this_one(items: Sequence[Item]) -> None:
    """'Two strawberry fields in this one': "one" after "this", "that" or "which" points
    at a thing (the photo, a field named), it does not count one field; nor does "two" in
    "a vegetable plot in between the two" (the two fields named)."""
    for before, item in itertools.pairwise(items):
        if (
            item.role == "number"
            and item.norm == "one"
            and before.norm in ("this", "that", "which")
        ):
            item.role = "filler"
    for index in range(2, len(items)):
        between, the, number = items[index - 2], items[index - 1], items[index]
        after = items[index + 1] if index + 1 < len(items) else None
        if (
            number.role == "number"
            and the.norm == "the"
            and ("between" in between.norm or between.norm in ("among", "amongst"))
            # ("between the two groves" counts the groves named before)
            and (after is None or after.role not in ("plot", "head", "category"))
        ):
            number.role = "filler"


def _all_as_intensifier(items: Sequence[Item]) -> None:
    """'our wheat, all green and even, drilled at 12.5 cm': "all" before a plain word
    stresses it; it does not say the rest of the sentence of every field."""
    for index, item in enumerate(items[:-1]):
        following = items[index + 1]
        if item.role != "all" or item.norm != "all" or following.role not in ("filler", "unknown"):
            continue
        if following.norm in _ALL_CARRIERS or not following.norm.isalpha():
            continue
        if following.norm in reader_words("bearing"):
            continue  # ("..., then cayenne, all hanging with ripe red fruit": every field)
        beyond = items[index + 2] if index + 2 < len(items) else None
        if beyond is None or beyond.role not in ATTRIBUTE_ROLES:
            item.role = "filler"
    for before, item, following in zip(items, items[1:], items[2:], strict=False):
        # "Albion still all flowers and no fruit": all of its own plants, not every field
        # ("the corn south of the track is all tasselled out": one field, said with "is")
        if (
            item.role == "all"
            and item.norm == "all"
            and before.norm in ("still", "now", "already", "is", "was", "s")
            and following.role in ("stage", "cue")
        ):
            item.role = "filler"
    for before, item in itertools.pairwise(items):
        # "Elsanta with ripe red berries everywhere": all over its own field
        if item.role == "all" and item.norm == "everywhere" and before.role in ("cue", "stage"):
            item.role = "filler"


def _each_row(items: Sequence[Item]) -> None:
    """'30 rows at 75 cm, each 200 m long': "each" right after a count of rows, before a
    measure, is each of those rows, not each field."""
    for before, comma, each, after in zip(items, items[1:], items[2:], items[3:], strict=False):
        if (
            each.role == "all"
            and each.norm == "each"
            and comma.norm == ","
            and before.role == "geometry"
            and any(m.key in ("rows", "beds") for m in before.data["geometry"])
            and after.role == "geometry"
            and all(m.key == "row_length_m" for m in after.data["geometry"])
        ):
            each.role = "filler"
    # "30 rows, 75 cm apart, each row 100 m long": "each" before one row's measure
    for each, after in itertools.pairwise(items):
        if (
            each.role == "all"
            and each.norm == "each"
            and after.role == "geometry"
            and after.tokens[0].norm in ("row", "ridge", "drill", "line")
            and all(m.key == "row_length_m" for m in after.data["geometry"])
        ):
            each.role = "filler"


def _every_plot(items: Sequence[Item]) -> None:
    """'Blight has hit every field - the potatoes, ...', 'each plot gets a 4 m headland',
    'all the strips are 50 m', 'Rows run E-W in both blocks': "every"/"each" before one
    plot word, or "all (the)" or "both" before a plural one, says something of every
    field; the plot word asks for none."""
    for index, item in enumerate(items):
        if item.role != "all" or item.norm not in ("every", "each", "all", "both"):
            continue
        if item.norm == "both" and not _named_in_a_sentence_before(items, index):
            continue  # ("grapes ripening in both blocks. Chardonnay: ...": the two named after)
        if item.norm == "all" and index and items[index - 1].norm in ("is", "s", "was"):
            continue  # ("the top is all fruit trees": what the place is, a field of them)
        at = index + 1
        if item.norm == "all" and at < len(items) and items[at].norm == "the":
            at += 1
        plot = items[at] if at < len(items) else None
        if (
            plot is not None
            and plot.role == "head"
            and item.norm in ("every", "each")
            and plot.norm in descriptive_words()
        ):
            plot.role = "filler"  # "it's on nearly every vine": the plants of the field
            continue
        spec = plot.data.get("value") if plot is not None and plot.role == "plot" else None
        if plot is None or not isinstance(spec, dict):
            continue
        # ("Rows run E-W in both blocks": "both" before a plural, like "all")
        plural_word = item.norm in ("all", "both")
        if bool(spec.get("plural")) != plural_word and not spec.get("individual"):
            continue
        # ("it's on nearly every vine", "every tree has fruit": the plants of the fields)
        after = items[at + 1] if at + 1 < len(items) else None
        # ("each field of wheat", "every plot 2 carrots") name the crop of each field
        if after is not None and after.role in ("head", "weak_variety", "of", "number"):
            # ("each strip with a 3 m headland": what every field has, not its crop)
            said = next((i for i in items[at + 2 :] if i.role not in ("number", "filler")), None)
            if not (after.norm == "with" and said is not None and said.role == "geometry"):
                continue
        plot.role = "filler"


def _named_in_a_sentence_before(items: Sequence[Item], index: int) -> bool:
    """Whether a crop was named in a sentence that ended before ``items[index]``."""
    ends = [k for k, i in enumerate(items[:index]) if i.norm in SENTENCE_MARKS]
    return bool(ends) and any(i.role == "head" for i in items[: ends[-1]])


def _plot_numbers_are_names(items: Sequence[Item]) -> None:
    """'in plot 2', 'Field 4 is ...', 'row 6 of the Lapins': a number right after one
    plot (or row) names it, it does not count fields (a count comes before its noun)."""
    for index, (item, number) in enumerate(itertools.pairwise(items)):
        spec = item.data.get("value") if item.role == "plot" else None
        # ("row 6 of the Sweetheart": one row, named)
        structure = item.norm in (
            *("tunnel", "polytunnel", "greenhouse", "glasshouse", "house"),
            *("row", "bed", "ridge", "bay", "span"),
        )
        if (
            not (isinstance(spec, dict) or structure)
            or (isinstance(spec, dict) and spec.get("plural"))
            or number.role != "number"
        ):
            continue
        after = items[index + 2] if index + 2 < len(items) else None
        # "plot 2 Nantes carrots", "tunnel two has California Wonder peppers": a label
        # opening what it names (a count would come before the plot word)
        opening = index == 0 or items[index - 1].role in ("separator", "conjunction")
        if not number.norm.isdigit() and not (opening and number.norm in _NUMBER_WORDS):
            continue
        if (
            after is None
            or after.role not in ("head", "plot", "weak_variety", "size", "geometry")
            or (opening and after.role in ("head", "weak_variety"))
        ):
            number.role = "filler"
            number.data["label"] = True


#: Number words a plot or tunnel is labelled with ("tunnel two has ...").
_NUMBER_WORDS = frozenset(
    {"one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"}
)


def _row_words_of_every_field(items: Sequence[Item]) -> None:
    """'Ridges and beds all 80 m long', 'Beds all 1.5 m': a sentence about the rows or beds
    of the fields named before, not a field of beds."""
    nouns = geometry_nouns()
    start = 0
    for index, item in enumerate(items):
        if item.role == "separator" and item.norm in SENTENCE_MARKS:
            start = index + 1
            continue
        if index != start or not any(i.role in ("head", "plot") for i in items[:start]):
            continue
        end = index
        while end < len(items) and (
            items[end].norm in nouns or (items[end].role == "conjunction" and end > index)
        ):
            end += 1
        if end > index and end < len(items) and items[end].role == "all":
            for noun in items[index:end]:
                if noun.role != "conjunction":
                    noun.role = "filler"


def _plots_of_a_list(items: Sequence[Item]) -> None:
    """'cabbages and onions in 2 plots', 'onions, carrots and lettuce as three plots',
    'Sturon and Walla Walla onions in adjacent 6 x 50 m strips': plots a list of crops is
    grown in are the list's own fields, one each, not more fields (the plot word and its
    count are read as said of them)."""
    for index, item in enumerate(items):
        # "onions and cabbages, 2 plots, ...": the count of plots said after a comma
        summary = (
            item.role == "separator"
            and item.norm == ","
            and index + 1 < len(items)
            and items[index + 1].role == "number"
        )
        if (item.norm not in ("in", "on", "into", "as") and not summary) or index == 0:
            continue
        cursor, between = index + 1, list[Item]()
        while (
            cursor < len(items)
            and len(between) < 3
            and (
                items[cursor].role in ("number", "size", "unknown", "geometry")
                or items[cursor].norm in reader_words("plot_adjectives")
                or (
                    items[cursor].role in ("relation", "trailer")
                    and items[cursor].norm in reader_words("plot_adjectives")
                )
            )
        ):
            between.append(items[cursor])
            cursor += 1
        if cursor >= len(items):
            continue
        plot = items[cursor]
        spec = plot.data.get("value") if plot.role == "plot" else None
        if is_structure(plot) and plot.norm.endswith("s"):
            spec = {"plural": True}  # "tomatoes and peppers in two long tunnels"
        if not isinstance(spec, dict) or spec.get("individual"):
            continue
        crops, comma, joined = 0, False, False
        for before in reversed(items[:index]):
            # ("Strawberry comparison: Elsanta, Sonata and Albion in three plots": the
            # list after its heading)
            if before.role == "separator" and (before.norm in SENTENCE_MARKS or before.norm == ":"):
                break
            comma = comma or (before.role == "separator" and crops == 0)
            # ("Jonagold and Conference in two orchards": a capitalised weak variety too)
            named = before.role in ("head", "weak_variety") and before.has("crop", "variety")
            if named and not joined:  # "tomatoes (san marzanno)": one crop named
                crops += 1
            joined = named or (joined and before.norm in ("(", ")"))
        counted = [i for i in between if i.role == "number"]
        followed = cursor + 1 < len(items) and items[cursor + 1].role in ("of", "head")
        # "on the terraces", "on steep slate terraces": where the crop named grows
        definite = any(i.norm == "the" or i.role == "unknown" for i in between) and not counted
        if summary and not (
            spec.get("plural") and counted and float(counted[0].data.get("value", 0)) == crops
        ):
            continue
        if spec.get("plural") and definite and crops >= 1:
            pass  # "Cavendish bananas on the terraces below the house": where they grow
        elif spec.get("plural"):
            if crops < 2 or (counted and float(counted[0].data.get("value", 0)) != crops):
                continue
        elif not (
            # "Pear trees, 1,000 of them at 3.5 x 1.2 m in a 60 m x 80 m block": the block
            # the one field named is planted in
            crops == 1
            and comma
            and not followed
            and any(i.role == "size" for i in between)
            and all(i.role != "number" or i.norm in ("a", "an", "one") for i in between)
        ):
            continue
        plot.role = "filler"
        plot.data["list_plots"] = True
        for word in counted:
            word.role = "filler"
        # ("in three plots of 10 x 25 m": each plot's size, said after the plot word)
        after = (
            items[cursor + 2 : cursor + 3] if followed and items[cursor + 1].role == "of" else []
        )
        for word in (*between, *after):
            if word.role in ("geometry", "size") and (spec.get("plural") or word in between):
                word.data["of_each_plot"] = True

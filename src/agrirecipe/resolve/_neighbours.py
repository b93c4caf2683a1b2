"""Fields placed beside each other in words (issue 8).

Before the prompt is read, a few ways people say that plots touch are written the way
the reader places fields (sides of the farm or of a view said in other words are
``_side_phrases``'): "in two neighbouring blocks" is "in two blocks side by side",
"with a ditch between" is scenery, "the polytunnel of cherry tomatoes" is a plot that
can be placed, "Right next to the tunnels" is next to the field under them, and
"flanked on both sides by wheat drilled at 12.5 cm" is "flanked by wheat on both sides
drilled at 12.5 cm", and "The vineyard north of it is Pinot Nero" is "The vineyard is
Pinot Nero north of it".
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Sequence

from agrirecipe.resolve._lexicon import Item, plot_nouns_pattern, scenery_words
from agrirecipe.resolve._side_phrases import CLOSE, NAMED

__all__ = [
    "name_the_placed_plot",
    "place_around_a_centre",
    "place_by_cover",
    "place_divided_plots",
    "place_flanks",
    "place_neighbouring_plots",
]


# "Savoy and January King in two neighbouring blocks": the plots of a list, side by side
_NEIGHBOURING = re.compile(
    # ("Fuji and Golden Delicious, two adjacent blocks, each 30 rows ...": said after a comma)
    # ("Red Baron and Walla Walla onions as two neighbouring plots")
    r"(?:\b(?P<at>(?i:in|on|as))|(?P<comma>,))\s+(?P<count>(?:\w+\s+)?)"
    # ("in three side-by-side strips": the adjective said hyphenated)
    r"(?i:neighbouring|neighboring|adjacent|adjoining|side[- ]by[- ]side)\s+"
    # ("in adjacent 24-ridge plots", "in three adjacent 10 m x 40 m plots")
    r"(?P<size>\d+[- ](?i:ridge|row|bed|tree)\s+|"
    r"\d+(?:\.\d+)?\s*(?:m\s*)?(?:x|×|by)\s*\d+(?:\.\d+)?\s*m\s+)?"
    r"(?P<plots>(?i:blocks|plots|fields|strips|beds|patches|paddocks|tunnels|polytunnels|"
    r"greenhouses|glasshouses))\b"
)


_OPENING_NEIGHBOURS = re.compile(
    r"(?:^|(?<=[.;:!?]\s))(?P<count>(?i:two|three|four|2|3|4)\s+)"
    r"(?i:neighbouring|neighboring|adjacent|adjoining|side[- ]by[- ]side)\s+"
    r"(?P<plots>(?i:plots|fields|blocks|strips|beds|patches|paddocks))\b"
    r"(?P<of>\s+(?i:of)\s+[A-Za-z][\w'’ -]*?"
    # ("three adjacent blocks of Jonagored, Fuji and Pink Lady apples": the whole list)
    r"(?:\s*,\s*[A-Za-z][A-Za-z'’ -]*?)*(?:\s*,?\s+(?i:and|&)\s+[A-Za-z][A-Za-z'’ -]*?)?)?"
    r"(?=\s*(?:[,:;.]|$))"
)
# "Padrón peppers on one bed and Jalapeños on the next": two plots side by side
_ONE_AND_THE_NEXT = re.compile(
    r"\s+(?i:on|in) (?i:one) "
    r"(?P<noun>(?i:bed|row|ridge|strip|plot|block|bench|bay|field|paddock))\s+"
    r"(?i:and|&)\s+(?P<b>[A-Za-z][^,;.:!?]*?)\s+(?i:on|in) (?i:the) (?i:next|other)"
    r"(?:\s+(?i:one|(?P=noun)))?\b"
)
# "..., plus an adjacent Agria potato plot": a field said to adjoin the one named before
_AN_ADJACENT = re.compile(
    r"(?P<lead>\b(?i:plus|and|with)|,)\s+(?P<article>(?i:an?|one))\s+"
    r"(?i:adjacent|neighbouring|neighboring|adjoining)\s+(?=[A-Za-z])"
)


def place_neighbouring_plots(text: str) -> str:
    """``text`` with "in two neighbouring blocks" written "in two blocks side by side",
    "Two plots ..., one beside the other: onions ... and carrots" written "..., side by
    side: ...", "the polytunnel of cherry tomatoes" written "the plot of cherry
    tomatoes", and "..., plus an adjacent Agria plot" written "..., plus alongside an Agria
    plot"; "Padrón on one bed and Jalapeños on the next" is "Padrón and Jalapeños side
    by side"."""
    text = _COVERED.sub(lambda m: f"{m.group('article')}plot{m.group('of')}", text)
    text = _BETWEEN_THE_TWO.sub(r"\g<between> them", text)
    # (after the fields named, not opening a sentence: "Between the two orchards there's a
    # vegetable garden" asks for the orchards)
    text = _BETWEEN_THE_TWO_PLOTS.sub(
        lambda m: (
            m.group(0)
            if re.search(r"(?:^|[.!?:;])\s*$", m.string[: m.start()])
            else f"{m.group('between')} them"
        ),
        text,
    )
    text = _SEPARATES.sub(lambda m: f": {m.group('a')} next to ", text)
    text = _MEET_AT.sub("side by side", text)
    text = _ONE_AND_THE_NEXT.sub(r" and \g<b> side by side", text)
    text = _AN_ADJACENT.sub(lambda m: f"{m.group('lead')} alongside {m.group('article')} ", text)
    text = _ONE_BESIDE_THE_OTHER.sub("side by side:", text)
    text = _ONE_BESIDE_THE_OTHER_EACH.sub(" side by side", text)
    # "Two adjacent plots of carrots, Imperator and Danvers": said opening a sentence
    text = _OPENING_NEIGHBOURS.sub(
        lambda m: f"{m.group('count')}{m.group('plots')}{m.group('of') or ''} side by side", text
    )
    return _NEIGHBOURING.sub(
        lambda m: (
            f"{m.group('at') or ','} {m.group('count')}{m.group('size') or ''}{m.group('plots')} "
            "side by side"
        ),
        text,
    )


# "an orchard ..., a vineyard ..., and between the two a strip of strawberries": the two
# fields just named (not "between the two tomato strips", which names them); "a cabbage
# field in between the two with fat blue-green heads": what it looks like, after
_BETWEEN_THE_TWO = re.compile(
    r"\b(?P<between>(?i:between|in between))\s+(?i:the two|the pair|both)"
    r"(?=\s+(?i:a|an|the|some|is|are|there|sits|lies|runs|we|you|i|with)\b)"
)
# "the Padron peppers sit between the two paddocks": the two fields named before, by the
# plot word they share (not "between the two tomato strips", which names a crop)
_BETWEEN_THE_TWO_PLOTS = re.compile(
    r"\b(?P<between>(?i:between|in between))\s+(?i:the two|both(?: the)?|the pair of)\s+"
    r"(?i:blocks|paddocks|fields|plots|strips|beds|orchards|groves|vineyards|tunnels|patches|"
    r"parcels|sections|areas|plantations)\b"
)
# "A hazel hedge separates our Golden Delicious apples, ..., from a field of January King
# cabbages": the two fields it divides touch it, side by side
_SEPARATES = re.compile(
    r"\s+(?i:separates|divides|splits|separating|dividing)\s+(?P<a>[^.;:!?]*?)\s+(?i:from)\s+"
    r"(?=(?i:a|an|the|our|my|their|some)\b)"
)
# "Two onion fields meet at the hedge": they touch along it
_MEET_AT = re.compile(
    r"\b(?i:meet|meeting|join|joining)\s+(?i:at|along|by|on)\s+(?i:the|a)\s+[\w-]+(?:\s+[\w-]+)?"
    r"(?=\s*(?:[,.;:!?]|$))"
)
# "Two plots for the weeding robot, one beside the other: onions ... and carrots ...": the
# plots named after the colon stand side by side (before it, "one next to the other"
# relates the two named first, in order)
_ONE_BESIDE_THE_OTHER = re.compile(
    r"\b(?i:one)\s+(?i:beside|next to|alongside|by)\s+(?i:the other)(?:\s+(?i:one))?\s*:"
)
# "Two salad plots one beside the other, each 6 beds ...": the plots just counted
_ONE_BESIDE_THE_OTHER_EACH = re.compile(
    r"(?<=[A-Za-z])\s+(?i:one)\s+(?i:beside|next to|alongside)\s+(?i:the other)"
    r"(?:\s+(?i:one))?(?=\s*,\s*(?i:each|both)\b)"
)
# "next to the polytunnel of cherry tomatoes", "a glasshouse full of lettuce": the crop's
# plot under cover (the cover is scenery; the plot can be placed)
_COVERED = re.compile(
    r"(?P<article>\b(?i:a|an|the|one|our|my|their|that|this)\s+(?:(?i:big|small|long|large|"
    r"little|old|new)\s+)?)(?i:poly ?tunnel|tunnel|greenhouse|glasshouse|glass house|"
    r"hoop ?house|high tunnel)"
    r"(?P<of>\s+(?:(?i:full of|of|with|growing|planted with|planted to)\s+))(?=[A-Za-z])"
)


#: A boundary, ditch or tree line said with up to two words before it ("a hawthorn
#: hedge", "a narrow gravel track"): scenery that divides two plots.
_A_DIVIDER = (
    r"(?i:a|an|the|one|just a|only a|a narrow|a wide|a little|a small)\s+"
    r"(?:[\w'-]+\s+){{0,2}}?(?i:{things})"
)
_DIVIDES = r"\s+(?:(?i:running|that runs|going)\s+)?(?:(?i:in)\s+)?(?i:between)"


@functools.cache
def _dividers() -> tuple[re.Pattern[str], re.Pattern[str], re.Pattern[str]]:
    """The ways scenery is said to divide two plots: "with a ditch between (them)",
    "separated only by a hedge", "with a ditch between the wheat and the maize"."""
    things = "|".join(re.escape(w) for w in scenery_words("boundaries", "ground", "trees"))
    divider = _A_DIVIDER.format(things=things)
    between = re.compile(
        rf"(?P<side>\b(?i:side by side)\s*)?(?:,\s*)?(?:(?i:with|and)\s+)?{divider}{_DIVIDES}"
        r"(?:\s+(?i:them|the two|the two of them|both|the plots|the fields|the blocks|"
        r"the two plots|the two fields|the two blocks))?"
        # (the fields it divides named after: read by the third)
        r"(?=\s*(?:[,.;:!?)]|$|(?i:and|with|but)\b))"
    )
    separated = re.compile(
        # (not "Bartlett pears on the left, Bing cherries on the right, separated by a
        # gravel track": said after a comma, of fields placed already)
        r"(?<![,;:])\s+(?i:separated|divided|split|kept apart)\s+(?:(?i:only|just|simply)\s+)?"
        rf"(?i:by)\s+{divider}(?=\s*(?:[,.;:!?)]|$|(?i:and|with|but)\b))"
    )
    named = re.compile(
        rf"(?:\s*,)?\s+(?:(?i:with|and)\s+)?{divider}{_DIVIDES}\s+"
        r"(?P<a>(?i:the)\s+[^,;.:!?]+?)\s+(?i:and)\s+(?P<b>(?i:the)\s+[^,;.:!?]+?)"
        r"(?=\s*(?:[.;!?]|$))"
    )
    return between, separated, named


@functools.cache
def _separating_plot() -> re.Pattern[str]:
    """ "Two carrot plots separated by an onion plot": a plot of its own parting the two
    (a hedge or ditch parting them is scenery: :func:`_dividers`)."""
    return re.compile(
        r"(?<=[A-Za-z])\s+(?i:separated|divided|split|parted|kept apart)\s+(?i:by)\s+"
        rf"(?P<plot>(?i:a|an|one|a single)\s+(?:[\w'-]+\s+){{0,3}}?(?i:{plot_nouns_pattern()})\b"
        r"(?:\s+(?i:of)\s+[^,.;:!?()]+?)?)"
        r"(?=\s*(?:[,.;:!?)]|$|(?i:and|with|but)\b))"
    )


@functools.cache
def _bounded_field() -> tuple[re.Pattern[str], str]:
    """ "Between the two hedgerows is the strawberry ground": a field said to lie between
    two things of scenery (and the pattern of a side of one of them)."""
    things = "|".join(re.escape(w) for w in scenery_words("boundaries", "ground", "trees"))
    field = r"(?P<field>(?i:the|our|my)\s+[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*)?)"
    bounded = re.compile(
        rf"\b(?i:between)\s+(?i:the)\s+(?i:two)\s+(?i:{things})\s+"
        rf"(?:(?i:is|lies|sits|runs)\s+)?{field}(?=\s*[,.;:!?]|\s+(?i:with|and)\b)"
        # ("the strawberry ground lies between the two hedges")
        rf"|(?:^|(?<=[.;!?]\s)){field.replace('<field>', '<field2>')}\s+"
        rf"(?i:is|lies|sits|runs)\s+(?i:between)\s+(?i:the)\s+(?i:two)\s+(?i:{things})\b"
    )
    side_of = (
        r"(?:(?i:on|along|at)\s+)?(?:(?i:the)\s+)?(?P<side>(?i:north|south|east|west))"
        rf"(?:\s+(?i:side))?\s+(?i:of)\s+(?i:the)\s+(?:[\w'-]+\s+)?(?i:{things})\b"
    )
    return bounded, side_of


@functools.cache
def _two_either_side() -> re.Pattern[str]:
    """ "Two fields of cereals either side of the farm road": two fields said at once,
    one on each side of a track, ditch or hedge (not "four fields, two either side")."""
    things = "|".join(re.escape(w) for w in scenery_words("boundaries", "ground", "trees"))
    return re.compile(
        r"(?P<lead>\b(?i:two|2|both|a pair of)\s+(?!(?i:either|each|both|on)\b)"
        r"[A-Za-z][^,;:.!?]*?)\s+(?:(?i:on)\s+)?(?i:either|each|both)\s+(?i:sides?)\s+(?i:of)\s+"
        + _A_DIVIDER.format(things=things)
        # (not "... either side of the lane and an onion field past the pond")
        + r"(?=\s*(?:[,.;:!?)]|$|(?i:with|but)\b))"
    )


def _past_the_bounds(text: str) -> str:
    """``text`` with "Between the two hedgerows is the strawberry ground, with wheat on
    the north side of the top hedge and onions south of the bottom hedge" written "...,
    with wheat north of the strawberry ground and onions south of the strawberry ground":
    past one of the two things a field lies between is past that field."""
    bounded, side_of = _bounded_field()
    found = bounded.search(text)
    if found is None:
        return text
    rest = re.sub(
        side_of,
        lambda m: f"{m.group('side').lower()} of {found.group('field') or found.group('field2')}",
        text[found.end() :],
    )
    return text[: found.end()] + rest


def place_divided_plots(text: str) -> str:
    """``text`` with "two plots, side by side with a ditch between: ..." written "two
    plots, side by side: ...", and "wheat and maize with a hedge between them" written
    "wheat and maize": a ditch, hedge or track between two plots is scenery, not a
    "between" that needs a field on each side (side by side only where it is said).
    "two wheat fields separated only by a hawthorn hedge" is "two wheat fields side by
    side", and "..., with a ditch between the wheat and the maize" is "..., the wheat
    next to the maize": what divides them is scenery and they touch it on either side;
    so do "two wheat fields either side of the track"."""
    between, separated, named = _dividers()
    text = _past_the_bounds(text)
    text = separated.sub(" side by side", text)
    # "two carrot plots separated by an onion plot": the plot that parts them is between
    text = _separating_plot().sub(lambda m: f", {m.group('plot')} between them", text)
    # "Two fields of cereals either side of the farm road": across it from each other
    text = _two_either_side().sub(lambda m: f"{m.group('lead')} side by side", text)
    # "..., with a ditch between the wheat and the maize": the two fields it divides touch
    text = named.sub(lambda m: f", {m.group('a')} next to {m.group('b')}", text)
    return between.sub(lambda m: "side by side" if m.group("side") else "", text)


# "Strawberry field under long plastic tunnels, ... Right next to the tunnels is an open
# field of Lollo Rosso": the field the cover was said of, placed again by its cover
_UNDER_COVER = re.compile(
    r"\b(?P<field>[A-Za-z][\w'-]*(?:\s+(?i:field|plot|beds?|crop|patch))?)\s+(?i:under)\s+"
    r"(?:(?i:the|long|low|high|plastic|poly|clear|white|some|its)\s+)*"
    r"(?P<cover>(?i:tunnels|polytunnels|poly tunnels|covers|fleece|netting|nets))\b"
)
_PLACED_BY = (
    r"(?i:next to|beside|by|alongside|near|behind|in front of|north of|south of|east of|west of)"
)


def place_by_cover(text: str) -> str:
    """``text`` with "next to the tunnels" written "next to the <field under them>" when
    one field was said to be under those tunnels (covers, fleece, netting) before."""
    covered = list(_UNDER_COVER.finditer(text))
    if len({m.group("cover").lower() for m in covered}) != 1 or len(covered) != 1:
        return text
    found = covered[0]
    later = re.compile(rf"(?P<by>\b{_PLACED_BY}\s+)(?i:the)\s+{re.escape(found.group('cover'))}\b")
    return text[: found.end()] + later.sub(
        lambda m: f"{m.group('by')}the {found.group('field')}", text[found.end() :]
    )


# "flanked on both sides by wheat drilled at 12.5 cm": the sides said before what is on them
_FLANKED_SIDES = re.compile(
    r"\b(?P<verb>(?i:flanked|bordered|edged|hemmed in|lined))\s+"
    r"(?P<sides>(?i:on\s+(?:both|either|each)\s+sides?|(?:both|either|each)\s+sides?))\s+"
    r"(?i:by)\s+(?P<words>(?:[A-Za-z][\w'-]*\s*){1,4})"
)


def place_flanks(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "flanked on both sides by wheat drilled at 12.5 cm" written "flanked
    by wheat on both sides drilled at 12.5 cm", so the sides follow the field on them
    (the longest run of the words after "by" that names a crop, variety or plot)."""

    def rewrite(match: re.Match[str]) -> str:
        words = match.group("words").split()
        for end in range(len(words), 0, -1):
            named = " ".join(words[:end])
            items = [i for i in tag(named) if i.role != "separator"]
            if items and all(i.has("crop", "variety", "plot", "category") for i in items):
                rest = " ".join(words[end:])
                tail = match.group("words")[len(match.group("words").rstrip()) :]
                sides = match.group("sides")
                return f"{match.group('verb')} by {named} {sides}{' ' + rest if rest else ''}{tail}"
        return match.group(0)

    def both_sides(match: re.Match[str]) -> str:
        # "cereals on both sides of the track": a field on each side of the scenery
        items = [i for i in tag(match.group("crop")) if i.role != "separator"]
        if not items or not all(i.has("crop", "variety", "category") for i in items):
            return match.group(0)
        return (
            f"{match.group('crop')} in two fields, one each side of "
            f"{match.group('the')}{match.group('thing')}"
        )

    def around_a_field(match: re.Match[str]) -> str:
        # "onions on both sides of the potatoes": the potatoes, with onions on both sides
        # ("layout with cabbages on either side of a carrot plot": the crop word said last)
        if re.search(r"(?i:\band|&|\bor)\s*$", match.string[: match.start()]):
            return match.group(0)  # ("Durondeau and Williams pears on either side of ...")
        x, lead = match.group("x"), ""
        first, _, rest = x.partition(" ")
        if (
            rest
            and first.lower() not in ("two", "2")
            and not any(i.has("crop", "variety", "category", "plot") for i in tag(first))
        ):
            x, lead = rest, f"{first} "
        for said in (x, match.group("y")):
            items = [i for i in tag(said) if i.role != "separator"]
            if not items or not all(i.has("crop", "variety", "category", "plot") for i in items):
                return match.group(0)
            if not any(i.has("crop", "variety", "category") for i in items):
                return match.group(0)
        return f"{lead}{match.group('y')}, {x} on both sides"

    def side_of_a_field(match: re.Match[str]) -> str:
        # "On the north side of the onions, a cabbage plot": north of the onions (not "on
        # the north side of the farmhouse", a side of the farm)
        items = [i for i in tag(match.group("words")) if i.role != "separator"]
        if not items or not items[0].has("crop", "variety", "category"):
            return match.group(0)
        return f"{match.group('side')} of {match.group('the') or ''}{match.group('words')}"

    text = _both_sides_of_scenery().sub(both_sides, _FLANKED_SIDES.sub(rewrite, text))

    def behind_a_field(match: re.Match[str]) -> str:
        # "a patch of onions behind the pears": next to the pears (not "a barn behind the
        # trees", scenery, nor "behind the farmhouse")
        before = _LAST_WORD.search(text, 0, match.start())
        if before is None or any(i.has("scenery", "non_agricultural") for i in tag(before[0])):
            return match.group(0)
        items = [i for i in tag(match.group("words")) if i.role != "separator"]
        if not items or not items[0].has("crop", "variety"):
            return match.group(0)
        return f"next to {match.group('the')}{match.group('words')}"

    text = _SIDE_OF.sub(side_of_a_field, text)
    text = _BEHIND.sub(behind_a_field, text)
    return _AROUND_A_FIELD.sub(around_a_field, text)


_LAST_WORD = re.compile(r"[A-Za-z][\w'-]*(?=\s*$)")
_BEHIND = re.compile(rf"\b{CLOSE}(?i:behind)\s+(?P<the>(?i:the|our|my)\s+){NAMED}")


_SIDE_OF = re.compile(
    r"\b(?i:on|along|at)\s+(?i:the)\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    rf"(?i:side|edge)\s+(?i:of)\s+(?P<the>(?i:the|our|my|an?)\s+)?{NAMED}"
)


# "onions on both sides of the potatoes", "wheat either side of the maize block", "two
# carrot fields either side of the lettuce plot" (the count goes with its fields)
_AROUND_A_FIELD = re.compile(
    r"(?P<x>\b(?:(?i:two|2)\s+)?[A-Za-z][\w'-]*(?:\s+(?!(?i:on|both|either|each)\b)[A-Za-z][\w'-]*)?)\s+"
    r"(?:(?i:on)\s+)?"
    r"(?i:both sides of|either side of|each side of)\s+(?:(?i:the|an?)\s+)?"
    r"(?P<y>[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*)?)(?=\s*(?:[,.;:!?]|$))"
)


@functools.cache
def _both_sides_of_scenery() -> re.Pattern[str]:
    """'cereals on both sides of the track', 'wheat either side of the lane'."""
    things = "|".join(re.escape(w) for w in scenery_words("boundaries", "ground"))
    return re.compile(
        r"(?P<crop>\b[A-Za-z][\w'-]*)\s+(?:(?i:on|growing on|grown on)\s+)?"
        r"(?i:both sides of|either side of|each side of)\s+"
        rf"(?P<the>(?i:the|a|an|our|that)\s+)(?P<thing>(?i:{things}))\b"
    )


# "Four fields around the farmhouse: wheat to the north of it, maize to the south, ...":
# each field on its own side of the centre named, not of the field before
_AROUND = re.compile(
    r"\b(?i:around|round|surrounding)\s+(?i:the|our|my)\s+(?P<centre>[A-Za-z][\w'-]*)"
)
_TO_THE_SIDE = re.compile(
    r"\b(?:(?i:to|on)\s+)?(?i:the)\s+(?P<side>(?i:north|south|east|west))(?:\s+(?i:side))?"
    r"(?:\s+(?i:of)\s+(?i:it|the\s+(?P<of>[A-Za-z][\w'-]*)))?\b(?=\s*(?:[,.;]|and\b|$))"
)


# "house in the middle, vines to the north, ..., tomatoes east and peppers west": the
# centre said by what is in the middle, then each field on its side (said bare too)
_IN_THE_MIDDLE = re.compile(
    r"(?:^|(?<=[:,;]\s))(?:(?i:the|our|my|a|an)\s+)?(?P<centre>[A-Za-z][\w'-]*)\s+"
    r"(?:(?i:is|sits|stands)\s+)?(?i:in the (?:middle|centre|center))\s*(?=[,;])"
)
_BARE_SIDE = re.compile(
    r"(?<=[A-Za-z]\s)(?P<side>(?i:north|south|east|west))(?P<of>)(?=\s*(?:[,.;]|and\b|$))"
)


def place_around_a_centre(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "around the farmhouse: wheat to the north of it, maize to the south"
    (or "house in the middle, vines to the north, ..., tomatoes east and peppers west")
    written "... wheat in the north, maize in the south" (zones of the farm), when the
    centre is no field ("around the vineyard" keeps its fields placed against it) and two
    or more sides are said after it."""
    around = _AROUND.search(text)
    middle = around is None
    if around is None:
        around = _IN_THE_MIDDLE.search(text)
    if around is None or any(
        i.has("crop", "variety", "plot", "category") for i in tag(around.group("centre"))
    ):
        return text
    matches = [
        m
        for m in _TO_THE_SIDE.finditer(text, around.end())
        if m.group("of") in (None, around.group("centre"))
    ]
    if middle:
        said = [m.span() for m in matches]
        matches += [
            m
            for m in _BARE_SIDE.finditer(text, around.end())
            if not any(a <= m.start() < b for a, b in said)
        ]
        matches.sort(key=lambda m: m.start())
    if len({m.group("side").lower() for m in matches}) < 2:
        return text
    for match in reversed(matches):
        text = (
            f"{text[: match.start()]}at the {match.group('side').lower()} end{text[match.end() :]}"
        )
    return text


@functools.cache
def _placed_plot() -> re.Pattern[str]:
    """ "the vineyard north of it is Pinot Nero": a plot, its place against what a pronoun
    names, then what it grows."""
    nouns = plot_nouns_pattern()
    return re.compile(
        rf"\b(?P<plot>(?i:the)\s+(?i:{nouns}))\s+"
        r"(?P<place>(?:(?i:just|right|directly|immediately)\s+)?"
        r"(?i:(?:north|south|east|west)\s+of|next\s+to|beside|behind|beyond|alongside))\s+"
        r"(?P<pronoun>(?i:it|them))\s+(?P<verb>(?i:is|are))\s+"
        r"(?P<crop>[A-Za-z](?:[^,;.:!?()]|[.,](?=\d))*?)(?=\s*(?:[;:!?()]|[.,](?!\d)|$))"
    )


def name_the_placed_plot(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "The vineyard north of it is Pinot Nero" written "The vineyard is Pinot
    Nero north of it": the plot placed is the one that grows the crop the verb names (not
    "the block north of it is ripe")."""

    def named(match: re.Match[str]) -> str:
        if not any(i.has("crop", "variety") for i in tag(match.group("crop"))):
            return match.group(0)
        return (
            f"{match.group('plot')} {match.group('verb')} {match.group('crop')} "
            f"{match.group('place')} {match.group('pronoun')}"
        )

    return _placed_plot().sub(named, text)

"""Sides of the farm, of a view or of a field said in other words (issue 8).

Before the prompt is read, ways people say which side a field is on are written the
way the reader places fields: "riesling in the middle w/ pinot noir on one side &
cabernet on the other" is "riesling between pinot noir and cabernet", "..., danvers one
east" is "..., danvers one east of the other", "the cherries are east" is "the cherries
are to the east", "on the 20 ha east field ..., on the 8 ha west field" is "in the east,
20 ha ..., in the west, 8 ha", "directly below it, so south of the maize" is "south of
the maize" and, on a map of the farm, "letuce under it" is "letuce below it"; "north:
vines. south: fruit trees." is "vines in the north. fruit trees in the south.", "one
either side of the farmhouse, east and west" is "one east of the farmhouse and one west
of it", "carry on north past it and you hit our wheat" is "our wheat north of it", and
"the west half is split between a potato field to the north and an onion field to the
south" is "a potato field in the north west and an onion field in the south west".
"""

from __future__ import annotations

import re

from agrirecipe.resolve._links import OPPOSITE

__all__ = ["CLOSE", "NAMED", "place_sides", "place_split_halves"]


# "riesling in the middle w/ pinot noir on one side & cabernet on the other": the field
# before "with" stands between the two (its "in the middle" said again)
_ONE_SIDE_AND_OTHER = re.compile(
    r"(?:\s+(?i:in the (?:middle|centre|center)))?\s*,?\s+(?:(?i:with)\s+)?"
    # (what it lies between is no side: "lies between the wheat on one side and ...")
    r"(?P<a>[A-Za-z](?:(?!\s(?i:between)\s)[^,;.:!?])*?)\s+(?i:on one side)\s*,?\s+"
    r"(?P<and>(?i:and|&)\s+)?(?!(?i:of)\b)"
    r"(?P<b>[A-Za-z][^,;.:!?]*?)\s+(?i:on the other)(?:\s+(?i:side|one))?\b"
)
# "imperator carots & danvers carots, danvers one east": one of two fields said to be on
# a side is on that side of the other
_ONE_ON_A_SIDE = re.compile(
    # (not "plum ones to the west": the sides said with "to the" are read as placements)
    r"\b(?P<name>[A-Za-z][\w'-]*) (?i:one|block|field|plot) (?:(?i:is) )?"
    r"(?P<side>(?i:north|south|east|west))\b(?!\s+(?i:of|side|end|half|field|block|plot)\b)"
    # (not "one with rows north-south and one east-west": a pair of sides is its rows' way)
    r"(?!\s*[-–—/]\s*(?i:north|south|east|west)\b)"
)


# "pinot nero & cabernet, 1ha each, pinot nero north": a field named again, then the one
# side said in the whole request
_NAMED_AGAIN_SIDE = re.compile(
    r"(?<=,\s)(?P<name>[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*)?)\s+"
    r"(?P<side>(?i:north|south|east|west))(?=\s*(?:[.;!?]|$))"
)
_A_SIDE = re.compile(r"\b(?i:north|south|east|west)(?:(?i:ern|wards))?\b")


def _named_again_on_a_side(text: str) -> str:
    """``text`` with "..., pinot nero north" written "..., pinot nero north of the other"
    when the name was said before and that is the only side said."""
    match = _NAMED_AGAIN_SIDE.search(text)
    if match is None or len(_A_SIDE.findall(text)) != 1:
        return text
    last = match.group("name").split()[-1]
    if not re.search(rf"(?<![\w-]){re.escape(last)}(?![\w-])", text[: match.start()], re.I):
        return text
    return f"{text[: match.end()]} of the other{text[match.end() :]}"


_ARE_A_SIDE = re.compile(
    # ("cabernet's north": "is" written "'s")
    r"(?:\b(?P<verb>(?i:are|is))\s+|(?<=[A-Za-z])(?P<s>['’]s)\s+)"
    r"(?P<side>(?i:north|south|east|west))(?=\s*(?:[,.;:!?]|$))"
)


# "Dent corn on the 20 ha east field ..., flint corn on the 8 ha west field": fields named
# by their side of the farm
_SIDE_FIELD = re.compile(
    r"\b(?i:on|in|at) (?i:the) (?P<size>\d[\d.,]*\s*(?i:ha|hectares?|acres?)\s+)?"
    r"(?P<side>(?i:north|south|east|west))(?i:ern)? (?i:field|block|plot|paddock)\b"
)


# "vineyard", "a big field": a plot named alone, no crop, opening its sentence
_A_PLOT_ALONE = re.compile(
    # ("pic of the feild by the barn, tomatos on one side and peppers on the other": the
    # plot a picture is of, placed by scenery)
    r"^\s*(?:(?i:pic|photo|picture|shot|image|snap)\s+(?i:of)\s+)?"
    r"(?:(?i:a|an|the|my|our|one|big|small|little|new|old|single)\s+)*"
    r"(?i:vineyard|orchard|field|feild|plot|block|garden|grove|plantation|patch|bed)"
    r"(?:\s+(?i:by|near|behind|beside|next to|past|across from)\s+(?i:the|our|my)\s+"
    r"(?i:barn|house|farmhouse|yard|shed|road|lane|track|gate|river|pond|woods|church))?\s*$"
)

# "Two plantations divided by a wire fence, bananas on one side and oranges on the other":
# two plots counted, then what is on each side (their members)
_TWO_PLOTS_ALONE = re.compile(
    r"^\s*(?i:two|2|both|a pair of)\s+(?:[A-Za-z][\w'-]*\s+){0,2}?"
    r"(?i:vineyards|orchards|fields|plots|blocks|gardens|groves|plantations|patches|beds|"
    r"strips|paddocks)(?:\s+(?i:side by side|next to each other|beside each other))?\s*$"
)


# "Agria potatoes furthest north, then a strip of onions, and carrots at the southern
# end": a walk from the field said to be furthest one way, the other way
_FURTHEST_THEN = re.compile(
    r"(?P<lead>(?:^|[:;.!?]\s*))(?P<first>[A-Za-z][^,;.:!?]*?)\s+"
    r"(?i:furthest|farthest|most|right at the|at the far)\s+"
    r"(?P<side>(?i:north|south|east|west))(?i:erly| end)?\s*,\s*(?i:then)\s+"
)
#: The opposite side ("north": "south"), from the relations' own table.
_OPPOSITE = {k.removesuffix("_of"): v.removesuffix("_of") for k, v in OPPOSITE.items()}


def _between_sides(match: re.Match[str]) -> str:
    """ " between A and B" for "with A on one side and B on the other"; only ", A and B"
    (the fields' names) when the sentence has placed the field between them already
    ("potatoes between 2 onion fields, sturon on one side red baron on the other")."""
    sentence = re.split(r"[.;!?]", match.string[: match.start()])[-1]
    if _TWO_PLOTS_ALONE.search(sentence) and match.group("and"):
        # "Two plantations ..., bananas on one side and oranges on the other": the two
        return f": {match.group('a')} and {match.group('b')}"
    if _A_PLOT_ALONE.search(sentence) and match.group("and"):
        # "vineyard w chardonay on one side & pinot noire on the other": its two halves
        # ("the field, carrots on one side and onions on the other": the same, listed)
        said_with = re.search(
            r"\b(?i:with|w)\b", match.group(0)[: match.start("a") - match.start()]
        )
        return f"{' with' if said_with else ':'} {match.group('a')} and {match.group('b')}"
    if re.search(r"\b(?i:between)\s*$", sentence):
        # "Our potato ground lies between the wheat on one side and the carrots on the
        # other": the two sides are what it lies between
        return f" {match.group('a')} and {match.group('b')}"
    if re.search(r"\b(?i:between)\b", sentence):
        return f", {match.group('a')} and {match.group('b')}"
    if not match.group("and"):
        return match.group(0)  # ("Cherry tomatoes ... on one side, a bed of ... on the other")
    return f" between {match.group('a')} and {match.group('b')}"


# "crisphead on the left and Boston on the right (looking north)": which way the viewer
# faces, so left is west and right east, as they are read anyway (not an order of fields)
_FACING_NORTH = re.compile(
    r"(?:(?<=[Ll]eft)|(?<=[Rr]ight))\s*(?:\(\s*|,\s*)?(?i:looking|facing)\s+(?:(?i:due)\s+)?"
    r"(?i:north)(?i:wards)?(?:\s*\))?"
)


# "I was facing due north ...: potatoes in the foreground and a wheat field beyond them":
# what lies beyond, seen one way, is on that side
_FACING = re.compile(
    r"\b(?i:facing|looking)\s+(?:(?i:due|straight)\s+)?"
    r"(?P<side>(?i:north|south|east|west))(?i:wards)?\b(?!\s+(?i:of)\b)"
)
#: "just", "right behind": a place said closer.
CLOSE = r"(?:(?i:just|right|directly|straight)\s+)?"
#: The one or two words that name what a side or a place is said of ("the Gala block").
NAMED = r"(?P<words>[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*)?)"
_BEYOND = re.compile(
    rf"\b{CLOSE}(?i:beyond|behind)"
    r"(?=\s+(?i:them|it|the|that|those|this|these)\b)"
)


# "a cherry orchard next to it with trees at 5 x 3 m": the placed field's own trees,
# said after what it is placed against
_PLACED_WITH_PLANTS = re.compile(
    r"\b(?P<it>(?i:it|them))\s+(?=(?i:with)\s+(?:(?i:its|their)\s+)?"
    r"(?i:trees|vines|plants|bushes|canes)\b)"
)
# "two fields: to the north, potatoes ...; to the south, wheat ...": each member's side said
# before it
_SIDE_BEFORE_A_MEMBER = re.compile(
    r"(?P<lead>[:;]\s*)(?i:to|in|on)\s+(?i:the)\s+(?P<side>(?i:north|south|east|west))(?i:ern)?"
    r"(?:\s+(?i:side|end))?\s*,\s*(?P<rest>[^;.:]+?)(?=\s*(?:[;.]|$))"
)
# "a wheat field with a maize plot to its east and a potato plot to its west": each on
# that side of "it", the field they are with
_TO_ITS_SIDE = re.compile(
    r"\b(?i:to)\s+(?P<its>(?i:its|their))\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\b"
)
_IT_OF = {"its": "it", "their": "them"}
# "beyond them, to the south, two fields of potatoes": further on, on that side of them
_BEYOND_TO_A_SIDE = re.compile(
    r"\b(?i:beyond|past|behind|on\s+the\s+far\s+side\s+of|on\s+the\s+other\s+side\s+of)\s+"
    r"(?P<thing>(?i:it|them))\s*,?\s*(?i:to|towards|on)\s+(?i:the)\s+"
    r"(?P<side>(?i:north|south|east|west))(?i:ern)?(?:\s+(?i:side))?\b"
)
_FURTHER_PAST = re.compile(
    r"\b(?i:further|farther)\s+(?P<side>(?i:north|south|east|west))\s*,?\s+(?i:past|beyond)\s+"
    r"(?P<thing>(?i:the|our|my)\s+[A-Za-z][\w'-]*)"
)


# "carry on north past it and you hit our winter wheat": what a walk that way past a field
# reaches lies on that side of it
_WALKED_PAST = re.compile(
    r"\b(?i:carry on|keep going|keep on|go on|go|walk|continue|head|drive)\s+"
    r"(?P<side>(?i:north|south|east|west))(?i:wards)?\s+(?i:past|beyond)\s+"
    r"(?P<it>(?i:it|them|that one|that|the\s+[A-Za-z][\w'-]*))\s*,?\s+(?i:and)\s+"
    r"(?i:you|you'll|you will|we|you'd)\s+(?i:hit|reach|come to|get to|find|see|come across|"
    r"arrive at|run into|end up in|end up at)\s+"
    r"(?P<field>[A-Za-z][^.;:!?,]*?)(?=\s*(?:[.;:!?,]|$))"
)


# "the west half is split between a potato field to the north and an onion field to the
# south": each part in its corner of that half
_HALF_SPLIT = re.compile(
    r"\b(?i:the)\s+(?P<half>(?i:north|south|east|west))(?i:ern)?\s+(?i:half|side|end)"
    r"(?:\s+(?i:of the farm|of it))?\s+(?:(?i:is|was)\s+)?(?i:split|divided|shared|cut)\s+"
    r"(?i:between|into)\s+(?P<a>[A-Za-z][^.;:!?,]*?)\s+(?i:to the|on the|in the)\s+"
    r"(?P<sa>(?i:north|south|east|west))(?:\s+(?i:side|end))?\s*,?\s+(?i:and|&)\s+"
    r"(?P<b>[A-Za-z][^.;:!?,]*?)\s+(?i:to the|on the|in the)\s+"
    r"(?P<sb>(?i:north|south|east|west))(?:\s+(?i:side|end))?\b"
)
_NORTH_SOUTH = frozenset({"north", "south"})


def _half_split(match: re.Match[str]) -> str:
    half, a, b = (match.group(k).lower() for k in ("half", "sa", "sb"))
    if _OPPOSITE.get(a) != b or (half in _NORTH_SOUTH) == (a in _NORTH_SOUTH):
        return match.group(0)

    def corner(side: str) -> str:
        return f"{side} {half}" if side in _NORTH_SOUTH else f"{half} {side}"

    return f"{match.group('a')} in the {corner(a)} and {match.group('b')} in the {corner(b)}"


def place_split_halves(text: str) -> str:
    """``text`` with "the west half is split between a potato field to the north and an
    onion field to the south" written "a potato field in the north west and an onion field
    in the south west" (read before the sides of the farm are: the half is no field)."""
    return _HALF_SPLIT.sub(_half_split, text)


# "north: vines. south: fruit trees. in between: potatoes.": compass sides as labels
_COMPASS_LABEL = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<place>(?i:north|south|east|west|in between|between|in the middle|"
    r"middle|centre|center))\s*:\s*(?P<field>[A-Za-z][^.;:!?]*?)\s*(?P<end>[.;!?]|$)"
)
_LABEL_PLACES = {
    "in between": "in between",
    "between": "in between",
    "in the middle": "in the middle",
    "middle": "in the middle",
    "centre": "in the middle",
    "center": "in the middle",
}


def _compass_labels(text: str) -> str:
    """ "north: vines. south: fruit trees. in between: potatoes." written "vines in the
    north. fruit trees in the south. potatoes in between." (two or more compass labels)."""
    labels = [m.group("place").lower() for m in _COMPASS_LABEL.finditer(text)]
    if sum(1 for label in labels if label in _OPPOSITE) < 2:
        return text

    def placed(match: re.Match[str]) -> str:
        place = match.group("place").lower()
        where = _LABEL_PLACES.get(place, f"in the {place}")
        return f"{match.group('field')} {where}{match.group('end')}"

    return _COMPASS_LABEL.sub(placed, text)


# "Two wheat fields, one either side of the farmhouse, east and west": which side each is on
_EITHER_SIDE_NAMED = re.compile(
    r"\b(?P<one>(?i:one|1))\s+(?:(?i:on)\s+)?(?i:either|each)\s+(?i:side)\s+(?i:of)\s+"
    r"(?P<thing>(?i:the|our|my|a)\s+[A-Za-z][\w'-]*)\s*,?\s+(?:(?i:to the|on the)\s+)?"
    r"(?P<a>(?i:north|south|east|west))\s+(?i:and|&)\s+(?:(?i:the)\s+)?"
    r"(?P<b>(?i:north|south|east|west))\b(?:\s+(?i:sides?))?"
)


def _either_side_named(match: re.Match[str]) -> str:
    a, b = match.group("a").lower(), match.group("b").lower()
    if _OPPOSITE.get(a) != b:
        return match.group(0)
    return f"{match.group('one')} {a} of {match.group('thing')} and one {b} of it"


_FURTHER_OPENING_PAST = re.compile(
    r"(?:^|(?<=[.;:!?]\s))(?P<further>(?i:further|farther)\s+(?i:north|south|east|west)"
    r"(?:\s+(?i:again|still))?)\s*,\s+(?i:past|beyond|across)\s+(?i:the|our|my)\s+"
    r"[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*){0,2}\s*,"
)


def _beyond_as_faced(text: str) -> str:
    """``text`` with "beyond them" written "north of them" when the viewer says once
    which one way they face ("facing due north"); several ways, or none, leave it."""
    sides = {m.group("side").lower() for m in _FACING.finditer(text)}
    if len(sides) != 1:
        return text
    return _BEYOND.sub(f"{sides.pop()} of", text)


_SIDE_LABEL = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<side>(?i:left|right|middle|centre|center))\s*:\s*(?=[A-Za-z])"
)
_SIDE_LABELS = {
    "left": "On the left",
    "right": "On the right",
    "middle": "In the middle",
    "centre": "In the middle",
    "center": "In the middle",
}


# "Middle block: Kordia cherries ...": a plot labelled by its place in the middle
_MIDDLE_LABEL = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?i:middle|centre|center|central)\s+"
    r"(?i:block|plot|field|strip|bed|section)\s*:\s*(?=[A-Za-z])"
)


# "East of the barn: Savoy cabbage. West of the barn: January King.": a side of scenery
# said as a label before the field on it
_SIDE_OF_A_THING_LABEL = re.compile(
    r"(?:^|(?<=[.;!?]\s))(?P<side>(?i:north|south|east|west)) (?i:of) "
    r"(?P<thing>(?i:the|our|my) [A-Za-z][\w'-]*(?: [A-Za-z][\w'-]*)?)\s*[:,]\s*"
    r"(?P<field>[^.;:!?]+?)\s*(?P<end>[.;!?]|$)"
)
_SAID_AGAIN = re.compile(
    r"\b(?:(?i:directly|just|right|immediately)\s+)?(?i:below|above|beneath|under|over|left of|"
    r"right of|next to|beside)\s+(?i:it|them)\s*,?\s+(?i:so|i\.?e\.?|that is|meaning)\s+"
    r"(?P<again>(?i:north|south|east|west)\s+(?i:of)\b)"
)


# "cabbage up top (north) & lettuce under it": on a map of the farm (one with a top, a
# bottom or a compass side), what lies under a field lies below it on the map
_UNDER_IT = re.compile(
    r"\b(?i:under|beneath|underneath)\s+(?P<it>(?i:it|them|that|those)(?:\s+(?i:one|ones))?)\b"
)
_A_MAP = re.compile(
    r"\b(?i:top|bottom|north|south|northern|southern|above|upper|lower|uphill|downhill)\b"
)


def _placed_by_a_thing(match: re.Match[str]) -> str:
    """ "East of the barn: Savoy cabbage." written "Savoy cabbage east of the barn."."""
    return (
        f"{match.group('field')} {match.group('side').lower()} of {match.group('thing')}"
        f"{match.group('end')}"
    )


_SHARES_ITS_SIDE = re.compile(
    r"\b(?P<it>(?i:it|this one|that one))\s+(?i:shares|borders)\s+(?i:its)\s+"
    r"(?P<side>(?i:north|south|east|west)(?:(?i:ern))?)\s+"
    r"(?i:edge|side|border|boundary|fence|hedge)\s+(?i:with)\s+"
)


def place_sides(text: str) -> str:
    """``text`` with "X with A on one side and B on the other" written "X between A and
    B", "..., danvers one east" written "..., danvers one east of the other", "the
    cherries are east" written "the cherries are to the east", and "on the
    20 ha east field ..., on the 8 ha west field" written "in the east, 20 ha ..., in the
    west, 8 ha" (two or more sides, not all the same)."""
    # "directly below it, so south of the maize, a field of cabbages": the side said
    # again in compass words
    text = _SAID_AGAIN.sub(r"\g<again>", text)
    # "It shares its north edge with 1 ha of cherries": north of it is what it shares it with
    text = _SHARES_ITS_SIDE.sub(lambda m: f"{m.group('side')} of {m.group('it')}, ", text)
    if _A_MAP.search(text):
        text = _UNDER_IT.sub(r"below \g<it>", text)
    # (the same thing on two sides: "East of the barn: ... West of the barn: ...")
    things = [m.group("thing").lower() for m in _SIDE_OF_A_THING_LABEL.finditer(text)]
    text = _SIDE_OF_A_THING_LABEL.sub(
        lambda m: (
            _placed_by_a_thing(m) if things.count(m.group("thing").lower()) >= 2 else m.group(0)
        ),
        text,
    )
    text = _FURTHEST_THEN.sub(
        lambda m: (
            f"{m.group('lead')}going {_OPPOSITE[m.group('side').lower()]}, "
            f"{m.group('first')}, then "
        ),
        text,
    )
    text = _ONE_SIDE_AND_OTHER.sub(_between_sides, text)
    text = _FACING_NORTH.sub("", text)
    text = _beyond_as_faced(text)
    text = _PLACED_WITH_PLANTS.sub(r"\g<it>, ", text)
    text = _MIDDLE_LABEL.sub("In the middle, ", text)
    text = _TO_ITS_SIDE.sub(
        lambda m: f"{m.group('side').lower()} of {_IT_OF[m.group('its').lower()]}", text
    )
    if len({m.group("side").lower() for m in _SIDE_BEFORE_A_MEMBER.finditer(text)}) >= 2:
        text = _SIDE_BEFORE_A_MEMBER.sub(
            lambda m: f"{m.group('lead')}{m.group('rest')} to the {m.group('side').lower()}", text
        )
    text = _BEYOND_TO_A_SIDE.sub(lambda m: f"{m.group('side').lower()} of {m.group('thing')}", text)
    # "...; further north again, past the lane, there's wheat": further on than the field
    # before, the lane passed on the way
    text = _FURTHER_OPENING_PAST.sub(r"\g<further>,", text)
    text = _compass_labels(_EITHER_SIDE_NAMED.sub(_either_side_named, text))
    # "carry on north past it and you hit our winter wheat": the wheat north of it
    text = _WALKED_PAST.sub(
        lambda m: f"{m.group('field')} {m.group('side').lower()} of {m.group('it')}", text
    )
    # "Valencia oranges further south, past the house": on that side of what is passed
    text = _FURTHER_PAST.sub(lambda m: f"{m.group('side')} of {m.group('thing')}", text)
    # "Left: corn. Middle: spuds. Right: cabbages.": the parts of the view as labels
    # (with a left or right among them: "Top: ... Middle: ... Bottom: ..." are zones)
    if any(m.group("side").lower() in ("left", "right") for m in _SIDE_LABEL.finditer(text)):
        text = _SIDE_LABEL.sub(lambda m: f"{_SIDE_LABELS[m.group('side').lower()]}, ", text)
    text = _ONE_ON_A_SIDE.sub(lambda m: f"{m.group(0)} of the other", text)
    text = _named_again_on_a_side(text)
    # "durondeau pears and bing cherries, the cherries r east": a side said bare after "are"
    text = _ARE_A_SIDE.sub(
        lambda m: f"{m.group('verb') or m.group('s')} to the {m.group('side')}",
        text,
    )
    for side, other in (("left", "right"), ("right", "left")):
        # "left of the yard there's a vineyard, on the right a strawberry field": the
        # sides of the view, both said
        if re.search(rf"\b(?i:on|to) (?i:the) (?i:{other})\b", text):
            text = re.sub(
                rf"\b(?:(?i:to the|on the) )?(?i:{side}) (?i:of) (?i:the) (?i:yard|house|farmhouse|"
                r"barn|lane|track|road|gate|shed|farm shop)\b",
                f"on the {side}",
                text,
            )
    if len({m.group("side").lower() for m in _SIDE_FIELD.finditer(text)}) < 2:
        return text
    return _SIDE_FIELD.sub(
        lambda m: (
            f"in the {m.group('side').lower()}"
            + (f", {m.group('size').strip()}" if m.group("size") else "")
        ),
        text,
    )

"""Fields named by a compass position, before the prompt is read.

A compass position used as a label ("the east plot is Bintje, the west plot
Fontane") is moved after what it names ("Bintje in the eastern block"), where the
reader places fields by a trailing direction; so are sides said in brackets
("Granny (west) and Fuji (east)", "Upper block (north):"), a compass word alone after
what it places ("carrots north, potatoes south"), two members told apart by their
sides ("The north block has downy mildew, the south block is clean") and an order said
as a walk from one side of the farm to the other.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from agrirecipe.resolve._labels import NAMING
from agrirecipe.resolve._lexicon import Item, reader_words

__all__ = [
    "place_compass_members",
    "place_leading_directions",
    "place_trailing_directions",
    "place_walked_orders",
]


# "top half corn bottom half wheat": the next side's part, said after a field's words
_SIDE_PART = (
    r"\s+(?:(?i:the)\s+)?(?i:north|south|east|west|top|bottom|upper|lower)(?i:ern)?\s+"
    r"(?i:plot|block|field|one|part|half|strip|parcel|section|paddock|area)\b"
)
# "the east plot is Bintje with late blight, ...": a field named by its compass position
_LEADING = re.compile(
    r"(?<!in )(?<!on )(?<!of )(?<!at )(?<!to )"
    r"(?:\b(?i:the)\s+|(?:^|(?<=[,;.:]\s)))(?P<side>(?i:north|south|east|west|top|bottom|upper|lower))(?i:ern)?\s+"
    r"(?P<noun>(?i:plot|block|field|one|part|half|strip|parcel|section|paddock|area|terraces|terrace))\b\s*"
    r"(?:(?i:is|are|has|holds|gets|grows|has got)\s+|[:\-–—]\s*)?"
    # (the rest runs to a mark, past a decimal point or a thousands comma: "drilled in
    # 12.5 cm rows", "at 80,000 plants/ha"; or to the next side's plot: "the south block
    # is Grande Naine and the north block is Lady Finger")
    r"(?P<rest>(?!(?i:of|to|and|with|in|on|at|is|are)\b)[^\s,;.:()]"
    r"(?:(?!\s+(?i:and|but|while|whereas)\s+(?:(?i:the)\s+)?"
    r"(?i:north|south|east|west|top|bottom|upper|lower)(?i:ern)?\s)"
    # (nor past closing words: "the lower field is cabbage and thats it")
    r"(?!\s+(?i:and|but)\s+(?i:that'?s|that\s+is|nothing|no\s+other|no\s+more)\b)"
    # ("top half corn bottom half wheat": to the next side's part, said without a mark)
    rf"(?!{_SIDE_PART})"
    r"[^,;.:()]|[.,](?=\d))*)"
)
_NEXT_SIDE = re.compile(_SIDE_PART)


# "the western block at 2.75 m between rows", "the eastern one at 3 m": a member named by
# its side, then its measures (to a mark, past a decimal point)
# ("the left one about a hectare and the right one half a hectare": a size said plainly)
_SIDE_MEMBER = re.compile(
    r"\b(?i:the)\s+(?P<side>(?i:north|south|east|west|left|right))(?i:ern)?\s+"
    r"(?P<noun>(?i:block|plot|field|strip|one|half|part|section|parcel|bed))\s+"
    r"(?P<rest>(?:(?i:at|with|on|of)\s+\d"
    r"|(?:(?i:about|around|roughly|approximately|nearly|almost|some)\s+)?"
    r"(?:\d|(?:(?i:half|a\s+quarter|quarter)\s+(?:(?i:of)\s+)?)?"
    r"(?i:a|an|one|two|three|four)\s+(?i:hectares?|ha|acres?)\b))"
    r"(?:(?!\s+(?i:and|but)\s+(?i:the)\s)[^,;.:()]|[.,](?=\d))*)"
)
#: Left and right in a picture, as the compass sides zones read them.
_SIDE_WORDS = {"left": "west", "right": "east"}


# "Upper block (north): Riesling": a block named by where it is, then its compass side
_SIDE_IN_BRACKETS = re.compile(
    r"\b(?i:upper|lower|top|bottom|left|right|front|back|near|far)\s+"
    r"(?P<noun>(?i:plot|block|field|strip|parcel|section|paddock|area))\s*"
    r"\(\s*(?P<side>(?i:north|south|east|west))(?i:ern)?(?:\s+(?i:side|end|half))?\s*\)"
    r"(?=\s*[:\-–—])"
)


#: "Over the hedge to the south the cherry trees ...": scenery crossed, then the side of
#: it the field lies on, as in "south of the hedge the cherry trees ..."
_OVER_THEN_SIDE = re.compile(
    r"\b(?i:over|across|beyond|past)\s+(?P<the>(?i:the)\s+)(?P<landmark>[a-z][\w-]*"
    r"(?:\s+[a-z][\w-]*)?)\s*,?\s+(?i:to\s+the)\s+(?P<side>(?i:north|south|east|west))\b"
)


def place_leading_directions(text: str) -> str:
    """``text`` with "the east plot is X" written "X in the eastern block", "X in the
    north orchard" written "X in the north block" (where X is, not one more field), and
    "over the hedge to the south X" written "south of the hedge X"."""
    # (only with the landmark's other side said too: "..., and north of the hedge the
    # carrots"; "across the road to the south our Cabernet" alone places it against the
    # field before)
    text = _OVER_THEN_SIDE.sub(
        lambda m: (
            f"{m.group('side').lower()} of {m.group('the')}{m.group('landmark')}"
            if re.search(
                rf"\b(?:north|south|east|west)\s+of\s+the\s+{re.escape(m.group('landmark'))}\b",
                text,
                re.IGNORECASE,
            )
            else m.group(0)
        ),
        text,
    )
    text = _SIDE_IN_BRACKETS.sub(lambda m: f"{m.group('side').lower()} {m.group('noun')}", text)
    for _ in range(_MAX_UNMARKED_SIDES):
        # (again after each, for the next side's part said without a mark)
        placed = _LEADING.sub(_placed_on_its_side, text)
        if placed == text:
            break
        text = placed
    if len({m.group("side").lower() for m in _SIDE_MEMBER.finditer(text)}) >= 2:
        # "the western block at 2.75 m between rows, the eastern block at 3 m": members
        # told apart by their sides, each said after its measures
        text = _SIDE_MEMBER.sub(
            lambda m: (
                f"the {m.group('noun')} {m.group('rest').rstrip()} on the "
                f"{_SIDE_WORDS.get(m.group('side').lower(), m.group('side').lower())} side"
            ),
            text,
        )
    return _IN_SIDE_PLOT.sub(lambda m: f"{m.group('at')} the {m.group('side').lower()} block", text)


#: Verbs that open what is said of a member named by its side ("the west one looks fine").
_SAID_OF_IT = re.compile(r"(?i:looks?|seems?|appears?|shows?|has|have|had|got|was|were)\b")

#: How many sides' parts said one after another without a mark are read.
_MAX_UNMARKED_SIDES = 4


def _placed_on_its_side(match: re.Match[str]) -> str:
    """ "the east plot is X" as "X in the eastern block"; "the top field is X" as "X in the
    top field", a zone read with the farm's other zones ("...; below it maize; and at the
    bottom, carrots")."""
    side = match.group("side")
    rest = match.group("rest").rstrip()
    # ("top half corn bottom half wheat": the next side's part begins)
    mark = "," if _NEXT_SIDE.match(match.string, match.end()) else ""
    if _SAID_OF_IT.match(rest) and side.lower() in _OPPOSITE_SIDES:
        # ("The one on the east side has got blight, the west one looks fine": what is
        # said of the member on that side, not a field it names)
        return f"the {match.group('noun')} on the {side.lower()} side {rest}{mark}"
    if side.lower() in _OPPOSITE_SIDES:
        return f"{rest} in the {side.lower()}ern block{mark}"
    return f"{rest} in the {side} {match.group('noun')}{mark}"


# "Durondeau pears in the north orchard", "Cos on the north beds": where the pears are
_IN_SIDE_PLOT = re.compile(
    r"\b(?P<at>(?i:in|on))\s+(?i:the)\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    r"(?i:orchard|vineyard|paddock|grove|plantation|patch|strip|beds|rows|terraces|garden|allotment)\b"
    r"(?!\s+(?i:of|is|has|are|with)\b)"
)


# "The north block has downy mildew, the south block is clean": two members told apart
# by their side, described, not named
_COMPASS_MEMBER = re.compile(
    # "the north block has ...", "in the west plot the leaves are ..."
    r"\b(?P<at>(?i:in)\s+)?(?P<the>(?i:the))\s+(?P<side>(?i:north|south|east|west))(?i:ern)?\s+"
    r"(?i:block|plot|field|one|strip|vineyard|orchard|half|bed|paddock|grove|patch)\b"
    r"(?=(?(at)\s*|(?:\s+(?i:has|is|shows|looks|was|carries|got|has got|with)\b"
    # ("..., the eastern one with black rot, the western one clean": a look said bare)
    r"|\s+(?!(?i:of|to|and|in|on|at|is|are|north|south|east|west)\b)(?=[a-z])))"
    r"(?P<rest>[^,;.]*))"
)
_OPPOSITE_SIDES = {"north": "south", "south": "north", "east": "west", "west": "east"}


def place_compass_members(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "the north block has X, the south block is Y" written "one to the
    north has X, the other to the south is Y" when X and Y name no crop (two members of a
    counted plot, told apart by side; "the east plot is Bintje" is left to name a field)."""
    matches = list(_COMPASS_MEMBER.finditer(text))
    if len(matches) != 2:
        return text
    first, second = matches
    sides = first.group("side").lower(), second.group("side").lower()
    if _OPPOSITE_SIDES[sides[0]] != sides[1]:
        return text
    if any(_names_a_crop(m.group("rest"), tag) for m in matches):
        return text
    one = "One" if (first.group("at") or first.group("the"))[0].isupper() else "one"
    other = "The other" if (second.group("at") or second.group("the"))[0].isupper() else "the other"
    before = text[: first.start()]
    # ("Two cherry orchards, one east of the other; the eastern one is ...": the sides
    # said again by the members, which place them)
    said = _ONE_OF_THE_OTHER.search(before)
    if said is not None and said.group("side").lower() in sides:
        before = before[: said.start()] + before[said.end() :]
    return (
        before
        + f"{one} to the {sides[0]}"
        + text[first.end() : second.start()]
        + f"{other} to the {sides[1]}"
        + text[second.end() :]
    )


#: "one east of the other": two members placed against each other, before their sides.
_ONE_OF_THE_OTHER = re.compile(
    r"\s*,?\s*\b(?i:one)\s+(?:(?i:to the)\s+)?(?P<side>(?i:north|south|east|west))\s+(?i:of)\s+"
    r"(?i:the)\s+(?i:other)\b"
)


def _names_a_crop(phrase: str, tag: Callable[[str], Sequence[Item]]) -> bool:
    """Whether ``phrase`` names a crop, a variety or a category (not "yellow-orange
    stripes of rust": a crop word joined by a hyphen to a colour is a colour)."""
    items = list(tag(phrase))
    colours = reader_words("colours")

    def a_colour(index: int) -> bool:
        item = items[index]
        return item.norm in colours and any(
            0 <= other < len(items)
            and items[other].norm in colours
            and phrase[
                min(items[index].end, items[other].end) : max(
                    items[index].start, items[other].start
                )
            ]
            == "-"
            for other in (index - 1, index + 1)
        )

    return any(item.has(*NAMING) and not a_colour(k) for k, item in enumerate(items))


# "the top field", "the bottom plot": north and south, as zones read them
_SIDES = {
    "north": "north",
    "south": "south",
    "east": "east",
    "west": "west",
    "top": "north",
    "upper": "north",
    "bottom": "south",
    "lower": "south",
}


# "carrots north, potatoes south": a compass word alone after what it places ("carrots
# (danvers) south": after its variety in brackets)
_TRAILING = re.compile(
    r"\b(?P<word>[A-Za-z][\w'-]*)\)?\s+(?P<side>(?i:north|south|east|west))\b(?=\s*(?:[,.;]|$))"
)
#: Words after which a compass word is a direction, not a place ("rows running north").
_NOT_PLACED = frozenset(
    {
        "run",
        "runs",
        "running",
        "facing",
        "face",
        "faces",
        "going",
        "heading",
        "looking",
        "look",
        "due",
        "to",
        "the",
        "of",
        "from",
        "towards",
        "toward",
        "pointing",
        "lying",
        "aligned",
        "oriented",
        "orientated",
        "far",
        "up",
        "down",
        "back",
        "out",
        "and",
    }
)


# "two apple blocks: Granny (west) and Fuji (east)": a side in brackets after a field
_BRACKETED_SIDE = re.compile(
    r"\(\s*(?P<side>(?i:north|south|east|west))(?i:ern)?(?:\s+(?i:side|end|half))?\s*\)"
)


def place_trailing_directions(text: str) -> str:
    """``text`` with "carrots north, potatoes south" written "carrots in the north,
    potatoes in the south" (two or more such places, not all the same), and likewise
    "Granny (west) and Fuji (east)"."""
    sides = {m.group("side").lower() for m in _BRACKETED_SIDE.finditer(text)}
    if len(sides) >= 2:
        # ("Zone 1 (north end): Bing cherries": a zone before its field, as "At the top:")
        text = _BRACKETED_SIDE.sub(
            lambda m: (
                f"at the {m.group('side').lower()} end"
                if text[m.end() :].lstrip().startswith(":")
                else f"in the {m.group('side').lower()}"
            ),
            text,
        )
    matches = [m for m in _TRAILING.finditer(text) if m.group("word").lower() not in _NOT_PLACED]
    if (
        len(matches) == 1
        and text[: matches[0].start()].rstrip().endswith(",")
        and _SIGN_OFF.fullmatch(text[matches[0].end() :])
    ):
        # "hamlin & valencia oranges, ripe, jan, valencia east": one field named again
        # last, with its side
        start, end = matches[0].span("side")
        return f"{text[:start]}to the {matches[0].group('side')}{text[end:]}"
    if len(matches) < 2 or len({m.group("side").lower() for m in matches}) < 2:
        return text
    for match in reversed(matches):
        start, end = match.span("side")
        text = f"{text[:start]}in the {match.group('side')}{text[end:]}"
    return text


#: What may close a prompt after the last field's side ("... pears south. thx a lot").
_SIGN_OFF = re.compile(
    r"[\s.!]*(?:(?i:thanks|thx|thank you|ty|cheers|ta|pls|please)\s*)?"
    r"(?:(?i:a lot|so much|very much|heaps|mate|in advance))?[\s.!]*"
)


#: The side words a walk across the farm starts and ends at, with the side opposite.
_WALK_SIDES = {
    "bottom": "top",
    "top": "bottom",
    "north": "south",
    "south": "north",
    "east": "west",
    "west": "east",
    "left": "right",
    "right": "left",
}
_SIDE = "|".join(_WALK_SIDES)
# "Starting at the bottom of the farm by the road and working up to the top: onions,
# then carrots, then potatoes", "from the bottom of the farm up to the top: ...": an
# order said as a walk from one side to the opposite one
_WALKED = re.compile(
    rf"\b(?:(?i:starting|beginning|start|begin)\s+(?i:at|from)|(?i:from))\s+(?i:the)\s+"
    rf"(?P<start>(?i:{_SIDE}))(?:\s+(?i:end|side|edge|boundary|fence|hedge|border))?\b"
    r"(?P<between>[^:;.,!?]{0,60}?)"
    r"\s+(?:(?i:and)\s+)?(?:(?i:working|going|moving|heading|walking|coming|running)\s+)?"
    r"(?:(?i:up|down|across|over|along|back)\s+)?(?i:to|towards|toward)\s+(?i:the)\s+"
    rf"(?P<end>(?i:{_SIDE}))(?:\s+(?i:end|side|edge|boundary|fence|hedge|border))?\b"
)


def place_walked_orders(text: str) -> str:
    """``text`` with "starting at the bottom ... and working up to the top" written
    "from bottom to top" (an order of the fields named after it), when the walk ends at
    the side opposite where it starts."""

    def order(match: re.Match[str]) -> str:
        start, end = match.group("start").lower(), match.group("end").lower()
        if _WALK_SIDES[start] != end:
            return match.group(0)
        return f"from {start} to {end}"

    text = _WALKED.sub(order, text)
    # "Top to bottom on our hillside farm in Madeira: ...": the place said first, so the
    # order stands right before the list it orders
    text = _ORDER_THEN_PLACE.sub(
        lambda m: (
            f"{m.group('place')}, {m.group('order').lower()}:"
            if _WALK_SIDES[m.group("a").lower()] == m.group("b").lower()
            else m.group(0)
        ),
        text,
    )
    return _EACH_FURTHER.sub(
        lambda m: f", laid out {_WALK_SIDES[m.group('side').lower()]} to {m.group('side').lower()}",
        text,
    )


_ORDER_THEN_PLACE = re.compile(
    rf"(?:^|(?<=[.;!?]\s))(?P<order>(?:(?i:from)\s+)?(?P<a>(?i:{_SIDE}))\s+(?i:to)\s+"
    rf"(?P<b>(?i:{_SIDE})))\s+(?P<place>(?i:on|at|in|across)\s+[^:;.,]{{1,60}}?)\s*:"
)


# "first the Hamlin grove, then the Navel, then the Moro, each one further north": the
# fields in the order named, from the opposite side to that one
_EACH_FURTHER = re.compile(
    r",?\s*\b(?i:each|every)\s+(?:(?i:one|block|field|plot|strip|orchard|grove)\s+)?"
    r"(?i:further|farther|a bit further|a little further)\s+(?P<side>(?i:north|south|east|west))\b"
    r"(?:\s+(?i:than the last|again))?"
)

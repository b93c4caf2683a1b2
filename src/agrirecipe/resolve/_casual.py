"""Casual text: texting forms read as the words they stand for ("nxt 2" -> "next to").

The forms are data (``data/casual.yaml``). :func:`expand_casual` rewrites them
once, in one pass of one regular expression (linear in the prompt's length),
before the prompt is split into words, so "b4" never becomes a count of 4
fields. The original prompt is kept for the recipe; the rewritten text is what
is read. :func:`count_said_after_crop` moves a count of fields said after their crop
("mostly potatoes - four fields of them -") before it.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Sequence
from typing import Any

from agrirecipe.resolve._geometry import number_words
from agrirecipe.resolve._key_values import read_key_values
from agrirecipe.resolve._lexicon import Item, everyday_words, load_data, plot_nouns_pattern
from agrirecipe.resolve._pictures import read_pictures
from agrirecipe.resolve._shares import read_shares
from agrirecipe.resolve._shorthand import expand_shorthand

__all__ = ["count_said_after_crop", "end_reciprocals", "expand_casual"]


@functools.cache
def _forms() -> tuple[re.Pattern[str], dict[str, str]]:
    data: dict[str, Any] = load_data("casual.yaml")
    forms = {str(k).lower(): str(v) for k, v in data["forms"].items()}
    ordered = sorted(forms, key=len, reverse=True)  # "nxt 2" before "nxt"
    alternation = "|".join(re.escape(form).replace(r"\ ", r"\s+") for form in ordered)
    pattern = re.compile(rf"(?<![A-Za-z0-9])(?:{alternation})(?![A-Za-z0-9])", re.IGNORECASE)
    return pattern, forms


@functools.cache
def _lower_forms() -> tuple[re.Pattern[str], dict[str, str]]:
    data: dict[str, Any] = load_data("casual.yaml")
    forms = {str(k): str(v) for k, v in data.get("lower_forms", {}).items()}
    alternation = "|".join(re.escape(form) for form in sorted(forms, key=len, reverse=True))
    return re.compile(rf"(?<=\s)(?:{alternation})(?=\s)"), forms


#: "with a few chillies mixed in", "with the odd lettuce dotted among them".
_MIXED_IN = re.compile(
    r"\s+(?i:with)\s+(?i:a\s+few|some|a\s+couple\s+of|the\s+odd|a\s+handful\s+of)\s+"
    r"[A-Za-z-]+(?:\s+[A-Za-z-]+)?\s+(?i:mixed|dotted|scattered)\s+(?i:in|among\s+them|through)\b"
)
#: ", all in one block", "all in a single field": the one plot a crop is grown in.
_ALL_IN_ONE = re.compile(r"\s*,?\s+(?i:all)\s+(?i:in)\s+(?=(?i:one|a\s+single)\s)")
#: "smthn w/ cereals & smthn w/ fruit": a field said as "something with" its crop, at the
#: start of a clause (not "something with the light", later in one)
_SOMETHING_WITH = re.compile(
    r"(?P<lead>^|[,;:.!?&(]|\b(?i:and|plus|then|also)\b)\s*(?i:something|anything)\s+"
    r"(?i:with|of)\s+(?!(?i:the|a|an|it|them|this|that)\b)"
)
#: "minus 2", "negative 3": a sign said as a word before a number.
_MINUS = re.compile(r"\b(?i:minus|negative)\s+(?=\d)")
#: "Where the orchard ends the maize begins": the second field begins at the first.
_WHERE_ENDS = re.compile(
    r"\b(?i:where)\s+(?P<a>(?i:the|our|my)\s+[^,.;:!?]+?)\s+(?i:ends|stops|finishes)\s*,?\s+"
    r"(?P<b>(?i:the|our|my)\s+[^,.;:!?]+?)\s+(?i:begins|starts)\b"
)
#: "Riesling uphill (north) of the Spätburgunder": the side in brackets is the relation.
_SLOPE_SIDE = re.compile(
    r"\b(?i:uphill|downhill|upslope|downslope|above|below|higher up|lower down)\s*"
    r"\(\s*(?P<side>(?i:north|south|east|west|north-?east|north-?west|south-?east|south-?west))"
    r"\s*\)\s*(?=(?i:of)\b)"
)
#: An arrow written between two words ("west→east", "wheat -> maize").
_ARROW = re.compile(r"\s*(?:-+>|→|⟶|⇒)\s*")


def expand_casual(prompt: str) -> str:
    """``prompt`` with every texting form replaced by its words."""
    pattern, forms = _forms()

    def replace(match: re.Match[str]) -> str:
        key = re.sub(r"\s+", " ", match.group(0).lower())
        return f" {forms[key]} " if forms[key] else " "

    lower, lower_forms = _lower_forms()
    # "crop=lettuce var=Iceberg rows=30 row_spacing=0.35m | ...": settings as words
    text = read_key_values(read_pictures(prompt))
    # "apples w of the pears", "onions just S of it": a compass letter before "of"
    text = _LETTER_SIDE.sub(lambda m: f"{_LETTER_SIDES[m.group('side').lower()]} of", text)
    # "iceburg lettuce on the W side & savoy cabage on the E side": a compass letter as
    # the side of a place
    text = _LETTER_PLACE.sub(lambda m: _LETTER_SIDES[m.group("side").lower()], text)
    # "a couple diff veg plots": a couple of them
    text = _a_couple().sub("a couple of", text)
    # "cab south of the pinot": the wine trade's short name (not a tractor's cab)
    text = _CAB.sub("cabernet", text)
    # "Where the orchard ends the maize begins": the maize next to the orchard
    text = _WHERE_ENDS.sub(lambda m: f"{m.group('b')} next to {m.group('a')}", text)
    # "Riesling uphill (north) of the Spätburgunder": north of it
    text = _SLOPE_SIDE.sub(lambda m: f"{m.group('side')} ", text)
    # "rows 6 m and 3 m apart respectively", "all along the west side", ...
    text = expand_shorthand(text)
    # "3 plots side by side west→east": an arrow between two places is "to"
    text = _ARROW.sub(" to ", text)
    # "bell types with a few chillies mixed in": a few plants among the field's own crop,
    # no field of their own
    text = _MIXED_IN.sub("", text)
    # "A 100-acre farm: half in wheat", "All healthy apart from the onions", "one big
    # orchard but 3 blocks": parts of a whole, said plainly
    text = read_shares(text)
    # "just cereals this year, all in one big 60 ha block": the plot the crop is in
    text = _ALL_IN_ONE.sub(" in ", text)
    # "rows at minus 2 metres spacing": a negative number said in words (refused later)
    text = _MINUS.sub("-", text)
    text = pattern.sub(replace, text)
    text = lower.sub(lambda match: lower_forms[match.group(0)], text)
    text = _SOMETHING_WITH.sub(r"\g<lead> some ", text)
    # "sweet corn next to cherry tomatoes, ripe, aug, both": what was said before a
    # closing "both" is said of both ("..., both ripe, aug")
    text = _BOTH_AFTER.sub(lambda m: f", both {m.group('said').strip().rstrip(',')}", text)
    # "strawbery beds pls, 6 of them": a "please" before a mark says nothing ("beds, 6 of
    # them" counts the beds)
    text = _PLEASE_BEFORE_MARK.sub("", text)
    # "corn and wheat and potatoes so 3 fields": the count of the list, after "so"
    text = _SO_COUNT.sub(", so ", text)
    # "in two open-field plots": how the plots are grown, not a field of its own
    text = _OPEN_FIELD_PLOTS.sub("outdoor ", text)
    # "forty acres of wheat": a measure in words of tens, written in digits (not "the
    # back forty", a field's name)
    text = _TENS_BEFORE_A_UNIT.sub(_tens_in_digits, text)
    # "small fruit fields, five or six of them": a count of them in words (the first of
    # two said as alternatives), written in digits
    text = _count_of_them_in_words().sub(_count_of_them_in_digits, text)
    # "Rows of Boston lettuce a foot apart": one unit, written as a number
    text = _A_UNIT_APART.sub(r"1 \g<unit>", text)
    # "near the city of Valencia in Spain": a place's name, not a variety
    text = _NAMED_PLACE.sub(r"\g<lead>", text)
    # "top: kordia cherries / middle: bintje / bottom: winter wheat": a slash between
    # labelled members is a comma
    text = _SLASH_BEFORE_LABEL.sub(", ", text)
    # "2 carrot fields, one nantes one chantenay": a list of members without commas
    text = _ONE_AFTER_ONE.sub(r"\g<first>, \g<second>", text)
    # "2 pepper fields, 1 jalapeno, 1 padron": a member counted "1" is "one" of the list
    text = _ONE_IN_A_LIST.sub("one", text)
    # "1) Roma tomatoes 2) San Marzano tomatoes": a numbered list's marks are its commas
    # (the first item after a colon or at the start needs no comma: "plots are: 1) ...")
    text = _NUMBERED_ITEM.sub(
        lambda m: (
            " "
            if not text[: m.start()].rstrip() or text[: m.start()].rstrip()[-1] in ":;,"
            else ", "
        ),
        text,
    )
    # "the greenhouse-to-field transfer test", "a sim-to-real benchmark": a purpose's
    # compound, not a field ("row-to-row", "north-to-south" keep their meaning)
    text = _COMPOUND.sub(lambda m: m.group(0) if _kept_compound(m) else " ", text)
    # "Jonagored on M9", "Gala on MM106", "cherries on Gisela 5": a rootstock, not a count
    text = _ROOTSTOCK.sub(" rootstock ", text)
    # "apples north pears south": a compass word ends one placement, the next crop begins
    text = _PLACED_AFTER_PLACED.sub(r"\g<first>, ", text)
    # "riesling on the left chardonnay on the right": likewise a side said with "the"
    text = _SIDE_AFTER_SIDE.sub(r"\g<first>, ", text)
    # "valencia one bigger (4ha) moro one 2ha": a size in brackets ends its member
    text = _SIZE_IN_BRACKETS.sub(r"\g<size>, ", text)
    # "one w rows n-s": "w" for "with" before what a plot has (not the "w" of "e-w")
    text = _W_FOR_WITH.sub("with", text)
    # "rows EW", "beds running NS": two compass letters written together
    text = _GLUED_SIDES.sub(lambda m: f"{m.group('a')}-{m.group('b')}", text)
    # "spec: crop = onion; beds = 10; rows: 24": a count or a crop written as a setting
    text = _SETTING_COUNT.sub(r"\g<n> \g<key>", text)
    text = _SETTING_CROP.sub("", text)
    # "[plot1] crop=potato, ...; [plot2] ..., placed east of plot1": a spec's plot labels
    text = _BRACKETED_LABEL.sub(r"\g<noun> \g<label>:", text)
    text = _JOINED_LABEL.sub(r"\g<noun> \g<label>", text)
    # "fruit & veg fields, like 4 or 5 of em": the fields' count said after them
    # ("some fruit & veg fields, like 3 or 4, dont mind which": said roughly, alone)
    for pattern in (_COUNT_OF_THEM, _COUNT_SAID_ROUGHLY):
        text = pattern.sub(
            lambda m: f"{m.group('lead')}{m.group('count')} {m.group('words')}{m.group('plots')}",
            text,
        )
    # "some veg plots?? like 4 or 5, need it b4 monday", "a few fruit fields idk 2 or 3":
    # a rough count after the plots, said as a count of them
    text = _ROUGH_COUNT_AFTER.sub(r"\g<plots>, \g<count> of them", text)
    # "some fields of fruit trees w/ fire blight, like 2 or 3": a rough count closing the
    # sentence of one plural plot word counts those plots
    text = _ROUGH_COUNT_LATER.sub(r"\g<count> \g<plots>\g<rest>", text)
    # "on the 2nd of May": a day of the month, not two fields
    text = _DAY_OF_MONTH.sub(r"\g<day> ", text)
    # "An acre and a half of chillies": one and a half acres
    text = _UNIT_AND_A_HALF.sub(lambda m: f"1.5 {m.group('unit')}s", text)
    # "Corn plot pair", "a lettuce strip trio": a count said after the plot noun
    text = _PLOT_COUNT_AFTER.sub(_count_before_plots, text)
    # "strawbery beds x6": a count written as a multiplier after the plural noun
    text = _TIMES_AFTER_PLURAL.sub(r"\g<count> \g<noun>", text)
    # "the Bing cherries ... are ripe for picking, and so are the strawberries ...": what
    # is said of the first is said of the second
    text = _SO_ARE.sub(
        lambda m: (
            f"{m.group('said')}{m.group('joint')}{m.group('subject')} "
            f"{m.group('copula')} {m.group('look')}"
        ),
        text,
    )
    # "1 of them 5 ha the other 3 ha": a measure ends one member, "the other" begins the next
    return _OTHER_AFTER_MEASURE.sub(r"\g<unit>, ", text)


_SO_ARE = re.compile(
    # ("Both of our potato fields have late blight, and so does the tomato field")
    r"(?P<said>\b(?P<copula>(?i:is|are|was|were|looks?|looking|has|have|had|shows?))\s+"
    r"(?P<look>[^,;.:!?]{2,60}?)"
    r"(?P<joint>\s*,?\s+(?i:and|&)\s+))(?i:so)\s+(?i:is|are|was|were|do|does)\s+"
    r"(?P<subject>(?i:the|our|my|those|these)\s+[^,;.:!?]{2,80}?)(?=\s*(?:[,;.:!?]|$))"
)


_COUNT_SAID_ROUGHLY = re.compile(
    r"(?P<lead>(?:^|(?<=[.;:!?])\s*)(?:(?i:the|our|my|some)\s+)?)"
    r"(?P<words>(?:[A-Za-z][\w'&-]*\s+){0,4}?)"
    r"(?P<plots>(?i:fields|plots|blocks|strips|beds|orchards|patches|paddocks))\s*,\s*"
    r"(?i:like|about|around|maybe|roughly|approx|say)\s+"
    r"(?P<count>\d+(?:\s+(?i:or|to|-)\s+\d+)?)(?=\s*(?:[,.!?;]|$))"
)
_DAY_OF_MONTH = re.compile(
    r"\b(?P<day>[0-3]?\d)(?i:st|nd|rd|th)\s+(?i:of)\s+"
    r"(?=(?i:jan|feb|mar|apr|may|jun|jul|aug|sep|sept|oct|nov|dec)[a-z]*\b)"
)
_ROUGH_COUNT_AFTER = re.compile(
    r"(?P<plots>\b(?i:fields|plots|blocks|strips|orchards|patches|paddocks))"
    r"(?:\s*[,?!]+\s*|\s+)(?:(?i:like|about|around|maybe|roughly|approx|say)\s+)?"
    r"(?P<count>\d+)\s+(?i:or|to|-)\s+\d+(?![\d.,]\d)(?=\s*(?:[,.!?;]|$))"
)
_ROUGH_COUNT_LATER = re.compile(
    r"(?:(?<=^)|(?<=[.;!?]\s))(?:(?i:some|a\s+few|several|a\s+couple\s+of)\s+)?"
    r"(?P<plots>(?i:fields|plots|blocks|strips|orchards|patches|paddocks))"
    r"(?P<rest>(?:\s+(?!(?i:fields|plots|blocks|strips|orchards|patches|paddocks)\b)"
    r"[A-Za-z/'-]+){1,8}?)\s*,\s*(?i:like|about|around|maybe|roughly|approx|say)\s+"
    r"(?P<count>\d+)\s+(?i:or|to|-)\s+\d+(?![\d.,]\d)\s*(?=[.!?;]|$)"
)
_COUNT_OF_THEM = re.compile(
    r"(?P<lead>(?:^|(?<=[.;:!?])\s*)(?:(?i:the|our|my|some)\s+)?)"
    r"(?P<words>(?:[A-Za-z][\w'&-]*\s+){0,4}?)"
    r"(?P<plots>(?i:fields|plots|blocks|strips|beds|orchards|patches|paddocks))\s*,\s*"
    r"(?:(?i:like|about|around|maybe|roughly|approximately|approx|say)\s+)?"
    # (ending the sentence: "the plots, 3 of them, wheat, maize and potatoes" is a list)
    r"(?P<count>\d+(?:\s+(?i:or|to|-)\s+\d+)?)\s+(?i:of)\s+(?i:them|em|'em)\b\s*"
    r"(?=[.!?;]|$)"
)
_OPEN_FIELD_PLOTS = re.compile(
    r"\b(?i:open)[\s-]+(?i:field)\s+(?=(?i:plots?|blocks?|strips?|beds?|trials?)\b)"
)


@functools.cache
def _count_of_them_in_words() -> re.Pattern[str]:
    """ ", five or six of them": a count from two to twelve in words (geometry.yaml's
    number words), the first of two said as alternatives."""
    words = "|".join(
        re.escape(word)
        for word, value in number_words().items()
        if " " not in word and 2 <= value <= 12
    )
    return re.compile(
        rf"(?<=, )(?P<a>(?i:{words}))(?:\s+(?i:or|to)\s+(?i:{words}))?"
        r"(?=\s+(?i:of)\s+(?i:them)\b)"
    )


def _count_of_them_in_digits(match: re.Match[str]) -> str:
    return str(int(number_words()[match.group("a").lower()]))


_TENS_BEFORE_A_UNIT = re.compile(
    r"\b(?P<tens>(?i:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety))"
    r"(?:[\s-]+(?P<units>(?i:one|two|three|four|five|six|seven|eight|nine)))?\s+"
    r"(?=(?i:acres?|hectares?|ha|metres?|meters?|m|feet|foot|ft|yards?|yds?|cm|inches|in|rows?|"
    r"trees|vines|plants|beds|ridges)\b)"
)


def _tens_in_digits(match: re.Match[str]) -> str:
    """ "forty" -> "40 ", "thirty-five" -> "35 " (the words' values from geometry.yaml)."""
    words = number_words()
    units = match.group("units")
    value = words[match.group("tens").lower()] + (words[units.lower()] if units else 0)
    return f"{value:g} "


_PLEASE_BEFORE_MARK = re.compile(r"\s+(?i:please|pls|plz|plss|thx|thanks)(?=\s*[,;:])")
_SO_COUNT = re.compile(
    r"(?<![,;:.])\s+(?i:so)\s+(?=(?:\d+|(?i:two|three|four|five|six|seven|eight|nine|ten))\s+"
    r"(?i:fields|plots|blocks|strips|crops|paddocks)\b)"
)
_A_UNIT_APART = re.compile(
    r"\b(?i:a|an|one)\s+(?P<unit>(?i:foot|metre|meter|yard|inch))\b"
    r"(?=\s+(?i:apart|between|wide|spacing|centres|centers|in the row|along the row)\b)"
)
_NAMED_PLACE = re.compile(
    r"(?P<lead>\b(?i:city|town|village|region|province|port|valley) of)\s+[A-Z][\w'-]*"
    r"(?:\s+[A-Z][\w'-]*)?"
)
_SLASH_BEFORE_LABEL = re.compile(r"\s+[/|]\s+(?=[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*){0,2}\s*:)")
_UNIT_AND_A_HALF = re.compile(r"\b(?i:an?|one)\s+(?P<unit>(?i:acre|hectare))\s+(?i:and a half)\b")
_GLUED_SIDES = re.compile(
    r"(?:(?<=\brows )|(?<=\bbeds )|(?<=\bridges )|(?<=\brunning )|(?<=\boriented ))"
    r"(?P<a>[EWNS])(?P<b>(?<=E)W|(?<=W)E|(?<=N)S|(?<=S)N)\b",
    re.IGNORECASE,
)
_W_FOR_WITH = re.compile(r"(?<=[A-Za-z] )(?i:w)(?= (?:rows?|beds?|ridges?|a|an|the|some|\d)\b)")
_SETTING_COUNT = re.compile(
    r"\b(?P<key>(?i:beds|rows|ridges|trees|plants|vines|plots|blocks|strips|fields))\s*[=:]\s*"
    # (the number is the whole setting: not "Two potato fields: 3 ha of Fontane")
    r"(?P<n>\d+)(?=\s*(?:[;,)]|\.(?!\d)|$))"
)
_SETTING_CROP = re.compile(
    # ("=" only: "three cultivars: Red Express, ..." is a list's heading)
    r"\b(?i:crop|crops|variety|varieties|cultivar|cultivars|cv|species)\s*=\s*(?=[A-Za-z])"
)
_BRACKETED_LABEL = re.compile(
    r"\[\s*(?P<noun>(?i:plot|block|field|strip|bed|area|zone))[\s_-]*(?P<label>\d{1,2}|[A-H])\s*\]"
    r"\s*:?"
)
_JOINED_LABEL = re.compile(r"\b(?P<noun>(?i:plot|block|field|strip|bed))[_-]?(?P<label>\d{1,2})\b")
_PLOT_COUNT_AFTER = re.compile(
    r"(?P<lead>\b(?i:a|an|the|our|my|this|that|for|of|with|and|need|want)\s+|^|(?<=[,.;:!?(])\s*)"
    r"(?P<words>(?:[A-Za-z][\w'-]*\s+){0,3}?)"
    r"(?P<noun>(?i:plot|block|field|strip|bed|orchard|vineyard|grove|tunnel|greenhouse|paddock))s?"
    r"\s+(?P<count>(?i:pair|duo|trio|quartet))\b(?!\s+of\b)"
)
_ONE_IN_A_LIST = re.compile(
    r"(?<=[,;:] )1(?= [A-Za-z])"
    r"(?! (?i:m|ha|acres?|ac|cm|mm|ft|in|x|by|rows?|beds?|ridges?|of|more|or|to|and|either|"
    r"each|on|per|side)\b)"
)
_TIMES_AFTER_PLURAL = re.compile(
    r"\b(?P<noun>(?i:beds|rows|ridges|plots|blocks|fields|strips))\s*[x×]\s*(?P<count>\d+)\b"
    # (ending its phrase: not "rows x 30 m", "5 rows x 30 trees")
    r"(?![.,]\d)(?=\s*(?:[,;:!?)]|\.(?!\d)|$))"
)
_COUNT_WORDS = {"pair": "two", "duo": "two", "trio": "three", "quartet": "four"}


def _count_before_plots(match: re.Match[str]) -> str:
    lead = match.group("lead")
    if lead.strip().lower() in {"a", "an", "the"}:
        lead = ""
    count = _COUNT_WORDS[match.group("count").lower()]
    return f"{lead}{count} {match.group('words')}{match.group('noun')}s"


_COMPOUND = re.compile(r"\b(?P<a>[A-Za-z]+)-to-(?P<b>[A-Za-z]+)\b")
_SIDES = frozenset(
    {"north", "south", "east", "west", "top", "bottom", "left", "right", "front", "back"}
)


def _kept_compound(match: re.Match[str]) -> bool:
    """A compound of one word twice ("row-to-row") or of sides ("north-to-south")."""
    a, b = match.group("a").lower(), match.group("b").lower()
    return a == b or a in _SIDES or b in _SIDES


# Apple, pear and cherry rootstocks by their series letters and number (M9, MM106, G.41,
# B9, Gisela 5): a letter (or two) joined to the number, or "Gisela" before one.
# (in capitals only, and never M2 or M3: "200 plants per m2" is a unit)
_ROOTSTOCK = re.compile(
    r"(?<![\w.])(?:(?:MM|M|G|B)\.?(?![23]\b)\d{1,3}|(?i:gisela)\s*\d{1,2})(?![\w.²³])"
)
_LETTER_SIDES = {"n": "north", "s": "south", "e": "east", "w": "west"}
# ("2 veggie plots, 1 N of the other": "1" for "one")
_LETTER_SIDE = re.compile(r"(?:(?<=[A-Za-z] )|(?<=\b1 ))(?P<side>[NSEWnsew]) of\b")
_LETTER_PLACE = re.compile(
    r"(?<=\b[Tt]he )(?P<side>[NSEWnsew])(?= (?i:side|end|half|edge|corner|part)s?\b)"
)


@functools.cache
def _a_couple() -> re.Pattern[str]:
    """ "a couple" said without "of" before plots ("a couple diff veg plots"), up to two
    words before the plot noun."""
    nouns = plot_nouns_pattern()
    return re.compile(rf"\b(?i:a couple)(?= (?!of\b)(?:[A-Za-z-]+ ){{0,2}}(?i:{nouns})s?\b)")


_CAB = re.compile(
    r"(?<!tractor )(?<!truck )(?<!lorry )(?<!combine )(?<!sprayer )(?<!digger )(?<!the )"
    r"(?<!my )(?<!its )(?<!a )\b(?i:cab)\b(?! (?i:sav|sauv|franc)\b)"
)
_BOTH_AFTER = re.compile(
    r",(?P<said>(?:\s*[^,;.:!?()]+,){1,3})\s*(?i:both)(?:\s+(?i:of)\s+(?i:them))?\s*(?=[.;!?]|$)"
)
_NUMBERED_ITEM = re.compile(r"(?<![\w.,(])\d{1,2}\)\s+(?=[A-Za-z])")
_COMPASS = r"(?i:north|south|east|west)"
_PLACED_AFTER_PLACED = re.compile(
    rf"(?P<first>\b[A-Za-z]+\s+{_COMPASS})\s+"
    # ("west to east", "north and south", "north or south of it" are one phrase)
    rf"(?=(?!(?i:to|and|or|of|then|through|via|into|towards?)\b)[A-Za-z]+\s+{_COMPASS}\b(?!-))"
)


_SIDE_WORDS = r"(?i:left|right|top|bottom|north|south|east|west)"
_SIDE_AFTER_SIDE = re.compile(
    rf"(?P<first>\b(?i:on|at|in|to) (?i:the) {_SIDE_WORDS})\s+"
    # (not "on the left of the barn", "at the top end", "on the left hand side")
    r"(?=(?!(?i:of|and|or|then|side|end|half|third|hand|corner|edge|part|field|block|plot|"
    r"rows?|beds?|there|is|are|was|with|by|near|next|beside|behind|one|ones)\b)[A-Za-z]+\s+"
    rf"(?:[A-Za-z]+\s+)?(?i:on|at|in|to) (?i:the) {_SIDE_WORDS}\b)"
)
_SIZE_IN_BRACKETS = re.compile(
    r"(?P<size>\(\s*\d[\d.,]*\s*(?i:ha|hectares?|acres?|ac|m2|m²)\s*\))\s+(?=[A-Za-z])"
    r"(?!(?i:and|or|each|both|of|with|next|north|south|east|west|beside)\b)"
)
_OTHER_AFTER_MEASURE = re.compile(
    r"\b(?P<unit>ha|hectares?|acres?|m|metres|meters|rows)\s+(?=(?i:the others?)\b)"
)

_ONE_AFTER_ONE = re.compile(
    r"(?P<first>\b(?i:one|1)\s+(?!of\b|each\b|another\b)(?:(?i:with|of)\s+)?"
    # ("one 40x60m one 30x60m": a size said for each)
    # ("one red express one january king": a name of up to three words)
    # (never a unit: "a 1 m x 1 m orchard")
    r"(?:(?!(?i:m|x|by|ha|cm|mm|ft|in)\b)[A-Za-z][\w'-]*"
    r"(?:\s+(?!(?i:one|and|or|then|m|x|by|ha|cm|mm|ft|in)\b)[A-Za-z][\w'-]*){0,2}"
    r"|\d[\d.]*\s*(?:x|by)\s*\d[\d.]*\s*m\b|\d[\d.]*\s*(?:ha|acres?)\b))"
    # (not the whole part of a decimal: "one vine every 1.2 m")
    r"\s+(?P<second>(?i:one|1)\b(?![.,]\d))"
)


_FIELDS_OF_THEM = re.compile(
    r"(?P<words>(?:[A-Za-z][\w'-]*\s+){0,2}[A-Za-z][\w'-]*)\s*(?P<open>[-\u2013\u2014,(])\s*"
    r"(?P<count>\d+|(?i:two|three|four|five|six|seven|eight|nine|ten|twelve))\s+"
    r"(?P<plots>(?i:fields|plots|blocks|strips|beds|orchards|patches|paddocks|vineyards|groves))"
    r"\s+(?i:of)\s+(?i:them|those|these|em|'em)\b\s*(?:[-\u2013\u2014)](?=\s)|(?=[,.;:!?]|$))"
)


_PLOTS_SAID_AFTER = re.compile(
    r"(?P<words>(?:[A-Za-z][\w'-]*\s+){0,2}[A-Za-z][\w'-]*)\s*(?:\(|,)\s*"
    r"(?P<count>\d+|(?i:one|a|two|three|four|five|six|seven|eight|nine|ten|twelve))\s+"
    # (not beds: "Elsanta strawberries, 6 beds, two rows per bed" are one field's beds)
    r"(?P<plots>(?i:fields?|plots?|blocks?|strips?|orchards?|patch(?:es)?|paddocks?|"
    r"vineyards?|groves?))\s*(?:\)|,(?=\s+[a-z]))"
)


# "a wheat field with yellow rust and a healthy one next to it": one more field of the
# crop just named, told apart by a word of its own
#: "vineyards nxt to each other grapes ripening": the word after a reciprocal.
_RECIPROCAL = re.compile(r"\b(?i:each\s+other|one\s+another)\s+(?P<word>[A-Za-z][\w'-]*)")


def end_reciprocals(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with a comma after "each other" or "one another" where a crop follows
    without one ("riesling & chardonnay vineyards nxt to each other grapes ripening"):
    the placement ends there, and the crop after it is a new clause (here one about the
    grapes already named), not a field joined to the placement."""

    def comma(match: re.Match[str]) -> str:
        items = [i for i in tag(match.group("word")) if i.role != "separator"]
        if not items or not items[0].has("crop", "variety", "category"):
            return match.group(0)
        start = match.start("word") - match.start()
        return f"{match.group(0)[:start].rstrip()}, {match.group(0)[start:]}"

    return _RECIPROCAL.sub(comma, text)


#: The words that place a field said as "one" ("a healthy one next to it", "the one
#: beyond it").
_PLACING_WORDS = (
    r"(?i:next|beside|by|near|north|south|east|west|alongside|behind|across|beyond|past"
    r"|further|farther)"
)
_ONE_MORE = re.compile(
    r"(?P<lead>(?:\b(?i:and)|,|&)\s+(?P<article>(?i:a|an|another|the))\s+)"
    r"(?P<said>(?:[A-Za-z][\w-]*\s+){0,2}?)"
    rf"(?i:one)\b(?=\s*,?\s+{_PLACING_WORDS}\b)"
)
# "and beyond it another one, still green": placed first, then "another one"
_PLACED_THEN_ONE = re.compile(
    rf"(?P<lead>\b{_PLACING_WORDS}(?:\s+(?i:of|to))?\s+(?i:it|that)\s*,?\s+"
    r"(?P<article>(?i:another|a second))\s+)(?P<said>)(?i:one)\b"
)
#: Words that count more than one field: "the one ..." after them is one of those.
_MORE_THAN_ONE = frozenset(
    {"two", "three", "four", "five", "both", "pair", "several", "2", "3", "4", "5"}
    | {"fields", "plots", "blocks", "orchards", "strips", "beds", "vineyards", "groves"}
)
#: What may stand between "the" and "one" for a field not named before ("the far one").
_THE_NEW_ONE = frozenset({"", "far", "farther", "further", "next", "second"})


def _one_of_the_crop(match: re.Match[str], tag: Callable[[str], Sequence[Item]]) -> str:
    """ "... and a healthy one next to it" with "one" said as the crop named last before it
    in its sentence ("a healthy wheat field"), when a word of it names one."""
    before = re.split(r"[.;!?]", match.string[: match.start()])[-1].split()
    lead = match.group("lead")
    if match.group("article").lower() == "the":
        # "the near wheat field is ripe, and the one beyond it is still green": "the one"
        # is another field only after a sentence naming one crop, with no word of its own
        # that could name one already said ("the other one")
        if (
            match.group("said").strip().lower() not in _THE_NEW_ONE
            or sum(1 for word in before if any(i.has("crop") for i in tag(word))) != 1
            # (not one of fields counted: "Two potato fields - the one by the wood ...")
            or any(word.lower().strip(",") in _MORE_THAN_ONE for word in before)
        ):
            return match.group(0)
        lead = lead[: match.start("article") - match.start()] + "a "
    for at in range(len(before) - 1, -1, -1):
        items = [i for i in tag(before[at]) if i.role != "separator"]
        if items and all(i.has("crop") for i in items):
            # (with the crop's own plot word: "a pear orchard, and a small one" is an orchard)
            after = before[at + 1].strip(",") if at + 1 < len(before) else ""
            # (else "plot", a word the traceability check accepts as read in: "ripe wheat
            # and a young one next to it")
            plot = after if after and all(i.has("plot") for i in tag(after)) else "plot"
            return f"{lead}{match.group('said')}{before[at]} {plot}"
    return match.group(0)


def count_said_after_crop(text: str, tag: Callable[[str], Sequence[Item]]) -> str:
    """``text`` with "The farm is mostly potatoes - four fields of them - with ..." written
    "... mostly four potatoes fields with ...": a count of plots "of them" said right after
    the words that name their crop (only words that all name a crop or variety)."""

    def rewrite(match: re.Match[str]) -> str:
        words = match.group("words").split()
        for start in range(len(words)):
            crop = " ".join(words[start:])
            items = [i for i in tag(crop) if i.role != "separator"]
            if items and all(i.has("crop", "variety") for i in items):
                lead = " ".join(words[:start])
                count, plots = match.group("count"), match.group("plots")
                return f"{lead}{' ' if lead else ''}{count} {crop} {plots} "
        return match.group(0)

    text = _ONE_MORE.sub(lambda m: _one_of_the_crop(m, tag), text)
    text = _PLACED_THEN_ONE.sub(lambda m: _one_of_the_crop(m, tag), text)
    text = _SAID_AGAIN_AND_MORE.sub(lambda m: _each_more(m, tag), text)
    text = _FIELDS_OF_THEM.sub(rewrite, text)
    # "bing cherries (one block) squeezed between ...", "cherries, two blocks, next to
    # wheat": the count of the crop's plots, said between brackets or commas after it
    # (not after a list: "lettuce, cabbage and onions, 3 fields" counts the list)
    return _PLOTS_SAID_AFTER.sub(
        lambda m: m.group(0) if _after_a_list(m, tag) else rewrite(m), text
    )


#: "wheat wheat and more wheat": a crop's name said again and again, then "and more" of it.
_SAID_AGAIN_AND_MORE = re.compile(
    r"\b(?P<word>[A-Za-z]+)(?P<again>(?:\s+(?P=word)\b)+)(?=\s+(?i:and|&)\s+(?i:more)\s+(?P=word)\b)",
    re.IGNORECASE,
)


def _each_more(match: re.Match[str], tag: Callable[[str], Sequence[Item]]) -> str:
    """ "wheat wheat and more wheat" as "wheat and more wheat and more wheat": each time
    the crop is said, one more field of it."""
    word = match.group("word")
    items = [i for i in tag(word) if i.role != "separator"]
    if not items or not all(i.has("crop", "variety") for i in items):
        return match.group(0)
    times = len(match.group("again").split())
    return word + f" and more {word}" * times


def _after_a_list(match: re.Match[str], tag: Callable[[str], Sequence[Item]]) -> bool:
    """Whether the crop a bracketed or comma'd count follows ends a list of crops (or of
    kinds: "cereals n potatoes, 2 fields")."""
    clause = re.split(r"[.;:!?]", match.string[: match.end("words")])[-1]
    # (a misspelt name not yet read counts: "valenica + hamlin, 2 groves")
    words = everyday_words()
    return bool(re.search(r"(?:,|\b(?i:and)\b|&|\+|\b(?i:or)\b)", clause)) and (
        sum(
            1
            for i in tag(clause)
            if i.has("crop", "variety", "category")
            or (not i.senses and len(i.norm) >= 5 and i.norm.isalpha() and i.norm not in words)
        )
        >= 2
    )

"""Parts of a whole said in words (issue 8): "A 100-acre farm: half in wheat, ...",
"All healthy apart from the onions, which have downy mildew", "one big orchard but 3
blocks", "the northern half (10 ha) is orchard", "9 plants/m2 in one and 7 plants/m2 in
the other", "20 rows total at 75 x 45 cm: the first 10 rows Savoy, the other 10 rows Red
Express" (the members' rows). :func:`read_shares` writes each as the plainer words the
reader takes ("50 acres in wheat", "the onions, which have downy mildew; the rest
healthy", "3 blocks in one big orchard", "the northern half is 10 ha of orchard", "one
with 9 plants/m2 and the other with 7 plants/m2", "at 75 x 45 cm: the first 10 rows
Savoy, ..."), in one pass of one regular expression each, before the prompt is split into
words.
"""

from __future__ import annotations

import re

__all__ = ["HOLDINGS", "read_shares"]

#: "one big orchard but 3 blocks": one plot said, then the blocks it is split into.
_ONE_PLOT_BUT = re.compile(
    r"\b(?P<one>(?i:one|a single)\s+(?:(?i:big|large|small|long)\s+)?"
    r"(?i:orchard|field|plot|block|vineyard|grove|farm|site))\s*,?\s+"
    r"(?i:but|split into|divided into|cut into|in|with)\s+"
    r"(?P<blocks>(?:\d+|(?i:two|three|four|five|six))\s+(?i:blocks|plots|sections|parts|fields|strips))\b"
)
#: "A 100-acre farm", "the farm is 40 ha": the size of the whole holding.
#: The words for the whole holding whose size a total is ("a 100-acre farm").
HOLDINGS = frozenset({"farm", "holding", "property", "estate", "smallholding"})
_HOLDING = "|".join(sorted(HOLDINGS))
_FARM_TOTAL = re.compile(
    r"\b(?P<n>\d+(?:\.\d+)?)[\s-]*(?P<unit>(?i:acres?|ha|hectares?))[\s-]+"
    rf"(?i:{_HOLDING})\b"
    rf"|\b(?i:{_HOLDING})\s+(?i:is|of)\s+(?:(?i:about|around|some)\s+)?"
    r"(?P<n2>\d+(?:\.\d+)?)\s*(?P<unit2>(?i:acres?|ha|hectares?))\b"
)
#: "half in wheat", "a third of it under potatoes": a share of the farm given to a crop.
_FARM_SHARE = re.compile(
    r"(?<!(?i:other) )\b(?P<share>(?i:half|a half|one half|a third|one third|a quarter|"
    r"one quarter|two thirds|three quarters))(?:\s+(?i:of it|of that|of the farm|of the land))?"
    r"\s+(?P<said>(?:(?i:is|are)\s+)?(?i:in|under|down to|planted with|planted to|sown to|"
    r"sown with|given to|given over to)\s+)"
)
_SHARES = {
    "half": 0.5,
    "a half": 0.5,
    "one half": 0.5,
    "a third": 1 / 3,
    "one third": 1 / 3,
    "a quarter": 0.25,
    "one quarter": 0.25,
    "two thirds": 2 / 3,
    "three quarters": 0.75,
}
_UNIT_PLURALS = {"acre": "acres", "hectare": "hectares"}
_UNIT_SINGULARS = {"acres": "acre", "hectares": "hectare"}


def _farm_shares(text: str) -> str:
    """``text`` with "half in wheat" written "50 acres in wheat" after "a 100-acre farm":
    a share of the farm's stated size, as an area of the field."""
    total = _FARM_TOTAL.search(text)
    if total is None:
        return text
    size = float(total.group("n") or total.group("n2"))
    unit = (total.group("unit") or total.group("unit2")).lower()
    unit = _UNIT_PLURALS.get(unit, unit)

    def area(match: re.Match[str]) -> str:
        value = round(size * _SHARES[re.sub(r"\s+", " ", match.group("share").lower())], 4)
        return f"{value:g} {unit} {match.group('said')}"

    return text[: total.end()] + _FARM_SHARE.sub(area, text[total.end() :])


#: "We farm 40 acres:", "we have 12 ha,": the whole area, said before what is in it.
_TOTAL_SAID = re.compile(
    r"\b(?i:we|i)\s+(?:(?i:only|just)\s+)?(?i:farm|have|own|run|crop|manage|grow on|work|rent)"
    r"\s+(?:(?i:about|around|some|roughly)\s+)?(?P<n>\d+(?:\.\d+)?)\s*"
    r"(?P<unit>(?i:acres?|ha|hectares?))\s*(?=[:,;])"
)
_NUMBER = r"(?P<n>\d+(?:\.\d+)?)"
#: "25 of them in dent corn": a number of the units the whole was said in.
_OF_THEM = re.compile(_NUMBER + r"\s+(?i:of them|of those|of it|of that)\b")
#: "... and 15 in durum": a bare number of the same units, given to a crop.
_BARE_SHARE = re.compile(
    r"(?:(?<=[,:;]\s)|(?<=\b(?i:and)\s)|(?<=&\s))"
    + _NUMBER
    + r"\s+(?=(?i:in|under|down to|planted with|planted to|sown to|sown with|of)\s)"
)
#: A number of things counted ("4 apple blocks"), once the areas are taken out.
_COUNTED = re.compile(r"\b\d+(?:\.\d+)?\s+(?:[A-Za-z][\w'-]*\s+){0,2}[A-Za-z][\w'-]*s\b")
_AN_AREA = re.compile(_NUMBER + r"\s*(?P<unit>(?i:acres?|ha|hectares?))\b")
#: "the rest in durum": what is left of the whole, given to one crop (not "the rest maize
#: and potatoes", shared by several, nor "the rest healthy", a look).
_THE_REST = re.compile(
    r"\b(?i:the rest|the remainder|the remaining (?:area|land|ground))\s+"
    r"(?:(?i:is|are|goes|went)\s+)?(?P<said>(?i:in|under|down to|planted with|planted to|"
    r"sown to|sown with|to|of)\s+)(?=[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*){0,2}\s*(?:[.;!?]|$))"
)


def _the_rest(text: str) -> str:
    """``text`` with the shares of a whole said in its units: after "We farm 40 acres:",
    "25 of them in dent corn" is "25 acres in dent corn", "and 15 in durum" is "15 acres
    in durum", and "the rest in durum" is "15 acres in durum" (the whole less the areas
    said; kept as it was when they leave nothing)."""
    total = _TOTAL_SAID.search(text) or _FARM_TOTAL.search(text)
    if total is None:
        return text
    size = float(total.group("n") or total.group("n2"))
    unit = (total.group("unit") or total.group("unit2")).lower()
    unit = _UNIT_PLURALS.get(unit, unit)
    head, rest = text[: total.end()], text[total.end() :]
    # (not "we have 12 ha: 4 apple blocks, 2 of them Gala": of what was counted since)
    rest = _OF_THEM.sub(
        lambda m: (
            m.group(0)
            if _COUNTED.search(_AN_AREA.sub("", m.string[: m.start()]))
            else f"{m.group('n')} {unit}"
        ),
        rest,
    )
    if _AN_AREA.search(rest):
        # (a bare number is an area only once some share was said in the whole's units)
        rest = _BARE_SHARE.sub(
            lambda m: f"{m.group('n')} {unit} " if float(m.group("n")) < size else m.group(0),
            rest,
        )
    said = [
        float(m.group("n"))
        for m in _AN_AREA.finditer(rest)
        if _UNIT_PLURALS.get(m.group("unit").lower(), m.group("unit").lower()) == unit
    ]
    left = round(size - sum(said), 4)
    if said and left > 0:
        rest = _THE_REST.sub(lambda m: f"{left:g} {unit} {m.group('said')}", rest, count=1)
    return head + rest


#: "All healthy apart from the onions, which have downy mildew": a look said of every
#: field but one, named after it.
_ALL_BUT = re.compile(
    r"\b(?i:all|everything|all of them|all the rest|the rest)\s+(?:(?i:is|are|look|looks|seem|"
    r"seems)\s+)?(?P<said>(?i:healthy|fine|clean|ok|okay|disease free|in good health))\s*,?\s+"
    r"(?i:apart from|except for|except|other than|bar|save for|but for|but)\s+"
    r"(?P<one>(?i:the)\s+[A-Za-z][\w'-]*(?:\s+[A-Za-z][\w'-]*)?)"
    r"(?P<rest>[^.;!?]*)(?P<end>[.;!?]|$)"
)


#: "the northern half (10 ha) is orchard": a part of the farm, its size in brackets, then
#: what grows there.
_PART_SIZE_FIRST = re.compile(
    r"\b(?P<part>(?i:the)\s+(?i:northern|southern|eastern|western|north|south|east|west|top|"
    r"bottom|upper|lower|left|right|front|back)\s+(?i:half|third|quarter|part|end|side))\s*"
    r"\(\s*(?P<size>\d[\d.,]*\s*(?i:ha|hectares?|acres?))\s*\)\s*"
    r"(?P<verb>(?i:is|are))\s+(?:(?i:in|under|planted with|given to)\s+)?"
)


#: "9 plants/m2 in one and 7 plants/m2 in the other": what each of two fields has, said
#: after it, as in "one with 9 plants/m2 and the other with 7 plants/m2".
_IN_ONE_IN_THE_OTHER = re.compile(
    r"(?:(?<=[,;:(]\s)|(?<=[,;:(])|^)(?P<a>[^\s,;:.()](?:[^,;:.()]|\.(?=\d))*?)"
    r"\s+(?i:in|on|for)\s+(?i:one)(?:\s+(?i:of them|plot|field|block|strip))?"
    r"\s*(?:,\s*(?:(?i:and|&|but)\s+)?|(?i:and|&|but)\s+)"
    r"(?P<b>[^\s,;:.()](?:[^,;:.()]|\.(?=\d))*?)\s+(?i:in|on|for)\s+(?i:the other)"
    r"(?:\s+(?i:one|plot|field|block|strip))?\b"
)


#: "one has greening... the hamlin one": a look said of "one", then which one it is.
_ONE_THEN_WHICH = re.compile(
    r"(?:(?<=^)|(?<=[,;:]\s)|(?<=[,;:]))(?i:one)\s+"
    r"(?P<look>(?i:has|is|got|with|looks|shows)\s+[^,;:.!?()]+?)\s*(?:\.{2,}|…|,|-+|–|—)\s*"
    r"(?P<which>(?i:the|its|it's|its the|it's the)\s+(?!(?i:other)\b)[a-z][\w'-]*\s+(?i:one))\b"
)


#: An area and the plot word it sizes ("a 1-acre test field", "3 ha"), in the words
#: that split it.
_AREA = r"(?P<n>\d+(?:\.\d+)?)[\s-]*(?P<unit>(?i:acres?|ha|hectares?|m2|m²))"
_CONTAINER = (
    r"(?:[\s-]+(?P<kind>(?:[A-Za-z-]+\s+){0,2}?)"
    r"(?P<noun>(?i:field|plot|block|area|site|paddock|parcel|orchard|vineyard|grove|plantation)))?"
)
#: Plot words that say what grows there ("our 10 acre orchard ... 4 blocks": orchard blocks).
_KIND_NOUNS = frozenset({"orchard", "vineyard", "grove", "plantation"})
_SPLIT = r"(?i:split|divided|cut|broken up|subdivided|partitioned|shared)"
_EVENLY = r"(?:\s+(?i:equally|evenly|in equal parts))?"
_COUNTS = {"two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8}
_PLOTS = r"(?i:plots|blocks|strips|sections|fields|beds|parcels|areas|parts|subplots)"
#: "a 1 ha field split into four plots", "Split a 1-acre test field into four quarter-acre
#: plots": the whole, then the plots it is split into.
_SPLIT_INTO_PLOTS = re.compile(
    r"(?:\b(?i:a|an|one|the|our|my)\s+)?"
    + _AREA
    + _CONTAINER
    + r"\s+(?:(?i:that is|which is|is|was)\s+)?"
    + _SPLIT
    + _EVENLY
    + r"\s+(?i:into|in|between|among)\s+"
    + r"|\b"
    + r"(?i:split|divide|cut|break up|subdivide|partition)\s+(?:(?i:a|an|one|the|our|my)\s+)?"
    + _AREA.replace("<n>", "<n2>").replace("<unit>", "<unit2>")
    + _CONTAINER.replace("<kind>", "<kind2>").replace("<noun>", "<noun2>")
    + _EVENLY
    + r"\s+(?i:into)\s+"
)
_INTO_COUNTED = re.compile(
    r"(?P<count>\d+|(?i:two|three|four|five|six|seven|eight))\s+"
    r"(?P<each>(?:(?i:quarter|half|third)|\d+(?:\.\d+)?)[\s-]*(?i:acres?|ha|hectares?|m2|m²)[\s-]+)?"
    r"(?P<plots>(?:[A-Za-z-]+\s+)?" + _PLOTS + r")\b"
)
#: A plain list of a few crops or varieties ("lettuce, cabbage, onions and carrots",
#: "Royal Gala and Granny"), ending where the list does.
_MEMBER = r"[A-Za-z][\w'-]*(?:\s+(?!(?i:and)\b)[A-Za-z][\w'-]*){0,2}?"
_INTO_LIST = re.compile(
    r"(?P<list>" + _MEMBER + r"(?:\s*,\s*" + _MEMBER + r")*\s*,?\s+(?i:and|&)\s+" + _MEMBER + r")"
    r"(?=\s*(?:[,.;:!?()–—-]|$)|\s+(?i:with|in|at|on|for|all)\b)"
)


def _split_areas(text: str) -> str:
    """``text`` with a stated area split into plots or between crops said as each part's
    area: "a 1 ha field split into four plots" is "four 0.25 ha plots", "3 ha split
    equally between Royal Gala and Granny" is "Royal Gala and Granny, 1.5 ha each"; when
    the parts have their own size ("into four quarter-acre plots") the whole's is dropped."""
    out: list[str] = []
    position = 0
    for whole in _SPLIT_INTO_PLOTS.finditer(text):
        if whole.start() < position:
            continue
        size = float(whole.group("n") or whole.group("n2"))
        unit = (whole.group("unit") or whole.group("unit2")).lower()
        unit = _UNIT_PLURALS.get(unit, unit)
        rest = text[whole.end() :]
        if (counted := _INTO_COUNTED.match(rest)) is not None:
            count = _COUNTS.get(counted.group("count").lower()) or int(counted.group("count"))
            if count < 2:
                continue
            adjective = _UNIT_SINGULARS.get(unit, unit)
            each = counted.group("each") or f"{round(size / count, 4):g}-{adjective} "
            # ("a 2 ha wheat field split into four plots": the whole's crop stays)
            kind = whole.group("kind") or whole.group("kind2") or ""
            noun = (whole.group("noun") or whole.group("noun2") or "").lower()
            if noun in _KIND_NOUNS:
                kind += f"{noun} "
            said = f"{counted.group('count')} {each}{kind}{counted.group('plots')}"
            end = whole.end() + counted.end()
        elif (listed := _INTO_LIST.match(rest)) is not None:
            members = re.split(r"\s*,\s*(?:(?i:and|&)\s+)?|\s+(?i:and|&)\s+", listed.group("list"))
            if len(members) < 2:
                continue
            said = f"{listed.group('list')}, {round(size / len(members), 4):g} {unit} each"
            end = whole.end() + listed.end()
        else:
            continue
        out.append(text[position : whole.start()] + said)
        position = end
    return "".join(out) + text[position:]


#: "20 rows total at 75 x 45 cm: the first 10 rows Savoy, the other 10 rows Red Express":
#: a count of rows before a colon, and the rows of the members listed after it.
_ROW_TOTAL = re.compile(
    r"\b(?P<n>\d+)\s+(?i:rows)(?:\s+(?i:in total|total|altogether|in all))?"
    r"(?P<rest>[^.;:!?]*):(?P<members>[^.;!?]*)"
)
_MEMBER_ROWS = re.compile(r"\b(\d+)\s+(?i:rows)\b")


def _row_total(match: re.Match[str]) -> str:
    """The heading's words without its count of rows when the members' rows add up to it."""
    counts = [int(n) for n in _MEMBER_ROWS.findall(match.group("members"))]
    if len(counts) < 2 or sum(counts) != int(match.group("n")):
        return match.group(0)
    return f"{match.group('rest').lstrip(' ,')}:{match.group('members')}"


def read_shares(text: str) -> str:
    """``text`` with the parts of a whole said plainly (see the module's words)."""
    # "..., one big orchard but 3 blocks pls": three blocks, in the one orchard
    text = _ONE_PLOT_BUT.sub(r"\g<blocks> in \g<one>", text)
    # "All healthy apart from the onions, which have ...": the one named first, then
    # the rest
    text = _ALL_BUT.sub(
        lambda m: f"{m.group('one')}{m.group('rest')}; the rest {m.group('said')}{m.group('end')}",
        text,
    )
    # "the northern half (10 ha) is orchard": the part is 10 ha of orchard
    text = _PART_SIZE_FIRST.sub(
        lambda m: f"{m.group('part')} {m.group('verb')} {m.group('size')} of ", text
    )
    # "one has greening... the hamlin one": the look of the one named after it
    text = _ONE_THEN_WHICH.sub(
        lambda m: f"{re.sub(r'(?i)^it.?s ', '', m.group('which'))} {m.group('look')}", text
    )
    # "9 plants/m2 in one and 7 plants/m2 in the other": each of the two, in turn
    text = _IN_ONE_IN_THE_OTHER.sub(r"one with \g<a> and the other with \g<b>", text)
    # "a 1 ha field split into four plots": each plot's share of the area
    text = _split_areas(text)
    # "20 rows total at 75 x 45 cm: the first 10 rows Savoy, the other 10 rows ...": the
    # members' rows, not one more field's
    text = _ROW_TOTAL.sub(_row_total, text)
    # "A 100-acre farm: half in wheat, ...": a share of the farm's size, as an area
    # ("We farm 40 acres: 25 of them in dent corn and the rest in durum": 15 acres)
    return _the_rest(_farm_shares(text))

"""Value lists said once for several plots: "at 100, 150 and 200 plants per m2".

The units are data (``data/value_lists.yaml``). :func:`spread_value_lists` rewrites
such a list into one member per value ("..., one at 100 plants per m2, one at 150
plants per m2 and one at 200 plants per m2"), which the reading of counted plots
and their members already understands; a list of one value is left alone.
"""

from __future__ import annotations

import functools
import re
from typing import Any

import yaml

from agrirecipe.resolve._lexicon import DATA_DIR

__all__ = ["fill_gapped_counts", "spread_value_lists"]

_NUMBER = r"\d+(?:[.,]\d+)?"
#: Length units a value of a list may be said with ("50 cm and 75 cm rows").
_LENGTH_UNIT = r"(?:cm|mm|m|in|ft)\b"


@functools.cache
def _data() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "value_lists.yaml").read_text("utf-8"))
    return data


@functools.cache
def _pattern() -> re.Pattern[str]:
    data = _data()
    leads = "|".join(
        re.escape(str(w)) for w in sorted(data["leads"], key=lambda w: len(str(w)), reverse=True)
    )
    units = _units()
    # ("two corn plots with 50 cm and 75 cm rows": each value may say the length unit)
    each = rf"{_NUMBER}(?:\s*{_LENGTH_UNIT})?"
    return re.compile(
        rf"\b(?P<lead>{leads})\s+(?P<values>{each}(?:\s*,\s*{each})*,?\s+(?:and|or|&)\s+"
        rf"{_NUMBER})\s*(?P<unit>{units})(?![\w²])",
        re.IGNORECASE,
    )


@functools.cache
def _units() -> str:
    """The measures a list of values may end in, as one alternation (longest first)."""
    units = sorted(_data()["units"], key=lambda u: len(str(u)), reverse=True)
    return "|".join(re.escape(str(u)) for u in units)


@functools.cache
def _leads() -> dict[str, str]:
    return {str(k).lower(): str(v) for k, v in _data()["leads"].items()}


@functools.cache
def _repeated_unit() -> re.Pattern[str]:
    """A value said with the same unit as the value after it in a list ("40 cm, 30 cm")."""
    units = r"cm|mm|m|in|inch(?:es)?|ft|feet|ha|acres?"
    return re.compile(
        rf"(?P<first>\b{_NUMBER})\s*(?P<unit>{units})\b(?=\s*(?:,\s*|,?\s+(?:and|or|&)\s+)"
        rf"{_NUMBER}\s*(?P=unit)(?![\w²]))",
        re.IGNORECASE,
    )


@functools.cache
def _measure() -> re.Pattern[str]:
    """One of the measures a list of values may end in, after its last value."""
    return re.compile(rf"\s*(?:{_units()})(?![\w²])", re.IGNORECASE)


def _one_unit(match: re.Match[str]) -> str:
    """The value without its unit, when the list it starts ends in a measure of
    ``value_lists.yaml`` and "respectively" ("40 cm, 30 cm and 75 cm apart respectively")."""
    text = match.string
    # (the values after it, each with the same unit but the last: "..., 30 cm and 75")
    unit = re.escape(match.group("unit"))
    rest = re.compile(
        rf"(?:\s*(?:,\s*|,?\s+(?:and|or|&)\s+){_NUMBER}"
        rf"(?:\s*{unit}(?=\s*(?:,|(?:and|or|&)\s)))?)+",
        re.IGNORECASE,
    )
    values = rest.match(text, match.end())
    if values is None:
        return match.group(0)
    measure = _measure().match(text, values.end())
    if measure is None or not _RESPECTIVELY.match(text, measure.end()):
        return match.group(0)
    return match.group("first")


#: "drilled at 12.5 cm, 25 cm and 37.5 cm": a list of row spacings after a drilling verb,
#: each value with its bare length unit (or the last only).
_DRILLED_LIST = re.compile(
    rf"\b(?P<lead>(?i:drilled|sown|planted|spaced)\s+(?:at|on))\s+"
    rf"(?P<values>{_NUMBER}(?:\s*(?:cm|mm|in|m)\b)?(?:\s*,\s*{_NUMBER}(?:\s*(?:cm|mm|in|m)\b)?)*"
    rf",?\s+(?i:and|or|&)\s+{_NUMBER})\s*(?P<unit>cm|mm|in|m)\b"
    r"(?!\s*(?:x|×|by|wide|long|tall|high|deep|apart|rows?|row spacing|spacing|between)\b)"
)


def _members(match: re.Match[str], member: str) -> str | None:
    """The list of values ``match`` read, as one "``member`` <value> <unit>" each joined
    by commas and "and"; None when it is no list to spread: "1,000" is one number
    (thousands separators stay whole), and "... respectively" gives the values out to
    the fields named."""
    if re.search(r"\d,\d{3}(?!\d)", match.group("values")):
        return None
    if _RESPECTIVELY.match(match.string, match.end()):
        return None
    unit = match.group("unit")
    members = [f"{member} {value} {unit}" for value in re.findall(_NUMBER, match.group("values"))]
    return ", ".join(members[:-1]) + " and " + members[-1]


def _drilled_each(match: re.Match[str]) -> str:
    """ "drilled at 12.5 cm, 25 cm and 37.5 cm" as one member drilled at each value."""
    members = _members(match, f"one {match.group('lead')}")
    return match.group(0) if members is None else members


#: "respectively" within a few words after a list of values.
_RESPECTIVELY = re.compile(r"(?:\s+[\w-]+){0,3}\s+respectively\b", re.IGNORECASE)


def spread_value_lists(text: str) -> str:
    """``text`` with each list of values of one measure spread into one member per value."""

    def spread(match: re.Match[str]) -> str:
        # (a unit said with a value is the list's own: not "at 75 cm and 9 plants/m2")
        said = re.findall(rf"\b{_LENGTH_UNIT}", match.group("values").lower())
        if any(not match.group("unit").lower().startswith(unit) for unit in said):
            return match.group(0)
        members = _members(match, _leads()[match.group("lead").lower()])
        return match.group(0) if members is None else ", " + members

    # "rows 40 cm, 30 cm and 75 cm apart respectively": one unit for the list
    text = _repeated_unit().sub(_one_unit, text)
    text = _pattern().sub(spread, text)
    # "three wheat plots drilled at 12.5 cm, 25 cm and 37.5 cm": how each is drilled
    text = _DRILLED_LIST.sub(_drilled_each, text)
    text = _SIZES_OF_COUNTED.sub(_one_size_each, text)
    # "..., each one hectare": "one hectare each" (not the pronoun "each one")
    text = _EACH_ONE_SIZE.sub(r"\g<size> \g<each>", text)
    # "Half a hectare each of Cos lettuce and Savoy cabbage": the size is each one's
    text = _SIZE_EACH_OF.sub(lambda m: f"{m.group('list')}, {m.group('size')} each", text)
    # "Three different vegetables, each a 20 x 30 m plot with 0.75 m rows": what each
    # field is, not one more plot
    text = _EACH_A_PLOT.sub(lambda m: f"each {m.group('said')}", text)
    # "Spring Wheat in one field and dinkel in the other": two members, listed
    text = _ONE_AND_THE_OTHER.sub(r"\g<a> and \g<b>", text)
    # "with exactly the same row spacing, tree spacing and row length": each the same
    return _SAME_LIST.sub(_each_the_same, text)


#: (not "on one side ... on the other": the sides of what lies between them)
_PART = r"(?:field|plot|block|bed|strip|one|paddock|patch)"
_ONE_AND_THE_OTHER = re.compile(
    rf"(?P<a>\b[^,.;:()]+?)\s+(?i:in)\s+(?i:one)(?:\s+(?i:{_PART}))?\s*,?\s+(?i:and)\s+"
    rf"(?P<b>[^,.;:()]+?)\s+(?i:in)\s+(?i:the)\s+(?i:other)(?:\s+(?i:{_PART}))?\b"
)


#: What a field may have "the same" of as the one before ("the same row spacing").
_SAME_MEASURES = (
    r"(?:(?:row|tree|plant|vine|in[- ]row|bed|bush)\s+)?(?:spacings?|length|width|count)"
    r"|number\s+of\s+rows|(?:row\s+)?(?:direction|orientation|bearing)|rows\s+per\s+bed"
)
_SAME_LIST = re.compile(
    rf"\b(?P<same>(?:the\s+)?same)\s+(?P<first>{_SAME_MEASURES})"
    rf"(?P<rest>(?:\s*,\s*(?:{_SAME_MEASURES}))*,?\s+(?:and|&)\s+(?:{_SAME_MEASURES}))\b",
    re.IGNORECASE,
)


def _each_the_same(match: re.Match[str]) -> str:
    """ "the same row spacing, tree spacing and row length" as "the same row spacing, the
    same tree spacing and the same row length"."""
    same = match.group("same")
    rest = re.sub(
        rf"(,\s*|,?\s+(?:and|&)\s+)(?={_SAME_MEASURES})",
        lambda m: f"{m.group(1)}{same} ",
        match.group("rest"),
        flags=re.IGNORECASE,
    )
    return f"{same} {match.group('first')}{rest}"


# "two potato fields of 3 ha and 1.5 ha": as many areas as plots counted, one each
_AREA = rf"{_NUMBER}\s*(?:ha|hectares?|acres?|m2|m²)\b"
_COUNTS = {"two": 2, "three": 3, "four": 4, "2": 2, "3": 3, "4": 4}
_SIZES_OF_COUNTED = re.compile(
    rf"\b(?P<count>{'|'.join(_COUNTS)})\s+(?P<what>(?:[\w-]+\s+){{0,3}}?"
    r"(?:fields|plots|blocks|strips|orchards|vineyards|paddocks|groves))"
    rf"(?:\s*,\s*|\s+(?:of|at)\s+)(?P<sizes>{_AREA}(?:\s*,\s*{_AREA})*,?\s+(?:and|&)\s+{_AREA})",
    re.IGNORECASE,
)


_EACH_ONE_SIZE = re.compile(
    r"\b(?P<each>(?i:each))\s+(?P<size>(?i:one|a|an|half an?)\s+"
    r"(?i:hectares?|ha|acres?|ac)\b)"
)


def _one_size_each(match: re.Match[str]) -> str:
    """ "two potato fields, one of 3 ha and one of 1.5 ha" for "two potato fields of 3 ha
    and 1.5 ha" (as many sizes as fields; otherwise left as said)."""
    sizes = re.findall(_AREA, match.group("sizes"), re.IGNORECASE)
    if len(sizes) != _COUNTS[match.group("count").lower()]:
        return match.group(0)
    members = [f"one of {size}" for size in sizes]
    said = f"{match.group('count')} {match.group('what')}"
    return f"{said}, " + ", ".join(members[:-1]) + " and " + members[-1]


_EACH_A_PLOT = re.compile(
    r"\b(?i:each)\s+(?i:a|an|one)\s+(?P<said>\d[^,.;:!?]*?)\s+"
    r"(?i:plot|field|block|strip|bed|patch|paddock)\b"
)


_SIZE_EACH_OF = re.compile(
    r"\b(?P<size>(?:(?i:half an?|an?|one|two|three|four|five)|\d[\d.,]*)\s*"
    r"(?i:hectares?|ha|acres?|ac|m2|m²|square metres))\s+(?i:each)\s+(?i:of)\s+"
    r"(?P<list>[A-Za-z][^,.;:!?]*?\s(?i:and|&)\s[^,.;:!?]+?)(?=\s*[,.;:!?]|$)"
)


@functools.cache
def _gapped() -> re.Pattern[str]:
    units = "|".join(re.escape(str(u)) for u in _data()["gapped_units"])
    # (a name, not a word of the measure: "each 12 rows, at 75, 50 and 30 cm")
    name = (
        r"(?!(?i:at|on|in|with|by|of|every|each|both|about|around|approx|roughly|spaced|"
        r"and|or|the|a|an|all|plus|also|then|to|from|x)\b)[A-Za-z][\w'-]*"
    )
    return re.compile(
        rf"\b(?P<said>\d+)\s+(?P<unit>{units})\b"
        # the next plot's name (one to three words, no number or unit among them), or its
        # label ("Block 1 has 200 trees; block 2 has 300")
        rf"(?P<gap>\s*(?:,|;|\band\b|\bwhile\b)\s*(?:{name}(?:\s+(?!\d){name}){{0,2}}|"
        r"(?i:block|plot|field|strip|bed|zone|area)\s+\d{1,2}\s+(?i:has|have|is|with))\s+)"
        # (a whole number, not "also 0.9 m rows")
        rf"(?P<count>\d+)(?![.,]?\d)(?=\s*(?:[.;,!?)]|$|\band\b))",
        re.IGNORECASE,
    )


@functools.cache
def _gapped_of() -> re.Pattern[str]:
    # (areas only: "12 beds of Sturon and 12 of Red Baron" is read as the same beds)
    units = "|".join(re.escape(str(u)) for u in _data()["gapped_area_units"])
    name = r"(?!(?i:and|or|the|a|an|with|then|plus)\b)[A-Za-z][\w'-]*"
    # ("two hectares of tomatoes and one of onions": numbers said in words too)
    number = r"(?:\d[\d.,]*|one|two|three|four|five|six|seven|eight|nine|ten|twelve)\b"
    return re.compile(
        rf"\b(?P<said>{number})\s+(?P<unit>{units})\s+of\s+{name}(?:\s+{name}){{0,2}}"
        rf"\s*(?:,|;|\band\b|\bwhile\b|\bplus\b)\s*(?:\band\s+)?"
        # (not "one of them": a member of the fields named)
        rf"(?P<count>{number})(?=\s+of\s+(?!(?:them|these|those|it|which|the)\b)[A-Za-z])",
        re.IGNORECASE,
    )


def fill_gapped_counts(text: str) -> str:
    """``text`` with "Chardonnay has 20 rows, Cabernet 16" written "..., Cabernet 16
    rows": a bare number after the next name counts what the one before it counted;
    likewise "25 acres of wheat and 15 of corn" ("15 acres of corn")."""
    text = _gapped().sub(
        lambda m: (
            f"{m.group('said')} {m.group('unit')}{m.group('gap')}{m.group('count')} "
            f"{m.group('unit')}"
        ),
        text,
    )
    text = _fill_measure_pairs(text)
    pattern = _gapped_of()
    position = 0
    while (match := pattern.search(text, position)) is not None:
        # (one at a time: "20 acres of wheat, 15 of corn and 5 of potatoes" fills each,
        # the next search starting at the count just filled, not at the prompt's start)
        at = match.end("count")
        text = f"{text[:at]} {match.group('unit')}{text[at:]}"
        position = match.start("count")
    return text


_LENGTH = rf"{_NUMBER}\s*(?:cm|m|in|ft)\b"
# "cherries 4.5 m between rows and 2.5 m between trees": two measures, each with its words
_NAMED_PAIR = re.compile(
    rf"(?P<a>{_LENGTH})\s+(?P<first>(?:between|apart|in)\b[\w\s-]{{0,20}}?)\s+(?:and|&)\s+"
    rf"(?P<b>{_LENGTH})\s+(?P<second>(?:between|apart|in)\b[\w\s-]{{0,20}}?)(?=\s*[,;.)]|$)",
    re.IGNORECASE,
)
# "..., apples 3.3 m and 0.9 m;": the same two measures of another field, said bare
_BARE_PAIR = re.compile(
    rf"(?<=[A-Za-z] )(?P<a>{_LENGTH})\s+(?:and|&)\s+(?P<b>{_LENGTH})(?=\s*[,;.)]|$)",
    re.IGNORECASE,
)


def _fill_measure_pairs(text: str) -> str:
    """``text`` with "..., apples 3.3 m and 0.9 m" written "..., apples 3.3 m between rows
    and 0.9 m between trees" after "cherries 4.5 m between rows and 2.5 m between trees":
    a bare pair of lengths after another field's pair of named measures says the same
    two measures, in the same order."""
    named = _NAMED_PAIR.search(text)
    if named is None:
        return text
    first, second = named.group("first"), named.group("second")
    return text[: named.end()] + _BARE_PAIR.sub(
        lambda m: f"{m.group('a')} {first} and {m.group('b')} {second}", text[named.end() :]
    )

"""Counts said of a crop's rows, beds or plants, written so that the number counts rows
or plants and not fields, before the prompt is tagged.

"12 maize rows" reads as "maize in 12 rows", "6 rows of peppers at 3 ft" as "peppers in
6 rows at 3 ft", "12 beds of Sturon and 12 of Red Baron" says "beds" twice, "150 Pink
Lady" is "150 Pink Lady plants". Each rewrite is one pattern below, applied once over
the text (linear in its length); only words that all name a crop or variety move.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence
from typing import Any

__all__ = ["hoist_counted_crops"]

#: "12 maize rows at 75 cm", "40 carrot ridges, two rows per ridge": a count of rows
#: with the crop between the number and the row noun (rows and ridges always; beds
#: only before a measure, since "two strawberry beds" may be two plots).
#: Words said between a count and its rows or beds ("8 raised strawberry beds", "on 12
#: raised beds").
_BED_MODIFIERS = "single|double|twin|raised|flat|mulched"
_COUNTED_CROP_ROWS = re.compile(
    r"(?<![\w.,])(?P<n>\d+|(?i:two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|"
    r"fifteen|twenty|thirty|forty|fifty|sixty))\s+"
    # ("8 raised strawberry beds on 1.5 m centres": one field of beds)
    rf"(?P<mod>(?i:{_BED_MODIFIERS})\s+)?"
    r"(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\s+"
    # ("10 Sonata strawberry beds south of 10 Centenary beds, all beds on 1.5 m centres")
    r"(?P<noun>(?i:rows|ridges|drills|beds(?=\s*(?:,\s*)?(?:(?:at|on|of|x|by|with|spaced|each|all|"
    r"north|south|east|west)\s|\d|\())))\b"
)

#: "30 onion beds": ten or more beds of a crop are one field's beds, whatever follows.
_MANY_CROP_BEDS = re.compile(
    r"(?<![\w.,])(?P<n>[1-9]\d+)\s+"
    rf"(?P<mod>(?i:{_BED_MODIFIERS})\s+)?"
    r"(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\s+(?P<noun>(?i:beds|ridges))\b"
)

_PLANT_UNITS = frozenset({"trees", "tree", "vines", "vine", "plants", "plant", "bushes", "palms"})
#: "40 Regina cherry trees and 60 Bing": a count of plants, then one said without its noun.
_ELLIPTIC_PLANTS = re.compile(
    r"(?<![\w.,])\d+\s+(?:[A-Za-z][\w'’-]*\s+){1,3}"
    r"(?P<unit>trees|vines|plants|bushes|palms)\b"
    r"\s*(?:,|(?i:and|&|\+|plus)|,\s*(?i:and))\s+"
    r"\d+\s+(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\b"
    r"(?!\s+(?:trees|tree|plants|plant|vines|vine|bushes|bush|palms|rows|beds|ridges|m|ha|acres?)\b)"
)
#: "30 in (76.2 cm) rows": a measure with the same in other units in brackets after it.
_CONVERTED = re.compile(
    r"(?P<measure>\b\d+(?:\.\d+)?\s*(?:in|inch|inches|ft|feet|foot|\"|cm|m|mm)\.?)\s*"
    r"\(\s*(?:=\s*|~\s*|(?i:approx|about|ca|c)\.?\s*)?\d+(?:\.\d+)?\s*"
    r"(?:cm|m|mm|in|inch|inches|ft|feet)\.?\s*\)"
)
#: "Kordia with 8 rows, Regina with 6": a count said with its noun, then one without.
#: ("Albion on 12 raised beds and Sonata on 8": said with "on" or "in" too)
_ELLIPTIC_WITH = re.compile(
    rf"\b(?P<prep>(?i:with|on|in))\s+\d+\s+(?:(?i:{_BED_MODIFIERS})\s+)?"
    r"(?P<unit>rows|beds|ridges|trees|vines|plants)\b[^.;:]*?(?:,\s*(?:(?i:and)\s+)?|\s+(?i:and)\s+)"
    r"(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\s+(?P=prep)\s+"
    r"\d+\b(?!\s*(?:[A-Za-z%]|\.\d))"
)
#: "a single tomato row 20 m long", "one lettuce bed": one row (or bed) of the crop.
_SINGLE_CROP_ROW = re.compile(
    r"(?<![\w.,])(?P<one>(?i:a single|one single|a lone|just one|only one))\s+"
    r"(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\s+"
    r"(?P<noun>(?i:row|ridge|drill|bed))\b(?!\s+(?i:of)\b)"
)


#: "strawberry beds (10 of them, 1.5 m centres)": the count of a crop's beds in brackets.
_BEDS_OF_THEM = re.compile(
    r"\b(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\s+(?P<noun>(?i:beds|ridges|rows))\s*"
    r"\(\s*(?P<n>\d+)\s+(?i:of\s+them)\s*,?\s*"
)
#: "albion 8 beds side by side": a crop's beds, then where its field lies.
_CROP_BEDS_SIDE_BY_SIDE = re.compile(
    r"\b(?P<words>[A-Za-z][\w'’-]*)\s+(?P<beds>\d+\s+(?i:beds|ridges))\s+(?=(?i:side by side)\b)"
)


def hoist_counted_crops(text: str, tag: Callable[[str], Sequence[Any]]) -> str:
    """``text`` with counts said of a crop's rows or plants written so that the number
    counts rows or plants, not fields: "12 maize rows" is "maize in 12 rows", "6 rows of
    peppers at 3 ft" is "peppers in 6 rows at 3 ft", "12 beds of Sturon and 12 of Red
    Baron" says "beds" twice, "150 Pink Lady" is "150 Pink Lady plants". ``tag`` reads a
    phrase into lexicon items; only words that all name a crop or variety move."""

    def names_a_crop(words: str) -> bool:
        items = [i for i in tag(words) if i.role != "separator"]
        return bool(items) and all(i.has("crop", "variety") for i in items)

    def crop_rows(tail: str) -> Callable[[re.Match[str]], str]:
        def rewrite(match: re.Match[str]) -> str:
            words = match.group("words")
            if not names_a_crop(words):
                return match.group(0)
            after = match.string[match.end() :].lstrip(" ,").split(" ", 1)[0].lower()
            number = match.group("n")
            if after in _PLACED_AFTER and not (number.isdigit() and int(number) >= 3):
                return match.group(0)  # "two strawberry beds south of ...": two plots
            modifier = match.groupdict().get("mod") or ""  # "10 single cabbage rows"
            return f"{words} in {match.group('n')} {modifier}{match.group('noun')}" + tail.format(
                **match.groupdict()
            )

        return rewrite

    def plot_of_many(match: re.Match[str]) -> str:
        # "a Ladyfinger block of 300": more than a scene's fields, so its plants
        if float(match.group("n").replace(",", "")) <= _MOST_FIELDS:
            return match.group(0)
        return f"{match.group(0)} plants"

    def many_plants(match: re.Match[str]) -> str:
        words = match.group("words")
        if float(match.group("n").replace(",", "")) <= _MOST_FIELDS:
            return match.group(0)
        if names_a_crop(words):
            return f"{match.group('n')} {words} plants"
        first, _, rest = words.partition(" ")
        if first.lower() in _PLANT_UNITS and rest.lower() in ("per", "each", "for"):
            return match.group(0)  # "500 vines per block": the plants of each plot
        plot = any(i.has("plot") for i in tag(rest))  # "100 apple orchards": fields
        if rest and names_a_crop(first) and not plot:  # "1,200 Valencia in one block"
            return f"{match.group('n')} {first} plants {rest}"
        return match.group(0)

    def single_row(match: re.Match[str]) -> str:
        # "a single tomato row 20 m long": the crop in one row
        if not names_a_crop(match.group("words")):
            return match.group(0)
        return f"{match.group('words')} in {match.group('one')} {match.group('noun')}"

    def same_plants(match: re.Match[str]) -> str:
        # "40 Regina cherry trees and 60 Bing": the second count is of trees too
        words = match.group("words")
        if words.split()[0].lower() in _PLANT_UNITS:
            return match.group(0)  # ("..., 500 vines per block": said with its noun)
        for said in (words, words.split()[0]):  # ("60 Bing in the next block")
            if names_a_crop(said):
                end = match.start("words") + len(said)
                return (
                    f"{match.string[match.start() : end]} {match.group('unit')}"
                    + (match.string[end : match.end()])
                )
        return match.group(0)

    def same_unit_with(match: re.Match[str]) -> str:
        # "Kordia with 8 rows, Regina with 6": the second count is of rows too
        if not names_a_crop(match.group("words")):
            return match.group(0)
        return f"{match.group(0)} {match.group('unit')}"

    def beds_then_placed(match: re.Match[str]) -> str:
        # "sonata strawbs 10 beds & albion 8 beds side by side": the beds of the crop
        # named right before them, and the fields side by side (not "two beds side by
        # side", two plots)
        if not names_a_crop(match.group("words")):
            return match.group(0)
        return f"{match.group('words')} {match.group('beds')}, "

    def beds_of_them(match: re.Match[str]) -> str:
        # "strawberry beds (10 of them, 1.5 m centres)": the crop in that many beds
        if not names_a_crop(match.group("words")):
            return match.group(0)
        return f"{match.group('words')} in {match.group('n')} {match.group('noun')} ("

    text = _CONVERTED.sub(r"\g<measure>", text)
    text = _BEDS_OF_THEM.sub(beds_of_them, text)
    text = _CROP_BEDS_SIDE_BY_SIDE.sub(beds_then_placed, text)
    text = _ELLIPTIC_WITH.sub(same_unit_with, text)
    for _ in range(8):  # ("120 Gala trees, 80 Fuji and 60 Jonagold": each in turn)
        text, before = _ELLIPTIC_PLANTS.sub(same_plants, text), text
        if text == before:
            break
    text = _ROW_TRIPLE.sub(r"\g<n> \g<rows> at \g<spacing>, rows \g<length> long", text)
    text = _PLOT_OF_MANY.sub(plot_of_many, text)
    text = _SPACING_KEY.sub("", text)
    text = _MANY_OF_A_CROP.sub(many_plants, text)
    text = _ELLIPTIC_COUNT.sub(r"\g<head> and \g<n> \g<noun> of", text)
    text = _ROWS_OF_CROP_AT.sub(crop_rows(" {tail}"), text)
    text = _SINGLE_CROP_ROW.sub(single_row, text)
    text = _COUNTED_CROP_ROWS.sub(crop_rows(""), text)
    # "west of them 30 onion beds, also 1.6 m": more beds than a scene has plots of a crop
    return _MANY_CROP_BEDS.sub(crop_rows(""), text)


#: Words after "N <crop> beds" that place them: only a larger number counts beds there
#: ("10 Sonata strawberry beds south of ..."; "two strawberry beds ..." are two plots).
_PLACED_AFTER = frozenset({"all", "north", "south", "east", "west"})
#: "8 rows x 76 cm x 30 m": the rows, their spacing and their length.
_ROW_TRIPLE = re.compile(
    r"(?<![\w.,])(?P<n>\d+)\s+(?P<rows>rows|ridges|beds)\s*[x×]\s*"
    r"(?P<spacing>\d+(?:\.\d+)?\s*(?:cm|m|in|ft))\s*[x×]\s*"
    r"(?P<length>\d+(?:\.\d+)?\s*(?:m|ft))\b"
)
#: More fields than a scene holds: a number above it before a crop counts plants.
_MOST_FIELDS = 64
#: "3.5 m x 1.0 m (row x tree)": a key saying which spacing is which, not a field.
_SPACING_KEY = re.compile(
    r"\s*\(\s*(?i:rows?|between rows|row spacing)\s*(?:x|by|×|/)\s*"
    r"(?i:trees?|plants?|vines?|in[- ]?row|in the row|within rows?)\s*\)"
)
#: "a Ladyfinger block of 300, both at 4 m by 3 m": a plot of that many plants.
_PLOT_OF_MANY = re.compile(
    r"\b(?i:block|plot|plantation|orchard|grove|vineyard|stand|patch|field|strip)\s+of\s+"
    r"(?P<n>\d{1,3}(?:,\d{3})+|\d{2,})(?=\s*(?:[,.;:)]|$))"
)
#: "150 Pink Lady in the bottom block": a count of plants named by their crop.
_MANY_OF_A_CROP = re.compile(
    r"(?<![\w.,])(?P<n>\d{1,3}(?:,\d{3})+|\d{2,})\s+"
    r"(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\b"
    r"(?!\s+(?:trees|tree|plants|plant|vines|vine|bushes|bush|stems|heads|rows|beds|ridges))"
    # ("4,000 vines/ha", "3,000 trees per hectare": a density, read as one)
    r"(?!\s*(?:/|(?i:per|an?)\s+(?i:ha|hectare|acre|m2|m²|square)))"
)
#: "12 beds of Sturon and 12 of Red Baron": the second count is of the same beds.
_ELLIPTIC_COUNT = re.compile(
    r"(?P<head>\b\d+\s+(?P<noun>rows|beds|ridges|drills)\s+of\s+[A-Za-z][\w' -]*?)\s+and\s+"
    r"(?P<n>\d+)\s+of\b"
)
#: "6 rows of peppers at 3 ft": the rows' spacing said after the crop.
_ROWS_OF_CROP_AT = re.compile(
    r"(?<![\w.,])(?P<n>\d+)\s+(?P<noun>rows|ridges|drills|beds)\s+of\s+"
    r"(?P<words>[A-Za-z][\w'’-]*(?:\s+[A-Za-z][\w'’-]*)?)\s+"
    r"(?P<tail>(?:at|on|every|spaced)\s+\d)"
)

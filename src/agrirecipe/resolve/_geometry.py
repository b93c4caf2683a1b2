"""Reading stated field geometry: rows, spacings, density, headland and row direction.

"10 rows of maize, 80 m long, 76 cm apart", "38-inch rows", "a plant every 20 cm",
"80,000 plants/ha", "two rows per bed on 1.5 m beds", "rows running east-west".
The patterns are data (``data/geometry.yaml``); this module fills their
placeholders, runs them once each over the prompt's normalised tokens (linear in
the prompt's length) and returns what each match states. The prompt reader turns
every match into one ``geometry`` item, which attaches to its field the way a
size does; :func:`row_spec` merges a field's items into a :class:`RowSpec`.
"""

from __future__ import annotations

import functools
import itertools
import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import replace
from typing import Any

import yaml

from agrirecipe._errors import PromptError
from agrirecipe.resolve._geometry_lists import counted_alike, respectively
from agrirecipe.resolve._geometry_values import (
    COUNTS,
    MINUS,
    GeometryMatch,
    Pattern,
    Tables,
    check,
    negated,
    raw_text,
    read_number,
)
from agrirecipe.resolve._intent import RowSpec
from agrirecipe.resolve._lexicon import DATA_DIR, Token, singular, tokenize, vocabulary

__all__ = [
    "GeometryMatch",
    "bearing",
    "compass_words",
    "find_geometry",
    "merge_geometry",
    "row_spec",
    "strip_geometry",
]

# How far (in words, punctuation not counted) a row word may be from "80 m long" for it
# to be the rows' length.
_NEAR_ROWS = 10


def _alternatives(words: Iterable[str]) -> str:
    """A regex alternation, longest first so "drill rows" wins over "drill"."""
    ordered = sorted({str(w) for w in words}, key=len, reverse=True)
    return "(?:" + "|".join(re.escape(w) for w in ordered) + ")"


@functools.cache
def _file() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "geometry.yaml").read_text("utf-8"))
    return data


def number_words() -> dict[str, float]:
    """Numbers said in words ("twelve", "forty"), from geometry.yaml."""
    return _tables().number_words


@functools.lru_cache(maxsize=1)
def _tables() -> Tables:
    data = _file()
    words = data["words"]
    number_words: dict[str, float] = {str(k): float(v) for k, v in words["number_words"].items()}
    # ("24 rows a quarter mile long": a fraction only before a unit of length)
    fractions: dict[str, float] = {str(k): float(v) for k, v in words["length_fractions"].items()}
    units: dict[str, float] = {str(k): float(v) for k, v in vocabulary()["length_units"].items()}
    areas: dict[str, float] = {str(k): float(v) for k, v in data["density_units"].items()}
    directions: dict[str, float] = {str(k): float(v) for k, v in words["directions"].items()}
    # a minus sign may stand before the number ("a row spacing of -75 cm": refused)
    number = rf"(?:[-−–] )?(?P<n>\d+(?:\.\d+)?|{_alternatives(number_words)})"
    number2 = number.replace("?P<n>", "?P<n2>")
    length = rf"(?:[-−–] )?(?P<n>\d+(?:\.\d+)?|{_alternatives({**number_words, **fractions})})"
    # "about 6 m", "roughly 18 inches": a length said roughly is still that length
    about = rf"(?:(?:{_alternatives(words['approximately'])}) )?"
    fill = {
        "{N2}": number2,
        "{LEN2}": rf"{about}{number2} ?(?P<unit2>{_alternatives(units)})(?! 2\b)",
        "{N}": number,
        "{LEN}": rf"{about}{length} ?(?P<unit>{_alternatives(units)})(?! 2\b)",
        "{ROWS}": _alternatives(words["rows"]),
        "{ROWMOD}": _alternatives(words["row_modifiers"]),
        "{PLANTS}": _alternatives(words["plants"]),
        "{CROP_PLANTS}": _alternatives(words["crop_plants"]),
        "{BEDS}": _alternatives(words["beds"]),
        "{PER}": _alternatives(words["per"]),
        "{AREA}": _alternatives(areas),
        "{DIR}": _alternatives(directions),
    }

    def compiled(pattern: str) -> re.Pattern[str]:
        # A pattern ends where a word ends ("\\b" fails after "°").
        source = re.sub(r"\\b$", "(?![a-z0-9])", pattern)
        for name, regex in fill.items():
            source = source.replace(name, regex)
        return re.compile(rf"(?<![\w.]){source}")

    patterns: list[Pattern] = []
    for entry in data["patterns"]:
        patterns.append(
            Pattern(
                key=str(entry["key"]),
                regex=compiled(str(entry["re"])),
                scale=float(entry.get("scale", 1.0)),
                invert=bool(entry.get("invert", False)),
                min_m=entry.get("min_m"),
                max_m=entry.get("max_m"),
                min_n=entry.get("min_n"),
                near_rows=bool(entry.get("near_rows", False)),
                max_n=entry.get("max_n"),
                key2=entry.get("key2"),
                same_unit=bool(entry.get("same_unit", False)),
                constant=entry.get("value"),
                constant2=entry.get("value2"),
                max2_m=entry.get("max2_m"),
                min2_m=entry.get("min2_m"),
                same_value=bool(entry.get("same_value", False)),
                scale2=float(entry.get("scale2", 1.0)),
            )
        )
    return Tables(
        patterns=tuple(patterns),
        number_words=number_words,
        fractions=fractions,
        units=units,
        areas=areas,
        directions=directions,
        # the nouns only: "crop rows" is near rows, "a root-crop harvester" is not
        row_words=frozenset(str(phrase).split()[-1] for phrase in (*words["rows"], *words["beds"])),
        unused=tuple(compiled(str(pattern)) for pattern in data["unused"]),
    )


def bearing(first: str, second: str) -> float | None:
    """The rows' bearing (0-180 degrees) two compass words say as a line ("east west",
    "n s"); None when they are no words of a direction or no line ("north east")."""
    directions = _tables().directions
    if first not in directions or second not in directions:
        return None
    a, b = directions[first], directions[second]
    return a % 180.0 if (a - b) % 180 == 0 and a != b else None


def compass_words() -> frozenset[str]:
    """The words for a compass direction ("north", "ne", "e")."""
    return frozenset(_tables().directions)


@functools.cache
def geometry_nouns() -> frozenset[str]:
    """The bare words for rows, beds and plants ("ridges", "rows", "trees")."""
    words = _file()["words"]
    return frozenset(str(w) for key in ("rows", "beds", "plants") for w in words[key])


_PLURAL_ROWS = re.compile(r"\b(?:one|1) (?:rows|lines|drills|beds|ridges)\b")


def find_geometry(
    tokens: Sequence[Token], unused: list[tuple[int, int]] | None = None
) -> list[GeometryMatch]:
    """Every stated geometry value in the prompt, in prompt order, never overlapping.

    Measures of things a recipe does not hold ("0.76 m bed tops", "beds 20 cm
    high", "sown 3 cm deep") are read first and are no geometry; their token
    spans (first, last + 1) are added to ``unused`` when it is given. Raises
    :class:`~agrirecipe.PromptError` for a value that cannot be a geometry
    ("0 cm apart", "nan rows").
    """
    tables = _tables()
    text_parts: list[str] = []
    starts: list[int] = []
    offset = 0
    for token in tokens:
        starts.append(offset)
        text_parts.append(token.norm)
        offset += len(token.norm) + 1
    text = " ".join(text_parts)
    word = list(itertools.accumulate(any(c.isalnum() for c in t.norm) for t in tokens))
    row_positions = [i for i, t in enumerate(tokens) if t.norm in tables.row_words]
    claimed = [False] * len(tokens)
    found: list[GeometryMatch] = []

    def token_at(char: int) -> int:
        # starts is sorted: binary search keeps the whole reading linear-logarithmic.
        low, high = 0, len(starts) - 1
        while low < high:
            mid = (low + high + 1) // 2
            if starts[mid] <= char:
                low = mid
            else:
                high = mid - 1
        return low

    for regex in tables.unused:
        for match in regex.finditer(text):
            if match.end() < len(text) and text[match.end()] not in " ":
                continue  # ended inside a token
            first = token_at(match.start())
            last = token_at(match.end() - 1) + 1
            if not any(claimed[first:last]):
                claimed[first:last] = [True] * (last - first)
                if unused is not None:
                    unused.append((first, last))
    for pattern in tables.patterns:
        for match in pattern.regex.finditer(text):
            if match.end() < len(text) and text[match.end()] not in " ":
                continue  # ended inside a token
            first = token_at(match.start())
            last = token_at(match.end() - 1) + 1
            if tokens[first].raw in MINUS and first + 1 < last and not negated(tokens, first + 1):
                first += 1  # ("Padrón - 6 beds each": a dash between words, no minus sign)
            if any(claimed[first:last]):
                continue
            if pattern.near_rows and not any(
                abs(word[position] - word[first]) <= _NEAR_ROWS for position in row_positions
            ):
                continue
            groups = match.groupdict()
            if groups.get("crop") and not _named_elsewhere(tokens, first, last, groups["crop"]):
                continue  # ("plant 40 carrots per metre": the only words naming the crop)
            if pattern.same_unit:
                groups["unit"] = groups.get("unit2")
            value = _value(pattern, groups, tables)
            if value is None:
                continue
            if pattern.key == "rows" and value == 1 and _PLURAL_ROWS.search(match.group(0)):
                continue  # "the other one rows e-w": "one" is the plot, not a count of rows
            second: float | None = None
            if pattern.key2 is not None:
                if pattern.constant2 is not None:
                    second = pattern.constant2
                elif pattern.same_value:
                    second = value
                else:
                    second = _value(
                        replace(
                            pattern,
                            key=pattern.key2,
                            min_m=pattern.min2_m,
                            max_m=pattern.max2_m,
                            min_n=None,
                            scale=pattern.scale2,
                            invert=False,
                            constant=None,
                        ),
                        {"n": groups["n2"], "unit": groups.get("unit2")},
                        tables,
                    )
                if second is None:
                    continue
                if match.groupdict().get("n2") and negated(tokens, token_at(match.start("n2"))):
                    second = -second  # "10 beds at -1.5 m bed spacing"
            raw = raw_text(tokens, first, last)
            # "-3 rows", "a row spacing of -75 cm": a minus sign on the number
            number_at = token_at(match.start("n")) if match.groupdict().get("n") else first
            if negated(tokens, number_at):
                value = -value
                if number_at == first:
                    raw = tokens[first - 1].raw + raw
            check(pattern.key, value, raw)
            found.append(GeometryMatch(pattern.key, value, first, last, raw))
            if pattern.key2 is not None and second is not None:
                check(pattern.key2, second, raw)
                found.append(GeometryMatch(pattern.key2, second, first, last, raw))
            for index in range(first, last):
                claimed[index] = True
    found.sort(key=lambda m: m.first)
    found = respectively(tokens, found, claimed, tables)
    alike = counted_alike(tokens, found, claimed, tables)
    return sorted([*found, *alike], key=lambda m: m.first) if alike else found


def _named_elsewhere(tokens: Sequence[Token], first: int, last: int, plants: str) -> bool:
    """Whether the crop of ``plants`` ("onions", "apple trees") is named outside the
    tokens ``first:last`` (as "onion strips", "the onions")."""
    word = singular(plants.split()[0])
    return any(t.norm.startswith(word) for i, t in enumerate(tokens) if not first <= i < last)


def _value(pattern: Pattern, groups: dict[str, str | None], tables: Tables) -> float | None:
    if pattern.constant is not None:
        return float(pattern.constant)
    if pattern.key == "row_bearing_deg" and groups.get("a") is not None:
        a = tables.directions[str(groups["a"])]
        if groups.get("b") is None:
            return a % 180.0  # "rows running north-east"
        b = tables.directions[str(groups["b"])]
        if (a - b) % 180 != 0:
            return None  # "north east" is one direction, not a line
        return a % 180.0
    if groups.get("twin") is not None:
        return 2.0
    value = (
        read_number(str(groups["n"]), {**tables.number_words, **tables.fractions}) * pattern.scale
    )
    if groups.get("unit") is not None:
        metres = value * tables.units[str(groups["unit"])]
        if pattern.max_m is not None and metres > pattern.max_m:
            return None
        if pattern.min_m is not None and metres < pattern.min_m:
            return None
        value = round(metres, 9)  # "35 cm" is 0.35 m, not 0.35000000000000003
    if groups.get("area") is not None:
        value = value / tables.areas[str(groups["area"])]
    if pattern.min_n is not None and value < pattern.min_n:
        return None
    if pattern.max_n is not None and value > pattern.max_n:
        return None
    if pattern.invert:
        if value <= 0 or not math.isfinite(value):
            raise PromptError(
                f"{groups['n']!r} is not a number of plants a row can hold",
                stage="resolve",
                hint="say how many plants per metre, e.g. '5 plants per metre'",
            )
        value = 1.0 / value
    if pattern.key == "row_bearing_deg":
        value = value % 180.0
    return round(value, 9) if pattern.scale != 1.0 else value


def row_spec(items: Sequence[Any], text: str) -> RowSpec | None:
    """Merge a field's geometry items into one :class:`RowSpec` (None when it states none).

    A key stated twice with different values is a :class:`~agrirecipe.PromptError`.
    """
    return merge_geometry(
        [match for i in items if i.role == "geometry" for match in i.data["geometry"]], text
    )


def _bare_apart(text: str) -> bool:
    """Whether a spacing was said only as "<length> apart" (or "<length> spacing"),
    naming neither rows nor plants."""
    words = text.lower().split()
    return bool(words) and words[-1] in ("apart", "spacing") and not set(words) & _ROW_WORDS


_ROW_WORDS = frozenset({"row", "rows", "line", "lines", "drill", "drills", "between"})


def merge_geometry(matches: Sequence[GeometryMatch], text: str) -> RowSpec | None:
    """One field's geometry matches as a :class:`RowSpec` (None when there are none)."""
    values: dict[str, float] = {}
    said: dict[str, str] = {}  # the words each value was read from
    words: list[str] = []
    for match in matches:
        previous = values.get(match.key)
        if (
            match.key == "row_spacing_m"
            and previous is not None
            and "in_row_spacing_m" not in values
            and match.value < previous
            and _bare_apart(match.text)
        ):
            # "Onions in 30 cm rows, 10 cm apart", "0.75 m rows, 0.4 m spacing": with the
            # rows spaced already, a bare "apart" is how far apart the plants stand in the row
            match = replace(match, key="in_row_spacing_m")
            previous = None
        elif (
            match.key == "row_spacing_m"
            and previous is not None
            and "in_row_spacing_m" not in values
            and match.value > previous
            and not _bare_apart(match.text)
            and _bare_apart(said[match.key])
        ):
            # "planted 6 feet apart in rows 10 feet apart": the bare "apart" said first is
            # how far apart the plants stand, once the rows' own spacing is said
            values["in_row_spacing_m"] = values.pop("row_spacing_m")
            previous = None
        if previous is not None and not math.isclose(previous, match.value, rel_tol=1e-9):
            raise PromptError(
                f"{text!r} states {match.key.replace('_', ' ')} twice ({previous:g} and "
                f"{match.value:g})",
                stage="resolve",
                hint="state each row measure once per field",
            )
        values[match.key] = match.value
        said[match.key] = match.text
        words.append(match.text)
    if not values:
        return None
    if (
        values.get("rows") == 1
        and "row_spacing_m" in values
        and "in_row_spacing_m" not in values
        and any(_bare_apart(m.text) for m in matches if m.key == "row_spacing_m")
    ):
        # "One row of 40 Bing cherry trees, 2.5 m apart": of one row, what stands apart
        # is the trees in it
        values["in_row_spacing_m"] = values.pop("row_spacing_m")
    counts = {k: int(v) for k, v in values.items() if k in COUNTS}
    plants_per_row = counts.pop("plants_per_row", None)
    lengths = {k: v for k, v in values.items() if k not in COUNTS}
    return RowSpec(**counts, **lengths, plants_per_row=plants_per_row, text="; ".join(words))


def strip_geometry(request: str) -> tuple[str, list[tuple[int, GeometryMatch]]]:
    """The request without its stated geometry, and where each match stood in it.

    For readers that cannot hold a geometry item (the llm strategy): "10 rows of
    maize, 76 cm apart" is read as "of maize," (no count of ten fields), and the
    matches are given back to the field named nearest before them.
    """
    tokens = tokenize(request)
    kept: list[str] = []
    removed: list[tuple[int, GeometryMatch]] = []
    cursor = 0
    length = 0
    for match in find_geometry(tokens):
        start, end = tokens[match.first].start, tokens[match.last - 1].end
        kept.append(request[cursor:start])
        length += start - cursor
        removed.append((length, match))
        cursor = end
    kept.append(request[cursor:])
    return "".join(kept), removed

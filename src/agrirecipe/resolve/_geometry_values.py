"""What the geometry reader finds and reads with: a match (one stated value and where it
was said), the compiled patterns and word tables of ``data/geometry.yaml``, and how a
number is read, written back and checked (:mod:`agrirecipe.resolve._geometry` runs the
patterns; :mod:`agrirecipe.resolve._geometry_lists` reads lists of values)."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass

from agrirecipe._errors import PromptError
from agrirecipe.resolve._lexicon import Token

__all__ = [
    "COUNTS",
    "MINUS",
    "GeometryMatch",
    "Pattern",
    "Tables",
    "check",
    "negated",
    "raw_text",
    "read_number",
]

# Keys whose value is a whole number.
COUNTS = frozenset({"rows", "beds", "rows_per_bed", "plant_count", "plants_per_row"})
MINUS = frozenset({"-", "−", "–"})


@dataclass(frozen=True, slots=True)
class GeometryMatch:
    """One stated geometry value and the tokens it was read from (``first``..``last`` - 1)."""

    key: str
    value: float
    first: int
    last: int
    text: str
    #: "3.4 m and 3.5 m row spacing respectively": this value's place among the values
    #: listed (index, how many, the first token of the list), each for one of the fields
    #: listed before, in order.
    share: tuple[int, int, int] | None = None


@dataclass(frozen=True, slots=True)
class Pattern:
    key: str
    regex: re.Pattern[str]
    scale: float
    invert: bool
    min_m: float | None
    max_m: float | None
    min_n: float | None
    near_rows: bool
    #: The largest count the words may say ("3 rows on 40-inch beds": rows on each bed).
    max_n: float | None = None
    #: A second value in the same words ("5 rows x 30 trees", "3.5 x 1 m spacing"),
    #: read from the groups n2 / unit2.
    key2: str | None = None
    #: The first number borrows the second's unit ("3.5 x 1 m").
    same_unit: bool = False
    #: A value the words stand for without a number ("a row of" is one row).
    constant: float | None = None
    constant2: float | None = None
    #: The longest sensible second length ("6 beds on 1.52 m centres": a bed is at most 3 m).
    max2_m: float | None = None
    min2_m: float | None = None
    #: The second value is the first ("3 m square spacing": 3 m both ways).
    same_value: bool = False
    #: What the second number is multiplied by ("30 rows at 30 in": inches to metres).
    scale2: float = 1.0


@dataclass(frozen=True, slots=True)
class Tables:
    patterns: tuple[Pattern, ...]
    number_words: dict[str, float]
    fractions: dict[str, float]
    units: dict[str, float]
    areas: dict[str, float]
    directions: dict[str, float]
    row_words: frozenset[str]
    #: Measures of things a recipe does not hold (bed tops, paths, sowing depth).
    unused: tuple[re.Pattern[str], ...] = ()


def negated(tokens: Sequence[Token], index: int) -> bool:
    """Whether a minus sign is written onto the number at ``tokens[index]`` ("-75")."""
    return (
        index > 0
        and tokens[index - 1].raw in MINUS
        and tokens[index - 1].end == tokens[index].start
    )


def raw_text(tokens: Sequence[Token], first: int, last: int) -> str:
    """The words of ``tokens[first:last]`` as written ("-75 cm", "76 cm apart")."""
    parts: list[str] = []
    for index in range(first, last):
        if index > first and tokens[index].start > tokens[index - 1].end:
            parts.append(" ")
        parts.append(tokens[index].raw)
    return "".join(parts)


def read_number(text: str, number_words: dict[str, float]) -> float:
    """The number a word or digits say ("twelve", "3.5")."""
    if text in number_words:
        return number_words[text]
    return float(text)


def check(key: str, value: float, raw: str) -> None:
    """A stated geometry must be a positive finite number (a count a whole one)."""
    if key == "row_bearing_deg" and math.isfinite(value):
        return
    if not math.isfinite(value) or value <= 0:
        raise PromptError(
            f"{raw!r}: a field's geometry needs a positive number, got {value:g}",
            stage="resolve",
            hint="give positive counts and distances, e.g. '10 rows, 76 cm apart'",
        )
    if key in COUNTS and value != int(value):
        raise PromptError(
            f"{raw!r}: {key.replace('_', ' ')} must be a whole number, got {value:g}",
            stage="resolve",
            hint="count rows, beds and plants in whole numbers",
        )

"""Casual text: texting forms read as the words they stand for ("nxt 2" -> "next to").

The forms are data (``data/casual.yaml``). :func:`expand_casual` rewrites them
once, in one pass of one regular expression (linear in the prompt's length),
before the prompt is split into words, so "b4" never becomes a count of 4
fields. The original prompt is kept for the recipe; the rewritten text is what
is read.
"""

from __future__ import annotations

import functools
import re
from typing import Any

import yaml

from agrirecipe.resolve._lexicon import DATA_DIR

__all__ = ["expand_casual"]


@functools.cache
def _forms() -> tuple[re.Pattern[str], dict[str, str]]:
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "casual.yaml").read_text("utf-8"))
    forms = {str(k).lower(): str(v) for k, v in data["forms"].items()}
    ordered = sorted(forms, key=len, reverse=True)  # "nxt 2" before "nxt"
    alternation = "|".join(re.escape(form).replace(r"\ ", r"\s+") for form in ordered)
    pattern = re.compile(rf"(?<![A-Za-z0-9])(?:{alternation})(?![A-Za-z0-9])", re.IGNORECASE)
    return pattern, forms


@functools.cache
def _lower_forms() -> tuple[re.Pattern[str], dict[str, str]]:
    data: dict[str, Any] = yaml.safe_load((DATA_DIR / "casual.yaml").read_text("utf-8"))
    forms = {str(k): str(v) for k, v in data.get("lower_forms", {}).items()}
    alternation = "|".join(re.escape(form) for form in sorted(forms, key=len, reverse=True))
    return re.compile(rf"(?<=\s)(?:{alternation})(?=\s)"), forms


def expand_casual(prompt: str) -> str:
    """``prompt`` with every texting form replaced by its words."""
    pattern, forms = _forms()

    def replace(match: re.Match[str]) -> str:
        key = re.sub(r"\s+", " ", match.group(0).lower())
        return f" {forms[key]} " if forms[key] else " "

    lower, lower_forms = _lower_forms()
    text = pattern.sub(replace, prompt)
    text = lower.sub(lambda match: lower_forms[match.group(0)], text)
    # "2 carrot fields, one nantes one chantenay": a list of members without commas
    text = _ONE_AFTER_ONE.sub(r"\g<first>, \g<second>", text)
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
    # "apples north pears south": a compass word ends one placement, the next crop begins
    text = _PLACED_AFTER_PLACED.sub(r"\g<first>, ", text)
    # "1 of them 5 ha the other 3 ha": a measure ends one member, "the other" begins the next
    return _OTHER_AFTER_MEASURE.sub(r"\g<unit>, ", text)


_NUMBERED_ITEM = re.compile(r"(?<![\w.,(])\d{1,2}\)\s+(?=[A-Za-z])")
_COMPASS = r"(?i:north|south|east|west)"
_PLACED_AFTER_PLACED = re.compile(
    rf"(?P<first>\b[A-Za-z]+\s+{_COMPASS})\s+"
    # ("west to east", "north and south", "north or south of it" are one phrase)
    rf"(?=(?!(?i:to|and|or|of|then|through|via|into|towards?)\b)[A-Za-z]+\s+{_COMPASS}\b(?!-))"
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
    r"\s+(?P<second>(?i:one|1)\b)"
)

"""Engineers' and farmers' shorthand, written out before the prompt is read (issue 8).

"one at 90 and one at 180 plants/m²" gives the unit to each value, "rows 6 m and 3 m
apart respectively" is a row spacing given out in turn, "a 2.5 m drill width x 60 m"
plot is 2.5 m wide, "all along the west side" is along it, and "can't remember how many
fields" asks for no fields. Each form is one anchored regular expression, applied once
by :func:`expand_shorthand` (from :func:`agrirecipe.resolve._casual.expand_casual`).
"""

from __future__ import annotations

import functools
import re

from agrirecipe.resolve._lexicon import plot_nouns_pattern

__all__ = ["expand_shorthand"]

#: "fruit trees all along the west side": the "all" of a side a field runs along.
_ALL_ALONG_A_SIDE = re.compile(
    r"\b(?i:all)\s+(?=(?i:along|down)\s+(?i:the|its|their)\s+"
    r"(?i:north|south|east|west)(?i:ern)?\s+(?i:side|edge|boundary|fence|hedge)\b)"
)
#: "a 2.5 m drill width x 60 m plot": the plot one drill (or planter) width wide.
_MACHINE_WIDTH = re.compile(
    r"(?<=\d)\s*(?P<unit>m|metres?|meters?|ft|feet)\s+(?i:drill|seeder|planter|sprayer|boom)\s+"
    r"(?i:widths?)\s+(?=(?:x|×|by)\s*\d)"
)
#: "rows 6 m and 3 m apart respectively": a row spacing given out to the fields in turn.
_APART_RESPECTIVELY = re.compile(
    r"\b(?i:rows)\s+(?P<a>\d[\d.]*\s*(?:m|cm|ft|in))\s+(?i:and)\s+"
    r"(?P<b>\d[\d.]*\s*(?:m|cm|ft|in))\s+(?i:apart)\s+(?=(?i:respectively)\b)"
)
#: "one at 90 and one at 180 plants/m²": a density whose unit is said only after the last.
_DENSITY_UNIT_SAID_LAST = re.compile(
    r"(?<=\b[Aa]t )(?P<a>\d[\d,.]*)(?P<mid>\s+(?i:and)\s+(?:(?i:one|the other)\s+)?(?i:at)\s+"
    r"\d[\d,.]*\s*)(?P<unit>(?i:(?:plants?|trees?|seeds?|vines?)\s*(?:/|per)\s*"
    r"(?:m²|m2|square met(?:re|er)|ha|hectare)))"
)


#: "a Chardonnay block of the same size and spacing": the same size and the same spacing.
_SAME_SIZE_AND_SPACING = re.compile(
    r"\b(?i:the\s+)?(?i:same)\s+(?i:size)\s+(?i:and)\s+(?P<what>(?i:row\s+|plant\s+)?(?i:spacing))\b"
)


#: "An orchard ... behind a field of young lettuces": behind a plot said with its article.
_BEHIND_A_PLOT = re.compile(
    r"\b(?:(?i:just|right|directly|close)\s+)?(?i:behind)\s+(?=(?i:a|an)\s+(?:[A-Za-z-]+\s+){0,2}"
    r"(?i:field|plot|block|orchard|vineyard|patch|strip|grove|bed|row)s?\b)"
)


@functools.cache
def _no_more_plots() -> re.Pattern[str]:
    """ "thats it for crops", "nothing else in the way of fields": closing words that the
    fields named are all there are, naming no plot of their own."""
    nouns = plot_nouns_pattern()
    return re.compile(
        r"\b(?P<said>(?i:that'?s|that\s+is)\s+(?i:it|all)|(?i:nothing)\s+(?i:else|more))\s+"
        rf"(?:(?i:for|in\s+the\s+way\s+of)\s+(?:(?i:the|our|my)\s+)?(?i:{nouns})s?)\b"
    )


@functools.cache
def _how_many_plots() -> re.Pattern[str]:
    """ "can't remember exactly how many fields": a question about the plots, no plots."""
    nouns = plot_nouns_pattern()
    return re.compile(rf"\b(?i:how many)\s+(?i:{nouns})s?\b")


def expand_shorthand(text: str) -> str:
    """``text`` with each shorthand form written out."""
    # "one at 90 and one at 180 plants/m²": each value with its unit
    text = _DENSITY_UNIT_SAID_LAST.sub(
        lambda m: f"{m.group('a')} {m.group('unit')}{m.group('mid')}{m.group('unit')}", text
    )
    # "rows 6 m and 3 m apart respectively": the row spacing of each in turn
    text = _APART_RESPECTIVELY.sub(r"row spacing \g<a> and \g<b> ", text)
    # "Spelt plot, 2.5 m drill width x 60 m": a plot one drill wide
    text = _MACHINE_WIDTH.sub(lambda m: f" {m.group('unit')} ", text)
    # "fruit trees all along the west side": along the west side
    text = _ALL_ALONG_A_SIDE.sub("", text)
    text = _SAME_SIZE_AND_SPACING.sub(
        lambda m: f"the same size and the same {m.group('what')}", text
    )
    text = _BEHIND_A_PLOT.sub("next to ", text)
    # "the lower field is cabbage and thats it for crops": no plot of its own
    text = _no_more_plots().sub(r"\g<said>", text)
    # "Mixed farm, can't remember exactly how many fields: ...": no fields of their own
    return _how_many_plots().sub("how many", text)

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


#: "24 in x 18 in", "24 x 18 in (row x plant)": a spacing in inches written "in", a word
#: read as the preposition unless a mark or the other inch value follows it.
_INCHES_BY_INCHES = re.compile(
    r"\b(?P<a>\d+(?:\.\d+)?)\s*(?:(?i:in)\s*)?(?P<by>x|×|(?i:by))\s*(?P<b>\d+(?:\.\d+)?)\s*"
    r"(?i:in)(?=\s*(?:[,;.(]|$))"
    r"|\b(?P<c>\d+(?:\.\d+)?)\s*(?i:in)\s*(?P<by2>x|×|(?i:by))\s*(?P<d>\d+(?:\.\d+)?)\s*(?i:in)\b"
)

#: "three 1.5 m beds next to each other: lettuce, onions and carrots": the members
#: listed, then said to lie side by side (a relation word before the colon would end the
#: heading before its list).
_SIDE_BY_SIDE_THEN_LISTED = re.compile(
    r"(?P<head>\b(?i:two|three|four|five|six|seven|eight|\d+)\s+[^,:;.()]{0,40}?"
    r"(?i:beds|plots|blocks|fields|strips|parcels|paddocks))\s+"
    r"(?P<rel>(?i:next\s+to\s+each\s+other|side\s+by\s+side|beside\s+each\s+other|"
    r"alongside\s+each\s+other))\s*:\s*"
    # (the list to its last member, said after "and")
    # (past a decimal point: "Ladyfinger at 2.5 x 2.5 m")
    r"(?P<list>(?:[^.;:!?]|(?<=\d)\.(?=\d))+?\s(?:(?i:and)|&)\s+"
    # (not when the last member's own measures follow: "..., and Pinot Noir, 10 rows")
    r"(?:[^,.;:!?()]|(?<=\d)\.(?=\d))++(?:\([^()]*\))?)"
    r"(?=\s*(?:\.(?!\d)|[;!?]|$|,\s*[^\d\s(]))"
)

#: "The two plots touch, only a narrow path between": the verb (not "a touch of frost").
_THEY_TOUCH = re.compile(
    r"\b(?P<who>(?i:the\s+(?:two|both)\s+[A-Za-z]+|both\s+(?:of\s+them|[A-Za-z]+)|they))\s+"
    r"(?i:touch|meet|adjoin)\b(?!\s+(?i:of)\b)"
)

#: "yellow blotches with white down under them": down (fluff) under the leaves, not
#: "down under" (Australia).
_DOWN_UNDER_A_THING = re.compile(
    r"\b(?i:down)\s+(?i:under)(?=\s+(?i:them|it|the|their|its|each|every|most|all)\b)"
)

#: "The experimental farm, as I caught it: ...": the photographer catching the scene, not
#: a field catching a disease ("the potatoes caught it too").
_I_CAUGHT_IT = re.compile(r"\b(?P<who>I|(?i:we))\s+(?i:caught)\s+(?=(?i:it|this|them)\b)")

#: "three 1.5 m beds next to each other, one each of lettuce, onions and carrots": the
#: members of the count, listed as after a colon.
_ONE_EACH_OF = re.compile(r"\s*[,;]\s*(?i:one)\s+(?i:each)\s+(?i:of|for)\s+")

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
def _plot_placed_then_planted() -> re.Pattern[str]:
    """ "The orchard on the south side of the farm has apple trees": a plot of no crop,
    placed on a side of the farm, then said to hold its crop."""
    nouns = plot_nouns_pattern()
    return re.compile(
        r"(?:^|(?<=[.!?;:]\s))(?P<plot>(?i:the|our|my)\s+(?:[A-Za-z-]+\s+){0,2}?"
        rf"(?i:{nouns}))\s+"
        r"(?P<place>(?i:on|in|at|along|across)\s+(?i:the)\s+(?i:(?:far\s+)?"
        r"(?:north|south|east|west|top|bottom|upper|lower)(?:ern)?)"
        r"(?:\s+(?i:side|end|part|corner|half|edge))?"
        r"(?:\s+(?i:of)\s+(?i:the|our|my)\s+(?i:farm|property|place|holding))?)\s+"
        r"(?=(?i:has|have|holds|grows|is\s+planted\s+with|is\s+down\s+to)\b)"
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
    # "three beds, one each of lettuce, onions and carrots": three beds: lettuce, ...
    text = _ONE_EACH_OF.sub(": ", text)
    text = _SIDE_BY_SIDE_THEN_LISTED.sub(r"\g<head>: \g<list>, \g<rel>", text)
    # "The two plots touch": they are next to each other
    text = _THEY_TOUCH.sub(r"\g<who> are next to each other", text)
    # "as I caught it": as I saw it
    text = _I_CAUGHT_IT.sub(r"\g<who> saw ", text)
    # "white down under them": the fluff beneath the leaves
    text = _DOWN_UNDER_A_THING.sub("down beneath", text)
    # "cabbages at 24 in x 18 in": 24 x 18 inches
    text = _INCHES_BY_INCHES.sub(
        lambda m: (
            f"{m.group('a') or m.group('c')} {m.group('by') or m.group('by2')} "
            f"{m.group('b') or m.group('d')} inches"
        ),
        text,
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
    # "The orchard on the south side of the farm has apple trees": placed, then planted
    text = _plot_placed_then_planted().sub(r"\g<place>, \g<plot> ", text)
    # "the lower field is cabbage and thats it for crops": no plot of its own
    text = _no_more_plots().sub(r"\g<said>", text)
    # "Mixed farm, can't remember exactly how many fields: ...": no fields of their own
    return _how_many_plots().sub("how many", text)

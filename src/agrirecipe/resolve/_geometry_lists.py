"""Values of one measure listed together: "3.4 m and 3.5 m row spacing respectively",
"60,000, 80,000 and 100,000 plants/ha" (one for each field listed before them, in order)
and "four beds of lettuce, four of onions" (a bare count after a count of beds counts
beds too). :func:`agrirecipe.resolve._geometry.find_geometry` asks these after its
patterns ran."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from agrirecipe.resolve._geometry_values import GeometryMatch, Tables, check, raw_text, read_number
from agrirecipe.resolve._lexicon import Token

__all__ = ["counted_alike", "respectively"]

#: Counts of rows or beds that the counts listed after them repeat ("four beds of
#: lettuce, four of onions").
_ALIKE_KEYS = frozenset({"rows", "beds"})
_OF_THOSE = frozenset({"them", "those", "these", "which", "it", "the", "each"})
#: How many words of a crop's name may stand between "of" and the next member.
_NAME_WORDS = 4


def counted_alike(
    tokens: Sequence[Token], found: Sequence[GeometryMatch], claimed: list[bool], tables: Tables
) -> list[GeometryMatch]:
    """'four beds of lettuce, four of onions, four of carrots', '10 rows of maize and 12
    of soybean': a bare count "of" a crop listed after a count of rows or beds "of" a
    crop counts the same thing (not fields)."""
    alike: list[GeometryMatch] = []
    for match in found:
        if match.key not in _ALIKE_KEYS or match.share is not None:
            continue
        cursor = match.last
        while cursor < len(tokens) and tokens[cursor].norm == "of":
            join = next(
                (
                    at
                    for at in range(cursor + 2, min(cursor + 2 + _NAME_WORDS, len(tokens)))
                    if tokens[at].norm in _LIST_JOINS or claimed[at]
                ),
                None,
            )
            if join is None or claimed[join] or join + 3 > len(tokens):
                break
            number_at = join + 1
            if (
                claimed[number_at]
                or tokens[number_at + 1].norm != "of"
                # (not "10 rows of maize and 2 of them weedy": some of the rows said)
                or (number_at + 2 < len(tokens) and tokens[number_at + 2].norm in _OF_THOSE)
            ):
                break
            try:
                value = read_number(tokens[number_at].norm, tables.number_words)
            except ValueError:
                break
            raw = raw_text(tokens, number_at, number_at + 1)
            check(match.key, value, raw)
            alike.append(GeometryMatch(match.key, value, number_at, number_at + 1, raw))
            claimed[number_at] = True
            cursor = number_at + 1
    return alike


#: Words that join the values of a "respectively" list ("3.4 m and 3.5 m", "36, 40").
_LIST_JOINS = frozenset({"and", ",", "&"})


def _listed_after(
    tokens: Sequence[Token], match: GeometryMatch, claimed: list[bool], tables: Tables
) -> list[GeometryMatch]:
    """The values listed after a measure up to "respectively" ("rows 15 cm and 76 cm
    respectively"), each read as that measure; [] when no "respectively" ends them."""
    unit = next((t.norm for t in tokens[match.first : match.last] if t.norm in tables.units), None)
    listed: list[GeometryMatch] = []
    cursor = match.last
    while cursor + 1 < len(tokens) and tokens[cursor].norm in _LIST_JOINS:
        number_at = cursor + 1
        try:
            number = read_number(tokens[number_at].norm, tables.number_words)
        except ValueError:
            return []
        end = number_at + 1
        said_unit = unit
        if end < len(tokens) and tokens[end].norm in tables.units:
            said_unit, end = tokens[end].norm, end + 1
        if any(claimed[number_at:end]) or (unit is None) != (said_unit is None):
            return []
        value = round(number * (tables.units[said_unit] if said_unit else 1.0), 9)
        listed.append(
            GeometryMatch(match.key, value, number_at, end, raw_text(tokens, number_at, end))
        )
        cursor = end
    if not listed or cursor >= len(tokens) or tokens[cursor].norm != "respectively":
        return []
    for value_match in listed:  # (only a list "respectively" ends is that measure)
        check(match.key, value_match.value, value_match.text)
    last = listed[-1]
    listed[-1] = replace(last, last=cursor + 1, text=raw_text(tokens, last.first, cursor + 1))
    return listed


def respectively(
    tokens: Sequence[Token],
    found: list[GeometryMatch],
    claimed: list[bool],
    tables: Tables,
) -> list[GeometryMatch]:
    """'3.4 m and 3.5 m row spacing respectively', '36 and 40 rows respectively': the
    values listed before a measure that "respectively" follows are the same measure,
    one for each field listed before them, in order (the reader gives them out)."""
    result: list[GeometryMatch] = []
    for match in found:
        ends = match.last < len(tokens) and tokens[match.last].norm == "respectively"
        if match.share is None and not ends:
            after = _listed_after(tokens, match, claimed, tables)
            if after:  # "rows 15 cm and 76 cm respectively"
                count, start = len(after) + 1, match.first
                result.append(replace(match, share=(0, count, start)))
                result.extend(
                    replace(value, share=(index + 1, count, start))
                    for index, value in enumerate(after)
                )
                continue
        if match.share is not None:
            result.append(match)
            continue
        listed = _listed_before(tokens, match, claimed, tables)
        # "60,000, 80,000 and 100,000 plants/ha": three or more values listed with commas
        # share the measure out like "respectively" does
        listing = (
            len(listed) >= 2
            and any(tokens[m.last].norm == "," for m in listed)
            and (listed[0].first == 0 or tokens[listed[0].first - 1].norm not in _RANGE_WORDS)
        )
        if not listed or not (ends or listing):
            result.append(match)
            continue
        for listed_match in listed:
            check(match.key, listed_match.value, listed_match.text)
        count, start = len(listed) + 1, listed[0].first
        for index, listed_match in enumerate(listed):
            result.append(replace(listed_match, share=(index, count, start)))
        last = match.last + 1 if ends else match.last  # "respectively" is read with it
        result.append(
            replace(
                match,
                last=last,
                text=raw_text(tokens, match.first, last),
                share=(count - 1, count, start),
            )
        )
    result.sort(key=lambda m: m.first)
    return result


#: Words before two values that make them a range, not a list ("between 3 and 4 m").
_RANGE_WORDS = frozenset({"between", "from"})


def _listed_before(
    tokens: Sequence[Token], match: GeometryMatch, claimed: list[bool], tables: Tables
) -> list[GeometryMatch]:
    """The values listed right before a measure ("3.4 m and" / "36, 40 and"), each read
    as that measure (unchecked), in order."""
    unit = next((t.norm for t in tokens[match.first : match.last] if t.norm in tables.units), None)
    listed: list[GeometryMatch] = []
    cursor = match.first
    while cursor >= 2 and tokens[cursor - 1].norm in _LIST_JOINS:
        # "3.4 m and", "3.4 and" (the unit of the measure), "36 and" (a count)
        has_unit = tokens[cursor - 2].norm in tables.units and unit is not None
        number_at = cursor - 3 if has_unit else cursor - 2
        if number_at < 0 or any(claimed[number_at : cursor - 1]):
            break
        try:
            number = read_number(tokens[number_at].norm, tables.number_words)
        except ValueError:
            break
        scale = tables.units[tokens[cursor - 2].norm if has_unit else unit] if unit else 1.0
        raw = raw_text(tokens, number_at, cursor - 1)
        value = round(number * scale, 9)
        listed.insert(0, GeometryMatch(match.key, value, number_at, cursor - 1, raw))
        cursor = number_at
    return listed

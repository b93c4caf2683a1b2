"""How a clause points at members of a counted plural (issue 8).

"four fields, two of them blighted" (a count of them: :func:`counted_reference`),
"..., one at 9 plants/m2 and one at 7 plants/m2, the denser plot to the east" (a member
said already, named again by its place or a measure: :func:`member_said_again`),
"Three potato fields in a line. The middle one has blight" (a member by its place:
:func:`place_said`), "..., 12 rows per plot" (a measure of every plot: :func:`per_plot`)
and "..., plots laid out east to west" (the plots named again: :func:`plots_again`).
:func:`agrirecipe.resolve._refinements.apply_refinements` asks these while it folds the
members into their plural.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._geometry import bearing, compass_words
from agrirecipe.resolve._lexicon import Item, vocabulary
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import with_plot_noun

__all__ = [
    "BACK_POINTERS",
    "counted_reference",
    "member_said_again",
    "per_plot",
    "place_said",
    "plots_again",
    "said_per_plot",
]

#: Words after "<number> of" that point back at the plural ("two of them").
BACK_POINTERS = frozenset({"them", "which", "these", "those", "the fields", "the plots"})

#: Where a reference by place points among the members ("the second one").
_PLACES = {
    **{
        f"{the}{word}{one}": at
        for at, word in enumerate(("first", "second", "third", "fourth"))
        for the in ("", "the ")
        for one in ("", " one")
    },
}
_MIDDLE = frozenset({"the middle one", "the centre one", "the center one", "the central one"})
_LAST = frozenset({"the last", "the last one", "last", "last one"})


def place_said(first: Item | None, parent: Mention) -> int | None:
    """The member (0-based) a reference said by its place points at ("the second one",
    "the middle one" of three, "the last one"), once the count is known; else None."""
    count = parent.count
    if first is None or first.role != "reference" or count is None or count < 2:
        return None
    if first.norm in _MIDDLE:
        return count // 2 if count % 2 else None
    at = count - 1 if first.norm in _LAST else _PLACES.get(first.norm)
    if at is None or at >= count:
        return None
    if at < len(parent.refinements) and not parent.refinements[at].unsaid:
        return None  # (already said: "the first ..., the second ..." in order)
    return at


def plots_again(mention: Mention) -> bool:
    """A plural plot word of no crop and no count ("plots laid out east to west")."""
    return (
        not mention.has_crop
        and mention.category is None
        and mention.plot is not None
        and bool(mention.plot["plural"])
        and (mention.count is None or mention.implied_count)
    )


def said_per_plot(items: Sequence[Item]) -> bool:
    """Whether the items (in order) say "per" right before a plot word ("8 rows per block")."""
    return any(a.norm == "per" and b.role == "plot" for a, b in itertools.pairwise(items))


def per_plot(mention: Mention) -> bool:
    """A measure said of every plot ("12 rows per plot"), read as a plot of no crop."""
    words = sorted(mention.items, key=lambda i: i.start)
    return (
        not mention.has_crop
        and mention.category is None
        and said_per_plot(words)
        and any(i.role == "geometry" for i in words)
    )


def counted_reference(items: Sequence[Item]) -> int | None:
    """The count of "<number> of them" / "two of which" opening a clause, else None."""
    words = [i for i in items if i.norm != "the"]
    if len(words) < 3 or words[0].role != "number" or words[1].role != "of":
        return None
    if words[2].norm not in BACK_POINTERS:
        return None
    value = float(words[0].data.get("value", 0))
    if value != int(value) or value < 1:
        return None
    return int(value)


def _measure(member: Mention, key: str) -> float | None:
    """The measure ``key`` a member states: a geometry key ("plants_per_ha", the density
    also from both spacings), or "area_m2" from its size; None when it states none."""
    values: dict[str, float] = {}
    for item in member.items:
        if item.role == "geometry":
            values.update((m.key, m.value) for m in item.data["geometry"])
        elif item.role == "size":
            size = item.data["size"]
            area = size.area_m2 or (
                size.width_m * size.length_m if size.width_m and size.length_m else None
            )
            if area:
                values["area_m2"] = area
    if "plants_per_ha" not in values and {"row_spacing_m", "in_row_spacing_m"} <= set(values):
        values["plants_per_ha"] = 10_000.0 / (values["row_spacing_m"] * values["in_row_spacing_m"])
    return values.get(key)


def _by_comparative(words: Sequence[Item], members: Sequence[Mention]) -> Mention | None:
    """The member "the denser plot" points at: the one whose measure is the most (or the
    least) of all the members' (``member_comparatives`` in vocabulary.yaml)."""
    said = vocabulary()["member_comparatives"]
    comparative = next((w.norm for w in words if w.norm in said), None)
    if comparative is None:
        return None
    key, most = str(said[comparative]["measure"]), bool(said[comparative]["most"])
    values = [_measure(m, key) for m in members]
    if any(v is None for v in values) or len(set(values)) != len(values):
        return None
    measured = [v for v in values if v is not None]
    at = measured.index(max(measured) if most else min(measured))
    return members[at]


def _by_value(words: Sequence[Item], members: Sequence[Mention]) -> Mention | None:
    """The member "the 9 plants/m2 plot" (or "the 7", its number alone) points at: the one
    member whose own measure is said with the same words or number."""
    said = [w for w in words if w.role in ("geometry", "number") and w.norm not in ("a", "an")]
    if len(said) != 1:
        return None
    word = said[0]

    def states(member: Mention) -> bool:
        for item in member.items:
            if item.role != "geometry":
                continue
            if word.role == "geometry" and item.norm == word.norm:
                return True
            if word.role == "number" and item.norm.split()[0] == word.norm:
                return True
        return False

    found = [m for m in members if states(m)]
    return found[0] if len(found) == 1 else None


def _by_look(words: Sequence[Item], members: Sequence[Mention]) -> Mention | None:
    """The member "the blighted plot" (or "the healthy one") points at: the one member
    said to look so (the same health or stage), when the others are not."""
    said = [(w.role, w.data.get("value")) for w in words if w.role in ("health", "stage")]
    if len(said) != 1 or said[0][1] is None:
        return None
    role, value = said[0]
    found = [
        m for m in members if any(i.role == role and i.data.get("value") == value for i in m.items)
    ]
    return found[0] if len(found) == 1 else None


#: Words before a plot noun that say which member of a list it is ("the middle strip").
_PLACE_WORDS = {"first": 0, "second": 1, "third": 2, "fourth": 3}
_MIDDLE_WORDS = frozenset({"middle", "centre", "center", "central"})


def _by_place_word(clause: Clause, mention: Mention, members: int) -> int | None:
    """The member (0-based) that "the middle strip" or "the second plot" in ``clause``
    points at, among ``members`` listed in order; None when the plot is not said so."""
    items = sorted(clause.items, key=lambda i: i.start)
    heads = [at for at, i in enumerate(items) if i in mention.heads and i.role == "plot"]
    if len(heads) != 1 or heads[0] < 2 or items[heads[0] - 2].norm != "the":
        return None
    word = items[heads[0] - 1].norm
    if word in _MIDDLE_WORDS:
        return members // 2 if members % 2 else None
    if word == "last":
        return members - 1
    at = _PLACE_WORDS.get(word)
    return at if at is not None and at < members else None


def member_said_again(clause: Clause, parent: Mention) -> Mention | None:
    """The member of ``parent``'s full list that ``clause`` names again by a measure
    ("the denser plot", "the 9 plants/m2 plot", "the 7") or by its place ("the first
    one"), when the clause says nothing else that names a field; else None."""
    members = list({id(r): r for r in parent.refinements}.values())
    if parent.count is None or parent.count < 2 or len(members) != parent.count:
        return None
    if any(m.unsaid for m in members):
        return None
    mention = clause.mentions[0] if len(clause.mentions) == 1 else None
    if len(clause.mentions) > 1 or (
        mention is not None
        and (
            mention.has_crop
            or mention.category is not None
            or mention.count is not None
            or mention.plot is None
            or bool(mention.plot["plural"])
        )
    ):
        return None
    words = [
        i
        for i in clause.items
        if i.role not in ("separator", "filler", "plot") and i.norm not in ("one", "ones")
    ]
    if mention is not None and not words and all(i.role == "plot" for i in clause.items):
        # "Two plots ...: an orchard ... and a vegetable field ..., orchard east of the
        # veg": the full list's one member of that plot noun, named bare
        noun = mention.plot["noun"] if mention.plot is not None else None
        same = with_plot_noun(members, noun)
        if noun is not None and len(same) == 1 and same[0].plot is not None:
            return same[0] if same[0].plot["options"] else None
    if mention is not None and (at := _by_place_word(clause, mention, len(members))) is not None:
        # "..., with a man hoeing the middle strip": the member in that place of the list
        return members[at]
    # ("put the blighted plot south of ...": a verb of the request before it)
    leading = itertools.takewhile(lambda i: i.role == "filler", clause.items)
    pointed = any(i.norm in ("the", "that", "this") for i in leading)
    if not pointed and not (words and words[0].role == "reference"):
        return None
    if words and words[0].role == "reference":
        if clause.link is not None and clause.link.role == "relation":
            return None  # ("Plot 2, south of the first: ...": read where relations are)
        at = _PLACES.get(words[0].norm)
        if words[0].norm in _LAST:
            at = len(members) - 1
        if words[0].norm in _MIDDLE and len(members) % 2:
            at = len(members) // 2
        return members[at] if at is not None and at < len(members) and len(words) == 1 else None
    fillers = [i for i in clause.items if i.role == "filler"]
    return (
        _by_comparative(fillers, members)
        or _by_look(words, members)
        or _by_value(words, members)
        or _by_measure(clause.items, members)
        or _by_direction(clause.items, members)
    )


def _by_direction(words: Sequence[Item], members: Sequence[Mention]) -> Mention | None:
    """The member "the E-W one" (or "the north-south one") points at: the one member whose
    rows run that way ("one with rows east-west")."""
    compass = [w.norm for w in words if w.norm in compass_words()]
    if len(compass) != 2 or (said := bearing(*compass)) is None:
        return None
    found = [m for m in members if _measure(m, "row_bearing_deg") == said]
    return found[0] if len(found) == 1 else None


def _by_measure(items: Sequence[Item], members: Sequence[Mention]) -> Mention | None:
    """The member "the 25 cm plot" points at: the one member whose own measure says the
    same length ("drilled at 25 cm")."""
    said = [
        f"{number.norm} {unit.norm}"
        for number, unit in itertools.pairwise(items)
        if number.data.get("measure") and unit.role == "length_unit"
    ]
    if len(said) != 1:
        return None
    found = [
        m
        for m in members
        if any(i.role == "geometry" and f" {said[0]}" in f" {i.norm}" for i in m.items)
    ]
    return found[0] if len(found) == 1 else None

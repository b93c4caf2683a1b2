"""How a clause points at members of a counted plural (issue 8).

"four fields, two of them blighted" (a count of them: :func:`counted_reference`),
"Three potato fields in a line. The middle one has blight" (a member by its place:
:func:`place_said`), "..., 12 rows per plot" (a measure of every plot: :func:`per_plot`)
and "..., plots laid out east to west" (the plots named again: :func:`plots_again`).
:func:`agrirecipe.resolve._refinements.apply_refinements` asks these while it folds the
members into their plural.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._decompose import Mention
from agrirecipe.resolve._lexicon import Item

__all__ = [
    "BACK_POINTERS",
    "counted_reference",
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

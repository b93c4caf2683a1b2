"""A crop named alone, then the plots it is grown in counted (issue 8).

"lettuce!! lots of it. 2 fields, like 50 by 20 m each", "carrots. three plots of them":
when a prompt names one crop and, after it, only counts plots of no crop, the count is
of that crop's fields, not of as many fields of other crops. :func:`count_the_crop`
lends the crop to the counted plots, which keep what is said after them.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import strong_crops

__all__ = ["count_the_crop"]


def count_the_crop(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """The fields left once plots counted after the only crop named take its crop."""
    if len(mentions) != 2:
        return mentions
    crop, plots = mentions
    crops = strong_crops(crop)
    options = set(plots.plot["options"]) if plots.plot is not None else set()
    if (
        not crops
        or crop.count is not None
        or crop.refinements
        or crop.clause >= plots.clause
        or plots.has_crop
        or plots.category is not None
        or plots.plot is None
        or (plots.count or 1) < 2
        or plots.refinements
        or (options and not crops & options)
    ):
        return mentions
    names = [h for h in crop.heads if h.role == "head"]
    plots.heads.extend(names)
    plots.items.extend(i for i in crop.items if i not in plots.items)
    plots.interpretations = crop.interpretations
    clauses[crop.clause].mentions = [m for m in clauses[crop.clause].mentions if m is not crop]
    return [plots]

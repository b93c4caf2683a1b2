"""A comparison said as a heading: "Bell pepper vs jalapeño comparison for the harvest
gripper: two plots ... California Wonder on the west plot, Jalapeños on the east one"
(issue 8).

Crops or varieties set against each other ("vs", "versus") before a colon name what the
plots after it compare; when those plots list as many members (or as many fields are
named after it), each of a crop or variety the heading named, the heading is no field of
its own: :func:`drop_compared_headings`
drops it (the members say their own crops).
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._links import link_norm
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import same_variety, strong_crops

__all__ = ["drop_compared_headings"]

#: The words that set one crop against another in a heading.
_VERSUS = frozenset({"vs", "v", "versus", "against", "compared with", "compared to"})


def drop_compared_headings(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """The fields left once a comparison heading before a colon is dropped."""
    for position, colon in enumerate(clauses):
        if link_norm(colon) != ":":
            continue
        heading = [m for c in clauses[:position] for m in c.mentions]
        joined = [c.link for c in clauses[1:position] if c.link is not None]
        if len(heading) < 2 or not any(link.norm in _VERSUS for link in joined):
            continue
        plots = [m for m in mentions if m.clause >= position and m.refinements]
        after = [m for m in mentions if m.clause >= position]
        if len(plots) == 1 and len({id(r) for r in plots[0].refinements}) == len(heading):
            members = list({id(r): r for r in plots[0].refinements}.values())
        elif not plots and len(after) == len(heading):
            # "Cherry vs cherry-tomato confusion test: a Lapins cherry block ..., and beside
            # it 4 rows of cherry tomatoes": the fields compared, each named after the colon
            members = after
        else:
            continue
        if not all(
            any(same_variety(h, m) or strong_crops(h) == strong_crops(m) for h in heading)
            for m in members
        ):
            continue
        for mention in heading:
            clause = clauses[mention.clause]
            clause.mentions = [m for m in clause.mentions if m is not mention]
        return [m for m in mentions if not any(m is h for h in heading)]
    return mentions

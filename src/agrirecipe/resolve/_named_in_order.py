"""Fields counted first, then named again one by one in the order they lie (issue 8).

"Two vegetable plots and one fruit plot, ..., laid out north to south as veg, fruit, veg":
the list after the order names the three fields already counted, each once, so "veg"
said twice is each of the two vegetable plots in turn, not a third one.
:func:`name_counted_in_order` makes the counted plural's members of the list's words
and points the rest of the list at the single fields named before.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import strong_crops

__all__ = ["name_counted_in_order"]


def _kind(mention: Mention) -> tuple[frozenset[str], str | None]:
    """What a field is named as: its crops, or its category when it names none."""
    crops = frozenset(strong_crops(mention))
    return (crops, None) if crops else (crops, mention.category)


def _bare(clause: Clause) -> Mention | None:
    """The one mention of a clause that only names a crop or category again ("veg")."""
    if len(clause.mentions) != 1:
        return None
    mention = clause.mentions[0]
    if mention.count is not None or mention.plot is not None or mention.refinements:
        return None
    if not (mention.has_crop or mention.category is not None):
        return None
    return mention if all(i in mention.heads or i.role == "filler" for i in mention.items) else None


def _lists(clauses: Sequence[Clause]) -> list[list[Clause]]:
    """Runs of two or more clauses in a row that each only name a field again."""
    runs: list[list[Clause]] = []
    run: list[Clause] = []
    for clause in clauses:
        if _bare(clause) is not None and (
            not run
            or (clause.link is not None and clause.link.role in ("separator", "conjunction"))
        ):
            run.append(clause)
            continue
        if len(run) >= 2:
            runs.append(run)
        run = [clause] if _bare(clause) is not None else []
    if len(run) >= 2:
        runs.append(run)
    return runs


def name_counted_in_order(clauses: Sequence[Clause], mentions: Sequence[Mention]) -> list[Mention]:
    """The fields left once a list naming the counted fields again, in order, is read as
    those fields (see the module's words)."""
    kept = list(mentions)
    for run in _lists(clauses):
        listed = [c.mentions[0] for c in run]
        before = [m for m in kept if m.clause < run[0].index and m not in listed]
        counted = [m for m in before if (m.count or 1) >= 2 and not m.refinements]
        if not counted or any(m.refinements for m in before):
            continue
        wanted = Counter({_kind(m): 0 for m in before})
        for m in before:
            wanted[_kind(m)] += m.count or 1
        if Counter(_kind(m) for m in listed) != wanted or len(set(map(_kind, before))) != len(
            before
        ):
            continue  # (each earlier field a kind of its own, named again as often as counted)
        owner = {_kind(m): m for m in before}
        for clause, mention in zip(run, listed, strict=True):
            field = owner[_kind(mention)]
            kept.remove(mention)
            if (field.count or 1) >= 2:
                field.refinements.append(mention)
                mention.is_refinement = True
                clause.mentions = []
                clause.refinement, clause.refined_parent = mention, field
            else:
                field.items.extend(i for i in mention.items if i not in mention.heads)
                clause.mentions = [field]
    return kept

"""A field said to be "too" what the one before it is (issue 8).

"lettuce bolting lol forgot to harvest, the cabbages too", "the wheat has rust, the
barley as well": a clause that names one field and only adds "too" (``likewise`` in
``reader_words``) takes the stage, health and cue words of the field named right before
it. :func:`share_likewise` lends them.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import reader_words
from agrirecipe.resolve._mentions import Clause
from agrirecipe.resolve._structure import attribute_of

__all__ = ["share_likewise"]

#: What a field said "too" takes from the one before it.
_LENT = ("stage", "health", "cue")


def share_likewise(clauses: Sequence[Clause]) -> None:
    """Lend the stage, health and cue words of a field to the next clause's one field
    that is said to be so "too" and says none of its own."""
    likewise = reader_words("likewise")
    for position in range(1, len(clauses)):
        clause = clauses[position]
        said_after = (
            # ("a field of Sturon beyond the ditch in the same state": said after the
            # scenery that places it)
            not clause.mentions
            and clause.link is not None
            and clause.link.role in ("relation", "trailer")
            and len(clauses[position - 1].mentions) == 1
        )
        if said_after:
            clause = clauses[position - 1]
        # the field before: the last one named before it, with the words said of it in
        # the head-less clauses after it ("..., tops flat, ready to lift, and a field of")
        lender_at = (
            next((k for k in range(clause.index - 1, -1, -1) if clauses[k].mentions), None)
            if said_after
            else (position - 1 if clauses[position - 1].mentions else None)
        )
        if lender_at is None:
            continue
        previous = clauses[lender_at]
        described = (
            [i for c in clauses[lender_at + 1 : clause.index] for i in c.items]
            if said_after
            else []
        )
        if len(clause.mentions) != 1 or not clause.items:
            continue
        words = [i for i in clauses[position].items if i.role != "separator"]
        following = clauses[position + 1] if position + 1 < len(clauses) else None
        # ("the carrots also": "also" read as the link of an empty clause after it)
        trailing = (
            not said_after
            and following is not None
            and following.link is not None
            and following.link.norm in likewise
            and not following.items
        )
        ends = {" ".join(i.norm for i in words[-n:]) for n in range(1, 5) if len(words) >= n}
        if not (trailing or ends & set(likewise)):
            continue
        mention = clause.mentions[0]
        if not mention.has_crop or any(attribute_of(i) in _LENT for i in mention.items):
            continue
        lent = [i for i in (*previous.mentions[-1].items, *described) if i.role in _LENT]
        mention.items.extend(lent)
        mention.borrowed.extend(lent)

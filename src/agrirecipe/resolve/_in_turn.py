"""Looks said in turn of fields named one by one (issue 8).

"wheat and maize, one sick and one healthy", "tbh just wheat & more wheat, 2 fields, 1
sick 1 healthy": after fields named each on its own (no count of them to refine), a run of
clauses that each open with "one" and say a look gives each field, in the order named,
the look of its clause; so does a run of clauses that each say one size ("roma toms north
of cayenne chillies, 20x40m & 30x40m"). :func:`say_in_turn` hands the words over before
the head-less clauses' words are attached elsewhere.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._fields import ATTRIBUTE_ROLES
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._measures import sentence_start
from agrirecipe.resolve._mentions import Clause, Mention

__all__ = ["say_in_turn"]


def _one_said(clause: Clause) -> list[Item] | None:
    """The attributes of a clause of no field that opens with "one" and says how it looks
    ("one sick"; "one fine": none, a word of no attribute), else None."""
    words = [i for i in clause.loose if i.role != "separator"]
    if clause.mentions or len(words) < 2 or words[0].role != "number":
        return None
    if words[0].data.get("value") != 1 or words[0].norm in ("a", "an"):
        return None
    said = [i for i in words[1:] if i.role not in ("filler", "of")]
    return said if all(i.role in ATTRIBUTE_ROLES and i.role != "all" for i in said) else None


def _size_said(clause: Clause) -> list[Item] | None:
    """The size of a clause of no field that says one size and nothing else ("20x40m")."""
    words = [i for i in clause.loose if i.role not in ("separator", "filler")]
    if clause.mentions or len(words) != 1 or words[0].role != "size":
        return None
    return words


def _counted_again(clause: Clause, fields: int) -> bool:
    """A clause of no field that only counts the fields again ("2 fields")."""
    return not clause.mentions and any(
        i.norm.isdigit() and int(i.norm) == fields for i in clause.loose
    )


def say_in_turn(clauses: Sequence[Clause]) -> None:
    """Give each of the fields named one by one the look its "one ..." clause says."""
    position = 0
    while position < len(clauses):
        said_by = next(
            (reader for reader in (_one_said, _size_said) if reader(clauses[position]) is not None),
            None,
        )
        if said_by is None:
            position += 1
            continue
        run = [position]
        while run[-1] + 1 < len(clauses) and said_by(clauses[run[-1] + 1]) is not None:
            run.append(run[-1] + 1)
        fields: list[Mention] = [
            m for c in clauses[sentence_start(clauses, position) : position] for m in c.mentions
        ]
        between = [
            c
            for c in clauses[sentence_start(clauses, position) : position]
            if not c.mentions and c.loose
        ]
        if (
            len(run) >= 2
            and len(fields) == len(run)
            and all((m.count or 1) == 1 and not m.refinements for m in fields)
            # (past a count said again, "2 fields", or words that say nothing of a field,
            # "(the plum ones)")
            and all(
                _counted_again(c, len(run)) or not any(i.role in ATTRIBUTE_ROLES for i in c.loose)
                for c in between
            )
        ):
            for mention, at in zip(fields, run, strict=True):
                words = said_by(clauses[at]) or []
                mention.items.extend(words)
                clauses[at].loose = []
        position = run[-1] + 1

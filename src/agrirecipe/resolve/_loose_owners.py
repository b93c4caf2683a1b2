"""The signs that say which fields a head-less clause's words are said of.

:func:`~agrirecipe.resolve._loose.attach_loose` asks these: whether the clause opens
on a member of a counted plural ("The other, east of the first, is 0.8 ha"), closes a
list said "with" ("... with 8 rows each"), goes on describing the crop named before
("and some plants wilting"), is said past a reference ("the one next to them has
yellowing"), of each plot or of the others, or of all the plants; and it hands the
words of "all", "both" and "each" to the fields of a group.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._fields import (
    ATTRIBUTE_ROLES,
)
from agrirecipe.resolve._lexicon import (
    Item,
)
from agrirecipe.resolve._links import PRONOUNS, link_norm
from agrirecipe.resolve._measures import (
    sentence_start,
)
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    describing_verbs,
    descriptive_words,
    strong_crops,
)
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = [
    "ALL_PLANTS",
    "about_the_others",
    "all_of_the_parts",
    "apply_group_words",
    "closes_a_with_list",
    "continues_a_description",
    "described_crop",
    "detach_trailing_all",
    "goes_on",
    "goes_on_saying_all",
    "last_new",
    "member_opening",
    "past_a_reference",
    "placed_with",
    "said_by_each",
    "same_as_before_next",
    "says_all_plants",
]


#: Words for all the plants of a field ("plants", "trees", "vines").
ALL_PLANTS = frozenset({"plants", "trees", "vines", "crops", "bushes"})
_OPENINGS = frozenset({".", "!", ";", ":"})


def member_opening(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The member of a counted plural that opens the sentence clause ``position`` is in
    ("The other, east of the first, is 0.8 ha, ..."), when no field is named between."""
    for index in range(position - 1, -1, -1):
        clause = clauses[index]
        if clause.mentions:
            return None
        if clause.refinement is not None:
            member = clause.refinement
            while index > 0 and clauses[index - 1].refinement is member:
                index -= 1  # (the member's first clause: "The other, ...")
            link = clauses[index].link
            opens = link is not None and link.norm in _OPENINGS
            return member if opens and clause.refined_parent is not None else None
        if clause.link is not None and clause.link.norm in (".", "!", ";"):
            return None  # (a colon goes on: "One: 200 x 150 m, rows N-S")
    return None


def closes_a_with_list(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The field whose "with" list an "and" clause closes: "Fontane on the right with
    late blight, blackened leaves and collapsed plants" (the clauses between it and the
    field only go on with the list)."""
    link = clauses[position].link
    if link is None or link.norm != "and":
        return None
    for previous in reversed(clauses[:position]):
        if previous.mentions:
            owner = previous.mentions[-1]
            last_head = max(h.start for h in owner.heads)
            after = [i for i in owner.items if i.start > last_head]
            with_ = any(i.norm == "with" for i in previous.items if i.start > last_head)
            return owner if with_ and not any(i.role == "plot" for i in after) else None
        if previous.link is None or previous.link.norm != ",":
            return None
        if not all(
            i.role in ATTRIBUTE_ROLES or i.role in ("filler", "of", "unknown")
            for i in previous.items
        ):
            return None
    return None


def placed_with(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The field a "with" clause (or one opened by a verb: "have fire blight") goes on
    about right after the placement ("in the middle", "next door") that ended the field's
    own clause."""
    clause = clauses[position]
    previous = clauses[position - 1] if position else None
    if (
        previous is None
        or not previous.mentions
        or clause.link is None
        or clause.link.role != "trailer"
        or not clause.items
        # ("the Williams pears next door have fire blight": or a verb saying how it is)
        or (clause.items[0].norm != "with" and clause.items[0].norm not in describing_verbs())
    ):
        return None
    return previous.mentions[-1]


def continues_a_description(clauses: Sequence[Clause], position: int) -> bool:
    """'..., the bananas still small and just planted': words joined by "and" to a
    sentence about a field named before ("the bananas ...") go on describing it."""
    previous = clauses[position - 1] if position else None
    link = clauses[position].link
    return (
        previous is not None
        and link is not None
        and link.role == "conjunction"
        and bool(previous.mentions)
        and bool(previous.items)
        and previous.items[0].norm in ("the", "their", "its", "those", "these")
        and previous.mentions[-1].heads[-1].end < previous.items[-1].end  # words after it
    )


def same_as_before_next(
    clauses: Sequence[Clause],
    position: int,
    attributes: Sequence[Item],
    forward: Mention | None,
) -> bool:
    """'Plot B is the same size, Beefsteak': "the same size" compares with a field named
    before, so in a sentence of its own it belongs to the field named right after it."""
    following = clauses[position + 1].link if position + 1 < len(clauses) else None
    start = sentence_start(clauses, position)
    return (
        position > 0
        and forward is not None
        and forward.clause == position + 1
        # the sentence names no field before it ("Field B, same size, is spelt")
        and start > 0
        and not any(c.mentions for c in clauses[start:position])
        and bool(attributes)
        and all(i.role in ("same_size", "same_spacing") for i in attributes)
        # ("the same size as the pears" names what it is compared with)
        and not any(i.norm.endswith(" as") for i in attributes)
        and following is not None
        and following.norm in (",", ":", "-")
    )


def goes_on(clause: Clause) -> bool:
    """Whether a clause of only descriptive words goes on with the one before it (", mottled
    leaves", "and some plants wilting")."""
    return (
        not clause.mentions
        and clause.link is not None
        and clause.link.norm in (",", "and")
        and all(
            i.role in ("filler", "cue", "health", "stage", "unknown", "of") for i in clause.items
        )
    )


def described_crop(clause: Clause, before: Sequence[Mention]) -> list[Mention]:
    """'The Riesling vineyard ... of the Fuji orchard. Half the vines show mildew': words
    about the plants of one crop go to the last field of that crop ([] if none)."""
    crops: set[str] = set()
    heads = [i for i in clause.loose if i.data.get("describes")]
    for item in heads:
        crops |= set(item.data["describes"])
    if not crops:
        return []
    # (a field named by its plot alone: "Vineyard and cherry orchard ..., the vines are in
    # flower" are the vineyard's)
    fields = [
        m
        for m in before
        if (
            strong_crops(m)
            or (
                set(m.plot["options"])
                if m.plot is not None and len(m.plot["options"]) == 1
                else set()
            )
        )
        & crops
    ]
    if not fields:
        # "fruit trees behind a vegetable patch, the trees pink with blossom": the one
        # field whose plot may hold those plants
        fields = [
            m
            for m in before
            if not strong_crops(m) and m.plot is not None and set(m.plot["options"]) & crops
        ]
        fields = fields if len(fields) == 1 else []
    if len(fields) >= 2 and _all_the_plants(clause, heads):
        # "Cabernet in the north block, Chardonnay in the south block, and the vines are
        # flowering": the plants of every field of that crop
        return fields
    return fields[-1:]


def _all_the_plants(clause: Clause, heads: Sequence[Item]) -> bool:
    """Whether the clause says "the vines" / "the trees" (a plural of all the plants, right
    after "the" and said with a verb), not a part of them ("half the vines", "one of the
    trees") nor plants held "with" a field ("with mildew on the vines")."""
    if clause.link is not None and clause.link.norm == "with":
        return False
    if any(i.role in ("fraction", "number", "reference", "quantity") for i in clause.items):
        return False
    for head in heads:
        before = [i for i in clause.items if i.end <= head.start]
        after = [i for i in clause.items if i.start >= head.end]
        if not (
            head.norm in ALL_PLANTS
            and len(before) == 1
            and before[0].norm in ("the", "these", "those", "both", "all")
            and after
            and after[0].norm in describing_verbs()
        ):
            return False
    return True


def goes_on_saying_all(clauses: Sequence[Clause], position: int, said_all: int) -> bool:
    """ "winter wheat next to durum, both still green and young": words joined by "and" to
    words said of every field are said of every field too."""
    clause = clauses[position]
    # ("each gets 10 beds 1.2 m wide (centre to centre) with 3 rows per bed and heads every
    # 30 cm": past a bracket of words that say nothing, the measures go on)
    before = position - 1
    while (
        before > said_all
        and not clauses[before].mentions
        # (nor past a member named since: "two adjacent plots, rows 50 m long in both.
        # Bintje potatoes, 30 rows at 75 cm. ...": the Bintje's own rows)
        and not any(i.role in (*ATTRIBUTE_ROLES, "head") for i in clauses[before].items)
    ):
        before -= 1
    joined = clause.link is not None and (
        clause.link.norm == "and"
        or (
            clause.link.norm in (")", ",")
            and before < position - 1
            and any(i.role == "geometry" for i in clause.items)
        )
        # "Each plot 30 m wide, 100 m long, ...": what follows "each plot" in its sentence
        or (clause.link.norm == "," and _each_plot(clauses[said_all]))
    )
    return (
        said_all == before
        and said_all >= 0
        and joined
        and not clause.mentions
        and not any(c.mentions for c in clauses[position + 1 :])
    )


def _each_plot(clause: Clause) -> bool:
    """Whether ``clause`` is only "each plot", "every field": a heading for what follows."""
    words = clause.items
    return (
        1 <= len(words) <= 2
        and words[0].role == "all"
        and words[0].norm in ("each", "every")
        and all(i.role in ("filler", "plot") for i in words[1:])
    )


def about_the_others(clause: Clause) -> bool:
    """A clause that opens with 'the others' / 'the rest' and says something of them."""
    first = next((i for i in clause.items if i.role != "filler"), None)
    return (
        first is not None
        and first.role == "reference"
        and first.data.get("value") == "rest"
        and any(i.role in ATTRIBUTE_ROLES and i.role != "all" for i in clause.loose)
    )


def past_a_reference(
    clauses: Sequence[Clause], position: int, targets: list[Mention]
) -> list[Mention]:
    """'a wheat plot to the south of the vineyard, 25 x 100 m': words after a field
    named again as a relation's object describe the relation's subject; a look in a
    sentence of its own after a list whose member was named again to place it ("...,
    with Red Express between the other two. Heads formed.") describes the whole list."""
    for at in (position, position - 1):
        # "Padron plot north of it, 20 rows", "the Danvers carrots beside them have
        # Alternaria, dark lesions ...": the words after "north of it" / "beside them"
        # are the placed field's, not those of the field the pronoun points at
        pointer = clauses[at] if at >= 1 else None
        if (
            pointer is not None
            and pointer.link is not None
            and pointer.link.role == "relation"
            and not pointer.mentions
            and bool(pointer.items)
            and pointer.items[0].norm in PRONOUNS
            and clauses[at - 1].mentions
        ):
            return clauses[at - 1].mentions[-1:]
    if len(targets) != 1:
        return targets
    index = position - 1
    while index >= 0 and not clauses[index].mentions:
        index -= 1
    if index < 1:
        return targets
    relation = clauses[index]
    named_before = any(targets[0] is m for c in clauses[:index] for m in c.mentions)
    start = sentence_start(clauses, index)
    listed = list({id(m): m for c in clauses[start:position] for m in c.mentions}.values())
    said = sorted(h.start for h in targets[0].heads)
    placing = [c.link for c in clauses[start + 1 : position] if c.link is not None]
    if (
        link_norm(clauses[position]) in SENTENCE_MARKS
        and len(listed) >= 2
        and bool(said)
        # (the member named again after the others, to place it)
        and any(said[0] < h.start < said[-1] for m in listed for h in m.heads)
        and any(link.role in ("relation", "between", "trailer") for link in placing)
    ):
        # "Savoy, Red Express and January King, ..., with Red Express between the other
        # two. Heads formed and ready for harvest.": a look of its own sentence after a
        # list whose member is named again to place it is the whole list's
        return listed
    # ("Regina, directly south of the Kordia cherries, 40 by 80 m": past the empty
    # clause a comma before the relation leaves)
    opening = index - 1
    while opening > 0 and not clauses[opening].items and link_norm(clauses[opening]) == ",":
        opening -= 1
    subject = clauses[opening].mentions[-1] if clauses[opening].mentions else None
    # "the maize field is south of the wheat, and you can see its rows run east-west":
    # "its" is the sentence's subject, not the field it is placed against
    possessive = any(i.norm in ("its", "their") for i in clauses[position].items)
    if (
        relation.link is not None
        and relation.link.role == "relation"
        and relation.mentions == [targets[0]]
        and (named_before or possessive)
        and subject is not None
        and subject is not targets[0]
    ):
        return [subject]
    return targets


def said_by_each(before: Sequence[Mention], others: Sequence[Item]) -> bool:
    """Whether the fields before the last already say, each, what ``others`` say (the
    same attribute, its own value): words after the last field are then its own."""
    wanted = {_says(i) for i in others} & {"stage", "health"}
    members = [r for m in before for r in (m.refinements or [m])]
    earlier = list({id(m): m for m in members}.values())[:-1]
    return (
        bool(wanted)
        and bool(earlier)
        and all(wanted <= {_says(i) for i in m.items} for m in earlier)
    )


def _says(item: Item) -> str:
    """The attribute an item says: its role, or for a visual cue ("heading out") the
    attribute the cue fills."""
    cue = item.data.get("cue") if item.role == "cue" else None
    return str(cue.attribute) if cue is not None else item.role


def says_all_plants(item: Item) -> bool:
    """'young plants', 'healthy trees': an attribute phrase about the plants in general."""
    words = item.norm.split()
    # "1.2 m between trees" is one field's spacing, not words about all the plants
    return item.role != "geometry" and len(words) > 1 and words[-1] in ALL_PLANTS


_WHOLE_PLANTS = frozenset(
    {"trees", "tree", "plants", "plant", "vines", "vine", "bushes", "crop", "crops", "palms"}
)


def all_of_the_parts(clause: Clause) -> None:
    """'the older leaves all shrivelled': "all" right after the plants' parts is all of
    those parts, not every field; it becomes a filler word."""
    ordered = sorted(clause.loose, key=lambda i: i.start)
    # (the parts, not the plants: "trees all white w blossom" is still every tree)
    parts = descriptive_words() - _WHOLE_PLANTS
    for before, item in itertools.pairwise(ordered):
        if item.role == "all" and item.norm == "all" and before.norm in parts:
            item.role = "filler"


def detach_trailing_all(clause: Clause) -> None:
    """'cherry trees and apple trees both carrying ripe fruit': after the last field of a
    clause, "both"/"all" and the words after it describe every field, not only that one."""
    if not clause.mentions:
        return
    mention = clause.mentions[-1]
    last_head = max(h.start for h in mention.heads)
    marker = next(
        (
            i
            for i in sorted(mention.items, key=lambda i: i.start)
            if i.role == "all" and i.start > last_head
        ),
        None,
    )
    if marker is None or all(marker is not i for i in clause.items):
        return  # (a field named again: its words are detached in the clause that says them)
    moved = [i for i in mention.items if i.start >= marker.start and i not in mention.heads]
    if not any(i.role in ATTRIBUTE_ROLES for i in moved if i is not marker):
        return
    mention.items = [i for i in mention.items if i not in moved]
    clause.loose = [*clause.loose, *moved]


def apply_group_words(loose: Sequence[Item], group: Sequence[Mention]) -> None:
    """Words about the fields listed just before: "grains and veggies: two of each" counts
    each of them; "five fields, each a different crop" makes them different crops."""
    roles = [i.role for i in loose if i.role != "filler"]
    if (
        len(roles) >= 2
        and roles[0] == "number"
        and roles[-1] == "all"
        and (roles[1:-1] in ([], ["of"]))
    ):
        number = next(i for i in loose if i.role == "number")
        count = float(number.data.get("value", 1))
        if count == int(count) and 1 <= count <= 64:
            for mention in group:
                if mention.count is None or mention.count == 1:
                    mention.count = int(count)
    if any(i.role == "distinct" for i in loose):
        for mention in group:
            if (mention.count or 1) > 1:
                mention.distinct = True
                mention.distinct_crops = not mention.has_crop


def last_new(mentions: Sequence[Mention]) -> Mention:
    """Of mentions in prompt order (a field named again stands again), the one whose
    first naming came last."""
    first: dict[int, int] = {}
    for index, mention in enumerate(mentions):
        first.setdefault(id(mention), index)
    return max(mentions, key=lambda m: first[id(m)])

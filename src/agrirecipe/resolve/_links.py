"""Words that link fields, shared by the relation readers.

The lists a relation word or a head-less clause is said of (:func:`coordinated`,
:func:`following_list`, :func:`listing`), the words that point back at a field
(:data:`PRONOUNS`), and :func:`field_relations`, which turns one relation between
mentions into relations between their fields (plural mentions expand).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Sequence
from typing import Any, get_args

from agrirecipe.recipe import RelationKind
from agrirecipe.resolve._intent import RelationIntent, TraceStep
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._mentions import Clause, Mention

__all__ = [
    "ARTICLES",
    "OPENING_MARKS",
    "OPPOSITE",
    "PRONOUNS",
    "THE_TWO",
    "before_brackets",
    "coordinated",
    "field_relations",
    "fields_of",
    "following_list",
    "gap_between_the_two",
    "last_named",
    "link_norm",
    "listed_after",
    "listing",
    "own_mentions",
    "relation_mentions",
    "says",
]


ARTICLES = frozenset({"the", "a", "an", "our", "my", "their", "its"})

#: The marks after a heading that open the list it heads ("west to east: wheat, ...",
#: "from north to south - potatoes, corn, wheat").
OPENING_MARKS = frozenset({":", "-", "–", "—"})


#: Words that point back at a field named before ("north of it", "beside them").
PRONOUNS = frozenset({"it", "them", "those", "these", "they", "this", "that", "which"})


THE_TWO = frozenset(
    {
        "the two",
        "both",
        "the two of them",
        "both of them",
        "those two",
        "these two",
        "the pair",
        "the other two",
        "the two others",
        "the other 2",
    }
)


OPPOSITE = {
    "north_of": "south_of",
    "south_of": "north_of",
    "east_of": "west_of",
    "west_of": "east_of",
}


def says(mention: Mention, words: tuple[str, str]) -> bool:
    """Whether the mention's words hold ``words`` one right after the other."""
    ordered = sorted(mention.items, key=lambda i: i.start)
    return any((a.norm, b.norm) == words for a, b in itertools.pairwise(ordered))


def field_relations(
    kind: Any,
    subject: Mention,
    objects: tuple[Mention, ...],
    members: dict[int, list[int]],
    link: Item,
    trace: list[TraceStep],
) -> list[RelationIntent]:
    """Field-level relations for a relation between mentions (plural ones expand)."""
    subject_fields = members.get(id(subject), [])
    object_fields = [members.get(id(o), []) for o in objects]
    if not subject_fields or not all(object_fields) or kind not in get_args(RelationKind):
        return []  # (a word read as a relation that no field relation is: not used)
    trace.append(
        TraceStep(
            stage="decompose",
            subject=link.raw,
            detail=f"{subject.text!r} {kind} " + " and ".join(repr(o.text) for o in objects),
        )
    )
    if kind == "between":
        if objects[0] is objects[1]:
            if len(object_fields[0]) < 2:
                return []  # "Gala in between Gala, Gala": one field is not two sides
            pair = (object_fields[0][0], object_fields[0][1])
        else:
            pair = (object_fields[0][0], object_fields[1][0])
        if len({subject_fields[0], *pair}) < 3:
            return []
        return [
            RelationIntent(kind="between", subject=subject_fields[0], objects=pair, text=link.raw)
        ]
    # a field named twice ("Valencia oranges ... near Valencia") is not beside itself;
    # members are on no side of themselves within the fields counted that hold them
    # ("Four plots ...: two lettuce plots on the north side, two onion plots on the south
    # side": not one lettuce plot north of the other)
    within = kind != "next_to" and set(subject_fields) < set(object_fields[0])
    pairs = [
        (s, o)
        for s in subject_fields
        for o in object_fields[0]
        if s != o and not (within and o in subject_fields)
    ]
    if kind == "next_to" and len(pairs) > 2:
        # Groups side by side: one field can touch at most two in a row, so
        # "two orchards next to three fields" means the groups touch.
        pairs = pairs[:1]
    return [RelationIntent(kind=kind, subject=s, objects=(o,), text=link.raw) for s, o in pairs]


def fields_of(group: Sequence[Mention], members: dict[int, list[int]]) -> list[int]:
    fields: list[int] = []
    for mention in group:
        for index in members.get(id(mention), []):
            if index not in fields:
                fields.append(index)
    return fields


def own_mentions(clause: Clause) -> list[Mention]:
    """The fields a clause names itself: its mentions, or the member it names ("and east
    of it a 3 ha wheat field" after "two plots: ..."), not one it only goes on about."""
    if clause.mentions:
        return clause.mentions
    member = clause.refinement
    return [member] if member is not None and member.clause == clause.index else []


def last_named(mentions: Sequence[Mention]) -> list[Mention]:
    """Each mention once, ordered by where it was last named."""
    order: dict[int, Mention] = {}
    for mention in mentions:
        order.pop(id(mention), None)
        order[id(mention)] = mention
    return list(order.values())


def listed_after(clauses: Sequence[Clause], position: int) -> list[Mention]:
    """'in two polytunnels next to each other: tunnel 1 is Elsanta, tunnel 2 is
    Centenary': the fields listed after a colon, when nothing before it named one."""
    following = clauses[position + 1 :]
    if not following or following[0].link is None or following[0].link.norm not in OPENING_MARKS:
        return []
    listed: list[Mention] = []
    for clause in following:
        if (
            clause is not following[0]
            and clause.link is not None
            and clause.link.norm
            in (
                ".",
                "!",
                "?",
                ";",
            )
        ):
            break
        listed.extend(clause.mentions)
    return listed


def coordinated(
    clauses: Sequence[Clause], position: int, *, past_asides: bool = False
) -> list[Mention]:
    """The mentions just before clause ``position``, with those listed with it.

    "bananas and oranges, ripe": both are ripe; "apples next to carrots, ripe":
    only the carrots. A member's bracketed words ("onions (fine) and lettuce (fine)")
    end the list's shared words, but not, with ``past_asides``, a list a row word
    orders ("..., all in a line north to south").
    """
    index = position - 1
    while index >= 0 and not clauses[index].mentions:
        index -= 1
    if index < 0:
        return []
    group = [clauses[index].mentions[-1]]
    said = clauses[index].items
    if said and said[0].norm in ("the", "these", "those", "both") and (group[0].count or 1) > 1:
        return group  # "2 cereal fields n 2 fruit ones, the fruit ones touching each other"
    if group[0].clause < index and said and said[0].norm in ("the", "its", "their"):
        # "..., and Red Express cabbage behind, the cabbage leaves chewed full of holes by
        # caterpillars": a field named again by "the" is the one described
        return group
    if any(i.role == "zone" for i in group[0].items) and clauses[index].link is not None:
        # "sweetcorn at the back, tomatoes in the middle - black blotchy stems": a field
        # placed in a zone of its own is no list with the one before it
        return group
    if _describes_itself(clauses[index], group[0]) and clauses[index].link is not None:
        # "..., and Roma tomatoes behind with curled, mottled leaves": the words after a
        # comma go on with the last member's own "with ..."
        return group
    if _placed_by_pronoun_after(clauses, index, position):
        # "..., and the Roma field beside it hit hard by blight, black stems and rotting
        # fruit": a field placed against the one before it by a pronoun is described
        # on its own
        return group
    seen = {id(group[0])}  # identity: comparing mentions field by field made this cubic
    index = _before_a_bracket(clauses, index, group, seen)
    # ("North plot, ..., Fontane potatoes; south plot, 40 x 120 m, ...": a semicolon
    # ends the member before it)
    while (
        index > 0
        and listing(clauses[index].link)
        and not _placed_by_pronoun(clauses[index])
        and link_norm(clauses[index]) != ";"
    ):
        previous = clauses[index - 1]
        if not previous.mentions and not previous.items and link_norm(previous) == ")":
            # "red onions (red baron) n walla wallas side by side, ready ...": past the
            # bracket to the member it follows
            opening = next(
                (k for k in range(index - 2, 0, -1) if link_norm(clauses[k]) == "("), None
            )
            # (only past a bracket that names the member again: "(0.3 ha, ripening)" is
            # the member's own words, which end the list's shared words)
            if (
                opening is None
                or not clauses[opening - 1].mentions
                or not (past_asides or any(c.mentions for c in clauses[opening:index]))
            ):
                break
            index = opening - 1
            mention = clauses[index].mentions[-1]
            if id(mention) not in seen:
                seen.add(id(mention))
                group.append(mention)
            continue
        if not previous.mentions:
            # "orchard, then potatoes": the bare comma between two members
            if previous.items or index < 2 or not listing(previous.link):
                break
            index -= 1
            continue
        index -= 1
        mention = clauses[index].mentions[-1]
        if id(mention) not in seen:  # a field named again stands twice
            seen.add(id(mention))
            group.append(mention)
        index = _before_a_bracket(clauses, index, group, seen)
    return group


def _describes_itself(clause: Clause, mention: Mention) -> bool:
    """Whether a field's clause goes on, after its name, with "with ..." words of its own
    at its end ("Roma tomatoes behind with curled")."""
    last_head = max(h.end for h in mention.heads)
    after = [i for i in clause.items if i.start >= last_head]
    with_at = next((n for n, i in enumerate(after) if i.norm == "with"), None)
    return (
        with_at is not None
        and with_at < len(after) - 1
        and all(
            i.role in ("unknown", "cue", "stage", "health", "filler") for i in after[with_at + 1 :]
        )
    )


def _before_a_bracket(
    clauses: Sequence[Clause], index: int, group: list[Mention], seen: set[int]
) -> int:
    """The clause before a bracket that clause ``index`` opens, its field joining
    ``group`` ("strawberries (sonata) + strawberries (albion), ..., flowering": both
    flower); ``index`` when clause ``index`` opens no bracket."""
    link = clauses[index].link
    if index == 0 or link is None or link.norm != "(" or not clauses[index - 1].mentions:
        return index
    mention = clauses[index - 1].mentions[-1]
    if id(mention) not in seen:
        seen.add(id(mention))
        group.append(mention)
    return index - 1


def link_norm(clause: Clause) -> str | None:
    return clause.link.norm if clause.link is not None else None


def before_brackets(clauses: Sequence[Clause], position: int) -> int:
    """The clause before ``position``, past a bracketed aside that ends right before it
    ("carrots (nantes) east of them": the carrots' clause)."""
    index = position - 1
    if index > 0 and not clauses[index].items and link_norm(clauses[index]) == ")":
        index -= 1
        while index > 0 and link_norm(clauses[index]) != "(":
            index -= 1
        index = max(index - 1, 0)
    return index


_PRONOUNS = ("them", "it", "those", "these")


def _placed_by_pronoun(clause: Clause) -> bool:
    """'..., and behind them a row of old pear trees': a field placed against the fields
    before it by a pronoun is not listed with them."""
    if not clause.mentions:
        return False
    head = min(h.start for h in clause.mentions[-1].heads)
    return any(i.norm in _PRONOUNS for i in clause.items if i.end <= head)


def _placed_by_pronoun_after(clauses: Sequence[Clause], index: int, position: int) -> bool:
    """Whether the field of clause ``index`` is placed by a pronoun in the clause right
    after it ("the Roma field beside it"), before clause ``position``."""
    after = index + 1
    if after >= position or clauses[after].mentions:
        return False
    link, said = clauses[after].link, clauses[after].items
    return link is not None and link.role == "relation" and bool(said) and said[0].norm in _PRONOUNS


def following_list(
    clauses: Sequence[Clause], position: int, first: Sequence[Mention] = ()
) -> list[Mention]:
    """The mentions listed right after clause ``position`` (a heading such as "west to
    east:"), in order: the first after it (or ``first``, named in the heading's own
    clause), then each joined to it by a comma, "and" or "then", up to a full stop or
    any other link."""
    group: list[Mention] = list(first)
    bracket = False
    for index in range(position + 1, len(clauses)):
        clause = clauses[index]
        link = clause.link.norm if clause.link is not None else None
        # ("Gros Michel bananas (Big Mike, as granddad calls them), then ...": the member
        # before it named again in the bracket)
        again = all(any(m is g for g in group) for m in clause.mentions)
        if group and again and (bracket or link in ("(", ")")):
            # "a tomato strip (6 rows, 1.5 m apart), then ...": what a bracket says of
            # the member before it
            bracket = link != ")"
            continue
        # ("Going from west to east the plots are: Chantenay carrots, ...": the list after
        # the colon of the heading's own clause)
        colon = index == position + 1 and link in OPENING_MARKS
        if group and not listing(clause.link) and not colon:
            if not clause.mentions and all(
                i.role in ("filler", "non_agricultural") for i in clause.items
            ):
                # "potatoes closest to me, then the wheat": placed by the viewer; "an
                # orchard by the road, then a maize field": by scenery on the way
                continue
            break
        if (
            not group
            and clause.link is not None
            # ("heading north you cross a hedge, then the strawberry beds, then ...")
            and clause.link.norm not in (*OPENING_MARKS, ",", "then")
            and (clause.mentions or clause.link.role not in ("separator", "conjunction"))
            # ("North to south along the lane: Kordia cherries, ...": scenery on the way)
            and not _along_scenery(clause)
            # ("Left to right along the road we've got 2 ha of Fontane potatoes, then ...")
            and not _along_scenery_then_field(clause)
        ):
            break
        if clause.mentions and all(clause.mentions[-1] is not m for m in group):
            group.append(clause.mentions[-1])
    return group


def _along_scenery(clause: Clause) -> bool:
    """A clause that only says what the fields lie along ("along the lane")."""
    return (
        not clause.mentions
        and clause.link is not None
        and clause.link.role == "relation"
        and any(i.scenery for i in clause.items)
        and all(i.scenery or i.role in ("filler", "of") for i in clause.items)
    )


def _along_scenery_then_field(clause: Clause) -> bool:
    """A clause that says what the fields lie along, then names the first of them ("along
    the road we've got 2 ha of Fontane potatoes")."""
    if len(clause.mentions) != 1 or clause.link is None or clause.link.role != "relation":
        return False
    first_head = min(h.start for h in clause.mentions[0].heads)
    before = [i for i in clause.items if i.start < first_head]
    return any(i.scenery or i.role == "non_agricultural" for i in before) and all(
        i.scenery or i.role in ("filler", "of", "non_agricultural", "size", "number")
        for i in before
    )


def listing(link: Item | None) -> bool:
    """A link inside a list of fields: "and", or a comma (not a full stop or a relation)."""
    if link is None:
        return False
    return link.role == "conjunction" or (link.role == "separator" and link.norm in (",", ";", "&"))


def relation_mentions(
    link: Item,
    before: Sequence[Mention],
    after: Sequence[Mention],
    *,
    pronoun: bool,
    attached: bool = False,
    fields: Callable[[Mention], int] | None = None,
) -> tuple[Any, Mention, tuple[Mention, ...]] | None:
    """The kind, subject and objects a relation word links among the mentions named
    ``before`` and ``after`` it (``pronoun``: said as "north of them"; ``attached``: the
    word ends the clause of the field it places; ``fields``: how many fields a mention
    stands for, its count when not given), or None."""
    kind = link.data.get("value", "between") if link.role != "between" else "between"
    if kind == "flanks":
        # "Durondeau and Williams pears on either side of a Jonagold block"
        if not after:
            return None
        if pronoun and before:
            # "the Cabernet, and either side of it Chardonnay ... and Pinot Nero ...": it
            # lies between the two named after
            return ("between", before[-1], (after[0], after[1])) if len(after) >= 2 else None
        if before and (before[-1].count or 1) >= 2:
            return "between", after[0], (before[-1], before[-1])
        if len(before) >= 2:
            return "between", after[0], (before[-2], before[-1])
        return None
    if pronoun and not after and len(before) >= 2:
        # "a couple of wheat fields and a maize field in between them".
        if kind == "between" and (before[-2].count or 1) >= 2:
            return kind, before[-1], (before[-2], before[-2])
        if kind != "between":
            return kind, before[-1], (before[-2],)
    if pronoun and not after and len(before) >= 3 and kind == "between":
        # "wheat, maize and a strawberry patch between them".
        return kind, before[-1], (before[-3], before[-2])
    if pronoun and before and after:
        # "two potato fields and between them / north of them a wheat field": the
        # pronoun is the object, named before; the subject comes after.
        objects = (before[-1],) if kind != "between" else (before[-1], before[-1])
        if kind != "between" or (before[-1].count or 1) >= 2:
            return kind, after[0], objects
        if len(before) >= 2:
            # "wheat in the north, maize in the south, and in between them a strip of
            # strawberries": the two fields named last
            return kind, after[0], (before[-2], before[-1])
    if link.role == "between":
        # each once ("carrots (nantes) & cabbage (savoy)" names each twice)
        after = list({id(m): m for m in after}.values())
        # ("Three strips: a maize strip between two wheat strips": a member counted two)
        if after and before and (fields(after[0]) if fields else after[0].count or 1) >= 2:
            return "between", before[-1], (after[0], after[0])
        if len(after) == 1 and len(before) >= 2 and attached:
            # "cabbages nearest to me, a strip of onions in between, and a field of
            # sweetcorn up the hill": between the fields named either side of it
            return "between", before[-1], (before[-2], after[0])
        if len(after) < 2:
            return None
        if before:
            return "between", before[-1], (after[0], after[1])
        if len(after) >= 3:
            return "between", after[2], (after[0], after[1])
        return None
    if link.role == "trailer":
        # ("cherries to the north, the cherry trees netted ...": a field named again after
        # the trailer is no field it places)
        after = [m for m in after if not any(m is b for b in before)]
        if len(before) >= 2 and before[-1].clause == before[-2].clause:
            return kind, before[-1], (before[-2],)
        if before and after and attached:
            return kind, before[-1], (after[0],)
        if before and after:
            return kind, after[0], (before[-1],)
        if len(before) >= 2:
            return kind, before[-1], (before[-2],)
        return None
    if before and after:
        return kind, before[-1], (after[0],)
    if len(after) >= 2:
        return kind, after[1], (after[0],)
    if len(before) >= 2:
        # "... with an onion field to the north of them": the object was named before.
        return kind, before[-1], (before[-2],)
    return None


#: Words for the space left between two fields ("a 3 m gap between them").
_GAPS = frozenset({"gap", "gaps", "space", "spacing", "distance", "buffer", "clearance"})


def gap_between_the_two(
    clauses: Sequence[Clause], position: int, members: dict[int, list[int]]
) -> tuple[int, int] | None:
    """The two fields of the prompt when clause ``position`` is "between them" (or "the
    two") right after a gap said with no field of its own ("half a metre gap between
    them"); else None."""
    clause = clauses[position]
    said = " ".join(i.norm for i in clause.items)
    if position == 0 or not (said in THE_TWO or said == "them"):
        return None
    previous = clauses[position - 1].items
    if not previous or previous[-1].norm not in _GAPS:
        return None
    fields = sorted({f for indexes in members.values() for f in indexes})
    return (fields[0], fields[1]) if len(fields) == 2 else None

"""Relations between fields: which mentions a relation word links, and in which direction.

"X north of Y" relates the mentions on either side; "X with Y to the north"
(a trailing direction) relates the last two named; "between" takes the two
mentions after it (or two members of one plural mention); a pronoun ("north of
them") points back at a mention already named; "side by side" after a list
makes a row. Plural mentions expand to their fields.

:func:`read_relations` is the one place the relation readers are called, in order:
fields in rows, orders and around a middle (``_rows``), fields placed by a direction
said around them (``_placements``), fields placed by scenery (``_landmarks``), relation
words said of scenery and not of fields (``_scenery_links``); the words that link
fields are in ``_links``.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from typing import get_args

from agrirecipe.recipe import RelationKind
from agrirecipe.resolve._intent import RelationIntent, TraceStep
from agrirecipe.resolve._landmarks import (
    across_landmarks,
    held_by,
    landmark_again,
    landmark_of,
    landmark_said_before,
)
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import (
    ARTICLES,
    PRONOUNS,
    THE_TWO,
    before_brackets,
    field_relations,
    gap_between_the_two,
    last_named,
    own_mentions,
    relation_mentions,
)
from agrirecipe.resolve._measures import sentence_start
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._placements import (
    a_distance,
    attached_to_the_field_before,
    between_said_last,
    directed_neighbours,
    fronted_between,
    fronted_pair,
    placed_by_the_middle,
    placement_pairs,
    placements,
    shared_subject,
)
from agrirecipe.resolve._rows import (
    FURTHER,
    OTHER_SIDE,
    TOWARDS,
    adjacent_rows,
    directed_row,
    furthest,
    listed_middle,
    on_the_other_side,
    one_and_the_other,
    one_side_and_the_other,
    ordinal_pair,
    side_by_side,
    surrounded,
)
from agrirecipe.resolve._scenery_links import (
    between_scenery,
    pronoun_of_scenery,
    scenery_in_the_middle,
    scenery_placed_by_a_field,
)
from agrirecipe.resolve._structure import strong_crops
from agrirecipe.resolve._then_chain import then_chain

__all__ = ["read_relations"]


#: Words of a clause that places a field by scenery alone ("the Royal Gala block north of
#: the packhouse is ripe": the look goes on describing the block).
_SAID_OF_A_LANDMARK = frozenset({"filler", "non_agricultural", "stage", "health", "season", "cue"})


def read_relations(
    clauses: Sequence[Clause],
    members: dict[int, list[int]],
    trace: list[TraceStep],
    warnings: list[str],
) -> list[RelationIntent]:
    """Relations between fields from the relation words between mentions.

    ``members`` maps ``id(mention)`` to the indexes of the fields it became.
    """
    relations: list[RelationIntent] = adjacent_rows(clauses, members, trace)
    placed = placements(clauses, members)
    # the last relation said with a pronoun: (its word, subject, object, kind)
    parallel: tuple[str, Mention, Mention, str] | None = None
    # relations read between mentions, and those said "on the other side of" a field
    read: list[tuple[str, Mention, tuple[Mention, ...]]] = []
    beyond: list[tuple[Mention, Mention, Item]] = []
    further: list[tuple[str, Mention, Mention, Item]] = []
    # the middle of three said side by side, unless the text puts another in the middle
    middles: list[RelationIntent] = []
    for position, subject, centre in placement_pairs(clauses, members, placed):
        link = clauses[position].link
        assert link is not None
        kind = link.data["value"]
        # ("further east", "and east again the Fuji": past the last one placed that way)
        if link.norm.split()[0] in FURTHER or link.norm.endswith(" again"):
            further.append((kind, subject, centre, link))  # read once the others are
            continue
        relations.extend(field_relations(kind, subject, (centre,), members, link, trace))
    landmarks: list[tuple[str, str, Mention, Item]] = []
    landmark_at: dict[int, str] = {}  # the landmark each relation clause placed against
    last_relation: int | None = None
    directed = directed_neighbours(clauses)
    for position, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role not in ("relation", "between", "trailer"):
            continue
        previous_relation, last_relation = last_relation, position
        if position in placed or position in directed.values():
            continue
        landmark = (
            landmark_again(clauses, position, landmark_at.get(previous_relation), landmarks[-1][0])
            if previous_relation in landmark_at
            else landmark_said_before(clauses, position)
        )
        if landmark is not None:
            # "wheat north of the farmhouse, maize south of it": the landmark again; "The
            # farmhouse is in the middle. Wheat to the north of it": the one said first
            named = [m for c in clauses[:position] for m in c.named]
            landmarks.append((str(link.data.get("value")), landmark, named[-1], link))
            landmark_at[position] = landmark
            continue
        landmark = landmark_of(clause)
        if landmark is not None and (held := held_by(clauses, position, landmark)) is not None:
            # "Centenary strawberries in the tunnels, ..., and right beside the tunnels an
            # orchard of Bing cherries": placed by the field the structure holds
            container, subject = held
            relations.extend(
                field_relations(
                    str(link.data["value"]), subject, (container,), members, link, trace
                )
            )
            continue
        if landmark is not None and clause.mentions:
            # "east of the yard there's 2 ha of apples": placed by the yard
            landmarks.append((str(link.data.get("value")), landmark, clause.mentions[0], link))
            landmark_at[position] = landmark
            continue
        if (
            link.role == "relation"
            and not clause.mentions
            and clause.items
            # ("tomatos right next to them in the glasshouse": next to the fields before)
            and clause.items[0].norm not in PRONOUNS
            # ("a lettuce field east of the big barn, and east of that again ...", "split
            # by a hawthorn hedge")
            and all(
                i.role in _SAID_OF_A_LANDMARK or (i.role == "number" and i.norm in ARTICLES)
                for i in clause.items
            )
            and any("scenery" in i.data or i.role == "non_agricultural" for i in clause.items)
        ):
            # "the Winter Wheat east of the farmhouse ..., and west of the house the Russet
            # potatoes": kept to pair with a field on the landmark's other side
            named = [m for c in clauses[:position] for m in c.named]
            landmark = landmark_of(clause)
            held = held_by(clauses, position, landmark)
            if held is not None:
                # "In the tomato tunnel: ... Outside, right beside the tunnel, 6 rows of
                # peppers": placed by the field the scenery holds
                container, subject = held
                kind = str(link.data["value"])
                relations.extend(field_relations(kind, subject, (container,), members, link, trace))
                continue
            if (row := side_by_side(clauses, position, members, trace, warnings)) is not None:
                # "the cabbage and the lettuce fields side by side with the tractor
                # between them": the fields side by side, the scenery with them
                relations += row.relations
                middles += row.middles
                read += row.said
                continue
            if named and landmark is not None and position - 1 == named[-1].clause:
                landmarks.append((str(link.data.get("value")), landmark, named[-1], link))
                landmark_at[position] = landmark
                continue
            # "a test strip along the farm track": placed by scenery, not by a field
            trace.append(
                TraceStep(
                    stage="decompose", subject=link.raw, detail="relative to scenery: not used"
                )
            )
            continue
        if scenery_placed_by_a_field(clauses, position):
            # "..., with the village road running along the east side", "Rain covers
            # rolled up above both": the scenery is placed, not a field
            trace.append(
                TraceStep(
                    stage="decompose", subject=link.raw, detail="relative to scenery: not used"
                )
            )
            continue
        # each field once, where last named ("blood oranges (Moro)" names one twice)
        before = last_named([m for c in clauses[:position] for m in c.named])
        if _of_everything(clause) and before and position - 1 == before[-1].clause:
            # "..., and a field of Agria potatoes south of everything": of each field
            for other in before[:-1]:
                relations.extend(
                    field_relations(link.data["value"], before[-1], (other,), members, link, trace)
                )
            continue
        # a pronoun's clause ("north of it") names no field of its own after the word
        # (in its own sentence: "..., a wheat field beyond the farm track to the north of
        # it. There's a tractor working in the maize" names the maize again, not after it)
        after = [
            m
            for c in clauses[position : _sentence_end(clauses, position)]
            for m in (c.named if c is not clause else own_mentions(c))
        ]
        said = " ".join(i.norm for i in clause.items)
        the_two = not clause.mentions and said in THE_TWO
        pronoun = bool(clause.items) and (
            clause.items[0].norm in PRONOUNS
            # "cherry tomatoes in between the two", "between both"
            or the_two
        )
        if pronoun and pronoun_of_scenery(clauses, position, the_two=the_two):
            # "A ditch runs through the middle. East of it is a field of sweetcorn", "...,
            # kids in yellow hats weeding between them": scenery placed, no field
            trace.append(
                TraceStep(stage="decompose", subject=link.raw, detail="said of scenery: not used")
            )
            continue
        # ("carrots (nantes) east of them": past the brackets after the subject)
        said_before = clauses[before_brackets(clauses, position)] if position else None
        if (
            pronoun
            # ("east of that block": a field named before, not one of its own)
            and all(m.clause != clause.index for m in clause.mentions)
            and said_before is not None
            and said_before.named
            and said_before.items  # not "one ... and, north of it, one ..."
            # (nor "cherry trees and, 20 m south of them, a plum tomato plot": a distance)
            and not a_distance(said_before)
        ):
            # "put valencia oranges north of it, and a banana plot ...": the pronoun
            # ends its clause after a subject, so it points back and the fields after
            # are not its subject ("a cherry orchard and, south of it, two fields" is)
            after = []
        if (row := side_by_side(clauses, position, members, trace, warnings)) is not None:
            relations += row.relations
            middles += row.middles
            read += row.said
            continue
        if link.role == "trailer" and str(link.data.get("value")) in TOWARDS:
            relations += directed_row(clauses, position, members, link, trace, warnings)
            continue
        if one_and_the_other(clauses, position) and link.role == "relation":
            # "bananas, 2 plots, one above the other": the two named last, the first
            # named on the relation's side
            kind = link.data["value"]
            if len(before) >= 2:
                relations.extend(
                    field_relations(kind, before[-2], (before[-1],), members, link, trace)
                )
            elif (
                before
                and len(fields := members.get(id(before[-1]), [])) == 2
                and kind in get_args(RelationKind)
            ):
                # "two wheat plots, one north of the other"
                relations.append(
                    RelationIntent(
                        kind=kind, subject=fields[0], objects=(fields[1],), text=link.raw
                    )
                )
            continue
        if (
            link.role == "relation"
            and len(before) >= 2
            and _each_against_the_one_before(clauses, position)
        ):
            # "Navel first, then Hamlin, then Moro, each block right up against the one
            # before": each field placed against the one named before it
            for named_first, named_next in itertools.pairwise(before):
                relations.extend(
                    field_relations(
                        link.data["value"], named_next, (named_first,), members, link, trace
                    )
                )
            continue
        if (
            link.role == "relation"
            and len(clause.mentions) == 1
            and len(before) >= 2
            and _both_fronted(clause)
        ):
            # "..., and north of both onion fields a field of Danvers carrots": the field
            # after the two named before is placed against each of them
            for other in before[-2:]:
                relations.extend(
                    field_relations(
                        link.data["value"], clause.mentions[0], (other,), members, link, trace
                    )
                )
            continue
        ordinals = ordinal_pair(clauses, position)
        if ordinals is not None and link.role == "relation" and before:
            # "one at 70,000 plants/ha, the other at 100,000; the first north of the second"
            fields = next(
                (f for m in reversed(before) if len(f := members.get(id(m), [])) >= 2), []
            )
            kind = link.data["value"]
            said_first, said_second = ordinals
            if max(ordinals) < len(fields) and kind in get_args(RelationKind):
                relations.append(
                    RelationIntent(
                        kind=kind,
                        subject=fields[said_first],
                        objects=(fields[said_second],),
                        text=link.raw,
                    )
                )
                continue
        listed = listed_middle(clauses, position, link)
        if listed is not None:
            relations.extend(field_relations("between", listed[0], listed[1], members, link, trace))
            continue
        if scenery_in_the_middle(clauses, position) or between_scenery(clauses, position):
            # "There's an irrigation reel in the middle of the lettuce": scenery placed
            trace.append(
                TraceStep(stage="decompose", subject=link.raw, detail="said of scenery: not used")
            )
            continue
        if link.role == "trailer" and link.data.get("value") in ("each_side", "middle"):
            pairs = surrounded(str(link.data["value"]), clauses, position, before, after)
        elif (sides := placed_by_the_middle(clauses, position)) is not None:
            # "To the north an orchard; in the middle wheat; to the south potatoes": each
            # side's field against the one in the middle
            pairs = (str(link.data["value"]), sides[0], (sides[1],))
        elif link.role == "relation" and (shared := shared_subject(clauses, position, read)):
            # "a potato field east of a carrot field and west of a cabbage field"
            pairs = (link.data.get("value", "next_to"), shared, (clause.mentions[0],))
        elif (earlier := _the_first(clause, before)) is not None:
            # "one field of wheat, one of maize, and a second wheat field beside the
            # first": the first field of the same crop
            pairs = (link.data.get("value", "next_to"), before[-1], (earlier,))
        elif (between := between_said_last(clauses, position)) is not None:
            # "a tomato plot and a pepper plot, with a lettuce strip in between"
            pairs = ("between", between[0], between[1:])
        elif (between := fronted_between(clauses, position)) is not None:
            # "Between the orchard and the vines, a vegetable garden"
            pairs = ("between", between[0], between[1:])
        elif (fronted := fronted_pair(clauses, position)) is not None:
            # "...; west of the peppers an onion plot": the field after the object
            pairs = (
                (link.data.get("value", "next_to"), fronted[0], (fronted[1],))
                if link.role != "between"
                else ("between", fronted[0], (fronted[1], fronted[1]))
            )
        else:
            # "pears on the north block, bananas ...": a trailer right after a field
            # places that field ("..., and to the north, pears" places the one after).
            attached = attached_to_the_field_before(clauses, position)
            pairs = relation_mentions(
                link,
                before,
                after,
                pronoun=pronoun,
                attached=attached,
                fields=lambda m: len(members.get(id(m), ())) or m.count or 1,
            )
        if pairs is None and (gap := gap_between_the_two(clauses, position, members)):
            # "durum wheat and dinkel strips, ..., half a metre gap between them": the
            # two fields side by side, the gap between them
            relations.append(
                RelationIntent(kind="next_to", subject=gap[0], objects=(gap[1],), text=link.raw)
            )
            continue
        if pairs is None:
            warnings.append(f"ignored {link.raw!r}: it needs a field on each side")
            continue
        kind, subject, objects = pairs
        if position in directed and kind == "next_to":
            kind = str(clauses[directed[position]].link.data["value"])  # type: ignore[union-attr]
        if pronoun and not the_two and len(objects) == 1:
            word = clause.items[0].norm
            if (
                parallel is not None
                and parallel[0] == word
                and parallel[1] is objects[0]
                and parallel[3] != kind
                and "next_to" not in (parallel[3], kind)
            ):
                # "A vineyard with an apple orchard north of it and a pear orchard south of
                # it": both "it"s are the vineyard (not the orchard named between); so in
                # "south of it is a carrot plot and east of it peppers" (a walk goes on
                # one way: "north of it ..., north of it ...")
                objects = (parallel[2],)
            parallel = (word, subject, objects[0], kind)
        relations.extend(field_relations(kind, subject, objects, members, link, trace))
        read.append((kind, subject, objects))
        if _both_said(clauses, position) and len(before) >= 2 and subject is before[-1]:
            # "a corn field and a wheat field, both north of an orchard": each of the two
            relations.extend(field_relations(kind, before[-2], objects, members, link, trace))
        if kind == "next_to" and len(objects) == 1 and link.norm in OTHER_SIDE:
            beyond.append((subject, objects[0], link))
        if (
            the_two
            and kind != "between"
            and len(before) >= 3
            and subject is before[-1]
            and objects == (before[-2],)
        ):
            # "Padron on the west side, Cayenne on the east side, and corn south of both"
            relations.extend(field_relations(kind, subject, (before[-3],), members, link, trace))
    for kind, subject, centre, link in further:
        # "strawberries east of the carrots, and cherries further east still": past the
        # field furthest that way already, not the one it was placed against
        objects = (furthest(kind, subject, centre, read),)
        relations.extend(field_relations(kind, subject, objects, members, link, trace))
        read.append((kind, subject, objects))
    relations += on_the_other_side(beyond, read, members, trace)
    relations += across_landmarks(landmarks, members, trace)
    related = {frozenset((r.subject, *r.objects)) for r in relations if len(r.objects) == 1}
    # ("onions, then carrots ..., and a strip of lettuce between the onions and the
    # carrots": a field placed between two is placed against each of them)
    related |= {
        frozenset((r.subject, other))
        for r in relations
        if r.kind == "between"
        for other in r.objects
    }
    relations += then_chain(clauses, members, related, trace)
    relations += one_side_and_the_other(clauses, members, relations, trace)
    said_between = [frozenset((r.subject, *r.objects)) for r in relations if r.kind == "between"]
    relations += [
        r
        for r in middles
        if not any(len(said & {r.subject, *r.objects}) >= 2 for said in said_between)
    ]
    # "San Marzano and beef tomatoes, with cherry tomatoes in between them": two fields
    # with a third between them are not next to each other
    flanking = {frozenset(r.objects) for r in relations if r.kind == "between"}
    relations = [
        r
        for r in relations
        if not (r.kind == "next_to" and frozenset((r.subject, *r.objects)) in flanking)
    ]
    unique: dict[tuple[object, ...], RelationIntent] = {}
    for relation in relations:  # "in a line, in this order": one row
        unique.setdefault((relation.kind, relation.subject, relation.objects), relation)
    return list(unique.values())


#: How the field named before is said ("right up against the one before").
_THE_ONE_BEFORE = (
    ["the", "one", "before"],
    ["the", "one", "before", "it"],
    ["the", "previous", "one"],
    ["the", "one", "before", "that"],
)


def _each_against_the_one_before(clauses: Sequence[Clause], position: int) -> bool:
    """Whether clause ``position`` places against "the one before" right after "each"
    said of the fields ("..., each block right up against the one before")."""
    clause = clauses[position]
    words = [i.norm for i in clause.items]
    previous = clauses[position - 1] if position else None
    return (
        not clause.mentions
        and words in _THE_ONE_BEFORE
        and previous is not None
        and not previous.mentions
        and bool(previous.items)
        and previous.items[0].norm in ("each", "every")
    )


def _both_fronted(clause: Clause) -> bool:
    """Whether a relation clause opens with "both" and the fields it names again, before
    the one field of its own ("north of both onion fields a field of carrots")."""
    first_head = min(h.start for h in clause.mentions[0].heads)
    before = [i for i in clause.items if i.start < first_head]
    return (
        bool(before)
        and before[0].norm == "both"
        and (
            any(i.role in ("head", "plot") for i in before)
            # ("... and to the west of both an orchard": "both" alone, then the new field)
            or [i.norm for i in before[1:]] in (["a"], ["an"])
        )
    )


#: The marks that end a sentence for a placement's fields ("." and not ";").
_FULL_STOPS = frozenset({".", "!", "?"})


def _sentence_end(clauses: Sequence[Clause], position: int) -> int:
    """The index of the first clause after ``position`` that opens a new sentence."""
    return next(
        (
            index
            for index in range(position + 1, len(clauses))
            # (a full stop, not a semicolon: "Navel ... on the north side; Valencia Late
            # ... on the south side" goes on about the same placing)
            if (link := clauses[index].link) is not None and link.norm in _FULL_STOPS
        ),
        len(clauses),
    )


def _the_first(clause: Clause, before: Sequence[Mention]) -> Mention | None:
    """The field "the first" points at after "a second X": the first named of X's crop."""
    if clause.mentions or [i.norm for i in clause.items] not in (["the first"], ["the first one"]):
        return None
    if not before or not (crops := strong_crops(before[-1])):
        return None
    return next((m for m in before[:-1] if strong_crops(m) == crops), None)


#: What "everything" a field is placed against may be said as ("south of all the rest").
_EVERYTHING = frozenset(
    {
        "everything",
        "everything else",
        "all the rest",
        "the rest",
        "all the others",
        "the others",
        "all of them",
        "all the other fields",
        "all the other plots",
    }
)


def _of_everything(clause: Clause) -> bool:
    """Whether a relation's clause names every other field ("south of everything")."""
    return not clause.mentions and " ".join(i.norm for i in clause.items) in _EVERYTHING


def _both_said(clauses: Sequence[Clause], position: int) -> bool:
    """Whether "both" (or "both of them") alone stands right before the relation at
    ``position``, after two fields joined by "and"."""
    if position < 2:
        return False
    previous = clauses[position - 1]
    words = [i.norm for i in previous.items]
    index = position - 2
    while index > 0 and not clauses[index].mentions and not clauses[index].items:
        index -= 1  # ("Lollo and Bibb lettuce in adjacent beds, both west of ...")
    joined = clauses[index]
    if (
        # "Onions and carrots both sit south of the wheat": "both" said with the second
        len(previous.mentions) == 1
        and previous.link is not None
        and previous.link.role == "conjunction"
        and "both" in words[1:]
        and all(i.role in ("head", "plot", "all", "unknown", "filler") for i in previous.items)
        and bool(clauses[position - 2].mentions)
    ):
        return True
    if (
        # "The Malling Centenary strawberries are west of the Sonata ones, and both lie
        # east of the Nantes carrots": the two just placed against each other
        not previous.mentions
        and previous.link is not None
        and previous.link.norm == "and"
        and words[:1] == ["both"]
        and all(w in _BOTH_VERBS for w in words[1:])
        and sum(len(c.mentions) for c in clauses[sentence_start(clauses, position) : position]) >= 2
    ):
        return True
    return (
        not previous.mentions
        and words[:1] == ["both"]
        and all(w in ("both", "of", "them") for w in words)
        and bool(joined.mentions)
        and joined.link is not None
        and joined.link.role == "conjunction"
    )


#: Verbs "both" may take before a relation word ("and both lie east of the carrots").
_BOTH_VERBS = frozenset({"lie", "are", "sit", "stand", "run", "go", "grow", "of", "them"})


#: Roles of the words that describe the field just named ("Navel oranges, ripe and being
#: picked, on the north side").

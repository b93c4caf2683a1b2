"""Fields placed by a direction said around them.

"wheat to the north, maize to the south" (trailing directions: :func:`placements`
and :func:`placement_pairs`), "West of the peppers, an onion plot" (a fronted
relation), "To the north an orchard; in the middle ..." (placed against the middle
field), "further north again, beyond the orchard, there's wheat" (a direction that
gives "next to" its side). :func:`agrirecipe.resolve._relations.read_relations`
calls them in its order.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._landmarks import landmark_said_before
from agrirecipe.resolve._links import OPPOSITE, PRONOUNS, before_brackets, link_norm
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = [
    "a_distance",
    "attached_to_the_field_before",
    "between_said_last",
    "directed_neighbours",
    "fronted_between",
    "fronted_pair",
    "placed_by_the_middle",
    "placement_pairs",
    "placements",
    "predicate_of_the_placed",
    "shared_subject",
]


#: The verbs that open what is said of a sentence's subject ("... is ripe", "... are
#: covered in ripe fruit").
_COPULAS = frozenset({"is", "are"})
#: Verbs whose words after a placed field may be said of the subject ("... have blight").
_VERBS = frozenset({*_COPULAS, "has", "have"})
_PLURAL_VERBS = frozenset({"are", "have"})


def _plural(mention: Mention) -> bool:
    """Whether a mention names its field(s) in the plural ("the tomatoes", "two plots")."""
    if mention.plot is not None:
        return bool(mention.plot.get("plural"))
    last = max(mention.heads, key=lambda h: h.end, default=None)
    return last is not None and last.tokens[-1].norm.endswith("s")


def predicate_of_the_placed(clauses: Sequence[Clause]) -> None:
    """'The wheat north of the maize is ripe', 'the Sonata strawberries next to the
    orange grove are covered in ripe fruit': what the copula says after the field a
    subject is placed against is said of the subject; its words move to the subject's
    mention."""
    for clause in clauses[1:]:
        link = clause.link
        previous = clauses[clause.index - 1]
        _predicate_after_a_pronoun(clause, previous)
        if (
            link is None
            or link.role != "relation"
            or len(clause.mentions) != 1
            or len(previous.mentions) != 1
            or previous.loose
        ):
            continue
        subject, placed = previous.mentions[0], clause.mentions[0]
        words = sorted(placed.items, key=lambda item: item.start)
        said = [i for i in subject.items if i.norm in _COPULAS]
        heads = [i.start for i in placed.heads]
        if not subject.has_crop or said or not heads:
            continue
        copula = next(
            (n for n, i in enumerate(words) if i.norm in _VERBS and i.start > max(heads)), None
        )
        if copula is None:
            continue
        verb = words[copula].norm
        # (the subject is its sentence's first field: not "apples and the wheat north of
        # ... is ripe", but "February, and the strawberries next to ..."; or the verb
        # agrees with it and not with the field it is placed against: "..., and the
        # tomatoes next to the vineyard have late blight")
        agrees = _plural(subject) == (verb in _PLURAL_VERBS) != _plural(placed)
        if not (agrees or (verb in _COPULAS and _first_of_its_sentence(clauses, previous))):
            continue
        moved = words[copula:]
        gone = {id(i) for i in moved}
        placed.items = [i for i in placed.items if id(i) not in gone]
        subject.items.extend(moved)


def _predicate_after_a_pronoun(clause: Clause, previous: Clause) -> None:
    """'and the strawberry field beside it is only young plants', '... next door is
    young plants': the field is placed against the one before (a pronoun, or a relation
    without object), and what the copula then says is the field's own, not words about
    every field's plants."""
    words = sorted(clause.loose, key=lambda item: item.start)
    link = clause.link
    if link is not None and link.role == "relation" and words and words[0].norm in PRONOUNS:
        words = words[1:]
    elif link is None or link.role != "trailer":
        return
    if (
        clause.mentions
        or len(previous.mentions) != 1
        or previous.loose
        or not previous.mentions[0].has_crop
        or len(words) < 2
        or words[0].norm not in _COPULAS
    ):
        return
    moved = words[1:]
    gone = {id(i) for i in moved}
    clause.loose = [i for i in clause.loose if id(i) not in gone]
    previous.mentions[0].items.extend(moved)


def _first_of_its_sentence(clauses: Sequence[Clause], clause: Clause) -> bool:
    """Whether no field is named in ``clause``'s sentence before it."""
    index = clause.index
    while (link := clauses[index].link) is not None and link.norm not in SENTENCE_MARKS:
        index -= 1
        if clauses[index].mentions:
            return False
    return True


def directed_neighbours(clauses: Sequence[Clause]) -> dict[int, int]:
    """'further north again, beyond the orchard, there's wheat': a direction said on its
    own just before a 'next to' word gives that word its side. Maps the position of
    the 'next to' clause to the direction's."""
    found: dict[int, int] = {}
    for position, clause in enumerate(clauses):
        link = clause.link
        if (
            link is None
            or link.role != "trailer"
            or link.data.get("value") not in OPPOSITE
            or clause.mentions
            or any(i.role != "filler" for i in clause.items)
        ):
            continue
        following = position + 1
        while (
            following < len(clauses)
            and not clauses[following].items
            and clauses[following].link is not None
            and clauses[following].link.role == "separator"  # type: ignore[union-attr]
        ):
            following += 1
        if following < len(clauses):
            nxt = clauses[following].link
            if nxt is not None and nxt.role == "relation" and nxt.data.get("value") == "next_to":
                found[following] = position
    return found


def placed_by_the_middle(
    clauses: Sequence[Clause], position: int
) -> tuple[Mention, Mention] | None:
    """The field a direction opening clause ``position`` places ("To the north an
    orchard; in the middle ...") and the field "in the middle" it is placed against, or
    None."""
    clause = clauses[position]
    link = clause.link
    if link is None or link.role != "trailer" or link.data.get("value") not in OPPOSITE:
        return None
    placed = _opened_by(clauses, position)
    if placed is None:
        return None
    middles = [
        c.mentions[0]
        for c in clauses
        if c.link is not None
        and c.link.role == "trailer"
        and c.link.data.get("value") == "middle"
        and len(c.mentions) == 1
    ]
    if len(middles) != 1 or middles[0] is placed:
        return None
    return placed, middles[0]


def _opened_by(clauses: Sequence[Clause], position: int) -> Mention | None:
    """The one field a direction opening clause ``position`` places: in that clause ("To
    the north an orchard") or right after a comma ("To the north, the orchard, ...")."""
    clause = clauses[position]
    if len(clause.mentions) == 1 and clause.items[:1] == clause.mentions[0].items[:1]:
        return clause.mentions[0]
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    if (
        not clause.mentions
        and not clause.items
        and following is not None
        and following.link is not None
        and following.link.norm == ","
        and len(following.mentions) == 1
    ):
        return following.mentions[0]
    return None


def a_distance(clause: Clause) -> bool:
    """A clause of only a distance ("20 m" before "south of them")."""
    return any(i.role == "length_unit" for i in clause.items) and all(
        i.role in ("filler", "number", "length_unit") for i in clause.items
    )


def fronted_pair(clauses: Sequence[Clause], position: int) -> tuple[Mention, Mention] | None:
    """'West of the peppers, an onion plot', 'north of A: Conference pears', 'Between the
    two orchards there's a vegetable garden': a relation that opens its sentence, its
    object and then its subject (subject, object)."""
    clause = clauses[position]
    link = clause.link
    if link is None or link.role not in ("relation", "between") or not clause.mentions:
        return None
    if link.role == "between" and (clause.mentions[0].count or 1) < 2:
        return None  # ("Between the two orchards there's a vegetable garden": two sides)
    if position:
        previous = clauses[position - 1]
        # ("plot 2, 10 m west of plot 1, is wheat": a distance before the relation)
        opens = (not previous.items or a_distance(previous)) and (
            previous.link is None
            or previous.link.norm in (";", ".", ":", "!", ",")
            or previous.link.role == "conjunction"  # ", and south of the bananas a citrus"
        )
        if not opens:
            return None
    if len(clause.mentions) >= 2:
        subject, target = clause.mentions[1], clause.mentions[0]
    else:
        after = position + 1
        target = clause.mentions[0]
        while after + 1 < len(clauses) and (
            _aside(clauses[after])
            or _beside_it_again(clauses[after])
            or _describes(clauses[after], target)
        ):
            # "south of the orchard, across the lane, there's ...": scenery between; "east
            # of that field, right up against it, onions": the same place said closer;
            # "beside the Gala block, where the apples are colouring up, ...": the object
            # described
            after += 1
        following = clauses[after] if after < len(clauses) else None
        # ("two plots: wheat, and south of the wheat, maize": a member of a plural said
        # after the relation, as its subject)
        if (
            following is None
            or following.link is None
            or following.link.norm not in (":", ",")
            or not following.named
        ):
            return None
        subject, target = following.named[0], clause.mentions[0]
    return None if subject is target else (subject, target)


#: Marks after which a clause opens a sentence.
_OPENINGS = SENTENCE_MARKS | {":"}


def fronted_between(
    clauses: Sequence[Clause], position: int
) -> tuple[Mention, Mention, Mention] | None:
    """'Between the orchard and the vines, a vegetable garden': a "between" that opens its
    sentence, its two sides joined by "and", then the field between them (subject, side,
    side)."""
    clause = clauses[position]
    link = clause.link
    if (
        link is None
        or link.role != "between"
        or len(clause.mentions) != 1
        or (clause.mentions[0].count or 1) > 2
        or position + 2 >= len(clauses)
    ):
        return None
    if position and (
        clauses[position - 1].items
        # (the prompt's opening, or after a full stop or colon)
        or (
            clauses[position - 1].link is not None
            and link_norm(clauses[position - 1]) not in _OPENINGS
        )
    ):
        return None
    if clause.mentions[0].count == 2:
        # "Between my two maize fields, both Dent, I've got a strip of Sonata": the two
        # fields counted, past words about them, then the field between them
        pair = clause.mentions[0]
        for later in clauses[position + 1 :]:
            if later.refined_parent is pair or not later.mentions:
                continue
            if link_norm(later) not in (",", ":") or len(later.mentions) != 1:
                return None
            return later.mentions[0], pair, pair
        return None
    other, placed = clauses[position + 1], clauses[position + 2]
    if (
        link_norm(other) != "and"
        or len(other.mentions) != 1
        or link_norm(placed) not in (",", ":")
        or len(placed.mentions) != 1
    ):
        return None
    subject, sides = placed.mentions[0], (clause.mentions[0], other.mentions[0])
    if any(subject is side for side in sides) or sides[0] is sides[1]:
        return None
    return subject, sides[0], sides[1]


def between_said_last(
    clauses: Sequence[Clause], position: int
) -> tuple[Mention, Mention, Mention] | None:
    """'a tomato plot and a pepper plot, with a lettuce strip in between': a "between"
    that ends its sentence, after the field it places and the two named before that
    (subject, side, side)."""
    clause = clauses[position]
    link = clause.link
    if link is None or link.role != "between" or clause.mentions or clause.items:
        return None
    following = clauses[position + 1] if position + 1 < len(clauses) else None
    if following is not None and link_norm(following) not in _OPENINGS:
        return None
    named: list[Mention] = []
    for earlier in reversed(clauses[:position]):
        for mention in reversed(earlier.mentions):
            if all(mention is not m for m in named):
                named.append(mention)
        if link_norm(earlier) in _OPENINGS:
            break
    if len(named) != 3 or any((m.count or 1) != 1 for m in named):
        return None
    subject, second, first = named
    return subject, first, second


def _aside(clause: Clause) -> bool:
    """A clause of a comma and filler only ("across the lane")."""
    return (
        not clause.mentions
        and clause.link is not None
        and clause.link.norm == ","
        and all(i.role in ("filler", "side", "of") for i in clause.items)
    )


def _describes(clause: Clause, target: Mention) -> bool:
    """A clause that only describes ``target`` ("where the apples are colouring up")."""
    return (
        clause.link is not None
        and clause.link.role != "relation"
        and bool(clause.mentions)
        and all(mention is target for mention in clause.mentions)
    )


def _beside_it_again(clause: Clause) -> bool:
    """ "right up against it", "right next to it": the field just placed, said to touch."""
    return (
        not clause.mentions
        and clause.link is not None
        and clause.link.role == "relation"
        and clause.link.data.get("value") == "next_to"
        and [i.norm for i in clause.items] in (["it"], ["them"])
    )


#: Words a placed field's clause may go on with after the direction: its own details.
_OWN = frozenset({"filler", "geometry", "of"})


def placements(clauses: Sequence[Clause], members: dict[int, list[int]]) -> dict[int, Mention]:
    """Fields placed by a trailing direction right after them: "wheat to the north, ...".

    Maps the position of the trailer's clause to the one mention of the clause before
    it ("an orchard with wheat to the north" names two and is read as before).
    """
    placed: dict[int, Mention] = {}
    for position, clause in enumerate(clauses):
        link = clause.link
        if link is None or link.role != "trailer" or link.data.get("value") not in OPPOSITE:
            continue
        if position == 0 or clause.mentions or any(i.role not in _OWN for i in clause.items):
            continue  # ("Gala on the north side planted at 3.5 m by 1 m": its own measures)
        if _across_a_landmark(clauses, position):
            continue  # ("The farmhouse is in the middle. Wheat north of it, maize to the south")
        before = clauses[position - 1]
        if (
            # (past a distance: "and, 20 m to the east, Durondeau pears")
            all(i.role in ("filler", "length_unit", "number") for i in before.items)
            and not before.mentions
            and link_norm(before) == ","
            and position >= 2
            and _a_bare_and(clauses[position - 2])
            and position + 1 < len(clauses)
        ):
            # "Bing cherries and, to the east, Durondeau pears": the field after it
            after = clauses[position + 1]
            following = after.mentions or ([after.refinement] if after.refinement else [])
            if len(following) == 1 and id(following[0]) in members:
                placed[position] = following[0]
            continue
        if not before.items and link_norm(before) in (".", "!", "?"):
            continue  # ("... 14 rows. To the south, a Navel block": it places what follows)
        if (
            not before.items
            and link_norm(before) == ";"
            and position + 1 < len(clauses)
            and link_norm(clauses[position + 1]) == ","
            and clauses[position + 1].named
        ):
            continue  # ("...; on the west, Elsanta in the same layout": so after a semicolon)
        previous = clauses[_past_a_bracket(clauses, position - 1)].named
        if len(previous) == 1 and id(previous[0]) in members:
            placed[position] = previous[0]
    return placed


def _across_a_landmark(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the trailer at ``position`` answers the relation said before it against a
    landmark ("The farmhouse is in the middle. Wheat to the north of it, maize to the
    south": the maize is south of the farmhouse too)."""
    links = [c.link for c in clauses]
    trailer = links[position]
    for earlier in range(position - 1, 0, -1):
        link = links[earlier]
        if link is not None and link.role == "relation":
            return (
                trailer is not None
                and landmark_said_before(clauses, earlier) is not None
                and OPPOSITE.get(str(link.data.get("value"))) == trailer.data.get("value")
            )
    return False


def _a_bare_and(clause: Clause) -> bool:
    """A clause of nothing but its joining word ("and", "&")."""
    link = clause.link
    return (
        not clause.items and not clause.mentions and link is not None and link.role == "conjunction"
    )


def _past_a_bracket(clauses: Sequence[Clause], index: int) -> int:
    """``index``, or the clause before the bracket that clause ``index`` closes ("a
    Cabernet vineyard (2.7 m rows) to the south": the vineyard is placed)."""
    link = clauses[index].link
    if clauses[index].named or link is None or link.norm != ")":
        return index
    for back in range(index - 1, 0, -1):
        opening = clauses[back].link
        if opening is not None and opening.norm == "(":
            # ("(2.7 m rows, 1.2 m vines)": the bracket may name the same field again)
            inside = {id(m) for c in clauses[back:index] for m in c.named}
            return back - 1 if inside <= {id(m) for m in clauses[back - 1].named} else index
    return index


def placement_pairs(
    clauses: Sequence[Clause], members: dict[int, list[int]], placed: dict[int, Mention]
) -> list[tuple[int, Mention, Mention]]:
    """(trailer position, placed field, what it is placed relative to) for each placement.

    A placed field is related to the nearest field named without a direction (the
    one before it, else the first after it): "an orchard, wheat to the north and
    maize to the south", "wheat to the north, maize to the south and strawberries
    between them". With no such field, opposite placements relate to each other:
    "wheat to the north, maize to the south" is wheat north of maize. A placement
    left without a partner is dropped here and read the usual way.
    """
    placed_ids = {id(m) for m in placed.values()}
    # A field placed by a direction word of its own ("valencia oranges north of it")
    # is not the centre others are placed around.
    for clause, following in itertools.pairwise(clauses):
        link = following.link
        if (
            clause.mentions
            and link is not None
            and link.role == "relation"
            and link.data.get("value") in OPPOSITE
        ):
            placed_ids.add(id(clause.mentions[-1]))
    free = [m for c in clauses for m in c.named if id(m) not in placed_ids and id(m) in members]
    pairs: list[tuple[int, Mention, Mention]] = []
    waiting: list[tuple[int, Mention]] = []
    for position, mention in placed.items():
        earlier = [m for m in free if m.clause < mention.clause]
        later = [m for m in free if m.clause > mention.clause]
        centre = earlier[-1] if earlier else (later[0] if later else None)
        if centre is not None:
            pairs.append((position, mention, centre))
            continue
        kind = clauses[position].link.data["value"]  # type: ignore[union-attr]
        partner = next(
            (
                (p, m)
                for p, m in waiting
                if clauses[p].link.data["value"] == OPPOSITE[kind]  # type: ignore[union-attr]
            ),
            None,
        )
        if partner is None:
            waiting.append((position, mention))
            continue
        waiting.remove(partner)
        pairs.append((partner[0], partner[1], mention))
    for position, _ in waiting:
        del placed[position]
    return pairs


def shared_subject(
    clauses: Sequence[Clause],
    position: int,
    read: Sequence[tuple[str, Mention, tuple[Mention, ...]]],
) -> Mention | None:
    """The subject of the relation said just before, when the relation at ``position``
    goes on with "and" and no subject of its own ("a potato field east of a carrot field
    and west of a cabbage field": the potatoes are west of the cabbage, not the carrots).
    """
    clause = clauses[position]
    joint = clauses[position - 1] if position else None
    if (
        len(clause.mentions) != 1
        or clause.mentions[0].clause != clause.index
        or not clause.items
        or clause.items[0].norm in PRONOUNS
        or joint is None
        or joint.items
        or link_norm(joint) != "and"
        or position < 2
    ):
        return None
    said = clauses[before_brackets(clauses, position - 1)]
    if said.link is None or said.link.role != "relation" or len(said.mentions) != 1:
        return None
    object_ = said.mentions[0]
    return next((subject for _, subject, objects in reversed(read) if objects == (object_,)), None)


_DESCRIBING = frozenset({"cue", "stage", "health", "filler", "unknown", "season", "month"})
_MEASURES = frozenset({"size", "geometry", "area"})


def attached_to_the_field_before(clauses: Sequence[Clause], position: int) -> bool:
    """Whether the relation at ``position`` right follows a field, or follows it past
    clauses that only describe it ("Navel oranges, ripe and being picked, on the north
    side; Valencia Late on the south side")."""
    index, described = position - 1, False
    previous = clauses[index]
    # ("Red Baron plot, 5 m x 20 m, to the north; Sturon plot ...": a direction that
    # closes its part of the sentence places the field of that part, past its measures)
    closes = (
        not clauses[position].items
        and position + 1 < len(clauses)
        and link_norm(clauses[position + 1]) in SENTENCE_MARKS
    )
    describing = _DESCRIBING | _MEASURES if closes else _DESCRIBING
    if not previous.items and link_norm(previous) in SENTENCE_MARKS:
        # ("... 14 rows. To the south, a Navel block": it opens a sentence; so it does
        # after a semicolon: "On the east, Albion ...; on the west, Elsanta ...")
        return False
    while index > 0 and not clauses[index].named:
        clause = clauses[index]
        if (
            clause.link is None
            or clause.link.norm not in (",", "and")
            or any(i.role not in describing for i in clause.items)
        ):
            return False
        # ("Winter Wheat just emerged, thin green lines, on the west side of the lane":
        # words after a comma describe it, read as a look or not; not "... and zone C on
        # the south side is peppers", a label of the field after)
        described = described or (
            any(i.role in ("cue", "stage", "health") for i in clause.items)
            or (bool(clause.items) and clause.link.norm == ",")
        )
        index -= 1
    # (not "apples, and to the north, pears": nothing said of the apples in between)
    return index >= 0 and bool(clauses[index].named) and (index == position - 1 or described)

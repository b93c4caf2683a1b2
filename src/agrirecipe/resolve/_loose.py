"""Head-less clauses' words to their fields (issue 8's reading, step 11).

A clause that names no field ("..., 10 rows each at 76 cm", "Fruit ripening, mid-August",
"and some plants wilting") says something of fields named elsewhere. :func:`attach_loose`
decides which: the field named right after it ("In autumn, ..."), the members of the list
it closes ("..., 8 rows each"), the field a description goes on about, the field named
last in a relative clause ("whose fruit has scabby spots"), the field placed past a
pronoun ("... next to them has yellowing"), or the coordinated fields before it; words
said of every field ("all", "everywhere") are returned for the whole scene.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._fields import (
    ATTRIBUTE_ROLES,
)
from agrirecipe.resolve._lexicon import (
    Item,
    reader_words,
)
from agrirecipe.resolve._links import PRONOUNS, coordinated, link_norm
from agrirecipe.resolve._measures import (
    after_list_plots,
    bracketed_by,
    each_row_long,
    heads_a_list,
    in_a_sentence_of_measures,
    opens_with_rows,
    parallel_fields,
    sentence_fields,
    sentence_start,
    shared_by_all,
    shared_by_all_after,
)
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    attribute_of,
    describing_verbs,
    descriptive_words,
    per_bed,
    strong_crops,
)
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = ["attach_loose"]


def attach_loose(clauses: Sequence[Clause], mentions: Sequence[Mention]) -> list[Item]:
    """Give each head-less clause's attributes to its field(s); return scene-wide items."""
    scene: list[Item] = []
    carried: tuple[int, list[Mention]] | None = None  # the last clause's own targets
    said_all = -1  # the last clause whose words were said of every field ("both ...")
    for position, clause in enumerate(clauses):
        _detach_trailing_all(clause)
        _all_of_the_parts(clause)
        if position and mentions:
            _apply_group_words(clause.loose, coordinated(clauses, position))
        attributes = [i for i in clause.loose if i.role in ATTRIBUTE_ROLES]
        before = [m for c in clauses[:position] for m in c.mentions]
        if not attributes and mentions and (described := _described_crop(clause, before)):
            # "the cherry trees are draped in white netting with the fruit deep red and
            # ripe": what follows still describes the cherries
            carried = (position, described)
        if not attributes or not mentions:
            continue
        refined = clauses[position - 1].refined_parent if position else None
        after = [m for c in clauses[position + 1 :] for m in c.mentions]
        says_all = any(i.role == "all" for i in attributes)
        seasons = [i for i in attributes if i.role in ("season", "month")]
        others = [i for i in attributes if i.role not in ("season", "month", "all")]
        if _about_the_others(clause):
            # "make the corn biggest like 5 ha, the others 1 ha each": every field
            # that does not say the same of itself
            for mention in mentions:
                # (each member of a counted plural, not the plural its members share)
                for sub in {id(r): r for r in mention.refinements}.values() or (mention,):
                    roles = {i.role for i in sub.items}
                    sub.items.extend(i for i in others if i.role not in roles)
            continue
        alls = [i for i in attributes if i.role == "all"]
        if says_all and after and all(i.norm in reader_words("here_everywhere") for i in alls):
            # "Field A - Russet potatoes, blight everywhere. Field B - ...": everywhere
            # in the field just named, when more fields follow
            attributes = [i for i in attributes if i.role != "all"]
            says_all = False
        pair = coordinated(clauses, position + 1) if clause.mentions else []
        fields = sum(len(m.refinements) or (m.count or 1) for m in mentions)
        if says_all and all(i.norm == "both" for i in alls) and len(pair) == 2 and fields > 2:
            # "Cherries and strawberries are both flowering, the potatoes were only just
            # planted": "both" is the two just named, not every field
            for mention in pair:
                mention.items.extend(i for i in attributes if i.role != "all")
            continue
        if says_all or _goes_on_saying_all(clauses, position, said_all):
            owner = bracketed_by(clauses, position)  # "two lettuce plots (10 rows each"
            (owner.items if owner is not None else scene).extend(attributes)
            said_all = position
            continue
        several = len(mentions) > 1 or any((m.count or 1) > 1 for m in mentions)
        if not before or (several and not after):
            # Opening words ("In autumn, ...") or closing words after several fields:
            # a time of year belongs to the whole scene.
            scene.extend(seasons)
            seasons = []
        if (with_list := _closes_a_with_list(clauses, position)) is not None:
            # "Fontane on the right with late blight, blackened leaves and collapsed
            # plants": the last words of a "with" list are still that field's
            with_list.items.extend(
                seasons + others + [i for i in attributes if i.role == "geometry"]
            )
            carried = (position, [with_list])
            continue
        if (
            before
            and not after
            and (len(before) > 1 or any((m.count or 1) > 1 for m in before))
            # (not inside the bracket of measures after the last field: "... between two
            # Fuji blocks (rows 3.5 m, trees 1 m)" is the Fuji blocks')
            and bracketed_by(clauses, position) is None
            # ("Albion strawberries, ripe; ... Beefsteak tomatoes, young plants": each field
            # its own look, so the last words are the last field's)
            and not _said_by_each(before, others)
            and (
                any(_says_all_plants(i) for i in others)
                # "... 8 rows. Trees in bloom.": a sentence about the plants in general
                or (
                    clause.link is not None
                    and clause.link.norm in (".", "!")
                    and bool(clause.items)
                    # ("... 80 m rows. Fruit ripening, mid-August.")
                    and clause.items[0].norm in (*_ALL_PLANTS, "fruit")
                )
                # "comice pears west of bartlett pears, late summer, fruit colouring
                # up": the plants of fields of one crop, said after them all
                or (
                    bool(clause.items)
                    and clause.link is not None
                    and clause.link.norm == ","
                    and clause.items[0].norm.split()[0] in (*_ALL_PLANTS, "fruit")
                    and len({id(m) for m in before}) > 1
                    and len({frozenset(strong_crops(m)) for m in before}) == 1
                    and bool(strong_crops(before[0]))
                )
                # "... onions in 12 rows. Rows are 60 m.": a closing sentence of
                # row measures is about every field's rows
                # ("... Granny Smith. Tall spindle, 3.5 m between rows, trees 1 m
                # apart, rows 120 m long.": each clause of a sentence of measures)
                or in_a_sentence_of_measures(clauses, position)
            )
        ):
            # "A next to B, young plants": closing words about "the plants" describe all.
            for target in before:
                target.items.extend(others)
            continue
        targets: list[Mention] = []
        shared_by_list = False
        forward = after[0] if after else None
        next_link = clauses[position + 1].link if position + 1 < len(clauses) else None
        starts_bare = (
            position + 1 < len(clauses)
            and bool(clauses[position + 1].items)
            and clauses[position + 1].items[0].role not in ("number", "quantity", "filler")
        )
        in_brackets = bracketed_by(clauses, position) if clause.link is not None else None
        if in_brackets is not None and clause.link is not None and clause.link.norm == "(":
            # "valencia one bigger (4ha), moro one 2ha": a bracket is about what it follows
            targets = [in_brackets]
        elif not before or (
            next_link is not None
            and next_link.role == "conjunction"
            and forward is not None
            and forward.clause == position + 1
            and starts_bare
            # ("onions, mature, sept, 1 ha + 1 ha of spuds": the spuds say their own)
            and not {i.role for i in attributes} & {i.role for i in forward.items}
            # (not "dent corn (field corn) 76cm rows & flint corn": after a bracket that
            # closes on the field before)
            and link_norm(clause) != ")"
        ):
            targets = [forward] if forward is not None else []
        elif _same_as_before_next(clauses, position, attributes, forward):
            # "Plot A is 200 ft by 300 ft of Roma. Plot B is the same size, Beefsteak."
            targets = [forward] if forward is not None else []
        elif refined is not None and refined.refinements:
            # The member the clause before named ("carrots (75 cm ridges), onions ..."),
            # or all of them ("..., 8 rows each at 76 cm").
            member = clauses[position - 1].refinement
            members = list({id(m): m for m in refined.refinements}.values())
            if clause.refined_parent is refined and clause.refinement is None:
                targets = members
                shared_by_list = True
            elif (
                any(i.role == "all" for i in refined.items)
                and member is members[-1]
                and len(members) >= (refined.count or 2)
            ):
                # "Both our fields, the tomatoes and the capsicum, have some disease": the
                # heading said "both" of the members listed after it
                targets = members
            else:
                targets = [member or refined.refinements[-1]]
        elif (opened := _member_opening(clauses, position)) is not None:
            # "Two maize fields. The other, east of the first, is 0.8 ha, rows east-west":
            # the sentence a member opens goes on about that member
            targets = [opened]
        elif clause.link is not None and clause.link.norm == "also" and before:
            # "a popping corn block, also 30 rows at 30 in": the same again, for it (the
            # field named last, not one named again: "peppers east of the tomatoes, also
            # on 1.2 m rows" are the peppers')
            targets = [_last_new(before)]
        elif _continues_a_description(clauses, position):
            # "the oranges colouring up, the bananas still small and just planted"
            targets = [clauses[position - 1].mentions[-1]]
        elif any(i.data.get("list_plots") for i in clause.items):
            # "carrots (...) and potatoes (...) in 25 x 60 m plots": the list's plots
            targets = sentence_fields(clauses, position)
        elif before and (
            (clause.link is not None and clause.link.norm in ("whose", "which", "that"))
            or (bool(clause.items) and clause.items[0].norm in ("whose", "which"))
        ):
            # "Padrón peppers whose leaves are spotted and whose fruit has raised
            # scabby spots": a relative clause about the field named last ("plot 2 Red
            # Baron onions that have caught downy mildew")
            targets = [before[-1]]
        elif (placed := _placed_with(clauses, position)) is not None:
            # "cabbages in the middle with caterpillar holes chewed through the leaves":
            # a "with" after the placement of the field just named is that field's
            targets = [placed]
        elif carried is not None and carried[0] == position - 1 and _goes_on(clause):
            # "the Ladyfinger block next to them has yellowing, mottled leaves and some
            # plants wilting": the description goes on for the field it was about (unless
            # it names another crop's plants: "the cherries are ripe, the vines in flower")
            targets = _described_crop(clause, before) or carried[1]
        else:
            targets = coordinated(clauses, position)
            targets = _past_a_reference(clauses, position, targets)
            targets = _described_crop(clause, before) or targets
        carried = (position, targets)
        # Rows and spacings describe one plot: the nearest field named ("each" shares them).
        geometry = [i for i in others if i.role == "geometry"]
        others = [i for i in others if i.role != "geometry"]
        if before:
            # "Gala and Fuji, 40 and 36 rows respectively": the list stays with the
            # fields named before it (give_respectively shares it out)
            listed = [i for i in geometry if any(m.share for m in i.data["geometry"])]
            before[-1].items.extend(listed)
            geometry = [i for i in geometry if i not in listed]
        # ("... a Riesling block whose rows run east-west": the rows of the field just named)
        relative = clause.link is not None and clause.link.norm in ("whose", "which")
        if (
            geometry
            and not relative
            and (
                shared_by_all(clauses, position)
                # "Rows run east-west in both blocks": said of both in its own clause
                or any(i.role == "all" and i.norm in ("both", "each") for i in clause.items)
                or opens_with_rows(clauses, position)
                or shared_by_all_after(clauses, position)
                # "rows east-west, 2.0 m between rows: Riesling ..., Pinot Noir ...": said
                # before the list of fields a colon opens
                or heads_a_list(clauses, position)
                # "8 rows each at 1.5 m": "each" inside the measure itself
                # ("20 rows, 50 m each": each row's length)
                or any(
                    t.norm in ("each", "both")
                    for i in geometry
                    if not per_bed(i) and not each_row_long(clauses, position, i)
                    for t in i.tokens
                )
            )
        ):
            # "A, B and C, each 20 x 30 m, rows at 90°": still about each of them;
            # "two lettuce plots (10 rows each, 35 cm row spacing)": each of those
            owner = bracketed_by(clauses, position)
            (owner.items if owner is not None else scene).extend(geometry)
            if not any(i.role == "all" for i in scene):
                scene.extend(i for i in clause.items if i.role == "all")
            geometry = []
        for target in targets:
            # "ripe wheat and maize, still green": words shared by a list go to the
            # members that do not state that attribute themselves.
            # ("Cayenne chillies going red and beef tomatoes ..., but still green":
            # a visual cue states the chillies' stage)
            own = {
                attribute_of(i)
                for i in target.items
                if i.role in ("stage", "health", "cue") and i not in target.borrowed
            }
            shared = seasons + others
            if len(targets) > 1:
                shared = [i for i in shared if i.role not in own]
            said = {attribute_of(i) for i in shared}
            # Its own words replace what a list lent it ("ripe wheat and maize, ..."; a
            # look too: "ripe wheat in front and maize behind it, still green").
            target.items[:] = [
                i for i in target.items if not (i in target.borrowed and attribute_of(i) in said)
            ]
            target.items.extend(shared)
        # "Bing and Lapins cherry blocks, 5 m rows": a plural noun shared by the list
        shared_noun = (
            len(targets) > 1
            and any(h.role == "plot" and h.data["value"]["plural"] for h in targets[0].heads)
            # (a plot word of its own, named before the shared noun, ends the sharing)
            and not any(
                h.role == "plot" and h.start < min(x.start for x in targets[0].heads)
                for t in targets[1:]
                for h in t.heads
            )
        )
        parallel = parallel_fields(clauses, position) if geometry else []
        if parallel:
            for target in parallel:
                target.items.extend(geometry)
            geometry = []
        # "Durondeau and Bartlett pears in neighbouring blocks, 3.5 m x 1 m": measures
        # said after the plots a list is grown in are each plot's
        in_plots = len(targets) > 1 and after_list_plots(clauses, position)
        # "Golden Delicious apples and Durondeau pears on trellis, rows 3.2 m apart": a
        # measure opening the clause after a list whose members state none of their own
        bare_list = (
            len(targets) > 1
            and clause.link is not None
            and clause.link.norm == ","
            and bool(clause.items)
            and clause.items[0].role == "geometry"
            and not any(i.role == "geometry" for t in targets for i in t.items)
        )
        to_each = shared_by_list or shared_noun or in_plots or bare_list
        for target in targets if to_each else targets[:1]:
            target.items.extend(geometry)
    return scene


_ALL_PLANTS = frozenset({"plants", "trees", "vines", "crops", "bushes"})
_OPENINGS = frozenset({".", "!", ";", ":"})


def _member_opening(clauses: Sequence[Clause], position: int) -> Mention | None:
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


def _closes_a_with_list(clauses: Sequence[Clause], position: int) -> Mention | None:
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


def _placed_with(clauses: Sequence[Clause], position: int) -> Mention | None:
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


def _continues_a_description(clauses: Sequence[Clause], position: int) -> bool:
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


def _same_as_before_next(
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


def _goes_on(clause: Clause) -> bool:
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


def _described_crop(clause: Clause, before: Sequence[Mention]) -> list[Mention]:
    """'The Riesling vineyard ... of the Fuji orchard. Half the vines show mildew': words
    about the plants of one crop go to the last field of that crop ([] if none)."""
    crops: set[str] = set()
    for item in clause.loose:
        crops |= set(item.data.get("describes", ()))
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
    return fields[-1:]


def _goes_on_saying_all(clauses: Sequence[Clause], position: int, said_all: int) -> bool:
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


def _about_the_others(clause: Clause) -> bool:
    """A clause that opens with 'the others' / 'the rest' and says something of them."""
    first = next((i for i in clause.items if i.role != "filler"), None)
    return (
        first is not None
        and first.role == "reference"
        and first.data.get("value") == "rest"
        and any(i.role in ATTRIBUTE_ROLES and i.role != "all" for i in clause.loose)
    )


def _past_a_reference(
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


def _said_by_each(before: Sequence[Mention], others: Sequence[Item]) -> bool:
    """Whether the fields before the last already say, each, what ``others`` say (the
    same attribute, its own value): words after the last field are then its own."""
    wanted = {i.role for i in others if i.role in ("stage", "health")}
    members = [r for m in before for r in (m.refinements or [m])]
    earlier = list({id(m): m for m in members}.values())[:-1]
    return (
        bool(wanted) and bool(earlier) and all(wanted <= {i.role for i in m.items} for m in earlier)
    )


def _says_all_plants(item: Item) -> bool:
    """'young plants', 'healthy trees': an attribute phrase about the plants in general."""
    words = item.norm.split()
    # "1.2 m between trees" is one field's spacing, not words about all the plants
    return item.role != "geometry" and len(words) > 1 and words[-1] in _ALL_PLANTS


_WHOLE_PLANTS = frozenset(
    {"trees", "tree", "plants", "plant", "vines", "vine", "bushes", "crop", "crops", "palms"}
)


def _all_of_the_parts(clause: Clause) -> None:
    """'the older leaves all shrivelled': "all" right after the plants' parts is all of
    those parts, not every field; it becomes a filler word."""
    ordered = sorted(clause.loose, key=lambda i: i.start)
    # (the parts, not the plants: "trees all white w blossom" is still every tree)
    parts = descriptive_words() - _WHOLE_PLANTS
    for before, item in itertools.pairwise(ordered):
        if item.role == "all" and item.norm == "all" and before.norm in parts:
            item.role = "filler"


def _detach_trailing_all(clause: Clause) -> None:
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


def _apply_group_words(loose: Sequence[Item], group: Sequence[Mention]) -> None:
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


def _last_new(mentions: Sequence[Mention]) -> Mention:
    """Of mentions in prompt order (a field named again stands again), the one whose
    first naming came last."""
    first: dict[int, int] = {}
    for index, mention in enumerate(mentions):
        first.setdefault(id(mention), index)
    return max(mentions, key=lambda m: first[id(m)])

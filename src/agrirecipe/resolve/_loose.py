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

from collections.abc import Sequence

from agrirecipe.resolve._fields import (
    ATTRIBUTE_ROLES,
)
from agrirecipe.resolve._lexicon import (
    Item,
    reader_words,
)
from agrirecipe.resolve._links import coordinated, link_norm
from agrirecipe.resolve._loose_owners import (
    ALL_PLANTS,
    about_the_others,
    all_of_the_parts,
    apply_group_words,
    closes_a_with_list,
    continues_a_description,
    described_crop,
    detach_trailing_all,
    goes_on,
    goes_on_saying_all,
    last_new,
    member_opening,
    past_a_reference,
    placed_with,
    said_by_each,
    same_as_before_next,
    says_all_plants,
)
from agrirecipe.resolve._measures import (
    after_list_plots,
    bracketed_by,
    each_row_long,
    fields_of_the_list_headed,
    heads_a_list,
    in_a_sentence_of_measures,
    labelled_by,
    one_bed_each,
    opens_with_rows,
    parallel_fields,
    sentence_fields,
    shared_by_all,
    shared_by_all_after,
)
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    attribute_of,
    per_bed,
    strong_crops,
)
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = ["attach_loose"]

#: "each" words said right after a list of fields ("2 ha each"): said of the list.
_EACH_OF_THE_LIST = frozenset({"each", "apiece"})


def attach_loose(clauses: Sequence[Clause], mentions: Sequence[Mention]) -> list[Item]:
    """Give each head-less clause's attributes to its field(s); return scene-wide items."""
    scene: list[Item] = []
    carried: tuple[int, list[Mention]] | None = None  # the last clause's own targets
    said_all = -1  # the last clause whose words were said of every field ("both ...")
    for position, clause in enumerate(clauses):
        detach_trailing_all(clause)
        all_of_the_parts(clause)
        if position and mentions:
            apply_group_words(clause.loose, coordinated(clauses, position))
        attributes = [i for i in clause.loose if i.role in ATTRIBUTE_ROLES]
        before = [m for c in clauses[:position] for m in c.mentions]
        if not attributes and mentions and (described := described_crop(clause, before)):
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
        if about_the_others(clause):
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
        if (
            says_all
            and all(i.norm in _EACH_OF_THE_LIST for i in alls)
            and position
            # (a field said next, in the same sentence: "..., with a 0.5 ha cherry block")
            and position + 1 < len(clauses)
            and clauses[position + 1].mentions
            and link_norm(clauses[position + 1]) not in SENTENCE_MARKS
            and not clauses[position - 1].mentions[1:]
            and len(the_list := coordinated(clauses, position)) >= 2
            and len(the_list) < len({id(m) for m in mentions})
        ):
            # "an apple orchard and a pear orchard, 2 ha each, with a 0.5 ha cherry block
            # between them": each of the fields listed, not the one said after them
            for mention in the_list:
                mention.items.extend(i for i in attributes if i.role != "all")
            continue
        if says_all or goes_on_saying_all(clauses, position, said_all):
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
        if (with_list := closes_a_with_list(clauses, position)) is not None:
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
            and not said_by_each(before, others)
            and (
                any(says_all_plants(i) for i in others)
                # "... 8 rows. Trees in bloom.": a sentence about the plants in general
                or (
                    clause.link is not None
                    and clause.link.norm in (".", "!")
                    and bool(clause.items)
                    # ("... 80 m rows. Fruit ripening, mid-August.")
                    and clause.items[0].norm in (*ALL_PLANTS, "fruit")
                )
                # "comice pears west of bartlett pears, late summer, fruit colouring
                # up": the plants of fields of one crop, said after them all
                or (
                    bool(clause.items)
                    and clause.link is not None
                    and clause.link.norm == ","
                    and clause.items[0].norm.split()[0] in (*ALL_PLANTS, "fruit")
                    and len({id(m) for m in before}) > 1
                    and len({frozenset(strong_crops(m)) for m in before}) == 1
                    # ("... vines every 1.2 m. South of it, a Chardonnay block: 20 rows at
                    # 2.2 m, vines 1 m apart": the block of this sentence, not the one before)
                    and len(sentence_fields(clauses, position)) > 1
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
            # ("cherry orchard (lapins) rows 4.5m apart, trees every 2.5m, 12 rows + pear
            # orchard ...": a run of measures goes on for the field it was about)
            and not (
                carried is not None
                and carried[0] == position - 1
                and _measures_only(clause)
                and _measures_only(clauses[position - 1])
                and link_norm(clause) == ","
            )
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
        elif (
            before
            and any(i.role == "size" for i in attributes)
            and shared_by_all(clauses, position)
        ):
            # "Butterhead and Cos plots, Butterhead west of Cos, 9 plants/m2 each, 15 x 15
            # m": a size in a run of measures said of each field is each field's
            targets = sentence_fields(clauses, position)
        elif same_as_before_next(clauses, position, attributes, forward):
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
        elif (opened := member_opening(clauses, position)) is not None:
            # "Two maize fields. The other, east of the first, is 0.8 ha, rows east-west":
            # the sentence a member opens goes on about that member
            targets = [opened]
        elif clause.link is not None and clause.link.norm == "also" and before:
            # "a popping corn block, also 30 rows at 30 in": the same again, for it (the
            # field named last, not one named again: "peppers east of the tomatoes, also
            # on 1.2 m rows" are the peppers')
            targets = [last_new(before)]
        elif continues_a_description(clauses, position):
            # "the oranges colouring up, the bananas still small and just planted"
            # ("the tomatoes are red and ready, the trees are just leafing out": the plants
            # of another crop named before are that crop's)
            targets = described_crop(clause, before) or [clauses[position - 1].mentions[-1]]
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
        elif (placed := placed_with(clauses, position)) is not None:
            # "cabbages in the middle with caterpillar holes chewed through the leaves":
            # a "with" after the placement of the field just named is that field's
            targets = [placed]
        elif position and clauses[position - 1].said_of and goes_on(clause):
            # "..., peppers fruiting and ripe": still said of every field the crop named
            # again stood for
            targets = clause.said_of = clauses[position - 1].said_of
        elif carried is not None and carried[0] == position - 1 and goes_on(clause):
            # "the Ladyfinger block next to them has yellowing, mottled leaves and some
            # plants wilting": the description goes on for the field it was about (unless
            # it names another crop's plants: "the cherries are ripe, the vines in flower")
            targets = described_crop(clause, before) or carried[1]
        else:
            targets = coordinated(clauses, position)
            targets = past_a_reference(clauses, position, targets)
            targets = described_crop(clause, before) or targets
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
            if listed_count := fields_of_the_list_headed(clauses, position):
                # ("three 1.5 m beds: lettuce, onions and carrots": a bed each)
                geometry = one_bed_each(geometry, listed_count)
            # ("Tomato plots: 10 rows each, 1.5 m apart.": each of the plots the label names)
            owner = bracketed_by(clauses, position) or labelled_by(clauses, position)
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
            if len(targets) > 1 and not clause.said_of:
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


def _measures_only(clause: Clause) -> bool:
    """Whether a clause names no field and says only measures ("12 rows")."""
    return (
        not clause.mentions
        and bool(clause.items)
        and all(i.role in ("geometry", "size") for i in clause.items)
    )

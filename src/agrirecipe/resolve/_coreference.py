"""Mentions that point back at fields already named.

:func:`merge_coreferences`: "the carrots ...", "fire blight on the pears", "imperator
north of danvers" add to the field already named instead of asking for a new one.

Plots said with a field ("Gala, a 2 ha block", "..., in a field bordered by a ditch")
are in ``_appositives``; headings of lists ("three plots: wheat, maize and potatoes")
in ``_headings``.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._back_references import (
    another_variety_in_brackets,
    as_many_of_that_kind,
    bare_one,
    both_of_the_counted,
    counted_host,
    is_summary,
    it_is_a,
    it_is_the_crop,
    its_plot_named,
    labels_its_sentence,
    listed_again,
    look_then_its_place,
    named_in_order,
    of_it,
    opens_a_list,
    rows_of_a_named_crop,
    same_modifier,
    with_one_named_before,
)
from agrirecipe.resolve._decompose import MentionBuilder
from agrirecipe.resolve._descriptions import said_with_a_verb
from agrirecipe.resolve._measures import sentence_start
from agrirecipe.resolve._member_refs import per_plot
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._placed_members import (
    in_another_zone,
    on_a_side_of_it,
    other_side,
    placed_against_another,
    placed_by_a_pronoun,
    placed_first,
    placed_past_a_pronoun,
    related_to,
)
from agrirecipe.resolve._structure import (
    EACH,
    another_field,
    definite_before_head,
    definite_words,
    first_word,
    names_a_variety,
    one_of_the,
    pronoun_one,
    same_variety,
    strong_crops,
)

__all__ = ["merge_coreferences"]


def _compatible(builder: MentionBuilder, target: Mention, mention: Mention) -> bool:
    if target.refinements or target.rest is not None:
        return False
    heads = [h for h in mention.heads if h.role in ("head", "plot")]
    return bool(heads) and all(builder.compatible(target, head) for head in heads)


def _subject_of_its_sentence(clauses: Sequence[Clause], clause: Clause) -> Mention | None:
    """The one field a sentence named before ``clause``, when it opened the sentence by
    naming the crop (after another sentence)."""
    start = sentence_start(clauses, clause.index)
    if start == 0:
        return None
    named = list({id(m): m for c in clauses[start : clause.index] for m in c.mentions}.values())
    return named[0] if len(named) == 1 and named[0].has_crop else None


def merge_coreferences(
    clauses: Sequence[Clause], mentions: Sequence[Mention], builder: MentionBuilder
) -> list[Mention]:
    """Merge mentions that point back at fields already named; return the fields left."""
    definite = definite_words()
    clause_of = {id(m): c for c in clauses for m in c.mentions}
    kept: list[Mention] = []
    merged: set[int] = set()  # clauses whose mention was a field named again
    for mention in mentions:
        clause = clause_of.get(id(mention))
        first = first_word(mention)
        # ("so the tall corn casts shadow on the tomatoes": a second definite mention of
        # a clause whose first named a field again)
        later_definite = (
            clause is not None
            and clause.index in merged
            and first is not None
            and first.norm in definite
            and mention.count is None
        )
        if (
            clause is None
            or not kept
            or (
                clause.mentions[0] is not mention
                and not later_definite
                and not with_one_named_before(clause, kept, mention)
            )
        ):
            if first is not None and first.norm == "both" and mention.count is None:
                mention.count = 2  # "Both cereal fields beside the dryer": two, named now
            kept.append(mention)
            continue
        if per_plot(mention) and (
            (subject := _subject_of_its_sentence(clauses, clause)) is not None
        ):
            # "Carrots on 75 cm ridges ..., 25 ridges per plot. Onions in single rows ...":
            # each plot of the crop the sentence is about, not every plot of the scene
            subject.items.extend(i for i in mention.items if i not in mention.heads)
            clause.mentions.remove(mention)
            merged.add(clause.index)
            continue
        said_of_all = both_of_the_counted(kept, mention)
        if said_of_all:
            # "Two apple blocks: Jonagored ..., and Pink Lady ... Rows NW-SE in both
            # blocks.": what is said of "both blocks" is said of each member
            attributes = [i for i in mention.items if i not in mention.heads]
            for each in said_of_all:
                each.items.extend(attributes)
            clause.mentions.remove(mention)
            merged.add(clause.index)
            continue
        by_order = named_in_order(kept, mention)
        if by_order is not None:
            # "Bintje, Agria and Fontane potatoes, ..., the sprayer boom folded up by the
            # first field": the field named first
            merged.add(clause.index)
            by_order.items.extend(i for i in mention.items if i not in mention.heads)
            clause.mentions[clause.mentions.index(mention)] = by_order
            continue
        # "the carrots ...", "fire blight on the pears", "the Roma one"; "one big field
        # of it" (of the crop just named)
        says_what_it_is = it_is_a(mention)
        is_definite = (
            (first is not None and first.norm in definite)
            or definite_before_head(clause, mention)
            or of_it(mention)
            or bare_one(kept, mention)
            or says_what_it_is
            # ("just the one field behind the dairy sheds, and it's carrots")
            or it_is_the_crop(kept, mention)
            # ("Drill rows and maize rows all running east-west": the maize's rows)
            or rows_of_a_named_crop(kept, mention)
        )
        if says_what_it_is:
            # "Durum wheat, ears out ...; it's a 3 hectare field": the field named, its size
            mention.count = None
        # "two potato plots with a maize plot between them ... One of the potato plots has
        # late blight": one member of the fields counted, not all of them
        one_member = (
            is_definite
            and mention.count == 1
            and one_of_the(clause, mention)
            and mention.plot is not None
            and mention.plot["plural"]
            and not mention.plot["individual"]
        )
        if (
            is_definite
            and mention.count == 1
            and (pronoun_one(mention) or one_of_the(clause, mention) or of_it(mention))
        ):
            mention.count = None
        bare = clause.link is not None and (
            # ("Left to right across the market garden: leafy greens, then peppers, then
            # tomatoes": the first member of a list after a colon, not the garden again)
            (clause.link.role == "separator" and not opens_a_list(clauses, clause, kept, mention))
            # "; cabbage and potato rows 75 cm apart": a list of fields named again
            # ("apples to the north and pears to the south": past the placement)
            or (clause.link.role == "conjunction" and _last_named(clauses, clause) in merged)
            # "the Royal Gala block ... and some apples have brown corky patches": the
            # crop of a field named before, said with a verb that describes it
            or (
                clause.link.role == "conjunction"
                and mention.count is None
                and mention.plot is None
                and not names_a_variety(mention)
                and said_with_a_verb(clause, mention)
            )
            # "Lettuce heads tight and ready to cut in the near field": where the look
            # just said is, the field before's plot
            or (clause.link.role == "conjunction" and look_then_its_place(clause, mention))
        )
        summary = (
            is_summary(mention)
            or (
                # "the peppers between the two tomato strips": fields of a crop named before
                is_definite
                and (mention.count or 1) >= 2
                and mention.has_crop
                and (
                    not names_a_variety(mention)
                    # ("sweetcorn / popcorn / sweetcorn, ... between the two sweetcorn plots":
                    # the fields of that kind named before, as many as counted)
                    or as_many_of_that_kind(kept, mention)
                )
            )
            or (
                # "a potato field between the two cereal fields": the fields of that kind
                # named before
                is_definite
                and (mention.count or 1) >= 2
                and mention.category is not None
                and not mention.has_crop
                and mention.interpretations is None
            )
        )
        # "imperator and danvers carrots, ..., imperator north of danvers": a variety
        # named again without an article is the field already named.
        # "plots: a Valencia block ... and a Hamlin block, ..., Valencia east of Hamlin":
        # also a listed member named again
        repeated = [
            m
            for k in reversed(kept)
            for m in (k.refinements[::-1] or [k])
            if m is not mention and same_variety(m, mention)
        ]
        if repeated and related_to(clauses, clause, repeated[0]):
            repeated = []  # "Valencia oranges next to Valencia oranges": two fields
        if repeated and listed_again(clauses, clause, repeated[0]):
            # "sweetcorn, popcorn and sweetcorn": a third member (said with commas only
            # too, "sweetcorn, popcorn, sweetcorn": the comma joins no kind named again)
            repeated, bare = [], False
        if bare and not repeated and (own_kind := strong_crops(mention)):
            # "apples, pears, apples": a crop listed again in a plain list is another field
            earlier = next((m for m in reversed(kept) if strong_crops(m) == own_kind), None)
            if earlier is not None and listed_again(clauses, clause, earlier):
                bare = False
        placed_again: Mention | None = None
        if (
            not repeated
            and clause.index - 1 in merged
            and clause.link is not None
            and clause.link.role in ("relation", "between")
            and mention.count is None
            and (own_crops := strong_crops(mention))
        ):
            # "...; maize north of potatoes": a field named again, placed against another
            # named again
            # ("two fruit tree blocks: apples ..., cherries ..., apples north of cherries":
            # a listed member too)
            repeated = [
                m
                for k in reversed(kept)
                for m in (k.refinements[::-1] or [k])
                # ("a wheat field & a maize field ..., wheat north of maize": one each)
                if strong_crops(m) == own_crops and (m.count or 1) == 1 and not m.refinements
            ][:1]
            if repeated and _compatible(builder, repeated[0], mention):
                placed_again = repeated[0]
        # "Valencia in the lower grove and Moro in the upper grove; the upper grove has
        # ...": the one field whose plot the same word set apart
        same_plot = (
            same_modifier(kept, mention)
            if is_definite and mention.count is None and not strong_crops(mention)
            else None
        )
        anaphoric = same_plot is not None or (
            (mention.count is None or summary)
            # "jonagored apples AND fuji apples, 2 separate blocks": still those two
            and (not mention.distinct or summary)
            and not mention.other
            and not mention.refinements
            and (is_definite or bare or bool(repeated))
            and not (
                another_field(clauses, clause, mention)
                # ("San Marzano and Beefsteak tomatoes ... Beefsteak plot to the south of
                # it": the variety named bare in a list, now with its plot)
                and not its_plot_named(repeated, clause, mention)
            )
            # ("North plot, ..., Fontane potatoes; south plot, ...": another side, another plot)
            and not (kept and other_side(kept[-1], mention))
            # ("Top left wheat, top right maize, bottom left maize": another quarter)
            and not in_another_zone(kept, mention)
            # ("tomatoes (beefsteak), tomatoes (roma)": the crop again, another variety)
            and not another_variety_in_brackets(clauses, clause, mention, kept)
            # ("Grain maize on the big field and, beside it, sweetcorn": a kind named
            # bare, placed against it)
            and not (
                not is_definite
                and names_a_variety(mention)
                and placed_past_a_pronoun(clauses, clause)
            )
            # ("Rows of capsicum ..., and the Jalapeño beds beside them": a kind placed
            # against the plants named before is not them)
            and not (
                names_a_variety(mention)
                and bool(kept)
                and bool(strong_crops(kept[-1]))
                and placed_by_a_pronoun(clauses, clause)
            )
        )
        if not anaphoric:
            if first is not None and first.norm == "both" and mention.count is None:
                mention.count = 2  # "Both cereal fields beside the dryer": two, named now
            kept.append(mention)
            continue
        run: list[Mention] = []
        own = strong_crops(mention)
        # "two pear blocks: Comice, ... and Durondeau, east of the Comice": the member
        # that variety named, not the plural mention listing it
        member = next(
            (
                sub
                for m in reversed(kept)
                for sub in m.refinements
                if sub is not mention and same_variety(sub, mention)
            ),
            None,
        )
        member = member or same_plot
        if member is None and placed_again is not None:
            # "..., apples north of cherries", "..., maize east of potatoes": the field
            # named again, past other fields named since
            member = placed_again
        host = (
            counted_host(
                builder,
                kept,
                mention,
                member=bare
                and (
                    labels_its_sentence(clauses, clause)
                    or any(i.role == "zone" for i in mention.items)
                ),
            )
            if (
                is_definite
                or placed_first(clauses, clause)
                or placed_against_another(clauses, clause, mention)
                # ("Two fields either side of the track. On the left is our Bintje; on
                # the right the Nantes carrots": each placed in its own part)
                or (bare and any(i.role == "zone" for i in mention.items))
                # ("Two fields either side of the concrete farm track. Left of it is our
                # Bintje, ...; right of it the Nantes carrots")
                or (bare and on_a_side_of_it(mention))
                # ("Two-block orchard for the mapping robot. Granny Smith: 15 rows, ...
                # Conferance pears: 15 rows, ...": each member under its own label)
                or (bare and labels_its_sentence(clauses, clause))
            )
            and not summary
            and (first is None or first.norm not in EACH)
            else None
        )
        if host is not None and member is None:
            # "three orchard blocks; the pear block is between the apple block and the
            # cherries", "two fields. The wheat is ripe, the maize is young": each one of
            # the fields counted, named now
            same = [
                r
                for r in host.refinements
                if (same_variety(r, mention) if strong_crops(host) else strong_crops(r) & own)
                and not in_another_zone([r], mention)
            ]
            if same:
                member = same[-1]
            else:
                host.refinements.append(mention)
                mention.is_refinement = True
                clause.refinement, clause.refined_parent = mention, host
                continue
        for earlier in [] if member is not None else reversed(kept):
            if not _compatible(builder, earlier, mention):
                break
            if own and strong_crops(earlier) and not own & strong_crops(earlier):
                break  # "cherries" is the cherry orchard, not the cherry tomatoes
            run.append(earlier)
        if member is not None:
            run = [member]
        if (
            len(run) > 1
            and not own
            and mention.plot is not None
            and not mention.plot["plural"]
            and not any(i.role == "zone" for i in mention.items)  # ("Middle terrace: ...")
        ):
            # "a banana plot ... and an orange grove ... Banana plot 50 x 50 m, grove 100 x
            # 60 m": the one field of that plot noun
            noun = mention.plot.get("noun")
            same_noun = [m for m in run if m.plot is not None and m.plot.get("noun") == noun]
            if len(same_noun) == 1:
                run = same_noun
        if summary and is_definite and len(run) != mention.count:
            # "a strip of Jalapeños between the two groves": the two earlier fields that
            # are groves, whatever was named in between
            fitting = [m for m in reversed(kept) if _compatible(builder, m, mention)]
            if len(fitting) == 1 and fitting[0].count == mention.count:
                pass  # "the two tomato plots": the two counted together before
            elif len(fitting) != mention.count:
                # "plots: Big Mike and Lady Finger, ..., the two plots adjacent": the members
                fitting = [
                    r
                    for m in reversed(kept)
                    for r in {id(x): x for x in m.refinements[::-1]}.values()
                    if _compatible(builder, r, mention)
                ]
            if len(fitting) == mention.count or (
                len(fitting) == 1 and fitting[0].count == mention.count
            ):
                run = fitting
        if summary and sum(m.count or 1 for m in run) != mention.count:
            kept.append(mention)
            continue
        names_variety = names_a_variety(mention)
        if names_variety and not summary:
            run = [m for m in repeated if _compatible(builder, m, mention)][:1] or run[:1]
        if not run and (is_definite or bare):
            # "three fields: potatoes, carrots and onions ..., the carrots have blight";
            # "pear trees and apple trees ..., pears to the west": a crop named again
            # after a comma is the one earlier field it can be (if only one can).
            # (each field once: "two wheat strips" is two members of a heading, one mention)
            members = list(
                {id(r): r for m in reversed(kept) for r in (m.refinements[::-1] or [m])}.values()
            )
            candidates = [m for m in members if _compatible(builder, m, mention)]
            named = [m for m in candidates if strong_crops(m) & own]
            if own and len(named) == 1 and len(candidates) > 1:
                # "Field robotics course layout: a ... onion plot south of a ... carrot plot.
                # Onion rows 30 cm apart": the one field that names the crop, not a
                # heading's plot word of no crop
                candidates = named
            if first is not None and first.norm in EACH and len(candidates) > 1:
                # "two potato blocks, Bintje ... and Agria ... . Both blocks 36 rows":
                # every member the list named
                run = candidates
            elif (
                is_definite
                and len(candidates) >= 2
                and len(candidates) == len(members)
                and not names_variety
                and mention.count is None
                and all(h.norm.endswith("s") for h in mention.heads if h.role == "head")
            ):
                # "two vineyard blocks: Pinot Nero on the west, Chardonnay on the east. ...
                # with the grapes ripening": the plural of the crop every field grows
                run = candidates
            elif is_definite or len(candidates) == 1:
                run = candidates[:1]
            elif bare and len(candidates) == len(members) and not names_variety:
                # "two vineyard blocks: Chardonnay and Riesling. October, grapes ripe":
                # the crop every field named is, said again, describes them all.
                run = candidates
            elif (
                bare
                and len(candidates) >= 2
                and not names_variety
                and mention.count is None
                and all(h.norm.endswith("s") for h in mention.heads if h.role == "head")
            ):
                # "Comice pears, Durondeau pears, Lapins cherries. Pears planted 3.5 m x
                # 1 m, cherries ...": the plural of a crop named again is all its fields
                run = candidates
        if not run:
            kept.append(mention)
            continue
        if (
            one_member
            and len(run) == 1
            and (run[0].count or 1) >= 2
            and len(run[0].refinements) < (run[0].count or 1)
        ):
            run[0].refinements.append(mention)
            mention.is_refinement = True
            clause.refinement, clause.refined_parent = mention, run[0]
            continue
        merged.add(clause.index)
        attributes = [i for i in mention.items if i not in mention.heads]
        for target in run:
            target.items.extend(attributes)
            if len(run) == 1:
                for head in mention.heads:
                    if head.role in ("head", "plot"):
                        builder.add_head(target, head)
        if len(run) == 1:
            # The field stands where it was named again, so relation words around
            # this clause ("the Gala north of the Fuji") link the right fields.
            clause.mentions[clause.mentions.index(mention)] = run[0]
        elif summary and is_definite and clause.link is not None and clause.link.role == "between":
            # "between the two groves": both fields stand there, in the order named
            at = clause.mentions.index(mention)
            clause.mentions[at : at + 1] = sorted(run, key=lambda m: m.clause)
        else:
            clause.mentions.remove(mention)
            clause.said_of = list(run)
    return kept


def _last_named(clauses: Sequence[Clause], clause: Clause) -> int:
    """The index of the last clause before ``clause`` that names a field (-1 if none)."""
    return next((c.index for c in reversed(clauses[: clause.index]) if c.mentions), -1)

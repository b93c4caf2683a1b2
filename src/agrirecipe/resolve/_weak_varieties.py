"""Weak variety names: names that are varieties only beside their crop (issue 8).

"Navel and Valencia oranges", "Flint on the north side, Popcorn on the south side",
"second plot of Sonata", "Albion on the table-tops and Centenary in the soil beds": a
name that is also an everyday word (``weak_variety_words`` in vocabulary.yaml) names a
variety when a field beside it grows that variety's crop, when it is what a plot or a
size is "of", when it opens a list of fields in capitals, or when another such name in
the prompt is a variety of the same crop. :func:`promote_weak_varieties` makes such a
name the head of its clause's mention.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from agrirecipe.resolve._decompose import MentionBuilder, colour_words
from agrirecipe.resolve._lexicon import Item, reader_words
from agrirecipe.resolve._links import listing
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_before_head,
    descriptive_words,
    plant_part_words,
    strong_crops,
)

__all__ = ["promote_weak_varieties"]


def promote_weak_varieties(clauses: Sequence[Clause], builder: MentionBuilder) -> None:
    """A clause holding only a weak variety name ("navel and valencia oranges") gets a head.

    The crop comes from the mention the clause is coordinated with (the next
    clause, joined by "and"), else from the nearest earlier mention.
    """
    supported = _named_together(clauses)
    # ("The big pivot circle is Russet, 50 ha, ...": the only name of a crop in a prompt
    # that says how big or how grown its field is; not "Flint walls around the yard")
    # ("Cos ready to cut, ..., the harvest rig working the far end of the field": the
    # field named again by "the" is the one the prompt opened with; "Freshly planted
    # Sonata runers ..., only a few leaves each. A trailer of plant trays at the end of
    # the field.")
    alone = (
        all(_the_field(c, m) for c in clauses for m in c.mentions)
        and sum(1 for c in clauses for i in c.loose if i.role == "weak_variety") == 1
        and (
            any(i.role in ("size", "geometry", "stage") for c in clauses for i in c.items)
            or _opens_a_look(clauses)
        )
    )
    for position, clause in enumerate(clauses):
        _fold_described_plants(clause)
        if clause.mentions:
            _promote_into_plot(clauses, clause, supported)
            continue
        weak = [item for item in clause.loose if item.role == "weak_variety"]
        if not weak:
            continue
        neighbours: list[Mention] = []
        following = clauses[position + 1] if position + 1 < len(clauses) else None
        # ("albion, sonata & centenary strawberys": past names of the list still weak)
        ahead = position + 1
        while (
            ahead + 1 < len(clauses)
            and clauses[ahead].link is not None
            and listing(clauses[ahead].link)
            and not clauses[ahead].mentions
            and bool(clauses[ahead].loose)
            and all(i.role == "weak_variety" for i in clauses[ahead].loose)
        ):
            ahead += 1
        if ahead > position + 1:
            following = clauses[ahead]
        if (
            following is not None
            and following.link is not None
            # "navel and valencia oranges"; "Sonata in 10 beds north of Malling Centenary";
            # "albion, sonata & centenary strawberys" (the first of a list)
            and (
                following.link.role in ("conjunction", "relation", "between")
                or following.link.norm == ","
            )
            and following.mentions
        ):
            neighbours.append(following.mentions[0])
        neighbours += [m for c in reversed(clauses[:position]) for m in reversed(c.mentions)]
        if weak[0].tokens[0].capitalised:
            # "Flint on the north side, Popcorn on the south side": a capitalised name
            # beside a variety of its crop later in the sentence
            for later in clauses[position + 1 :]:
                if later.link is not None and later.link.norm in (".", "!", "?", ";"):
                    break
                neighbours += later.mentions[:1]
        for neighbour in neighbours:
            crops = strong_crops(neighbour)
            senses = [s for s in weak[0].senses_of("variety") if s.crop in crops]
            if not senses:
                continue
            mention = _promote(clause, weak[0], senses[0])
            if neighbour is (following.mentions[0] if following and following.mentions else None):
                mention.plot = neighbour.plot
            break
        else:
            crops = {s.crop for s in weak[0].senses_of("variety") if s.crop}
            in_list = clause.link is not None and (listing(clause.link) or clause.link.norm == ":")
            at = clause.loose.index(weak[0])
            # "half acre of russets": what a size or a plot is "of" is a crop
            planted = at > 0 and clause.loose[at - 1].role == "of"
            if len(crops) == 1 and (
                planted
                or crops <= supported
                or (in_list and _listed_among_its_kind(clauses, position, crops, builder))
            ):
                # ("Albion on the table-tops and Centenary in the soil beds": two names of
                # varieties of one crop name it together)
                _promote(clause, weak[0], weak[0].senses_of("variety")[0])
            elif len(crops) == 1 and (
                (weak[0].tokens[0].capitalised and (in_list or alone))
                # ("lollo for the leaf camera: beds on 1.2 m centres, 4 rows per bed"):
                # the only name in a prompt of row measures, whatever its case
                or (alone and any(i.role == "geometry" for c in clauses for i in c.items))
            ):
                # "west to east: Lollo, then Imperator carrots": a capitalised name in a
                # list of fields is its variety even when no field beside it is its crop
                _promote(clause, weak[0], weak[0].senses_of("variety")[0])


def _listed_among_its_kind(
    clauses: Sequence[Clause], position: int, crops: set[str], builder: MentionBuilder
) -> bool:
    """'royal gala (ripe) + conference (ripe) + kordia cherries': a name listed between
    fields of its crop's kind (fruit between fruit) names its variety."""
    clause = clauses[position]
    if [i.role for i in clause.loose] != ["weak_variety"] or (
        clause.loose[0].norm in colour_words()
    ):
        return False  # (only a name said alone: not "bunches golden and ready to pick")
    kinds = {builder.crop_categories.get(c) for c in crops}
    before = [m for c in clauses[:position] for m in c.mentions][-1:]
    after = [m for c in clauses[position + 1 :] for m in c.mentions][:1]
    near = before + after
    return len(near) == 2 and all(
        (named := strong_crops(m)) and {builder.crop_categories.get(c) for c in named} == kinds
        for m in near
    )


def _the_field(clause: Clause, mention: Mention) -> bool:
    """A plot word named again by "the" that names no crop ("the far end of the field")."""
    return (
        not mention.has_crop
        and mention.category is None
        and mention.count is None
        and all(h.role == "plot" for h in mention.heads)
        and definite_before_head(clause, mention)
    )


def _opens_a_look(clauses: Sequence[Clause]) -> bool:
    """ "Centenary on the tabletop gutters ..., berries deep red", "Lollo looking gorgeous,
    frilly dark red heads": a prompt that opens with the name and goes on to say how the
    plants' parts look is about that variety's field (not "Flint walls around the yard")."""
    # (after words that only open the picture: "A shot of the Big Mike bunches hanging")
    opening = [
        i
        for i in (clauses[0].loose if clauses else ())
        if not (i.role in ("filler", "of") or i.scenery or i.norm in ("a", "an", "shot", "photo"))
    ]
    if not opening or opening[0].role != "weak_variety":
        return False
    parts = reader_words("coloured_parts") | reader_words("young_parts") | plant_part_words()
    return any(
        i.norm in parts or (i.role in ("stage", "cue") and not i.data.get("negated"))
        for c in clauses
        for i in c.items
    )


def _fold_described_plants(clause: Clause) -> None:
    """ "Sonata with grey mould furring the fruit": after a weak variety name, a mention
    made only of words for plants or fruit describes that variety's field; its words
    become the clause's loose words so the name can head the clause."""
    weak = [
        i
        for i in clause.items
        if i.role == "weak_variety" or (i.role == "filler" and i.senses_of("variety"))
    ]
    if not weak or not clause.mentions:
        return
    words = descriptive_words()
    if not all(h.norm in words for m in clause.mentions for h in m.heads):
        return
    first = min(h.start for m in clause.mentions for h in m.heads)
    if weak[0].start > first:
        return
    loose = {id(i): i for i in clause.loose}
    for mention in clause.mentions:
        for head in mention.heads:
            head.role = "filler"
        loose.update((id(i), i) for i in mention.items)
    clause.loose = sorted(loose.values(), key=lambda i: i.start)
    clause.mentions = []
    weak[0].role = "weak_variety"


def _named_together(clauses: Sequence[Clause]) -> set[str]:
    """Crops two or more different capitalised weak variety names in the prompt are all
    varieties of ("Albion ... and Centenary ...": strawberries)."""
    names: dict[str, set[str]] = {}
    for clause in clauses:
        for item in clause.items:
            weak = item.role == "weak_variety" or (
                item.role == "filler" and item.senses_of("variety")
            )
            if weak and item.tokens[0].capitalised:
                for sense in item.senses_of("variety"):
                    if sense.crop:
                        names.setdefault(str(sense.crop), set()).add(item.norm)
    return {crop for crop, said in names.items() if len(said) >= 2}


def _promote_into_plot(clauses: Sequence[Clause], clause: Clause, supported: set[str]) -> None:
    """ "second plot of Sonata", "Sonata in the open ground": a weak variety name right
    after a crop-less plot's "of", or opening the plot's clause, names the plot's crop
    when an earlier field grows that crop."""
    if len(clause.mentions) != 1:
        return
    mention = clause.mentions[0]
    if mention.has_crop or mention.plot is None or mention.category is not None:
        return
    ordered = sorted(clause.items, key=lambda i: i.start)
    for index, item in enumerate(ordered):
        # ("Plot 1 Iceberg, plot 2 Lollo Rosso, plot 3 Cos": right after a plot's label)
        labelled = (
            index >= 2
            and ordered[index - 2].role == "plot"
            and (ordered[index - 1].norm.isdigit() or len(ordered[index - 1].norm) == 1)
        )
        # ("sonata strawbs 10 beds & albion 8 beds": in lower case, listed right after a
        # field of its crop)
        listed = (
            clause.index > 0
            and clause.link is not None
            and listing(clause.link)
            and any(
                s.crop in strong_crops(m)
                for m in clauses[clause.index - 1].mentions[-1:]
                for s in item.senses_of("variety")
            )
        )
        # ("Along the top of the plantation we have Big Mike. Below that ... Grande Naine,
        # ... the Ladyfinger bananas": a capitalised name said as what the plot holds,
        # beside varieties of its crop anywhere in the prompt)
        held = (
            index > 0 and item.tokens[0].capitalised and ordered[index - 1].norm in _HOLDING_VERBS
        )
        opens = (index == 0 and (item.tokens[0].capitalised or listed)) or labelled
        if (
            item.role not in ("weak_variety", "filler")
            or not item.senses_of("variety")  # ("of the plantation": not a name)
            or not (opens or held or (index > 0 and ordered[index - 1].role == "of"))
        ):
            continue
        named = {c for c2 in clauses[: clause.index] for m in c2.mentions for c in strong_crops(m)}
        named |= supported
        if held:
            named |= {c for c2 in clauses for m in c2.mentions for c in strong_crops(m)}
        if opens:
            # "Big Mike in the first block, Ladyfinger in the second": a capitalised name
            # beside a variety of its crop later in the sentence
            for later in clauses[clause.index + 1 :]:
                if later.link is not None and later.link.norm in (".", "!", "?", ";"):
                    break
                named |= {c for m in later.mentions[:1] for c in strong_crops(m)}
        senses = [s for s in item.senses_of("variety") if s.crop in named]
        crops = {s.crop for s in item.senses_of("variety")}
        if (
            not senses
            and index > 0
            and len(crops) == 1
            and not any(strong_crops(m) for c2 in clauses for m in c2.mentions)
        ):
            # "a few beds of Cos": what the only plot of the prompt is "of" names its crop
            # (not a field of a crop chosen at random)
            senses = item.senses_of("variety")
        if senses:
            item.role = "head"
            item.data["promoted"] = True
            if item not in mention.items:
                mention.items.append(item)
            mention.heads.append(item)
            mention.interpretations = [(str(senses[0].crop), str(senses[0].value), False)]
        return


#: Verbs after which a name is what a plot holds ("... we have Big Mike").
_HOLDING_VERBS = frozenset({"have", "grow", "got", "planted", "holds", "has"})


def _promote(clause: Clause, item: Item, sense: Any) -> Mention:
    """Make a weak variety name the head of its clause's one mention."""
    item.role = "head"
    item.data["promoted"] = True
    mention = Mention(clause=clause.index)
    mention.items = [i for i in clause.loose if i is not item]
    mention.heads.append(item)
    mention.items.append(item)
    mention.interpretations = [(str(sense.crop), str(sense.value), False)]
    clause.mentions, clause.loose = [mention], []
    return mention

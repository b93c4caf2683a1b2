"""Mentions that head a list rather than ask for a field (issue 8).

"Three plots: wheat, maize and potatoes", "Pruning-robot vineyard, two blocks:
Chardonnay, ..., Cabernet", "onions!!! just 1 big field of onions": a plot word or a
crop named before the fields that say what it holds is their heading (or title), not
one more field. :func:`drop_list_headings` drops such mentions once back-references
are merged. Mentions that sum up fields named elsewhere ("Two blocks for drone
flights.") are read in :mod:`agrirecipe.resolve._summaries`.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._links import link_norm
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_words,
    first_word,
    names_a_variety,
    same_variety,
    strong_crops,
)
from agrirecipe.resolve._summaries import SUMMARY_ROLES, lend_and_drop
from agrirecipe.resolve._words import SENTENCE_MARKS

__all__ = [
    "drop_joint_headings",
    "drop_list_headings",
    "drop_plural_headings",
    "fill_counted_lists",
    "lend_heading_category",
    "lend_heading_crop",
    "name_counted_plots",
]


def _heads_its_list(mention: Mention, later: Sequence[Mention]) -> bool:
    crops = strong_crops(mention)
    return (
        bool(crops)
        and not names_a_variety(mention)
        and len(later) >= 2
        and all(strong_crops(m) and strong_crops(m) <= crops for m in later[:2])
    )


#: The marks that end a sentence (a semicolon goes on with a list).
_FULL_STOPS = (".", "!", "?")


def drop_list_headings(
    clauses: Sequence[Clause], mentions: list[Mention], crop_categories: dict[str, str]
) -> list[Mention]:
    """ "My allotment in one picture: a strawberry bed, a patch of sweetcorn": one plot
    naming no crop, ending its clause before a colon that lists two or more fields of
    named crops, is the list's heading, not another field. Return the fields left."""
    kept: list[Mention] = []
    for position, mention in enumerate(mentions):
        # the colon may come after words naming no field ("..., July:")
        following = next(
            (
                c
                for c in clauses[mention.clause + 1 :]
                if c.mentions
                or (c.link is not None and c.link.norm in (":", "-", "–", "—", *_FULL_STOPS))
            ),
            None,
        )
        if following is not None and link_norm(following) in _FULL_STOPS:
            # ("Northwest: orchard. Northeast: vineyard.": the colon after the full stop is
            # another sentence's)
            following = None
        # (right after the heading's colon, a plot that names its crops is a field of them:
        # "Sensor rig field: a vineyard ... south of a strawberry field")
        right_after = following is not None and following.index == mention.clause + 1
        later = [
            m
            for m in mentions[position + 1 :]
            if m.has_crop
            or m.category is not None
            or (right_after and m.plot is not None and bool(m.plot["options"]))
        ]
        if (
            following is not None
            and following.link is not None
            # ("the veg garden at the school farm - a bed of peppers, a bed of ...")
            and following.link.norm in (":", "-", "–", "—")
            and clauses[mention.clause].mentions[-1:] == [mention]
            and (
                (mention.plot is not None and not mention.has_crop and mention.category is None)
                # "this is the veg garden at the school farm - a bed of peppers, a bed of ..."
                # ("Vegetables for the weeder: a ... cabbage plot ..., and ... a carrot plot")
                or (
                    (
                        (mention.plot is not None and following.link.norm != ":")
                        or (mention.plot is None and mention.category is not None)
                    )
                    and not mention.has_crop
                    and len(later) >= 2
                    and all(strong_crops(m) for m in later[:2])
                )
                # "Citrus test site in Chile, July: a blood orange block next to a Valencia
                # block": a crop heading the fields of that crop it lists
                or _heads_its_list(mention, later)
                # "the veg field: capsicum on one side and chillies on the other": a plot of
                # a category heading two or more fields of crops of that category
                or _heads_its_category(mention, later, crop_categories)
            )
            # ("sensor test strips: a capsicum strip between ...": a plural, not counted)
            and (
                (mention.count or 1) == 1
                or not any(i.role == "number" for i in mention.items)
                # ("Two fields in this one, separated by a ditch: on the near side wheat
                # ..., and on the far side onions": as many as it counts)
                or mention.count == sum(m.count or 1 for m in later)
            )
            and not mention.refinements
            and mention.rest is None
            # "my allotment: three different veg patches": two or more fields listed
            # ("We went down to a single crop: one 4 ha block of Gala apples": the one
            # field it counts)
            and (sum(m.count or 1 for m in later) >= 2 or _counts_one(mention, later))
            and later[0].clause >= following.index
        ):
            # ("Citrus harvest robot trial in Chile in July: a Navel block ...": the time
            # the heading says is its fields')
            lend_and_drop(clauses, mention, later)
            clauses[mention.clause].mentions = []
            continue
        if (
            _heads_counted_plots(clauses, mention)
            or _heads_fitting_list(clauses, mention, later)
            or _crop_title(clauses, mention, mentions[position + 1 : position + 2])
        ):
            clauses[mention.clause].mentions = []
            continue
        kept.append(mention)
    return kept


def _heads_its_category(
    mention: Mention, later: Sequence[Mention], crop_categories: dict[str, str]
) -> bool:
    return (
        mention.plot is not None
        and mention.category is not None
        and not mention.has_crop
        and (mention.count or 1) == 1
        and len(later) >= 2
        and all(
            strong_crops(m)
            and {crop_categories.get(c) for c in strong_crops(m)} == {mention.category}
            for m in later
        )
    )


def _counts_one(heading: Mention, later: Sequence[Mention]) -> bool:
    """Whether a heading counts one field ("a single crop", "one crop") and one is named."""
    return (
        heading.count == 1
        and any(i.role == "number" and i.norm not in ("a", "an") for i in heading.items)
        and sum(m.count or 1 for m in later) == 1
    )


def _crop_title(clauses: Sequence[Clause], mention: Mention, following: Sequence[Mention]) -> bool:
    """'onions!!! just 1 big field of onions', 'Wheat. A 2 ha wheat field by the barn': a
    sentence of only a crop's name, before a sentence asking for a field of that crop, is
    its title, not another field."""
    clause = clauses[mention.clause]
    if (
        not following
        or clause.mentions != [mention]
        or (clause.link is not None and clause.link.norm not in SENTENCE_MARKS)
        or names_a_variety(mention)
        or not strong_crops(mention)
        or any(i.role not in ("head", "filler") for i in mention.items)
    ):
        return False
    after = clauses[mention.clause + 1 :]
    first = next((c for c in after if c.mentions), None)
    ends = next((c for c in after if c.link is not None), None)
    nxt = following[0]
    return (
        first is not None
        and ends is not None
        and ends.link is not None
        and ends.link.norm in SENTENCE_MARKS
        and first.index >= ends.index
        and nxt.clause == first.index
        and strong_crops(mention) <= strong_crops(nxt)
        and (nxt.plot is not None or nxt.count is not None)
    )


def _heads_fitting_list(
    clauses: Sequence[Clause], mention: Mention, later: Sequence[Mention]
) -> bool:
    """'vineyard in NZ, cabernet on one block n chardonnay on the other': a plot word
    naming no crop, then (after a comma) two or more fields of crops only it holds."""
    if (
        mention.plot is None
        or mention.has_crop
        # ("A patchwork of veg beds ..., I can make out onions, carrots and lettuce")
        or (mention.count not in (None, 1) and mention.quantity is None)
        or mention.refinements
        or mention.clause + 1 >= len(clauses)
        or clauses[mention.clause].mentions[-1:] != [mention]
    ):
        return False
    following = clauses[mention.clause + 1]
    options = set(mention.plot["options"])
    members = [m for m in later if m.clause > mention.clause][:2]
    # ("New Zealand orchard, a single block of Royal Gala, ...": the one block it is)
    single = len(later) == 1 and _said_single(later[0])
    return (
        following.link is not None
        and following.link.norm == ","
        and bool(following.mentions)
        and bool(options)
        and (len(members) == 2 or (single and members == list(later)))
        and all(strong_crops(m) and strong_crops(m) <= options for m in members)
    )


def _said_single(mention: Mention) -> bool:
    """Whether a mention is said to be one field ("a single block", "one block of")."""
    return mention.count == 1 and any(
        i.role == "number" and i.norm in ("a single", "one", "single", "just one", "only one")
        for i in mention.items
    )


def _heads_counted_plots(clauses: Sequence[Clause], mention: Mention) -> bool:
    """'Pruning-robot vineyard, two blocks: Chardonnay, ..., Cabernet', 'Lettuce trial ...,
    three plots from north to south: Cos, crisphead, Lollo Rosso', 'test for cherries: two
    blocks, Kordia and Regina': a plot word or a crop right before a count of plots that
    lists members it can hold is their heading."""
    heading_crop = mention.has_crop and not names_a_variety(mention)
    # ("Wheat plots for the phenotyping rover: two strips, ...": a plural said without a
    # number before a colon)
    plural_heading = (
        mention.implied_count
        and mention.clause + 1 < len(clauses)
        and link_norm(clauses[mention.clause + 1]) == ":"
    )
    if (
        (mention.plot is None and not heading_crop)
        or (mention.has_crop and not heading_crop)
        or ((mention.count or 1) != 1 and not plural_heading)
        or mention.refinements
        or mention.clause + 1 >= len(clauses)
        or clauses[mention.clause].mentions[-1:] != [mention]
    ):
        return False
    following = clauses[mention.clause + 1]
    # ("Rain-cover test for cherries: two blocks, Kordia and Regina"; "sensor test field -
    # 3 plots side by side, west to east: wheat, maize, potatoes")
    if following.link is None or following.link.norm not in (",", ":", "-", "–", "—"):
        return False
    if len(following.mentions) != 1:
        return False
    plots = following.mentions[0]
    plot = mention.plot
    options = strong_crops(mention) if heading_crop or plot is None else set(plot["options"])
    members = {id(r): r for r in plots.refinements}.values()
    # ("Market garden, two plots: tomatoes ... and peppers": a plot word for any crop)
    holds_any = plot is not None and not heading_crop and not options
    return (
        # ("Plant-counting model test field, three wheat plots stacked north to south:
        # Winter Wheat, then Spelt, then Durum": plots of a crop the heading may hold)
        (not plots.has_crop or holds_any or strong_crops(plots) <= options)
        and (plots.count or 0) >= 2
        and len(members) >= 2
        and (bool(options) or holds_any)
        and all(strong_crops(r) and (holds_any or strong_crops(r) <= options) for r in members)
    )


def drop_joint_headings(
    clauses: Sequence[Clause], mentions: list[Mention], crop_categories: dict[str, str]
) -> list[Mention]:
    """'Carrot variety strips plus a lettuce strip ..., north to south: Imperator, then
    Danvers, then Bibb lettuce': two or more crops named before a colon, each as many
    times as the list after it names fields of that crop, head that list together; they
    are dropped before the members are read as those crops named again. So do kinds
    ("fruit and veg plots: an apple plot and a carrot plot", "grain and veg test strips -
    a corn strip ... and a spud strip"). Return the fields left."""
    headings = _joint_headings(clauses, mentions, crop_categories)
    members = [m for m in mentions if not any(m is h for h in headings)]
    for heading in headings:
        # ("potato field 2ha, onion field 1ha, ..., in a line n to s: potatoes then
        # onions ...": what a heading of one field says of it goes to its member)
        named = [
            m
            for m in members
            if m.clause > heading.clause
            and strong_crops(heading)
            and strong_crops(m) == strong_crops(heading)
        ]
        if (heading.count or 1) == 1 and len(named) == 1:
            own = {i.role for i in named[0].items}
            named[0].items.extend(
                i
                for i in heading.items
                if i.role in (*SUMMARY_ROLES, "size", "geometry") and i.role not in own
            )
        clause = clauses[heading.clause]
        clause.mentions = [m for m in clause.mentions if m is not heading]
    return [m for m in mentions if not any(m is h for h in headings)]


def _joint_headings(
    clauses: Sequence[Clause], mentions: Sequence[Mention], crop_categories: dict[str, str]
) -> list[Mention]:
    def kinds(mention: Mention) -> set[str]:
        if mention.category is not None and not mention.has_crop:
            return {c for c, k in crop_categories.items() if k == mention.category}
        return strong_crops(mention)

    for colon in clauses:
        if colon.link is None or colon.link.norm not in (":", "-", "–", "—"):
            continue
        start = colon.index
        while start > 0 and not _ends_sentence(clauses[start]):
            start -= 1
        end = colon.index + 1
        while end < len(clauses) and not _ends_sentence(clauses[end]):
            end += 1
        before = [m for m in mentions if start <= m.clause < colon.index]
        after = [m for m in mentions if colon.index <= m.clause < end]
        if colon.link.norm == ":" and _varieties_named_again(before, after):
            return list(before)
        if len(before) < 2 or not all(
            kinds(m) and not names_a_variety(m) and not m.refinements for m in before
        ):
            continue
        if colon.link.norm != ":" and any(m.category is None for m in before):
            continue  # (a dash heads a list of kinds only)
        if after and all(_definite(m) for m in after):
            # ("A wheat field with a field of spuds to the east, both ill: the wheat has
            # rust and the potatoes ... blight": the fields named before, described)
            continue
        owners: dict[int, int] = {}
        seen: list[Mention] = []
        for member in after:
            # ("a block of Bing and a block of Durondeau, Bing east of the Durondeau": a
            # variety named again is the same member)
            if any(same_variety(earlier, member) for earlier in seen):
                continue
            seen.append(member)
            # ("Fruit and veg in this one: an apple orchard ... and a big vegetable
            # plot": a member of a kind the heading named)
            own = strong_crops(member) or kinds(member)
            fitting = [h for h in before if own <= kinds(h)]
            if len(fitting) != 1 or not own:
                break
            owners[id(fitting[0])] = owners.get(id(fitting[0]), 0) + (member.count or 1)
        else:
            if all(
                owners.get(id(h), 0) == (h.count or 1)
                or (h.implied_count and owners.get(id(h), 0) >= 1)
                # ("fruit and veg plots: ...": a kind heads as many fields as it lists)
                or (h.category is not None and h.count is None and owners.get(id(h), 0) >= 1)
                for h in before
            ):
                return list(before)
    return []


def _varieties_named_again(before: Sequence[Mention], after: Sequence[Mention]) -> bool:
    """'Gros Michel and Cavendish plots for a wilt survey: 600 Gros Michel plants showing
    wilt, and 600 healthy Cavendish plants ...': varieties named before a colon, each named
    once again after it (and nothing else), head that list."""
    if len(before) < 2 or len(after) != len(before) or any(m.refinements for m in after):
        return False
    if not all(names_a_variety(m) and m.count is None for m in before):
        return False
    return all(
        sum(1 for m in after if same_variety(heading, m)) == 1 for heading in before
    ) and all(any(same_variety(heading, m) for heading in before) for m in after)


def _definite(mention: Mention) -> bool:
    first = first_word(mention)
    return first is not None and first.norm in definite_words()


def _ends_sentence(clause: Clause) -> bool:
    return clause.link is not None and clause.link.norm in SENTENCE_MARKS


def drop_plural_headings(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Vineyard test blocks for a grape-yield camera, three blocks from west to east:
    Chardonnay, Riesling, Cabernet': the first field named, a plural plot with no number
    (two fields only by its plural) and no variety, followed in its sentence or the next
    by two or more fields of named crops (of its own crop, when it names one), is what
    those fields are: a heading, not two fields more. Its stage, health, cues and season
    go to each field after it that states none of its own. Return the fields left."""
    if len(mentions) < 2:
        return mentions
    heading, later = mentions[0], mentions[1:]
    if (
        not heading.implied_count
        or heading.refinements
        or names_a_variety(heading)
        or any(i.role in ("relation", "between", "size", "geometry") for i in heading.items)
    ):
        return mentions
    members = [r for m in later for r in ({id(r): r for r in m.refinements}.values() or (m,))]
    crops = strong_crops(heading)
    if len(members) < 2 or not all(
        strong_crops(m) and (not crops or strong_crops(m) <= crops) for m in members
    ):
        return mentions
    ends = [
        c.index
        for c in clauses[heading.clause + 1 :]
        if c.link is not None and c.link.norm in SENTENCE_MARKS
    ]
    # (the fields begin in the heading's sentence or the next)
    if len(ends) >= 2 and later[0].clause >= ends[1]:
        return mentions
    if any(
        c.link is not None and c.link.role in ("relation", "between")
        for c in clauses[heading.clause + 1 : later[0].clause + 1]
    ):
        return mentions  # ("test plots next to a wheat field and a maize field": placed)
    lend_and_drop(clauses, heading, later)
    return later


def fill_counted_lists(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'three fields: cabbages nearest to me, a strip of onions in between, and a field of
    sweetcorn up the hill': fields named later in the sentence of a counted plot of no
    crop whose list named fewer members than its count are its members too, when they are
    exactly as many as it lacks (never a member of any crop made up for the gap). Return
    the fields left."""
    for heading in mentions:
        members = list({id(r): r for r in heading.refinements}.values())
        if heading.has_crop or not members or (heading.count or 1) <= len(members):
            continue
        # (a semicolon goes on with the list: "a 2-acre pear block, ...; and west of it a
        # 1 acre apple block")
        ends = next(
            (
                c.index
                for c in clauses[heading.clause + 1 :]
                if c.link is not None and c.link.norm in SENTENCE_MARKS and c.link.norm != ";"
            ),
            len(clauses),
        )
        if any(
            i.role == "reference" and i.norm == "the other"
            for c in clauses[heading.clause + 1 : ends]
            for i in c.items
        ):
            continue  # ("Two veg plots, one north of the other, and a wheat field": both said)
        later = [
            m
            for m in mentions[mentions.index(heading) + 1 :]
            if m.clause < ends and all(m is not r for r in members)
        ]
        if len(later) != (heading.count or 1) - len(members) or not all(
            strong_crops(m) and (m.count or 1) == 1 and not m.refinements for m in later
        ):
            continue
        for mention in later:
            mention.is_refinement = True
            heading.refinements.append(mention)
        return [m for m in mentions if all(m is not other for other in later)]
    return mentions


def name_counted_plots(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Wheat micro-plots for a rust-detection drone: two adjacent plots, 1.5 m x 10 m
    each, ...': a first field of a crop, plural with no number, then in the same sentence
    a counted plot of no crop, are one request: the counted plots of that crop. Return
    the fields left."""
    if len(mentions) < 2:
        return mentions
    heading, counted = mentions[0], mentions[1]
    if (
        not heading.implied_count
        or not heading.has_crop
        or heading.refinements
        or counted.has_crop
        or counted.category is not None
        or counted.plot is None
        or any(r.has_crop or r.category is not None for r in counted.refinements)
        or (counted.count or 1) < 2
        # (in the heading's sentence: a colon may end the heading)
        or any(
            c.link is not None and c.link.norm in SENTENCE_MARKS and c.link.norm != ":"
            for c in clauses[heading.clause + 1 : counted.clause + 1]
        )
        or any(strong_crops(m) for m in mentions[2:])
    ):
        return mentions
    counted.heads.extend(h for h in heading.heads if h.role == "head")
    counted.items.extend(heading.items)
    counted.interpretations = heading.interpretations
    for member in counted.refinements:  # ("one with yellow rust and one clean")
        member.interpretations = heading.interpretations
    for clause in clauses:
        clause.mentions = [m for m in clause.mentions if m is not heading]
    return mentions[1:]


def lend_heading_crop(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Canopy LiDAR study in Washington Navel: a super-high-density block, ..., and south
    of it a conventional block, ...': a crop named alone before a colon, then two or more
    plots of no crop, is the crop of those plots, not a field of its own. Return the
    fields left."""
    if len(mentions) < 3:
        return mentions
    heading, plots = mentions[0], mentions[1:]
    if (
        not heading.has_crop
        or not _alone_before_a_colon(clauses, heading)
        or any(
            m.has_crop or m.category is not None or m.plot is None or (m.count or 1) != 1
            for m in plots
        )
        or any(r.has_crop for m in plots for r in m.refinements)
    ):
        return mentions
    # (only plots that can hold the crop: "Navel: a block, a vineyard" is no heading)
    crops = strong_crops(heading)
    if any(
        m.plot is not None and m.plot["options"] and not crops & set(m.plot["options"])
        for m in plots
    ):
        return mentions
    names = [h for h in heading.heads if h.role == "head"]
    for mention in plots:
        mention.heads.extend(names)
        mention.items.extend(names)
        mention.interpretations = heading.interpretations
    clauses[heading.clause].mentions = []
    return plots


def lend_heading_category(clauses: Sequence[Clause], mentions: list[Mention]) -> list[Mention]:
    """'Vegetables: three different crops in long strips': a category named alone before a
    colon, then fields of no crop and no category in that sentence, is their category, not
    a field of its own. Return the fields left."""
    kept: list[Mention] = []
    for position, heading in enumerate(mentions):
        listed = _category_list(clauses, heading, mentions[position + 1 :])
        if not listed:
            kept.append(heading)
            continue
        names = [h for h in heading.heads if h.role == "head"]
        for mention in listed:
            mention.category = heading.category
            mention.heads.extend(names)
            mention.items.extend(names)
        clauses[heading.clause].mentions = []
    return kept


def _category_list(
    clauses: Sequence[Clause], heading: Mention, later: Sequence[Mention]
) -> list[Mention]:
    """The fields of no crop and no category ``heading``, a category alone before a colon,
    heads in its sentence ([] when it heads none)."""
    colon = heading.clause + 1
    if (
        heading.has_crop
        or heading.category is None
        or not _alone_before_a_colon(clauses, heading)
        or clauses[colon].mentions[:1] != list(later[:1])
    ):
        return []
    end = next(
        (c.index for c in clauses[colon + 1 :] if link_norm(c) in SENTENCE_MARKS), len(clauses)
    )
    listed = [m for m in later if m.clause < end]
    if any(
        m.has_crop
        or m.category is not None
        or (m.plot is not None and m.plot["options"])
        or any(r.has_crop or r.category is not None for r in m.refinements)
        for m in listed
    ):
        return []
    return listed


def _alone_before_a_colon(clauses: Sequence[Clause], heading: Mention) -> bool:
    """Whether ``heading``, one field of no plot word and no members, ends its clause
    right before a colon ("Washington Navel: ...", "Vegetables: ...")."""
    colon = heading.clause + 1
    return (
        heading.plot is None
        and (heading.count or 1) == 1
        and not heading.refinements
        and colon < len(clauses)
        and link_norm(clauses[colon]) == ":"
        and clauses[heading.clause].mentions[-1:] == [heading]
    )

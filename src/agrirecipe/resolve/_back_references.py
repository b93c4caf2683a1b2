"""The signs that a mention points back at a field named before, and which field.

:func:`~agrirecipe.resolve._coreference.merge_coreferences` asks these: whether a
definite mention is one member of a counted plural named before ("three orchard
blocks ... the Gala block"), a field named again by its order ("the second plot"),
its modifier ("the upper grove") or "one" ("the agria one"); whether a crop named
again is the next member of a plain list ("sweetcorn, popcorn and sweetcorn") or a
second field ("tomatoes (beefsteak) + tomatoes (roma)"); whether a count of plots
only restates the fields just listed ("..., three fields").
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from agrirecipe.resolve._decompose import MentionBuilder
from agrirecipe.resolve._lexicon import Item
from agrirecipe.resolve._links import ARTICLES
from agrirecipe.resolve._measures import sentence_start
from agrirecipe.resolve._members import ORDINAL_WORDS
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import (
    definite_words,
    first_word,
    has_room,
    names_a_group,
    names_a_variety,
    pronoun_one,
    said_of_all_plots,
    same_variety,
    strong_crops,
)

__all__ = [
    "another_variety_in_brackets",
    "as_many_of_that_kind",
    "bare_one",
    "both_of_the_counted",
    "counted_host",
    "is_summary",
    "it_is_a",
    "it_is_the_crop",
    "its_plot_named",
    "labels_its_sentence",
    "listed_again",
    "look_then_its_place",
    "named_in_order",
    "of_it",
    "opens_a_list",
    "same_modifier",
    "with_one_named_before",
]


def counted_host(
    builder: MentionBuilder, kept: Sequence[Mention], mention: Mention, *, member: bool = False
) -> Mention | None:
    """The counted plural of no crop named last ("three orchard blocks") that a definite
    crop mention is one member of, if it still has room; else None. A counted plural of
    one crop ("two cherry blocks: the Bing trees ..., the Kordia block ...") hosts the
    varieties of its crop named after it. With ``member`` (the mention is said as a
    member: under a label of its own, or in its own part of the farm) a plot that says
    its crops, or a category, is a member too ("two blocks. Vineyard: ...", "three strips.
    Cherries across the top end, root veg through the middle, ...")."""
    if not kept or mention.count is not None:
        return None
    if not strong_crops(mention) and not (member and names_a_group(mention)):
        return None
    host = kept[-1]
    crops = strong_crops(host)
    if (
        (host.count or 1) < 2
        or (crops and not (names_a_variety(mention) and strong_crops(mention) <= crops))
        or not has_room(host)
        or any(not r.is_refinement for r in host.refinements)
    ):
        return None
    heads = [h for h in mention.heads if h.role in ("head", "plot")]
    return host if heads and all(builder.compatible(host, h) for h in heads) else None


def labels_its_sentence(clauses: Sequence[Clause], clause: Clause) -> bool:
    """Whether ``clause`` opens a sentence and a colon follows it ("... . Granny Smith:")."""
    return (
        clause.link is not None
        and clause.link.norm in (".", "!", "?", ";")
        and clause.index + 1 < len(clauses)
        and clauses[clause.index + 1].link is not None
        and clauses[clause.index + 1].link.norm == ":"  # type: ignore[union-attr]
    )


def opens_a_list(
    clauses: Sequence[Clause], clause: Clause, kept: Sequence[Mention], mention: Mention
) -> bool:
    """Whether ``mention``, a group of crops ("leafy greens") right after a colon that
    follows one field of a group of crops, is the first member of a list ("the market
    garden: leafy greens, then peppers, ...") and not that field named again: the next
    clause that names a field, joined to it by commas or "and"/"then" only, names
    another one (not "the grapes", the field described). (A member that names its crop
    makes the field before the colon that crop's field, as a list heading's member.)"""
    if clause.link is None or clause.link.norm != ":" or not kept or strong_crops(mention):
        return False
    host = kept[-1]
    if (
        strong_crops(host)
        # (a garden of a category, not "Plot register: P1 Imperator carrots, P2 ...")
        or not (names_a_group(host) or (host.plot or {}).get("category"))
        # ("a veg patch: greens, peppers and tomatoes": one patch, said with "a")
        or host.count not in (None, 1)
        or (host.plot and host.plot["plural"])
    ):
        return False
    start = sentence_start(clauses, clause.index)
    if any(c.mentions for c in clauses[start : host.clause]):
        return False  # ("Orchard and vineyard ...: Royal Gala apples ... and Cabernet vines")
    for following in clauses[clause.index + 1 :]:
        link = following.link
        if link is not None and link.role == "relation" and not following.mentions:
            continue  # ("greens by the gate, peppers ...": where the member is)
        if link is None or link.role not in ("separator", "conjunction"):
            return False
        if link.norm in (".", "!", "?", ";", ":", "(", ")"):
            return False
        if following.mentions:
            first = first_word(following.mentions[0])
            return following.mentions[0].has_crop and (
                first is None or first.norm not in definite_words()
            )
        if following.items:
            return False
    return False


#: The words that say what "it" is ("it's a 3 hectare field", "it is a 2 ha block").
_IT_IS = (("it s",), ("it", "is"), ("its",), ("it", "s"))


def it_is_a(mention: Mention) -> bool:
    """Whether the mention says what the field named is, a plot of no crop of its own
    ("it's a 3 hectare field with power lines across the middle")."""
    words = [i.norm for i in mention.items]
    opening = next((o for o in _IT_IS if tuple(words[: len(o)]) == o), None)
    return (
        opening is not None
        and words[len(opening) : len(opening) + 1] in (["a"], ["an"])
        and not mention.has_crop
        and mention.category is None
        and bool(mention.heads)
        and all(h.role == "plot" for h in mention.heads)
    )


def rows_of_a_named_crop(kept: Sequence[Mention], mention: Mention) -> bool:
    """Whether the mention is the rows of the one field named before that grows its crop
    ("..., and maize in 75 cm rows. Drill rows and maize rows all running east-west")."""
    own = strong_crops(mention)
    if (
        not own
        or len(mention.heads) != 1
        or mention.count is not None
        or mention.plot is not None
        or names_a_variety(mention)
    ):
        return False
    ordered = sorted(mention.items, key=lambda i: i.start)
    at = ordered.index(mention.heads[0])
    if at + 1 >= len(ordered) or ordered[at + 1].norm not in _ROW_NOUNS:
        return False
    growing = [m for k in kept for m in (k.refinements or [k]) if strong_crops(m) == own]
    return len({id(m) for m in growing}) == 1 and (growing[0].count or 1) == 1


#: Words for a field's rows said after its crop ("maize rows").
_ROW_NOUNS = frozenset({"rows", "lines", "drills", "row", "ridges", "beds"})


def it_is_the_crop(kept: Sequence[Mention], mention: Mention) -> bool:
    """Whether the mention says what crop the field named last, a plot of no crop,
    holds ("just the one field behind the dairy sheds, and it's carrots", "..., and it's
    all wheat")."""
    words = [i.norm for i in mention.items]
    opening = next((o for o in _IT_IS if tuple(words[: len(o)]) == o), None)
    last = kept[-1] if kept else None
    # ("..., and it's all wheat": past a word that says the crop fills it)
    said = len(opening or ()) + (words[len(opening or ()) : len(opening or ()) + 1] == ["all"])
    return (
        opening is not None
        and mention.heads[:1] == mention.items[said : said + 1]
        and (mention.has_crop or mention.category is not None)
        and mention.plot is None
        and mention.count is None
        and last is not None
        and last.plot is not None
        and last.interpretations is None
        and last.category is None
        and not last.refinements
        and (last.count or 1) == 1
    )


def same_modifier(kept: Sequence[Mention], mention: Mention) -> Mention | None:
    """'Valencia in the lower grove and Moro in the upper grove; the upper grove has ...':
    the one field named before with the word that sets this plot apart ("upper")."""
    plots = [h for h in mention.heads if h.role == "plot"]
    if len(plots) != 1:
        return None
    before = [i for i in mention.items if i.end <= plots[0].start]
    if (
        not before
        or before[-1].role not in ("unknown", "filler", "stage", "other", "zone")
        or before[-1].norm in ARTICLES | definite_words()
    ):
        return None
    word = before[-1].norm
    fields = [r for m in kept for r in (m.refinements or [m])]
    same = [
        m
        for m in fields
        if any(a.norm == word and b.role == "plot" for a, b in itertools.pairwise(m.items))
    ]
    return same[0] if len(same) == 1 else None


def as_many_of_that_kind(kept: Sequence[Mention], mention: Mention) -> bool:
    """Whether the fields named before that grow the kind ``mention`` names are exactly as
    many as it counts ("the two sweetcorn plots" after two sweetcorn plots)."""

    def kinds(m: Mention) -> set[tuple[str, str]]:
        return {(c, v) for c, v, weak in m.interpretations or () if v is not None and not weak}

    own = kinds(mention)
    members = {id(r): r for m in kept for r in (m.refinements or [m])}.values()
    same = [r for r in members if own and kinds(r) == own]
    return sum(r.count or 1 for r in same) == mention.count


def listed_again(clauses: Sequence[Clause], clause: Clause, earlier: Mention) -> bool:
    """Whether ``clause`` names a kind again as the next member of the plain list that
    named it first ("sweetcorn, popcorn and sweetcorn"): every clause from the first to
    this one names one bare field and is joined by a comma or "and", and none is placed
    (not "Valencia and Hamlin, Valencia east of Hamlin")."""
    run = clauses[earlier.clause : clause.index + 1]
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    if len(run) < 3 or earlier.clause >= clause.index:
        return False
    if (
        following is not None
        and following.link is not None
        and following.link.role in ("relation", "between", "trailer")
    ):
        return False
    return all(
        len(c.mentions) == 1
        and c.mentions[0].count is None
        # (each member only named: not "riesling & chardonnay, riesling on the left ...",
        # "spuds & carrots & onions, spuds r flowering", "cherries 5 x 3 m over 2 ha")
        and all(_naming_only(i) for i in c.items)
        and (c is run[0] or (c.link is not None and c.link.role in ("separator", "conjunction")))
        # ("butterhead (boston) lettuce": a name in brackets is the same kind again)
        and (
            c is run[0]
            or (c.link is not None and c.link.norm not in (".", ";", ":", "!", "?", "(", ")"))
        )
        for c in run
    )


def _naming_only(item: Item) -> bool:
    """Whether a word of a listed member only names it ("sweetcorn", "a", "plot")."""
    return item.role in ("head", "weak_variety", "plot") or item.norm in ("a", "an", "the", "some")


#: Where an ordinal word points among the fields named in order.
_ORDER_OF = {**{word: at for at, word in enumerate(ORDINAL_WORDS)}, "the last": -1}


def named_in_order(kept: Sequence[Mention], mention: Mention) -> Mention | None:
    """The field "the first field" / "the second plot" / "the last block" points at among
    two or more fields named before, in the order named ("place the second plot east of
    the first": past the request's verb); None for any other mention."""
    ordered = sorted(mention.items, key=lambda item: item.start)
    first = next((i for i in ordered if i.role != "filler"), None)
    if (
        first is None
        or first.role != "reference"
        or first.norm not in _ORDER_OF
        or mention.has_crop
        or mention.category is not None
        or mention.count not in (None, 1)
        or not mention.heads
        or any(h.role != "plot" or h.data["value"].get("plural") for h in mention.heads)
    ):
        return None
    fields = list({id(r): r for m in kept for r in (m.refinements or [m])}.values())
    at = _ORDER_OF[first.norm]
    if len(fields) < 2 or at >= len(fields):
        return None
    return fields[at]


def both_of_the_counted(kept: Sequence[Mention], mention: Mention) -> list[Mention]:
    """The members of the counted plural named last, when ``mention`` is only "both" (or
    "all") and a plural plot noun naming no crop ("in both blocks"); else none."""
    if mention.has_crop or mention.count is not None or not said_of_all_plots(mention):
        return []
    host = next((m for m in reversed(kept) if m.refinements), None)
    if host is None:
        return []
    members = list({id(r): r for r in host.refinements}.values())
    if len(members) < 2 or (any(i.norm == "both" for i in mention.items) and len(members) != 2):
        return []
    return members


def bare_one(kept: Sequence[Mention], mention: Mention) -> bool:
    """'fruit one north of the veg one', 'agria one south of the fontane': a crop said
    with "one" after it and nothing before it stands for the field of that crop named
    before (not "a spring wheat one", a new field)."""
    first = first_word(mention)
    own = strong_crops(mention)
    if first is None or first not in mention.heads or not pronoun_one(mention):
        return False
    if own:
        return any(own <= strong_crops(m) for m in kept)
    # ("fruit one north of the veg one": a field of a group of crops named before)
    return mention.category is not None and any(
        m.category == mention.category and not m.has_crop for m in kept
    )


def with_one_named_before(clause: Clause, kept: Sequence[Mention], mention: Mention) -> bool:
    """'carrots + onions + peppers w/ the onions in the middle': "with the" and a crop a
    field named before (no variety, no count) after another field in the same clause is
    that field again, placed by what follows."""
    first = first_word(mention)
    if first is None or first.norm != "the" or mention.count is not None:
        return False
    before = [i for i in clause.items if i.end <= first.start]
    own = strong_crops(mention)
    return (
        bool(before)
        and before[-1].norm == "with"
        and bool(own)
        and not names_a_variety(mention)
        and not own & strong_crops(clause.mentions[0])
        and any(strong_crops(m) == own for m in kept if m not in clause.mentions)
    )


def of_it(mention: Mention) -> bool:
    """'one big field of it', 'a field of those': a plot word whose crop is "it", "them" or
    "those", named before."""
    if mention.has_crop or not any(h.role == "plot" for h in mention.heads):
        return False
    norms = [i.norm for i in mention.items]
    return any(
        a == "of" and b in ("it", "them", "those", "these") for a, b in itertools.pairwise(norms)
    )


def look_then_its_place(clause: Clause, mention: Mention) -> bool:
    """Whether the clause opens with a look and names only a singular plot of no crop
    after "in the" or "on the" ("ready to cut in the near field")."""
    words = sorted(clause.items, key=lambda i: i.start)
    plots = [i for i in words if i.role == "plot"]
    if (
        not words
        or words[0].role not in ("cue", "stage")
        or mention.has_crop
        or mention.category is not None
        or mention.count is not None
        or mention.plot is None
        or mention.plot["plural"]
        or len(plots) != 1
    ):
        return False
    # ("in the near field": at most one word between "the" and the plot)
    before = [i.norm for i in words if i.start < plots[0].start][-3:]
    return any(a in ("in", "on") and b == "the" for a, b in itertools.pairwise(before))


def is_summary(mention: Mention) -> bool:
    """'..., three fields', '..., two orchards': a count of plots restating the fields just
    listed (a plot noun that narrows must fit them: the coreference check sees to it)."""
    return (
        (mention.count or 1) >= 2
        and mention.interpretations is None
        and all(h.role == "plot" for h in mention.heads)
        and (mention.category is None or all(h.data["value"]["narrows"] for h in mention.heads))
    )


def another_variety_in_brackets(
    clauses: Sequence[Clause], clause: Clause, mention: Mention, kept: Sequence[Mention]
) -> bool:
    """Whether a crop named bare is followed by a variety of it in brackets that no field
    of that crop named before has: "tomatoes (beefsteak) + tomatoes (roma)" is two."""
    following = clauses[clause.index + 1] if clause.index + 1 < len(clauses) else None
    if (
        names_a_variety(mention)
        or clause.mentions[-1:] != [mention]
        or following is None
        or following.link is None
        or following.link.norm != "("
        or len(following.mentions) != 1
    ):
        return False
    said = following.mentions[0]
    crops = strong_crops(mention)
    if not crops or not names_a_variety(said) or strong_crops(said) != crops:
        return False
    same_crop = [k for k in kept if strong_crops(k) == crops]
    return bool(same_crop) and all(
        names_a_variety(k) and not same_variety(k, said) for k in same_crop
    )


def its_plot_named(repeated: Sequence[Mention], clause: Clause, mention: Mention) -> bool:
    """Whether ``mention`` ("Beefsteak plot") names the plot of the one field of its
    variety named bare before ("San Marzano and Beefsteak tomatoes"), not a second one."""
    return (
        len(repeated) == 1
        and repeated[0].plot is None
        and (repeated[0].count or 1) == 1
        and names_a_variety(mention)
        and not any(i.norm in ("second", "another", "new", "other") for i in clause.items)
    )

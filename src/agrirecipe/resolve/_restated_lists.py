"""A list of fields said again as its fields, not more fields (issue 8).

"my gran wants 'some veg and a few fruit trees' so like 1 veg field & 1 orchard",
"Roma tomatoes and Bintje potatoes, that is one tomato field and one potato field":
after a word that says the same thing again (``reader_words: restating``), as many
single fields as were named before, each one that could be the field in its place,
are those fields said again. Each pair becomes one field: the one that says more
(the narrower choice of crops; the first when alike), with the other's stage,
health, cues and season where it states none, and one field's count.
"""

from __future__ import annotations

from collections.abc import Sequence

from agrirecipe.resolve._lexicon import reader_words
from agrirecipe.resolve._mentions import Clause, Mention
from agrirecipe.resolve._structure import strong_crops
from agrirecipe.resolve._summaries import lend_and_drop

__all__ = ["drop_restated_lists"]


def drop_restated_lists(
    clauses: Sequence[Clause], mentions: list[Mention], crop_categories: dict[str, str]
) -> list[Mention]:
    """The fields left once a list said again after "so", "that is"... is one list."""
    half, odd = divmod(len(mentions), 2)
    if odd or half == 0:
        return mentions
    earlier, later = mentions[:half], mentions[half:]
    restating = _restating_between(clauses, earlier[-1], later[0])
    if restating is None:
        return mentions
    colon = restating == ":"
    if any(m.refinements or m.count not in (None, 1) for m in mentions):
        return mentions
    if not all(_said_as_one(m) for m in later):
        return mentions
    choices = [_could_be(m, crop_categories) for m in mentions]
    pairs = list(zip(range(half), range(half, len(mentions)), strict=True))
    if not all(_alike(choices[a], choices[b]) for a, b in pairs):
        return mentions
    dropped: list[Mention] = []
    for a, b in pairs:
        first, second = mentions[a], mentions[b]
        # (alike, the one said after a colon, where its measures are: "vines and cherries
        # for the net: a 1.5 acre vineyard with 3 m rows, ...")
        if _narrower(choices[b], choices[a]) or (colon and not _narrower(choices[a], choices[b])):
            kept, other = second, first
        else:
            kept, other = first, second
        lend_and_drop(clauses, other, [kept])
        kept.count, kept.quantity, kept.implied_count = 1, None, False
        dropped.append(other)
    return [m for m in mentions if all(m is not d for d in dropped)]


def _restating_between(clauses: Sequence[Clause], before: Mention, after: Mention) -> str | None:
    """The restating word that opens ``after`` ("..., so like 1 veg field"): after
    ``before``'s last head, with nothing but ``after``'s own words and a filler ("like",
    a comma) between it and ``after``'s head (not "a vine every 1.6 m or so, and ..."); None
    when there is none."""
    if not before.heads or not after.heads:
        return None
    start = max(h.end for h in before.heads)
    end = min(h.start for h in after.heads)
    items = [i for c in clauses for i in ([c.link] if c.link else []) + c.items]
    between = sorted((i for i in items if start <= i.start < end), key=lambda i: i.start)
    own = {id(i) for i in after.items}
    for phrase in sorted(reader_words("restating"), key=len, reverse=True):
        words = phrase.split()
        for at in range(len(between) - len(words) + 1):
            if [i.norm for i in between[at : at + len(words)]] != words:
                continue
            if at and between[at - 1].norm in _NOT_RESTATING:
                continue  # "or so", "and so"
            rest = between[at + len(words) :]
            if all(id(i) in own or i.norm in _FILLERS for i in rest):
                return phrase
    return None


#: Words before "so" that make it no restating word ("1.6 m or so", "and so on").
_NOT_RESTATING = frozenset({"or", "and", "about", "just", "not"})
#: Words that may stand between a restating word and the list it says again.
_FILLERS = frozenset({"like", ",", ":", "-", "just", "basically", "really", "kinda", "um"})


def _said_as_one(mention: Mention) -> bool:
    """ "1 veg field", "one orchard", "a veg field": one field, said so."""
    head = min(h.start for h in mention.heads)
    return any(
        i.start < head and (i.norm in ("one", "1", "single", "a", "an") or i.role == "number")
        for i in mention.items
    ) and mention.count in (None, 1)


def _could_be(mention: Mention, crop_categories: dict[str, str]) -> frozenset[str] | None:
    """The crops a mention could be (None: any crop)."""
    choices: frozenset[str] | None = None

    def narrow(crops: set[str] | frozenset[str]) -> None:
        nonlocal choices
        choices = frozenset(crops) if choices is None else choices & frozenset(crops)

    if strong := strong_crops(mention):
        narrow(strong)
    elif mention.interpretations:
        narrow({crop for crop, _, _ in mention.interpretations})
    if mention.category is not None:
        narrow({c for c, category in crop_categories.items() if category == mention.category})
    plot = mention.plot or {}
    if plot.get("options"):
        narrow(set(plot["options"]) | set(plot.get("tolerates", ())))
    if plot.get("category") is not None:
        narrow({c for c, category in crop_categories.items() if category == plot["category"]})
    return choices


def _alike(a: frozenset[str] | None, b: frozenset[str] | None) -> bool:
    return a is None or b is None or bool(a & b)


def _narrower(a: frozenset[str] | None, b: frozenset[str] | None) -> bool:
    """Whether choice ``a`` says strictly more than ``b``."""
    return a is not None and (b is None or a < b)

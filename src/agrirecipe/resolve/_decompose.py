"""Decomposition: from role-tagged items to field mentions, their attributes and relations.

The prompt is cut into *clauses* at separators, conjunctions and relation
words. Inside a clause, consecutive compatible *heads* (crop, variety,
category and plot words) form one *mention* ("a healthy Pink Lady apple
orchard"); an incompatible head starts another ("an apple orchard with a
carrot field"). Attributes (stage, season, month, health, size) attach to the
mention of their clause; a clause without a head ("..., all in autumn",
"..., ripe and healthy") attaches to every field when it says so ("all",
"both"), else to its neighbour. A plural mention can be refined by the
clauses after it ("Two orchards: one of Gala, one of Fuji"). Relation words
link the mentions on either side ("north of", "next to", "between X and Y").
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Collection, Sequence
from typing import Any

from agrirecipe._errors import PromptError
from agrirecipe.resolve._contradictions import (
    check_adjacent_variety,
    names_plants_of,
    plot_conflict,
    plot_excludes,
)
from agrirecipe.resolve._lexicon import Item, Token, vocabulary
from agrirecipe.resolve._mentions import (
    PRE_HEAD,
    Clause,
    Interpretation,
    Mention,
    combine_interpretations,
    head_interpretations,
    split_clauses,
)

__all__ = [
    "MentionBuilder",
    "colour_words",
    "decompose",
    "resolve_weak_varieties",
]

_HEADS = ("head", "plot", "other_crop")


def _plots_agree(one: dict[str, Any], other: dict[str, Any], categories: dict[str, str]) -> bool:
    """Whether two plot words can name one field: a plot of a category ("vegetable
    garden") cannot be a plot of crops outside it ("vineyard")."""
    for first, second in ((one, other), (other, one)):
        category = first.get("category")
        if (
            category is not None
            and second["options"]
            and not any(categories.get(c) == category for c in second["options"])
        ):
            return False
    return True


def _another_variety_than_the_weak_one(mention: Mention, item: Item) -> bool:
    """Whether head ``item`` names a variety other than the one a weak variety word before
    ``mention``'s crop names ("Navel oranges with Valencia oranges", "big mike bananas w/
    lady finger bananas": a second field)."""
    if not item.has("variety"):
        return False
    said = {
        str(s.value)
        for i in mention.items
        if i.role == "weak_variety"
        for s in i.senses_of("variety")
    }
    named = {str(s.value) for s in item.senses_of("variety")}
    return bool(said) and not said & named


class MentionBuilder:
    """Reads a clause's items into mentions; decides which heads can name one field."""

    def __init__(self, crop_categories: dict[str, str]) -> None:
        self.crop_categories = crop_categories

    def compatible(self, mention: Mention, item: Item) -> bool:
        """Whether head ``item`` can describe the same field as ``mention``."""
        if item.role == "other_crop":
            return (
                mention.interpretations is None
                and mention.category is None
                and not any(h.role == "other_crop" for h in mention.heads)
            )
        if any(h.role == "other_crop" for h in mention.heads):
            return item.role == "plot"
        if item.role == "plot":
            spec = item.data["value"]
            if (
                mention.plot is not None
                and spec["options"]
                and mention.plot["options"]
                and not set(spec["options"]) & set(mention.plot["options"])
            ):
                return False  # "an orchard vineyard": two plots, two fields
            if mention.plot is not None and not _plots_agree(
                spec, mention.plot, self.crop_categories
            ):
                return False  # "the vegetable garden south of the vineyard": two fields
            if mention.has_crop and spec["options"]:
                return not plot_excludes(spec, mention)  # "a carrot orchard": two things
            # "cereals at the top, root veg at the bottom": two fields
            return (
                mention.category is None
                or not spec["options"]
                or any(self.crop_categories.get(c) == mention.category for c in spec["options"])
            )
        interpretations = head_interpretations(item)
        categories = [str(s.value) for s in item.senses_of("category")]
        if categories and not interpretations:
            if mention.category is not None and mention.category not in categories:
                return False
            if (
                mention.plot is not None
                and mention.plot.get("category") is not None
                and mention.plot["category"] not in categories
            ):
                return False  # "Vegetable garden ..., fruit on the west side of it"
            if (
                mention.plot is not None
                and mention.plot["options"]
                and not any(
                    self.crop_categories.get(c) in categories for c in mention.plot["options"]
                )
            ):
                return False  # "an orchard, vegetables": two fields, not vegetable trees
            if mention.has_crop:
                return any(
                    self.crop_categories.get(c) in categories
                    for c, _, weak in mention.interpretations or ()
                    if not weak
                )
            return True
        category = mention.category or (
            mention.plot["category"]
            if mention.plot is not None and mention.plot.get("strict", False)
            else None
        )
        if category is not None:
            # ("a vegetable garden to the east, ..., wheat north of the orchard": two fields)
            interpretations = [
                i for i in interpretations if self.crop_categories.get(i[0]) == category
            ]
            if not interpretations:
                return False
        if mention.plot is not None and mention.plot["options"] and interpretations:
            # "a 2 ha orchard with a potato field": the orchard cannot be the potatoes
            allowed = (*mention.plot["options"], *mention.plot["tolerates"])
            if not any(c in allowed for c, _, _ in interpretations):
                return False
        return combine_interpretations(mention.interpretations, interpretations) is not None

    def add_head(self, mention: Mention, item: Item) -> None:
        """Add a head to a mention, narrowing its crop, variety, category or plot."""
        mention.heads.append(item)
        mention.items.append(item)
        if item.role == "plot":
            spec = item.data["value"]
            if spec["individual"] and mention.has_crop and plot_excludes(spec, mention):
                return  # "tomato vines" are tomato plants, not a vineyard
            held = mention.plot["options"] if mention.plot is not None else ()
            if held and set(held) <= set(spec["options"]):
                return  # "stone fruit trees": the trees of the narrower group named first
            if mention.plot is None or spec["narrows"]:
                mention.plot = spec
            return
        if item.role == "other_crop":
            return
        categories = [str(s.value) for s in item.senses_of("category")]
        interpretations = head_interpretations(item)
        if categories and not interpretations:
            mention.category = categories[0]
            if mention.interpretations is not None:
                mention.interpretations = [
                    i
                    for i in mention.interpretations
                    if self.crop_categories.get(i[0]) == mention.category
                ] or mention.interpretations
            return
        if mention.category is not None:
            interpretations = [
                i for i in interpretations if self.crop_categories.get(i[0]) == mention.category
            ] or interpretations
        combined = combine_interpretations(mention.interpretations, interpretations)
        mention.interpretations = combined if combined is not None else interpretations

    def read(self, clause: Clause) -> None:
        """Fill ``clause.mentions`` (or ``clause.loose`` when it names no field)."""
        current: Mention | None = None
        pending: list[Item] = []
        for index, item in enumerate(clause.items):
            if item.role not in _HEADS:
                pending.append(item)
                continue
            if current is None:
                current = Mention(clause=clause.index)
                self._absorb(current, pending, before_head=True)
            elif not pending and names_plants_of(current, item):
                item.role = "filler"  # "tomato vines": the tomato's own vines
                current.items.append(item)
                continue
            elif (
                self.compatible(current, item)
                # ("Navel oranges with Valencia oranges beside them": two varieties)
                and not _another_variety_than_the_weak_one(current, item)
            ) and not (
                # "west of the vineyard there's a block of ...": a plot named by its kind
                # alone, then a new one ("on the chilli side there's a plot of ..." is
                # still the chilli plot); "the cherry orchard has a plot of ..."
                (
                    item.role == "plot"
                    and (
                        (not current.has_crop and _existential(clause, pending))
                        # ("... the 2 ha maize field there's a 1 ha strip of onions")
                        or (
                            _existential(clause, pending) and any(p.role == "size" for p in pending)
                        )
                        or _possessed(pending)
                        or (current.has_crop and _with_a_plot_of(clause.items, index, pending))
                        # ("a vineyard with a block of carrots to the north of it": a
                        # plot of a crop the vineyard cannot hold)
                        or (
                            _with_a_plot_of(clause.items, index, pending)
                            and not self.compatible(current, clause.items[index + 2])
                        )
                        or _placed_new(clause, pending)
                    )
                )
                # "between the two groves a block of bananas": a plot counted again;
                # "north of the orchard a big block of Winter Wheat": a plot named again
                or (
                    current.plot is not None
                    and (
                        (current.count or 1) >= 2
                        # ("north of both onion fields a field of Danvers carrots")
                        or any(i.role == "all" and i.norm == "both" for i in current.items)
                        or (
                            # ("South of the grove a banana block": a crop named after
                            # the plot named again)
                            (item.role == "plot" or not current.has_crop)
                            and _opens_definite(current)
                            # (not "The only crop we have is a small block of ...")
                            and not any(p.norm in ("is", "are", "was", "were") for p in pending)
                        )
                    )
                    and any(
                        (p.role == "number" and p.norm in ("a", "an"))
                        # ("east of the grove the Dwarf Cavendish": a field named by "the")
                        or (
                            p.norm == "the"
                            and not current.has_crop
                            and current.count is None
                            and _opens_definite(current)
                            and item.has("crop", "variety")
                        )
                        for p in pending
                    )
                    and not any(p.role in ("of", "geometry") for p in pending)
                    # ("north of the garden a 10-acre corn field": a size after "a")
                    and not any(
                        p.role == "size" and (k == 0 or pending[k - 1].norm not in _ARTICLE)
                        for k, p in enumerate(pending)
                    )
                )
            ):
                current.conflict = current.conflict or plot_conflict(current, item, pending)
                self._absorb(current, pending, before_head=False, counts=_counts_fields(item))
            else:
                conflict = plot_conflict(current, item, pending)
                current.continued = conflict is not None
                check_adjacent_variety(current, item, pending)
                cut = _pre_head_start(pending)
                self._absorb(current, pending[:cut], before_head=False)
                clause.mentions.append(current)
                current = Mention(clause=clause.index, conflict=conflict)
                self._absorb(current, pending[cut:], before_head=True)
            pending = []
            self.add_head(current, item)
        if current is not None:
            self._absorb(current, pending, before_head=False)
            clause.mentions.append(current)
        else:
            clause.loose = pending
        for mention in clause.mentions:
            resolve_weak_varieties(mention)
            mention.distinct_crops = mention.distinct and not mention.has_crop

    @staticmethod
    def _absorb(
        mention: Mention, items: Sequence[Item], *, before_head: bool, counts: bool = True
    ) -> None:
        for index, item in enumerate(items):
            mention.items.append(item)
            # "an old wind pump in the corner of the field": the article is the pump's;
            # the field is named by "the" after it
            of_another = (
                before_head
                and item.norm in ("a", "an")
                and any(later.norm in ("the", "its", "their") for later in items[index + 1 :])
            )
            # "each carrying a double row of plants": the article is the row's
            of_another = of_another or (
                item.norm in ("a", "an")
                and index + 1 < len(items)
                and items[index + 1].role == "geometry"
            )
            # The amount nearest the head wins: "a combine ... a few cereal fields".
            counted = before_head or counts or bool(item.data.get("counts_kinds"))
            if item.role == "number" and counted and not of_another:
                value = float(item.data.get("value", 1))
                if before_head or item.norm not in ("a", "an"):
                    mention.count = _count(value, item)
                    mention.quantity = None
            elif item.role == "quantity" and (before_head or counts):
                mention.quantity = int(item.data["value"])
                if before_head:
                    mention.count = None
            elif item.role == "distinct":
                mention.distinct = True
            elif item.role == "other":
                mention.other = True


@functools.lru_cache(maxsize=1)
def _plant_words() -> frozenset[str]:
    nouns = vocabulary()["plot_nouns"]
    return frozenset(
        phrase.split()[-1] for phrase, spec in nouns.items() if (spec or {}).get("individual")
    )


def _counts_fields(item: Item) -> bool:
    """Whether a number before this head counts fields: "carrots in 3 fields", "two
    apples orchards" do; "an orchard with 200 trees" does not (it counts plants)."""
    if item.role == "plot":
        return not item.data["value"]["individual"]
    # "apple trees", "tomato plants": crop names that end in a word for the plants.
    return item.role == "head" and item.tokens[-1].norm not in _plant_words()


def _count(value: float, item: Item) -> int:
    if not math.isfinite(value) or value != int(value) or value < 1:
        raise PromptError(
            f"cannot make {item.raw!r} fields",
            stage="resolve",
            hint="say how many fields as a whole number, e.g. 'two carrot fields'",
        )
    if value > 64:
        raise PromptError(
            f"{int(value)} fields is more than a scene holds",
            stage="resolve",
            hint="ask for at most 64 fields",
        )
    return int(value)


#: "there's", "there is", "there are": words that bring in something new
_EXISTENTIAL = frozenset({"s", "is", "are", "was", "were", "stands", "lies", "sits"})
_ARTICLE = frozenset({"a", "an"})


def _said(pending: Sequence[Item], first: Collection[str], then: Collection[str]) -> bool:
    """Whether the words before a head hold a word of ``first`` right before one of
    ``then`` ("there" "is", "has" "a")."""
    norms = [t.norm for item in pending for t in item.tokens]
    return any(a in first and b in then for a, b in itertools.pairwise(norms))


def _existential(clause: Clause, pending: Sequence[Item]) -> bool:
    """'west of the vineyard there's a block of Navel oranges': after "there is" comes a
    new field, not more words about the one before; so it does after "west of the
    vineyard is a ..." (a place, then what stands there)."""
    if any(t.norm == "theres" for item in pending for t in item.tokens):
        return True
    if _said(pending, {"there"}, _EXISTENTIAL):
        return True
    return _placed_new(clause, pending)


#: "we've planted a", "we put in a": words that bring in a field newly planted
_PLANTED = frozenset({"planted", "put", "sown", "sowed", "grow", "growing", "set"})


def _placed_new(clause: Clause, pending: Sequence[Item]) -> bool:
    """'Next to the Navel oranges is a new block of Valencia', '... we've just planted a
    block of ...': after a place and the field it is said against, "is a" or "planted a"
    brings in a new field."""
    placed = clause.link is not None and clause.link.role == "relation"
    return placed and (_said(pending, _EXISTENTIAL, _ARTICLE) or _said(pending, _PLANTED, _ARTICLE))


def _possessed(pending: Sequence[Item]) -> bool:
    """'The cherry orchard has a plot of cherry tomatoes': what a field has is another."""
    return _said(pending, {"has", "have", "had"}, _ARTICLE)


def _with_a_plot_of(items: Sequence[Item], index: int, pending: Sequence[Item]) -> bool:
    """'5 ha of maize with a 1 ha field of onions': after "with a", a plot of another crop
    (the plot noun at ``index`` followed by "of" and a crop) is a field of its own."""
    norms = [p.norm for p in pending]
    said = [i for i, norm in enumerate(norms) if norm == "with"]
    if not said or norms[said[-1] + 1 : said[-1] + 2] not in (["a"], ["an"]):
        return False
    after = items[index + 1 : index + 3]
    return len(after) == 2 and after[0].norm == "of" and after[1].role == "head"


def _pre_head_start(pending: Sequence[Item]) -> int:
    """Where the next head's own noun phrase starts inside ``pending``."""
    cut = len(pending)
    # "1 ha of Red Baron onions with 1 ha of Sturon onions": the size is the next one's
    # ("a block of 2 hectares with golden acre cabbages": the block's own size)
    if cut >= 2 and pending[-1].norm == "of" and pending[-2].role == "size":
        cut -= 2
    while cut > 0 and pending[cut - 1].role in PRE_HEAD:
        cut -= 1
        if pending[cut].role == "number" or pending[cut].norm in ("a", "an", "the"):
            break
    return cut


def resolve_weak_varieties(mention: Mention) -> None:
    """A weak name ("golden", "navel") names a variety only next to its crop's name."""
    weak_items = [item for item in mention.items if item.role == "weak_variety"]
    if not weak_items:
        return
    strong_crops = {c for c, _, weak in mention.interpretations or () if not weak}
    plot_crops = set(mention.plot["options"]) if mention.plot and not strong_crops else set()
    for item in weak_items:
        options: list[Interpretation] = [
            (s.crop, str(s.value), False)
            for s in item.senses_of("variety")
            if s.crop in strong_crops
        ]
        if options and mention.interpretations is not None:
            combined = combine_interpretations(mention.interpretations, options)
            if combined:
                mention.interpretations = combined
                item.role = "head"
                mention.heads.append(item)
                continue
        # "a conference orchard": a plot that holds the variety's crop names it too
        held: list[Interpretation] = [
            (s.crop, str(s.value), False)
            for s in item.senses_of("variety")
            if s.crop is not None and s.crop in plot_crops
        ]
        if len({crop for crop, _, _ in held}) == 1 and mention.interpretations is None:
            mention.interpretations = held
            item.role = "head"
            mention.heads.append(item)
            continue
        # "Russet field": a name, not a colour, right before a plot of any crop names
        # the plot's variety (the mention names no crop of its own).
        named: list[Interpretation] = [
            (s.crop, str(s.value), False) for s in item.senses_of("variety") if s.crop
        ]
        if (
            len({crop for crop, _, _ in named}) == 1
            and mention.interpretations is None
            and _names_plot(mention, item)
        ):
            mention.interpretations = named
            item.role = "head"
            mention.heads.append(item)
            continue
        item.role = "filler"


def _names_plot(mention: Mention, item: Item) -> bool:
    """Whether ``item`` stands right before the mention's plot noun, which holds any crop,
    or right after it and "of" ("a block of Conference"), and is not also a colour word
    ("golden field" is a colour)."""
    if mention.plot is None or mention.plot.get("options") or mention.plot.get("category"):
        return False
    if item.norm in colour_words():
        return False
    position = next((k for k, i in enumerate(mention.items) if i is item), None)
    if position is None:
        return False
    following = mention.items[position + 1] if position + 1 < len(mention.items) else None
    if following is not None and following.role == "plot":
        return True
    before = mention.items[max(position - 2, 0) : position]
    return [i.role for i in before] == ["plot", "of"]


@functools.lru_cache(maxsize=1)
def colour_words() -> frozenset[str]:
    """The words of colours (``colour_words`` in vocabulary.yaml): "golden" is a look."""
    words = vocabulary()["colour_words"]
    return frozenset(str(w) for group in words.values() for w in group)


def _opens_definite(mention: Mention) -> bool:
    """Whether the mention opens with "the" (a plot named again: "the orchard")."""
    first = min(mention.items, key=lambda i: i.start, default=None)
    return first is not None and first.norm == "the"


def decompose(items: Sequence[Item], builder: MentionBuilder) -> list[Clause]:
    """Clauses with their mentions (refinements and coreference not yet applied)."""
    clauses = split_clauses(items)
    for clause in clauses:
        builder.read(clause)
    return _split_bare_lists(clauses)


def _split_bare_lists(clauses: list[Clause]) -> list[Clause]:
    """'3 fruit orchards: apple pear cherry', '4 veg plots: carrots onions lettuce &
    cabbage': crops named one after another with no mark between are a list, one clause
    per member as if commas parted them."""
    split: list[Clause] = []
    for clause in clauses:
        bare = len(clause.mentions) >= 2 and all(
            len(m.items) == 1 and m.items[0].role == "head" for m in clause.mentions
        )
        if not bare or len(clause.items) != len(clause.mentions):
            clause.index = len(split)
            for mention in clause.mentions:
                mention.clause = clause.index
            split.append(clause)
            continue
        for number, mention in enumerate(clause.mentions):
            link = clause.link
            if number:
                word = mention.items[0]
                mark = Token(",", ",", word.start, word.start)
                link = Item(tokens=(mark,), senses=(), role="separator")
            mention.clause = len(split)
            split.append(Clause(list(mention.items), link, len(split), mentions=[mention]))
    return split
